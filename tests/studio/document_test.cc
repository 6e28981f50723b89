// Editor logic without a window: every edit goes through the undo stack,
// selection follows the graph, copy/paste and grouping, dirty state, saving.
#include "app/studio/editor/document.h"

#include <gtest/gtest.h>

#include <fstream>

#include "app/studio/editor/canvas_layout.h"
#include "app/studio/editor/exposed_default.h"
#include "graph/pxg.h"
#include "tests/studio/studio_test_util.h"

namespace procex::studio {
namespace {

using test::house_recipe;
using test::read_text;
using test::temp_dir;

// c1 -> add (a), c2 -> add (b)
struct Small {
  Document doc;
  NodeId c1 = 0, c2 = 0, add = 0;
  Small() {
    c1 = *doc.add_node("test.Const", 0, 0);
    c2 = *doc.add_node("test.Const", 0, 100);
    add = *doc.add_node("test.Add", 250, 50);
    EXPECT_TRUE(doc.connect({c1, 0}, {add, 0}));
    EXPECT_TRUE(doc.connect({c2, 0}, {add, 1}));
  }
};

TEST(Document, AnAbortedGestureLeavesNoTrace) {
  Small s;
  const std::string before = to_pxg(s.doc.graph());
  const std::string last = s.doc.undo_label();
  const std::uint64_t rev = s.doc.revision();
  s.doc.begin_gesture("two edits");
  ASSERT_TRUE(s.doc.set_param(s.c1, 0, Value::make(4.0)));
  ASSERT_TRUE(s.doc.add_node("test.Const", 0, 200));
  s.doc.abort_gesture();
  EXPECT_FALSE(s.doc.in_gesture());
  EXPECT_EQ(to_pxg(s.doc.graph()), before);
  EXPECT_EQ(s.doc.undo_label(), last);
  EXPECT_GT(s.doc.revision(), rev) << "the graph changed twice since: evaluate again";
}

TEST(Document, EditsAreUndoneAndRedoneOneByOne) {
  Small s;
  const std::string full = to_pxg(s.doc.graph());
  ASSERT_TRUE(s.doc.set_param(s.c1, 0, Value::make(4.0)));
  EXPECT_EQ(s.doc.graph().node(s.c1)->params[0].get<double>(), 4.0);
  EXPECT_TRUE(s.doc.undo());
  EXPECT_EQ(to_pxg(s.doc.graph()), full);
  EXPECT_TRUE(s.doc.redo());
  EXPECT_EQ(s.doc.graph().node(s.c1)->params[0].get<double>(), 4.0);
  // Five edits so far besides the parameter: 3 adds and 2 connects.
  int undone = 0;
  while (s.doc.undo()) ++undone;
  EXPECT_EQ(undone, 6);
  EXPECT_TRUE(s.doc.graph().nodes().empty());
}

TEST(Document, RefusedConnectionExplainsAndChangesNothing) {
  Small s;
  const std::uint64_t before = s.doc.revision();
  // A cycle: the sum back into its own input.
  Status st = s.doc.connect({s.add, 0}, {s.add, 0});
  EXPECT_FALSE(st);
  EXPECT_FALSE(st.message().empty());
  EXPECT_EQ(s.doc.revision(), before);
  // A wrong type: a string output into a float input.
  NodeId every = *s.doc.add_node("test.Everything", 0, 300);
  st = s.doc.connect({every, 0}, {s.add, 0});
  EXPECT_FALSE(st);
  EXPECT_NE(st.message().find("string"), std::string::npos) << st.message();
}

TEST(Document, GestureIsOneUndoStep) {
  Small s;
  s.doc.begin_gesture("drag value");
  for (int i = 1; i <= 10; ++i) ASSERT_TRUE(s.doc.set_param(s.c1, 0, Value::make(static_cast<double>(i))));
  s.doc.end_gesture();
  EXPECT_EQ(s.doc.graph().node(s.c1)->params[0].get<double>(), 10.0);
  EXPECT_TRUE(s.doc.undo());
  EXPECT_EQ(s.doc.graph().node(s.c1)->params[0].get<double>(), 1.0);  // the default
}

// The inspector's expression edits: each one undo step; the same value set
// over an expression replaces it (the inspector's "Use value"); a refusal
// changes nothing, not even the revision.
TEST(Document, ExpressionsAndBackToAValueAreOneUndoStepEach) {
  Small s;
  const std::string before = to_pxg(s.doc.graph());
  const double value = s.doc.graph().node(s.c1)->params[0].get<double>();
  ASSERT_TRUE(s.doc.set_expression(s.c1, 0, "2 + 3"));
  EXPECT_TRUE(s.doc.graph().node(s.c1)->expressions.count(0));
  const std::uint64_t rev = s.doc.revision();
  EXPECT_FALSE(s.doc.set_expression(s.c1, 0, "2 +"));
  EXPECT_FALSE(s.doc.set_expression(s.c1, 0, "true"));  // a bool for a float
  EXPECT_EQ(s.doc.revision(), rev);
  ASSERT_TRUE(s.doc.set_expression(s.c1, 0, "2 + 3"));  // the same text: no step
  EXPECT_EQ(s.doc.revision(), rev);
  ASSERT_TRUE(s.doc.set_param(s.c1, 0, Value::make(value)));
  EXPECT_FALSE(s.doc.graph().node(s.c1)->expressions.count(0));
  ASSERT_TRUE(s.doc.undo());
  EXPECT_EQ(s.doc.graph().node(s.c1)->expressions.at(0)->text(), "2 + 3");
  ASSERT_TRUE(s.doc.undo());
  EXPECT_EQ(to_pxg(s.doc.graph()), before);
}

TEST(Document, MoveOfSelectionIsOneStepAndChangesNoValue) {
  Small s;
  s.doc.select({s.c1, s.c2}, false);
  ASSERT_TRUE(s.doc.move_selection(10, -5));
  EXPECT_EQ(s.doc.graph().node(s.c1)->editor.x, 10);
  EXPECT_EQ(s.doc.graph().node(s.c2)->editor.y, 95);
  EXPECT_EQ(s.doc.graph().node(s.add)->editor.x, 250);
  EXPECT_TRUE(s.doc.undo());
  EXPECT_EQ(s.doc.graph().node(s.c1)->editor.x, 0);
  EXPECT_EQ(s.doc.graph().node(s.c2)->editor.y, 100);
}

TEST(Document, DeleteSelectionTakesLinksAndUndoRestoresThem) {
  Small s;
  s.doc.select_only(s.c1);
  ASSERT_TRUE(s.doc.remove_selection());
  EXPECT_EQ(s.doc.graph().node(s.c1), nullptr);
  EXPECT_TRUE(s.doc.selection().empty());
  EXPECT_FALSE(s.doc.graph().source({s.add, 0}));
  EXPECT_TRUE(s.doc.undo());
  ASSERT_TRUE(s.doc.graph().source({s.add, 0}));
  EXPECT_EQ(s.doc.graph().source({s.add, 0})->node, s.c1);
}

TEST(Document, SelectionDropsNodesThatAnUndoRemoves) {
  Small s;
  NodeId extra = *s.doc.add_node("test.Const", 0, 400);
  EXPECT_EQ(s.doc.selected(), extra);
  EXPECT_TRUE(s.doc.undo());
  EXPECT_TRUE(s.doc.selection().empty());
}

TEST(Document, CopyPasteDuplicatesNodesParametersAndInnerLinks) {
  Small s;
  ASSERT_TRUE(s.doc.set_param(s.c2, 0, Value::make(7.5)));
  s.doc.select({s.c2, s.add}, false);
  const std::string clip = s.doc.copy_selection();
  auto pasted = s.doc.paste(clip, 40, 40);
  ASSERT_TRUE(pasted) << pasted.message();
  const std::vector<NodeId>& ids = pasted.value();
  ASSERT_EQ(ids.size(), 2u);
  EXPECT_EQ(s.doc.graph().nodes().size(), 5u);
  EXPECT_EQ(s.doc.selection(), std::set<NodeId>(ids.begin(), ids.end()));
  const Node* c2_copy = s.doc.graph().node(ids[0]);
  const Node* add_copy = s.doc.graph().node(ids[1]);
  EXPECT_EQ(c2_copy->params[0].get<double>(), 7.5);
  EXPECT_EQ(c2_copy->editor.y, 140);
  // The link between the copied nodes is copied; the one from c1 (not copied) is not.
  EXPECT_EQ(s.doc.graph().source({add_copy->id, 1})->node, c2_copy->id);
  EXPECT_FALSE(s.doc.graph().source({add_copy->id, 0}));
  // The whole paste is one undo step.
  EXPECT_TRUE(s.doc.undo());
  EXPECT_EQ(s.doc.graph().nodes().size(), 3u);
}

TEST(Document, PasteOfForeignTextIsRefusedWithReason) {
  Small s;
  auto r = s.doc.paste("hello world", 0, 0);
  ASSERT_FALSE(r);
  EXPECT_NE(r.message().find("clipboard"), std::string::npos);
  EXPECT_EQ(s.doc.graph().nodes().size(), 3u);
}

TEST(Document, GroupSelectionMakesOneNodeAndUndoes) {
  Small s;
  s.doc.select({s.c1, s.c2}, false);
  auto g = s.doc.group_selection();
  ASSERT_TRUE(g) << g.message();
  EXPECT_EQ(s.doc.graph().nodes().size(), 2u);
  EXPECT_EQ(s.doc.graph().node(*g)->group, "group1");
  EXPECT_EQ(s.doc.selected(), *g);
  EXPECT_TRUE(s.doc.undo());
  EXPECT_EQ(s.doc.graph().nodes().size(), 3u);
}

// An opened group: graph() is its graph and edits there change the group,
// the breadcrumb names the way down, leaving selects the group node, the
// saved file holds the edited group, and undo reaches edits of any level.
TEST(Document, EditsInsideAGroupAreSavedAndUndoneFromAnyLevel) {
  const auto dir = temp_dir();
  Small s;
  s.doc.select({s.c1, s.c2}, false);
  const Result<NodeId> g = s.doc.group_selection();
  ASSERT_TRUE(g) << g.message();
  EXPECT_EQ(s.doc.enter_group(s.add).message(), "node " + std::to_string(s.add) + " is not a group node");
  ASSERT_TRUE(s.doc.enter_group(*g));
  EXPECT_EQ(s.doc.scope(), std::vector<NodeId>{*g});
  EXPECT_EQ(s.doc.breadcrumb(), (std::vector<std::string>{"untitled", "group1"}));
  EXPECT_TRUE(s.doc.selection().empty());
  EXPECT_EQ(s.doc.graph().nodes().size(), 2u) << "the two constants inside";
  const auto inner = [&](NodeId id) { return s.doc.recipe().node(*g)->type->body->node(id); };
  const std::uint64_t rev = s.doc.revision();
  ASSERT_TRUE(s.doc.set_param(s.c1, 0, Value::make(4.0)));
  EXPECT_GT(s.doc.revision(), rev) << "the recipe changed: evaluated again";
  EXPECT_EQ(inner(s.c1)->params[0].get<double>(), 4.0);
  s.doc.select_only(s.c2);
  ASSERT_TRUE(s.doc.move_selection(10, 0));
  EXPECT_EQ(inner(s.c2)->editor.x, 10);
  s.doc.leave_group(0);
  EXPECT_TRUE(s.doc.scope().empty());
  EXPECT_EQ(s.doc.selected(), *g);
  s.doc.save_as(dir / "grouped.pxg");
  EXPECT_EQ(load_pxg(dir / "grouped.pxg").groups().at("group1").type->body->node(s.c1)->params[0].get<double>(), 4.0);

  ASSERT_TRUE(s.doc.undo());  // the move inside, from the recipe's level
  EXPECT_EQ(inner(s.c2)->editor.x, 0);
  ASSERT_TRUE(s.doc.enter_group(*g));
  ASSERT_TRUE(s.doc.undo());  // the parameter
  EXPECT_EQ(inner(s.c1)->params[0].get<double>(), 1.0);
  ASSERT_TRUE(s.doc.undo());  // the grouping, from inside the group: back out to the recipe
  EXPECT_TRUE(s.doc.scope().empty());
  EXPECT_EQ(s.doc.graph().nodes().size(), 3u);
  ASSERT_TRUE(s.doc.redo());
  ASSERT_TRUE(s.doc.redo());
  EXPECT_EQ(s.doc.recipe().node(*g)->type->body->node(s.c1)->params[0].get<double>(), 4.0);
}

// The inspector reads a node of graph() after editing it in the same frame:
// an edit inside a group replaces the group's graph, and the one read from
// must outlive the edit until the frame ends (under ASan a use after free).
TEST(Document, ANodeOfTheGroupEnteredOutlivesItsEditUntilTheFrameEnds) {
  Small s;
  s.doc.select({s.c1, s.c2}, false);
  const Result<NodeId> g = s.doc.group_selection();
  ASSERT_TRUE(g) << g.message();
  ASSERT_TRUE(s.doc.enter_group(*g));
  const Node& before = *s.doc.graph().node(s.c1);
  const std::weak_ptr<const Graph> body = s.doc.recipe().node(*g)->type->body;
  ASSERT_TRUE(s.doc.set_param(s.c1, 0, Value::make(4.0)));
  ASSERT_TRUE(s.doc.set_param(s.c1, 0, Value::make(5.0)));
  EXPECT_FALSE(body.expired()) << "replaced by the edits, held until the frame ends";
  EXPECT_EQ(before.params[0].get<double>(), 1.0);
  EXPECT_EQ(s.doc.graph().node(s.c1)->params[0].get<double>(), 5.0);
  s.doc.end_frame();
  EXPECT_TRUE(body.expired()) << "no graph is kept past its frame";
}

TEST(Document, DirtyUntilSavedAndCleanAfterUndoingBack) {
  const auto dir = temp_dir();
  auto doc = Document::open(house_recipe());
  EXPECT_FALSE(doc->dirty());
  ASSERT_TRUE(doc->set_param(1, 1, Value::make(20.0)));
  EXPECT_TRUE(doc->dirty());
  EXPECT_TRUE(doc->undo());
  EXPECT_FALSE(doc->dirty());  // the same text as the file
  ASSERT_TRUE(doc->set_param(1, 1, Value::make(20.0)));
  doc->save_as(dir / "copy.pxg");
  EXPECT_FALSE(doc->dirty());
  EXPECT_EQ(doc->title(), "copy.pxg");
  const Graph reread = load_pxg(dir / "copy.pxg");
  EXPECT_EQ(reread.node(1)->params[1].get<double>(), 20.0);
  EXPECT_EQ(read_text(dir / "copy.pxg"), to_pxg(doc->graph()));
  // Only the target file: the temporary of the atomic write is gone.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()), 1);
}

TEST(Document, RecoveredEditsAreDirtyUntilSavedOverTheRecipe) {
  const auto dir = temp_dir();
  std::filesystem::copy_file(house_recipe(), dir / "house.pxg");
  Graph edited = load_pxg(dir / "house.pxg");
  ASSERT_TRUE(edited.set_param(1, "width", Value::make(21.0)));
  auto doc = Document::recovered(parse_pxg(to_pxg(edited), dir / "house.pxg"), dir / "house.pxg");
  EXPECT_TRUE(doc->dirty());
  EXPECT_EQ(doc->title(), "house.pxg");
  doc->save();
  EXPECT_FALSE(doc->dirty());
  EXPECT_EQ(load_pxg(dir / "house.pxg").node(1)->params[1].get<double>(), 21.0);
}

TEST(Document, SavingUntitledNeedsAName) {
  Document doc;
  EXPECT_THROW(doc.save(), std::runtime_error);
}

TEST(Document, OpenOfBadFileThrowsWithLocation) {
  const auto dir = temp_dir();
  {
    std::ofstream(dir / "bad.pxg") << "{\"format\": \"procex-graph\", \"version\": 2, \"nodes\": [ {\"id\": 1, \"type\": \"Extrud\"} ]}";
  }
  try {
    Document::open(dir / "bad.pxg");
    FAIL() << "expected a PxgError";
  } catch (const PxgError& e) {
    EXPECT_NE(std::string(e.what()).find("Extrude"), std::string::npos) << e.what();
  }
}

// Variadic ports: Merge's `inputs` (an int) and Switch's `cases` (a list of strings).
TEST(Document, PortCountsChangeAsOneUndoStepAndNeverDropAConnectedPort) {
  Document doc;
  const NodeId extrude = *doc.add_node("Extrude", 0, 0);
  const NodeId merge = *doc.add_node("Merge", 250, 0);
  const std::size_t inputs = *doc.graph().node(merge)->decl().param_index("inputs");
  ASSERT_EQ(doc.graph().node(merge)->decl().inputs().size(), 2u);
  ASSERT_TRUE(doc.set_port_count(merge, inputs, 3));
  EXPECT_EQ(doc.graph().node(merge)->decl().inputs().size(), 3u);
  ASSERT_TRUE(doc.connect({extrude, 0}, {merge, 2}));  // mesh_3
  const std::uint64_t before = doc.revision();
  const Status refused = doc.set_port_count(merge, inputs, 2);
  EXPECT_FALSE(refused);
  EXPECT_NE(refused.message().find("'mesh_3'"), std::string::npos) << refused.message();
  EXPECT_NE(refused.message().find("disconnect"), std::string::npos) << refused.message();
  EXPECT_EQ(doc.revision(), before);
  EXPECT_EQ(doc.graph().node(merge)->decl().inputs().size(), 3u);
  EXPECT_FALSE(doc.set_port_count(merge, inputs, 0));  // below the declared range
  ASSERT_TRUE(doc.set_port_count(merge, inputs, 5));
  EXPECT_EQ(doc.graph().node(merge)->decl().inputs().size(), 5u);
  EXPECT_TRUE(doc.undo());
  EXPECT_EQ(doc.graph().node(merge)->decl().inputs().size(), 3u);
  EXPECT_EQ(doc.graph().source({merge, 2}), (PortRef{extrude, 0}));

  const NodeId sw = *doc.add_node("Switch", 250, 200);
  const std::size_t cases = *doc.graph().node(sw)->decl().param_index("cases");
  ASSERT_TRUE(doc.set_param(sw, cases, Value::make(std::vector<std::string>{"house", "shop"})));
  ASSERT_TRUE(doc.set_port_count(sw, cases, 3));
  EXPECT_EQ(doc.graph().node(sw)->params[cases].get<std::vector<std::string>>(), (std::vector<std::string>{"house", "shop", ""}));
  EXPECT_EQ(doc.graph().node(sw)->decl().inputs().size(), 4u);  // default + 3 cases
  ASSERT_TRUE(doc.set_port_count(sw, cases, 1));
  EXPECT_EQ(doc.graph().node(sw)->params[cases].get<std::vector<std::string>>(), (std::vector<std::string>{"house"}));
  // Not a port-count parameter.
  EXPECT_FALSE(doc.set_port_count(sw, *doc.graph().node(sw)->decl().param_index("value"), 2));
}

// Making an asset: a parameter exposed with a name, label, range, default and
// unit (saved, and the range and unit on the group node made from the recipe);
// metadata; a preset saved and recalled; each one undo step.
TEST(Document, ExposesParametersEditsMetadataAndKeepsPresets) {
  const auto dir = test::temp_dir();
  auto doc = Document::open(test::house_recipe());
  ExposedParam style;
  style.name = "wall_height";
  style.label = "Wall height";
  style.unit = "m";
  style.min = 2.0;
  style.max = 30.0;
  const NodeId shape = 1;
  const std::size_t width = *doc->graph().node(shape)->decl().param_index("width");
  ASSERT_TRUE(doc->expose(shape, width, style, Value::make(16.0)));
  EXPECT_DOUBLE_EQ(doc->graph().node(shape)->params[width].get<double>(), 16.0);
  ASSERT_TRUE(doc->edit_recipe("set licence", [](Graph& g) {
    g.metadata.licence = "CC-BY-4.0";
    return Status::ok();
  }));
  ASSERT_TRUE(doc->save_preset("wide"));
  ASSERT_TRUE(doc->set_param(shape, width, Value::make(9.0)));
  ASSERT_TRUE(doc->apply_preset("wide"));
  EXPECT_DOUBLE_EQ(doc->graph().node(shape)->params[width].get<double>(), 16.0);
  EXPECT_FALSE(doc->expose(shape, width, style, Value()));  // the name is taken
  doc->save_as(dir / "asset.pxg");

  const Graph saved = load_pxg(dir / "asset.pxg");
  ASSERT_EQ(saved.exposed_params().size(), 1u);
  const ExposedParam& e = saved.exposed_params()[0];
  EXPECT_EQ(e.label, "Wall height");
  EXPECT_EQ(e.unit, "m");
  EXPECT_EQ(e.min, 2.0);
  EXPECT_EQ(e.max, 30.0);
  EXPECT_EQ(saved.metadata.licence, "CC-BY-4.0");
  ASSERT_EQ(saved.presets().size(), 1u);
  EXPECT_DOUBLE_EQ(saved.presets()[0].values.at("wall_height").get<double>(), 16.0);
  // Used as a group, the exposed parameter has the asset's range and unit, its value as default.
  auto type = make_group_type("asset", std::make_shared<Graph>(saved));
  ASSERT_TRUE(type);
  const ParamDecl& p = (*type)->decl.params()[0];
  EXPECT_EQ(p.name, "wall_height");
  EXPECT_EQ(p.min, 2.0);
  EXPECT_EQ(p.max, 30.0);
  EXPECT_EQ(p.unit, "m");
  EXPECT_NE(p.doc.find("Wall height"), std::string::npos);
  EXPECT_DOUBLE_EQ(p.default_value.get<double>(), 16.0);
  // Each edit undoes in one step: apply, set, preset, licence, expose.
  for (int i = 0; i < 5; ++i) ASSERT_TRUE(doc->undo());
  EXPECT_TRUE(doc->graph().exposed_params().empty());
  EXPECT_TRUE(doc->graph().presets().empty());
  EXPECT_TRUE(doc->graph().metadata.licence.empty());
  EXPECT_DOUBLE_EQ(doc->graph().node(shape)->params[width].get<double>(), 14.0);
}

// A preset naming a parameter the recipe does not expose is refused where it is.
TEST(Document, APresetForAnUnknownParameterIsALoadError) {
  const auto dir = test::temp_dir();
  std::string text = test::read_text(std::filesystem::path(PROCEX_SAMPLES) / "house.pxg");
  const std::string pitch = "\"steep\", \"values\": {\"pitch\"";
  ASSERT_NE(text.find(pitch), std::string::npos);
  text.replace(text.find(pitch), pitch.size(), "\"steep\", \"values\": {\"colour\"");
  std::ofstream(dir / "bad.pxg") << text;
  try {
    load_pxg(dir / "bad.pxg");
    ADD_FAILURE() << "loaded";
  } catch (const PxgError& e) {
    EXPECT_EQ(e.where(), "/presets/1/values/colour");
    EXPECT_NE(e.message().find("no exposed parameter named 'colour'"), std::string::npos) << e.message();
  }
}

// Inside a group, a parameter the group exposes is only the group's default:
// the inspector's note says so, naming the exposed name, the group and its instances.
TEST(Document, AGroupsExposedParameterInsideItIsNotedAsTheGroupsDefault) {
  auto doc = Document::open(std::filesystem::path(PROCEX_SAMPLES) / "city.pxg");
  ASSERT_EQ(doc->graph().node(1)->group, "building");
  const std::size_t switch_value = *doc->graph().node(6)->decl().param_index("value");
  EXPECT_EQ(exposed_default_note(*doc, 6, switch_value), "") << "the recipe's exposed parameters are its interface, not a default";
  const ExposedParam hip = doc->graph().node(1)->type->body->exposed_params().front();
  ASSERT_EQ(hip.name, "hip");
  const std::size_t hip_on_instance = *doc->graph().node(1)->decl().param_index("hip");
  const Value instance_value = doc->graph().node(2)->params[hip_on_instance];
  ASSERT_TRUE(doc->enter_group(1));
  const std::string note = exposed_default_note(*doc, hip.node, hip.param);
  EXPECT_NE(note.find("'hip'"), std::string::npos) << note;
  EXPECT_NE(note.find("group's default"), std::string::npos) << note;
  EXPECT_NE(note.find("5 instances"), std::string::npos) << note << " (the city's five buildings)";
  EXPECT_NE(note.find("'building' node"), std::string::npos) << note;
  // And it is so: set inside, the group's default changes and no instance's value does.
  std::vector<Vec2> points = doc->graph().node(hip.node)->params[hip.param].get<std::vector<Vec2>>();
  ASSERT_FALSE(points.empty());
  points.back().x += 0.25;
  ASSERT_TRUE(doc->set_param(hip.node, hip.param, Value::make(points)));
  EXPECT_EQ(doc->recipe().groups().at("building").type->body->node(hip.node)->params[hip.param].get<std::vector<Vec2>>(), points);
  EXPECT_EQ(doc->recipe().node(2)->params[hip_on_instance].get<std::vector<Vec2>>(), instance_value.get<std::vector<Vec2>>());
  // A parameter it does not expose has no note.
  for (std::size_t i = 0; i < doc->graph().node(hip.node)->decl().params().size(); ++i)
    if (i != hip.param) {
      EXPECT_EQ(exposed_default_note(*doc, hip.node, i), "");
    }
  doc->leave_group(0);
  EXPECT_EQ(exposed_default_note(*doc, hip.node, hip.param), "") << "at the recipe's level, node " << hip.node << " is an instance";
}

// The group library: a group saved beside the recipe as lib/NAME.pxg, then
// placed from there (read from the file, named apart from the recipe's own
// groups), one undo step; saved, the recipe names the file.
TEST(Document, GroupLibrarySavesAGroupAndPlacesItFromItsFile) {
  const auto dir = temp_dir();
  std::filesystem::copy_file(std::filesystem::path(PROCEX_SAMPLES) / "city.pxg", dir / "city.pxg");
  auto doc = Document::open(dir / "city.pxg");
  doc->select_only(6);  // the Switch: not a group
  EXPECT_FALSE(doc->save_group_to_library());
  doc->select_only(1);
  const Result<std::filesystem::path> saved = doc->save_group_to_library();
  ASSERT_TRUE(saved) << saved.message();
  EXPECT_EQ(*saved, std::filesystem::absolute(dir / "lib" / "building.pxg"));
  EXPECT_FALSE(doc->dirty()) << "saving a group to the library leaves the recipe as it was";
  EXPECT_EQ(to_pxg(load_pxg(*saved)), to_pxg(*doc->graph().node(1)->type->body));
  std::ofstream(dir / "lib" / "broken.pxg") << "{\"version\": 2, \"nodes\": [";
  EXPECT_EQ(library_files(dir), (std::vector<std::string>{"lib/broken.pxg", "lib/building.pxg"}));

  const std::uint64_t rev = doc->revision();
  const Result<NodeId> refused = doc->place_library_group("lib/broken.pxg", 0, 0);
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.message().find("broken.pxg"), std::string::npos) << refused.message();
  EXPECT_EQ(doc->revision(), rev) << "a refused file changes nothing";

