#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "graph/conformance.h"
#include "graph/registry.h"
#include "tests/support/scratch_dir.h"

namespace procex {
namespace {

TEST(Registry, ListsRegisteredTypesSortedWithTheirFiles) {
  auto all = NodeRegistry::global().all();
  ASSERT_GE(all.size(), 8u);
  EXPECT_TRUE(std::is_sorted(all.begin(), all.end(), [](auto& a, auto& b) { return a->name() < b->name(); }));
  auto add = NodeRegistry::global().find("test.Add");
  ASSERT_NE(add, nullptr);
  EXPECT_EQ(add->version(), 2);
  EXPECT_NE(add->source_file.find("test_nodes.cc"), std::string::npos);
  EXPECT_EQ(add->decl.inputs().size(), 2u);
  EXPECT_TRUE(add->decl.inputs()[1].optional);
  EXPECT_EQ(add->decl.params()[0].unit, "m");
  EXPECT_EQ(NodeRegistry::global().find("test.Nope"), nullptr);
}

// The check tests/nodes runs on nodes/: every file that uses PROCEX_REGISTER_NODE is registered.
TEST(Registry, EveryFileThatRegistersANodeIsRegistered) {
  const std::filesystem::path here = std::filesystem::path(PROCEX_TEST_DATA).parent_path() / "graph";
  EXPECT_EQ(unregistered_node_files(here), std::vector<std::filesystem::path>{});
  // And the check can fail: a file with a registration the registry never saw.
  const test::ScratchDir dir("unregistered");
  std::ofstream(dir / "dropped.cc") << "PROCEX_REGISTER_NODE(\"Dropped\", 1, declare, evaluate);\n";
  EXPECT_EQ(unregistered_node_files(dir.path()), std::vector<std::filesystem::path>{dir / "dropped.cc"});
}

TEST(Registry, SuggestsTheClosestName) {
  EXPECT_EQ(NodeRegistry::global().closest_name("test.add"), "test.Add");
  EXPECT_EQ(NodeRegistry::global().closest_name("tset.Mull"), "test.Mul");
  EXPECT_EQ(NodeRegistry::global().closest_name("CompletelyDifferentThing"), "");
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
  EXPECT_EQ(edit_distance("", "abc"), 3u);
}

TEST(Registry, MarkdownDocumentsPortsAndParameters) {
  const std::string md = NodeRegistry::global().markdown();
  EXPECT_NE(md.find("## Test"), std::string::npos);
  EXPECT_NE(md.find("### test.Add (v2)"), std::string::npos);
  EXPECT_NE(md.find("| `scale` | float | `1.0` | -100 .. 100 | m |"), std::string::npos) << md;
  EXPECT_NE(md.find("north, south, east"), std::string::npos);
}

void declare_bad(NodeDecl& d) {
  d.input<double>("x");
  d.input<double>("x");
}

TEST(NodeDecl, ValidateNamesTheMistake) {
  NodeDecl d("Bad", 1);
  declare_bad(d);
  EXPECT_EQ(d.validate().message(), "node type 'Bad': two inputs named 'x'");

  NodeDecl r("Ranged", 1);
  r.param<double>("h").default_value(20.0).range(0, 10);
  EXPECT_EQ(r.validate().message(), "node type 'Ranged': default: parameter 'h' = 20 is outside its range [0, 10]");

  NodeDecl n("Names", 1);
  n.output<double>("Bad Name");
  EXPECT_NE(n.validate().message().find("is not an identifier"), std::string::npos);

  NodeDecl m("Missing", 1);
  m.param<double>("h");
  EXPECT_EQ(m.validate().message(), "node type 'Missing': parameter 'h' has no default value");
}

TEST(NodeDecl, ParamCheckRefusesWrongTypesRangesAndChoices) {
  auto t = NodeRegistry::global().find("test.Everything");
  const auto& p = t->decl.params();
  EXPECT_TRUE(p[0].check(Value::make(0.25)));
  EXPECT_EQ(p[0].check(Value::make(2.0)).message(), "parameter 'f' = 2 is outside its range [0, 1]");
  EXPECT_EQ(p[0].check(Value::make<std::int64_t>(0)).message(), "parameter 'f' takes float, not int");
  EXPECT_EQ(p[1].check(Value::make<std::int64_t>(-1)).message(), "parameter 'i' = -1 is outside its range [0, inf]");
  EXPECT_EQ(p[6].check(Value::make(EnumValue{"west"})).message(),
            "parameter 'e' has no choice 'west' (choices: north, south, east)");
}

}  // namespace
}  // namespace procex
