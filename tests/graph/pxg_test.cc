#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "graph/conformance.h"
#include "graph/evaluator.h"
#include "graph/pxg.h"
#include "tests/graph/test_graphs.h"
#include "tests/support/scratch_dir.h"

namespace procex {
namespace {

namespace fs = std::filesystem;

const fs::path kData = fs::path(PROCEX_TEST_DATA).parent_path() / "graph" / "data";

// A graph with everything the format holds: metadata, interface, every parameter type,
// an embedded group with an exposed parameter, editor state.
Graph rich_graph() {
  auto body = std::make_shared<Graph>();
  body->metadata.description = "adds one";
  (void)body->add_input(GraphInput{"x", &value_type<double>(), "in", {}});
  const NodeId inner = test::add(*body, "test.Add");
  const NodeId one = test::constant(*body, 1);
  test::link(*body, one, 0, inner, 1);
  (void)body->connect(PortRef{kGraphInputs, 0}, PortRef{inner, 0});
  test::output(*body, "y", inner);
  (void)body->expose_param(ExposedParam{"scale", inner, 0});

  Graph g;
  g.metadata = {"rich", "every feature of the format", "tests", "", ""};
  (void)g.add_input(GraphInput{"seed", &value_type<std::int64_t>(), "random seed", Value::make<std::int64_t>(7)});
  (void)g.add_input(GraphInput{"x", &value_type<double>(), "", {}});
  (void)g.add_group("plus_one", body);
  const NodeId e = test::add(g, "test.Everything");
  (void)g.set_param(e, "s", Value::make(std::string("quote \" and \\ and ünïcode")));
  (void)g.set_param(e, "v3", Value::make(Vec3{0.1, -2.5e-7, 3}));
  (void)g.set_param(e, "e", Value::make(EnumValue{"east"}));
  (void)g.set_param(e, "l", Value::make(std::vector<double>{}));
  const NodeId grp = g.add_group_node("plus_one").value();
  (void)g.set_param(grp, "scale", Value::make(3.0));
  (void)g.connect(PortRef{kGraphInputs, 1}, PortRef{grp, 0});
  test::output(g, "y", grp);
  (void)g.add_output(GraphOutput{"summary", &value_type<std::string>(), "text"});
  (void)g.connect(PortRef{e, 0}, PortRef{kGraphOutputs, 1});
  (void)g.set_editor_state(e, EditorState{12.5, -3, "look here", true});
  (void)g.expose_param(ExposedParam{"plus_scale", grp, 0});
  return g;
}

std::string error_of(std::string_view text, PxgOptions options = {}) {
  try {
    parse_pxg(text, "t.pxg", options);
  } catch (const PxgError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Pxg, SavesAreCanonicalAndRoundTripsAreByteIdentical) {
  Graph g = rich_graph();
  const std::string text = to_pxg(g);
  EXPECT_EQ(text, to_pxg(g));
  Graph back = parse_pxg(text, "rich.pxg");
  EXPECT_EQ(to_pxg(back), text);
  ResultCache cache;
  Evaluator ev(cache, "pxg");
  const Bindings b{{"x", Value::make(2.0)}};
  EXPECT_EQ(ev.hash_outputs(g, b).outputs[0].hash, ev.hash_outputs(back, b).outputs[0].hash);
  EvalResult r = ev.evaluate(back, b);
  ASSERT_TRUE(r.ok()) << r.diagnostics[0].to_string();
  EXPECT_EQ(r.output("y")->get<double>(), 9.0);
  EXPECT_EQ(back.node(1)->editor, (EditorState{12.5, -3, "look here", true}));
}

TEST(Pxg, StableLayoutForReadableDiffs) {
  const std::string text = to_pxg(test::diamond().g);
  // Keys sorted, one link and one node per line, format and version present.
  EXPECT_LT(text.find("\"editor\""), text.find("\"format\""));
  EXPECT_NE(text.find("\"format\": \"procex-graph\""), std::string::npos);
  EXPECT_NE(text.find("\"version\": 2"), std::string::npos);
  EXPECT_NE(text.find("\n    {\"from\": \"5.sum\", \"to\": \"7.a\"},\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\n    {\"from\": \"7.product\", \"to\": \"@result\"}\n"), std::string::npos);
  EXPECT_NE(text.find("\n    {\"id\": 7, \"params\": {}, \"type\": \"test.Mul\", \"version\": 1}\n"), std::string::npos);
}

TEST(Pxg, SaveIsAtomicAndLeavesNoTemporaryFiles) {
  const test::ScratchDir dir("pxg_save");
  const fs::path file = dir / "g.pxg";
  test::Diamond d = test::diamond();
  save_pxg(d.g, file);
  (void)d.g.set_param(d.c1, "value", Value::make(9.0));
  save_pxg(d.g, file);
  EXPECT_EQ(test::read_text(file), to_pxg(d.g));
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir.path())) ++files;
  EXPECT_EQ(files, 1u);
  EXPECT_THROW(save_pxg(d.g, dir / "no_such_dir" / "g.pxg"), std::runtime_error);
}

TEST(Pxg, Version1FilesMigrate) {
  std::vector<std::string> warnings;
  PxgOptions options;
  options.warnings = &warnings;
  Graph g = load_pxg(kData / "v1_diamond.pxg", options);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find("migrated from format version 1 to 2"), std::string::npos);
  EXPECT_NE(warnings[1].find("/nodes/4: 'test.Add' saved at version 1, now 2; parameters were upgraded"), std::string::npos)
      << warnings[1];
  EXPECT_EQ(g.node(5)->editor.comment, "left");
  EXPECT_EQ(g.node(5)->params[0].get<double>(), 2.0);  // version 1's "factor" is version 2's "scale"
  EXPECT_EQ(g.node(7)->editor.x, 400);
  ResultCache cache;
  Evaluator ev(cache, "pxg");
  EXPECT_EQ(ev.evaluate(g, {}).output("result")->get<double>(), 42.0);
  // Saving writes version 2 and reads back identically.
  const std::string v2 = to_pxg(g);
  EXPECT_NE(v2.find("\"version\": 2"), std::string::npos);
  EXPECT_EQ(to_pxg(parse_pxg(v2, kData / "v1_diamond.pxg")), v2);
}