  // Wanted on top of the first node: placed at the nearest spot where it covers none.
  const NodeBox first = *find_box(layout(doc->graph()), 1);
  const Result<NodeId> placed = doc->place_library_group("lib/building.pxg", first.rect.min.x + 40, first.rect.min.y + 30);
  ASSERT_TRUE(placed) << placed.message();
  const Node* n = doc->graph().node(*placed);
  ASSERT_TRUE(n);
  EXPECT_EQ(n->group, "building2") << "the recipe's own group keeps its name";
  const std::vector<NodeBox> boxes = layout(doc->graph());
  const Rect at = find_box(boxes, *placed)->rect;
  for (const NodeBox& b : boxes)
    if (b.id != *placed) {
      EXPECT_FALSE(at.overlaps(b.rect)) << "placed over node " << b.id;
    }
  EXPECT_EQ(doc->graph().groups().at("building2").file, "lib/building.pxg");
  EXPECT_EQ(doc->selected(), *placed);
  ASSERT_TRUE(doc->undo());
  EXPECT_FALSE(doc->graph().node(*placed));
  EXPECT_FALSE(doc->graph().groups().count("building2"));
  ASSERT_TRUE(doc->redo());
  ASSERT_TRUE(doc->graph().node(*placed)) << "redo places the same node";
  EXPECT_EQ(find_box(layout(doc->graph()), *placed)->rect, at) << "at the same spot";
  // Where nothing is, it is centred where it is wanted.
  const Result<NodeId> far = doc->place_library_group("lib/building.pxg", 20000, 10000);
  ASSERT_TRUE(far) << far.message();
  const Rect far_at = find_box(layout(doc->graph()), *far)->rect;
  EXPECT_EQ((far_at.min + far_at.max) * 0.5f, glm::vec2(20000, 10000));
  ASSERT_TRUE(doc->undo());
  doc->save();
  EXPECT_NE(read_text(dir / "city.pxg").find("\"file\": \"lib/building.pxg\""), std::string::npos);
  const Graph reloaded = load_pxg(dir / "city.pxg");
  EXPECT_EQ(reloaded.node(*placed)->group, "building2");

  Document untitled;
  EXPECT_NE(untitled.place_library_group("lib/building.pxg", 0, 0).message().find("save the recipe first"), std::string::npos);
}

// A recipe opened in place of another, both unedited: their revisions differ,
// so the studio evaluates the new one rather than keep the old one's preview.
TEST(Document, NoTwoDocumentsShareARevision) {
  auto first = Document::open(house_recipe());
  auto second = Document::open(house_recipe());
  EXPECT_NE(first->revision(), second->revision());
  EXPECT_FALSE(second->dirty());
  const std::uint64_t opened = second->revision();
  ASSERT_TRUE(second->set_param(1, 1, Value::make(20.0)));
  EXPECT_GT(second->revision(), opened);
  EXPECT_TRUE(second->dirty());
}

}  // namespace
}  // namespace procex::studio
