// Every node file in nodes/ is registered, and every node type from nodes/
// passes the graph's generic conformance checks.
#include <algorithm>
#include <filesystem>

#include <gtest/gtest.h>

#include "graph/conformance.h"
#include "nodes/values.h"
#include "tests/support/scratch_dir.h"

namespace procex {
namespace {

// A 2 x 1 bay at 1 m in the middle of every edge.
PlanEditSpec bay_edit() {
  PlanEdit bay;
  bay.kind = PlanEdit::Kind::Natural;
  bay.width = 2.0;
  bay.depth = 1.0;
  bay.edges.assign(3, EdgeSpec{0.0, -1, -1});
  return {{{"bay", {}, 1.0, -1, {}}, ""}, {bay}, {}};
}

const std::filesystem::path kNodesDir = std::filesystem::path(PROCEX_SAMPLES) / ".." / "nodes";

bool from_nodes_dir(const NodeType& t) { return registered_in(t, kNodesDir); }

TEST(NodeRegistration, EveryNodeFileIsRegistered) {
  EXPECT_EQ(unregistered_node_files(kNodesDir), std::vector<std::filesystem::path>{});
}

TEST(NodeRegistration, EveryNodeFileRegistersOneType) {
  std::vector<std::string> files, registered;
  for (const auto& e : std::filesystem::directory_iterator(kNodesDir))
    if (e.path().extension() == ".cc" && e.path().filename() != "values.cc") files.push_back(e.path().stem().string());
  for (const auto& t : NodeRegistry::global().all())
    if (from_nodes_dir(*t)) registered.push_back(std::filesystem::path(t->source_file).stem().string());
  std::sort(files.begin(), files.end());
  std::sort(registered.begin(), registered.end());
  EXPECT_EQ(files, registered);
  EXPECT_GE(registered.size(), 14u);  // not zero: the linker kept the registrations
}

TEST(NodeRegistration, EveryTypeIsDocumented) {
  for (const auto& t : NodeRegistry::global().all()) {
    if (!from_nodes_dir(*t)) continue;
    SCOPED_TRACE(t->name());
    EXPECT_FALSE(t->decl.doc().empty());
    EXPECT_FALSE(t->decl.category().empty());
    for (const ParamDecl& p : t->decl.params()) EXPECT_FALSE(p.doc.empty()) << p.name;
  }
}

TEST(NodeRegistration, EveryTypeConforms) {
  const test::ScratchDir tmp("nodes_conformance");
  const Profile wall = Profile::straight(0, 3, "wall");
  MeshSet mesh;
  SampleInputs samples = {
      {&value_type<Footprint>(), Value::make(make_footprint({{{0, 0}, {10, 0}, {10, 6}, {0, 6}}}, 45))},
      {&value_type<Profile>(), Value::make(wall)},
      {&value_type<std::vector<Profile>>(), Value::make(std::vector<Profile>{wall, Profile::straight(40, 20)})},
      {&value_type<MeshSet>(), Value::make(mesh)},
      {&value_type<AnchorSpec>(), Value::make(AnchorSpec{{"window", {}, 1.0, -1, {}}, ""})},
      {&value_type<PlanEditSpec>(), Value::make(bay_edit())},
      {&value_type<std::vector<std::int64_t>>(), Value::make(std::vector<std::int64_t>{1})},
  };
  for (const auto& t : NodeRegistry::global().all()) {
    if (!from_nodes_dir(*t)) continue;
    SCOPED_TRACE(t->name());
    EXPECT_EQ(check_node_type(*t, samples, tmp.path()), std::vector<std::string>{});  // Export writes its default file there
  }
}

}  // namespace
}  // namespace procex