TEST(Pxg, LibraryGroupsAreSharedByReference) {
  Graph g = load_pxg(kData / "uses_library.pxg");
  ASSERT_EQ(g.groups().size(), 1u);
  EXPECT_EQ(g.groups().at("scaler").file, "lib/scaler.pxg");
  ResultCache cache;
  Evaluator ev(cache, "pxg");
  EvalResult r = ev.evaluate(g, {});
  ASSERT_TRUE(r.ok()) << r.diagnostics[0].to_string();
  EXPECT_EQ(r.output("a")->get<double>(), 10.0);
  EXPECT_EQ(r.output("b")->get<double>(), 50.0);
  // The recipe keeps the reference; the library file is the canonical form of its own graph.
  EXPECT_EQ(to_pxg(g), test::read_text(kData / "uses_library.pxg"));
  EXPECT_EQ(to_pxg(load_pxg(kData / "lib" / "scaler.pxg")), test::read_text(kData / "lib" / "scaler.pxg"));
}

TEST(Pxg, GroupFilesMustStayInsideTheRecipeFolder) {
  EXPECT_NE(std::string(error_of(R"({"format": "procex-graph", "version": 2, "groups": [{"name": "g", "file": "/etc/passwd"}]})"))
                .find("/groups/0/file: group file '/etc/passwd' must be a path relative to the recipe's folder"),
            std::string::npos);
  try {
    load_pxg(kData / "lib" / "escapes.pxg");
    FAIL() << "loaded a file outside the folder";
  } catch (const PxgError& e) {
    EXPECT_EQ(e.where(), "/groups/0/file");
    EXPECT_NE(e.message().find("lies outside the recipe's folder"), std::string::npos) << e.what();
  }
  try {
    load_pxg(kData / "lib" / "self_a.pxg");
    FAIL() << "loaded a cycle of library files";
  } catch (const PxgError& e) {
    EXPECT_NE(e.message().find("includes itself"), std::string::npos) << e.what();
  }
  EXPECT_NE(error_of(R"({"format": "procex-graph", "version": 2, "groups": [{"name": "g", "file": "missing.pxg"}]})")
                .find("cannot read"),
            std::string::npos);
}

TEST(Pxg, LibraryFilesReferencedManyTimesAreReadOnce) {
  // level_k references level_{k-1} ten times: read naively, 10^12 file loads.
  const test::ScratchDir dir("pxg_fanout");
  std::ofstream(dir / "level_0.pxg") << R"({"format": "procex-graph", "version": 2})";
  for (int k = 1; k <= 12; ++k) {
    std::string groups;
    for (int i = 0; i < 10; ++i)
      groups += std::string(i ? ", " : "") + "{\"name\": \"g" + std::to_string(i) + "\", \"file\": \"level_" +
                std::to_string(k - 1) + ".pxg\"}";
    std::ofstream(dir / ("level_" + std::to_string(k) + ".pxg"))
        << R"({"format": "procex-graph", "version": 2, "groups": [)" << groups << "]}";
  }
  Graph g = load_pxg(dir / "level_12.pxg");
  EXPECT_EQ(g.groups().size(), 10u);
  EXPECT_EQ(g.groups().at("g0").type->body, g.groups().at("g9").type->body);  // one shared body
}

struct BadCase {
  const char* what;
  const char* text;
  const char* expected;  // a substring of the error
};

TEST(Pxg, UntrustedInputGetsLocatedErrors) {
  const std::string head = R"({"format": "procex-graph", "version": 2, )";
  const std::vector<BadCase> cases = {
      {"malformed", "{\n  \"format\": \"procex-graph\",\n  \"nodes\": [1, 2,,]\n}", "t.pxg: line 3, column 18: malformed JSON"},
      {"not an object", "[]", "t.pxg: expected a JSON object at the top"},
      {"wrong format", R"({"format": "other", "version": 2})", "t.pxg: /format: not a procex recipe"},
      {"newer", R"({"format": "procex-graph", "version": 99})", "written by a newer procex (format version 99)"},
      {"version type", R"({"format": "procex-graph", "version": "2"})", "/version: expected an integer version"},
      {"unknown type", R"("nodes": [{"id": 1, "type": "test.Adf", "version": 1}]})",
       "/nodes/0/type: unknown node type 'test.Adf'; did you mean 'test.Add'?"},
      {"newer node", R"("nodes": [{"id": 1, "type": "test.Add", "version": 3}]})",
       "/nodes/0/version: node type 'test.Add' version 3 is newer than this build's version 2"},
      {"param type", R"("nodes": [{"id": 1, "type": "test.Add", "version": 2, "params": {"scale": "big"}}]})",
       "/nodes/0/params/scale: bad float value: expected a number, got string"},
      {"param range", R"("nodes": [{"id": 1, "type": "test.Add", "version": 2, "params": {"scale": 1e300}}]})",
       "/nodes/0/params/scale: parameter 'scale' = 1e+300 is outside its range [-100, 100]"},
      {"param name", R"("nodes": [{"id": 1, "type": "test.Add", "version": 2, "params": {"scal": 1}}]})",
       "/nodes/0/params/scal: 'test.Add' has no parameter 'scal'; did you mean 'scale'?"},
      {"enum choice", R"("nodes": [{"id": 1, "type": "test.Fail", "version": 1, "params": {"how": "explode"}}]})",
       "/nodes/0/params/how: parameter 'how' has no choice 'explode' (choices: error, throw, out_of_memory)"},
      {"duplicate id",
       R"("nodes": [{"id": 4, "type": "test.Const", "version": 1}, {"id": 4, "type": "test.Const", "version": 1}]})",
       "/nodes/1/id: duplicate node id 4 (also at /nodes/0)"},
      {"id zero", R"("nodes": [{"id": 0, "type": "test.Const", "version": 1}]})", "/nodes/0/id: expected a node id"},
      {"id huge", R"("nodes": [{"id": 99999999999, "type": "test.Const", "version": 1}]})", "/nodes/0/id: expected a node id"},
      {"dangling", R"("nodes": [{"id": 1, "type": "test.Add", "version": 2}], "links": [{"from": "9.out", "to": "1.a"}]})",
       "/links/0/from: dangling link: there is no node 9"},
      {"bad port", R"("nodes": [{"id": 1, "type": "test.Add", "version": 2}], "links": [{"from": "1.nope", "to": "1.a"}]})",
       "/links/0/from: node 1 (test.Add) has no output 'nope'"},
      {"bad end", R"("links": [{"from": "x", "to": "1.a"}]})", "/links/0/from: 'x' is not \"node.port\" or \"@name\""},
      {"cycle",
       R"("nodes": [{"id": 1, "type": "test.Add", "version": 2}, {"id": 2, "type": "test.Add", "version": 2}],
          "links": [{"from": "1.sum", "to": "2.a"}, {"from": "2.sum", "to": "1.a"}]})",
       "/links/1: linking 2.sum to 1.a would make a cycle"},
      {"self loop", R"("nodes": [{"id": 1, "type": "test.Add", "version": 2}], "links": [{"from": "1.sum", "to": "1.a"}]})",
       "would make a cycle"},
      {"link types",
       R"("nodes": [{"id": 1, "type": "test.Everything", "version": 1}, {"id": 2, "type": "test.Add", "version": 2}],
          "links": [{"from": "1.summary", "to": "2.a"}]})",
       "/links/0: cannot link 1.summary (string) to 2.a (float): the types differ"},
      {"double feed",
       R"("nodes": [{"id": 1, "type": "test.Const", "version": 1}, {"id": 2, "type": "test.Add", "version": 2}],
          "links": [{"from": "1.out", "to": "2.a"}, {"from": "1.out", "to": "2.a"}]})",
       "/links/1: input 2.a is already fed by 1.out"},
      {"input type", R"("inputs": [{"name": "fp", "type": "footprnt"}]})", "/inputs/0/type: unknown value type 'footprnt'"},
      {"input name", R"("inputs": [{"name": "Foot Print", "type": "float"}]})", "/inputs/0: graph input name 'Foot Print' is not an identifier"},
      {"unknown graph port", R"("links": [{"from": "@nope", "to": "@out"}]})", "/links/0/from: no graph input named 'nope'"},
      {"editor ghost", R"("editor": {"nodes": {"3": {"x": 1}}}})", "/editor/nodes/3: editor state for a node that does not exist"},
      {"group name", R"("nodes": [{"id": 1, "group": "nope"}]})", "/nodes/0/group: no group named 'nope' in this recipe"},
      {"group needs body", R"("groups": [{"name": "g"}]})", "/groups/0: a group needs \"file\""},
      {"nodes not array", R"("nodes": {"1": {}}})", "/nodes: expected an array, got object"},
      {"exposed param", R"("nodes": [{"id": 1, "type": "test.Add", "version": 2}], "exposed": [{"name": "s", "node": 1, "param": "x"}]})",
       "/exposed/0/param: node 1 has no parameter 'x'"},
  };
  for (const BadCase& c : cases) {
    const std::string text = c.text[0] == '"' ? head + c.text : c.text;
    EXPECT_NE(error_of(text).find(c.expected), std::string::npos) << c.what << ":\n  " << error_of(text);
  }
}

TEST(Pxg, AbsurdSizesAndNestingAreRefused) {
  std::string deep = R"({"format": "procex-graph", "version": 2, "metadata": )";
  for (int i = 0; i < 100000; ++i) deep += "[";
  EXPECT_NE(error_of(deep).find("line 1, column 117: nesting deeper than 64 levels"), std::string::npos) << error_of(deep);

  PxgOptions small;
  small.limits.max_file_bytes = 100;
  EXPECT_NE(error_of(std::string(200, ' '), small).find("file is 200 bytes; the limit is 100"), std::string::npos);

  PxgOptions few;
  few.limits.max_nodes = 2;
  EXPECT_NE(error_of(R"({"format": "procex-graph", "version": 2, "nodes": [{}, {}, {}]})", few).find("/nodes: 3 entries; the limit is 2"),
            std::string::npos);

  PxgOptions short_strings;
  short_strings.limits.max_string = 8;
  EXPECT_NE(error_of(R"({"format": "procex-graph", "version": 2, "metadata": {"name": "a very long name"}})", short_strings)
                .find("/metadata/name: string of 16 bytes is too long"),
            std::string::npos);
}

TEST(Pxg, EveryGoodDataFileRoundTripsByteIdentically) {
  for (const fs::path& p : {kData / "uses_library.pxg", kData / "lib" / "scaler.pxg"})
    EXPECT_EQ(check_pxg_round_trip(p), std::vector<std::string>{});
  // The check can fail: a file written by hand is valid but not canonical.
  const auto problems = check_pxg_round_trip(kData / "v1_diamond.pxg");
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].find("saving does not reproduce the file byte for byte"), std::string::npos);
}

}  // namespace
}  // namespace procex
