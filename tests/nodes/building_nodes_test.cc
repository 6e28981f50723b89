// The building nodes through a real graph: labels and seeded picks, the
// extrusion's tags, switching, transforming, merging.
#include <gtest/gtest.h>

#include <set>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "core/io/glb_read.h"
#include "core/io/gltf_write.h"
#include "core/mesh/validate.h"
#include "graph/evaluator.h"
#include "graph/pxg.h"
#include "nodes/support/profile_presets.h"
#include "nodes/values.h"
#include "tests/nodes/node_runner.h"
#include "tests/support/scratch_dir.h"

namespace procex {
namespace {

using test::run_node;

Value rectangle(double w, double d, double angle = 45) {
  return Value::make(make_footprint({{{0, 0}, {w, 0}, {w, d}, {0, d}}}, angle));
}

Value presets() {
  std::vector<Profile> out;
  for (const std::string& name : preset_names()) out.push_back(make_preset(name, {}));
  return Value::make(out);
}

std::vector<int> assigned(const test::NodeRun& r) {
  std::vector<int> out;
  for (const Loop& l : r.outputs.at(0).get<Footprint>().loops)
    for (const EdgeSpec& e : l.edges) out.push_back(e.profile);
  return out;
}

std::map<std::string, std::size_t> faces_per_tag(const MeshSet& set) {
  std::map<std::string, std::size_t> out;
  for (const TaggedMesh& p : set.parts)
    for (std::size_t f = 0; f < p.face_tags.size(); ++f) ++out[face_tag(p, f)];
  return out;
}

//   3 +-----------+ 2      edge 2 (top) faces north: back
//     |           |        edges 1, 3: side
//   0 +-----------+ 1      edge 0 (bottom) faces south, the street
TEST(AssignProfiles, ByStreetOrientation) {
  const auto r = run_node("Assign Profiles",
                          {{"rules", Value::make(std::string("street = gable_end; back = hip; * = vertical_wall"))},
                           {"street", Value::make(EnumValue{"direction"})},
                           {"street_direction", Value::make(-90.0)}},
                          {{"footprint", rectangle(20, 8)}, {"profiles", presets()}});
  ASSERT_TRUE(r.ok()) << r.messages();
  EXPECT_EQ(assigned(r), (std::vector<int>{2, 0, 1, 0}));
  // The longest edge's side is the street by default: both long edges tie, the first wins.
  const auto by_longest = run_node("Assign Profiles", {{"rules", Value::make(std::string("street = 2; * = 0"))}},
                                   {{"footprint", rectangle(20, 8)}, {"profiles", presets()}});
  EXPECT_EQ(assigned(by_longest), (std::vector<int>{2, 0, 0, 0}));
}

// A terraced lot: edges 1 and 3 are shared with the neighbours. `party` picks
// them out, and the street is beyond the longest edge that is not a party wall.
TEST(AssignProfiles, PartyWalls) {
  const auto r = run_node("Assign Profiles",
                          {{"rules", Value::make(std::string("party = vertical_wall; street = gable_end; * = hip"))}},
                          {{"footprint", rectangle(6, 20)},
                           {"profiles", presets()},
                           {"party_edges", Value::make(std::vector<std::int64_t>{1, 3})}});
  ASSERT_TRUE(r.ok()) << r.messages();
  // Without party walls the 20 m edge 1 would face the street; with them edge 0 (6 m, south) does.
  EXPECT_EQ(assigned(r), (std::vector<int>{2, 0, 1, 0}));
  const auto alone = run_node("Assign Profiles",
                              {{"rules", Value::make(std::string("party = vertical_wall; street = gable_end; * = hip"))}},
                              {{"footprint", rectangle(6, 20)}, {"profiles", presets()}});
  EXPECT_EQ(assigned(alone), (std::vector<int>{1, 2, 1, 1}));
}

// Streets from data: edge 1 (20 m, east) faces a street line. `street` is it
// alone, edge 3 opposite is the back, edges 0 and 2 the sides.
TEST(AssignProfiles, StreetEdgesFromData) {
  const auto r = run_node("Assign Profiles",
                          {{"rules", Value::make(std::string("street = gable_end; back = vertical_wall; * = hip"))}},
                          {{"footprint", rectangle(6, 20)},
                           {"profiles", presets()},
                           {"street_edges", Value::make(std::vector<std::int64_t>{1})}});
  ASSERT_TRUE(r.ok()) << r.messages();
  EXPECT_EQ(assigned(r), (std::vector<int>{1, 2, 1, 0}));
  // Two street edges (a corner lot): both street, the back against the longer.
  const auto corner = run_node("Assign Profiles",
                               {{"rules", Value::make(std::string("street = gable_end; back = vertical_wall; * = hip"))}},
                               {{"footprint", rectangle(6, 20)},
                                {"profiles", presets()},
                                {"street_edges", Value::make(std::vector<std::int64_t>{0, 1})}});
  EXPECT_EQ(assigned(corner), (std::vector<int>{2, 2, 1, 0}));
}

TEST(AssignProfiles, ByLengthSelectionAndIndex) {
  const auto r = run_node("Assign Profiles",
                          {{"rules", Value::make(std::string("#3 = 5; selected = 4; long = 1; short = 3; * = 0"))},
                           {"selection", Value::make(std::vector<std::int64_t>{2})},
                           {"short_below", Value::make(9.0)}},
                          {{"footprint", rectangle(20, 8)}, {"profiles", presets()}});
  ASSERT_TRUE(r.ok()) << r.messages();
  EXPECT_EQ(assigned(r), (std::vector<int>{1, 3, 4, 5}));
}

TEST(AssignProfiles, SeededPerBuilding) {
  auto run = [](const std::string& building, std::int64_t seed, const char* draw) {
    return assigned(run_node("Assign Profiles",
                             {{"rules", Value::make(std::string("* = hip, gable_end"))},
                              {"seed", Value::make(seed)},
                              {"draw", Value::make(EnumValue{draw})}},
                             {{"footprint", rectangle(20, 8)},
                              {"profiles", presets()},
                              {"building_id", Value::make(building)}}));
  };
  std::set<std::vector<int>> per_building, per_edge;
  for (int b = 0; b < 40; ++b) {
    const std::string id = std::string("w").append(std::to_string(b));
    EXPECT_EQ(run(id, 1, "per_building"), run(id, 1, "per_building"));
    per_building.insert(run(id, 1, "per_building"));
    per_edge.insert(run(id, 1, "per_edge"));
  }
  // per_building: all edges alike, both choices occur over 40 buildings.
  EXPECT_EQ(per_building, (std::set<std::vector<int>>{{1, 1, 1, 1}, {2, 2, 2, 2}}));
  EXPECT_GT(per_edge.size(), 2u);
  std::set<std::vector<int>> seeds;
  for (std::int64_t seed = 0; seed < 20; ++seed) seeds.insert(run("w1", seed, "per_building"));
  EXPECT_EQ(seeds.size(), 2u);
}

TEST(AssignProfiles, BadRulesAreNodeErrors) {
  const auto r = run_node("Assign Profiles", {{"rules", Value::make(std::string("* = dome"))}},
                          {{"footprint", rectangle(20, 8)}, {"profiles", presets()}});
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.messages().find("rules: rule 1 ('* = dome'): no profile named 'dome'"), std::string::npos) << r.messages();
}

TEST(Extrude, HipRoofTagsAndVolume) {
  const auto r = run_node("Extrude", {{"validate", Value::make(true)}}, {{"footprint", rectangle(10, 6)}});
  ASSERT_TRUE(r.ok()) << r.messages();
  const MeshSet& m = r.outputs[0].get<MeshSet>();
  ASSERT_EQ(m.parts.size(), 1u);
  EXPECT_EQ(faces_per_tag(m), (std::map<std::string, std::size_t>{{"base", 1}, {"roof", 4}}));
  // A 45-degree hip roof on 10 x 6: ridge at height 3, volume = 6*6*3/3 (pyramid ends) + 4*(6*3/2) = 36 + 36.
  EXPECT_NEAR(validate(*m.parts[0].mesh).volume, 72.0, 1e-6);
}

TEST(Extrude, ProfilesGiveTagsAndHeight) {
  const auto assign = run_node("Assign Profiles", {{"rules", Value::make(std::string("* = vertical_wall"))}},
                               {{"footprint", rectangle(10, 6)}, {"profiles", presets()}});
  const auto r = run_node("Extrude", {{"validate", Value::make(true)}}, {{"footprint", assign.outputs[0]}});
  ASSERT_TRUE(r.ok()) << r.messages();
  const MeshSet& m = r.outputs[0].get<MeshSet>();
  EXPECT_EQ(faces_per_tag(m), (std::map<std::string, std::size_t>{{"base", 1}, {"cap", 1}, {"wall", 4}}));
  EXPECT_NEAR(validate(*m.parts[0].mesh).volume, 10 * 6 * 3.0, 1e-9);
}

TEST(Extrude, BadFootprintNamesLoopAndVertex) {
  const Value bowtie = Value::make(make_footprint({{{0, 0}, {4, 4}, {4, 0}, {0, 4}}}, 30));
  const auto r = run_node("Extrude", {}, {{"footprint", bowtie}});
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.messages().find("(Extrude)"), std::string::npos) << r.messages();
  EXPECT_NE(r.messages().find("loop 0"), std::string::npos) << r.messages();
}

TEST(Switch, ChoosesByValue) {
  auto run = [](const std::string& value) {
    const auto r = run_node("Switch",
                            {{"value", Value::make(value)},
                             {"cases", Value::make(std::vector<std::string>{"church, chapel", "garage", "shed", "hut"})}},
                            {{"default", Value::make(1.0)}, {"case_1", Value::make(2.0)}, {"case_4", Value::make(4.0)}});
    return r.outputs.at(0).get<double>();
  };
  EXPECT_EQ(run("chapel"), 2.0);
  EXPECT_EQ(run("church"), 2.0);
  EXPECT_EQ(run("yes"), 1.0);
  EXPECT_EQ(run("garage"), 1.0);  // case_2 is not connected: default
  EXPECT_EQ(run("hut"), 4.0);     // four cases, four case inputs
}

// Items are separated by commas and trimmed of spaces; an empty item (a
// trailing comma, a blank case) chooses nothing, not even the empty value.
TEST(Switch, ListsAreCommaSeparatedAndTrimmed) {
  auto run = [](const std::string& value) {
    const auto r = run_node("Switch",
                            {{"value", Value::make(value)},
                             {"cases", Value::make(std::vector<std::string>{"  a b , c,", " ", ",d"})}},
                            {{"default", Value::make(1.0)}, {"case_1", Value::make(2.0)}, {"case_2", Value::make(3.0)},
                             {"case_3", Value::make(4.0)}});
    return r.outputs.at(0).get<double>();
  };
  EXPECT_EQ(run("a b"), 2.0);
  EXPECT_EQ(run("c"), 2.0);
  EXPECT_EQ(run("d"), 4.0);
  EXPECT_EQ(run(""), 1.0);
  EXPECT_EQ(run(" "), 1.0);
  EXPECT_EQ(run("a"), 1.0);
}

// Version 1 had six fixed Merge inputs and five fixed Switch cases: files of
// that time load with those counts, every link in place.
TEST(MergeAndSwitch, VersionOneFilesUpgrade) {
  const std::string v1 = R"({"format": "procex-graph", "version": 2,
    "nodes": [{"id": 1, "type": "Footprint Shape", "version": 1, "params": {}},
              {"id": 2, "type": "Extrude", "version": 1, "params": {}},
              {"id": 3, "type": "Merge", "version": 1, "params": {}},
              {"id": 4, "type": "Switch", "version": 1,
               "params": {"value": "hut", "case_1": "church", "case_5": "hut, shed"}}],
    "links": [{"from": "1.footprint", "to": "2.footprint"}, {"from": "2.mesh", "to": "3.mesh_1"},
              {"from": "2.mesh", "to": "3.mesh_6"}, {"from": "3.mesh", "to": "4.default"},
              {"from": "2.mesh", "to": "4.case_5"}],
    "inputs": [], "outputs": [{"name": "mesh", "type": "mesh", "doc": ""}], "exposed": [], "groups": []})";
  Graph g = parse_pxg(v1, "v1.pxg");
  EXPECT_EQ(g.node(3)->params[0].get<std::int64_t>(), 6);
  EXPECT_EQ(g.node(4)->params[1].get<std::vector<std::string>>(),
            (std::vector<std::string>{"church", "", "", "", "hut, shed"}));
  EXPECT_EQ(g.source(PortRef{3, 5}), (PortRef{2, 0}));
  EXPECT_EQ(g.source(PortRef{4, 5}), (PortRef{2, 0}));
  ASSERT_TRUE(g.connect(PortRef{4, 0}, PortRef{kGraphOutputs, 0}));
  ResultCache cache(16 << 20);
  Evaluator ev(cache, "nodes test");
  const EvalResult r = ev.evaluate(g, {});
  ASSERT_TRUE(r.ok()) << r.diagnostics.at(0).to_string();
  EXPECT_EQ(r.output("mesh")->get<MeshSet>().parts.size(), 1u);  // "hut" chose case_5, not the merge of two
}

TEST(TransformAndMerge, MoveAndJoin) {
  const auto a = run_node("Extrude", {}, {{"footprint", rectangle(10, 6)}});
  const auto moved = run_node("Transform", {{"translate", Value::make(Vec3{0, 0, 5})}, {"rotate", Value::make(90.0)}},
                              {{"mesh", a.outputs[0]}});
  ASSERT_TRUE(moved.ok()) << moved.messages();
  double zmin = 1e9, xmin = 1e9;
  const Mesh& m = *moved.outputs[0].get<MeshSet>().parts[0].mesh;
  for (const auto v : m.vertices()) zmin = std::min(zmin, m.point(v)[2]), xmin = std::min(xmin, m.point(v)[0]);
  EXPECT_NEAR(zmin, 5, 1e-12);
  EXPECT_NEAR(xmin, -6, 1e-12);  // turned a quarter: y in [0, 6] became x in [-6, 0]
  const auto merged = run_node("Merge", {{"inputs", Value::make<std::int64_t>(3)}},
                               {{"mesh_1", a.outputs[0]}, {"mesh_3", moved.outputs[0]}});
  EXPECT_EQ(merged.outputs[0].get<MeshSet>().parts.size(), 2u);
  EXPECT_EQ(faces_per_tag(merged.outputs[0].get<MeshSet>()).at("roof"), 8u);
}

TEST(FootprintGeoJson, ReadsOneFeatureByIdOrIndex) {
  const std::filesystem::path samples = PROCEX_SAMPLES;
  const auto by_id = run_node("Footprint GeoJSON", {{"file", Value::make(std::string("footprints/sample_block.geojson"))},
                                                    {"id", Value::make(std::string("r1484217"))}}, {}, samples);
  ASSERT_TRUE(by_id.ok()) << by_id.messages();
  EXPECT_EQ(by_id.outputs[0].get<Footprint>().loops.size(), 2u);  // a courtyard
  const auto missing = run_node("Footprint GeoJSON", {{"id", Value::make(std::string("w0"))}}, {}, samples);
  EXPECT_NE(missing.messages().find("no feature with id 'w0' (18 features)"), std::string::npos) << missing.messages();
  const auto no_file = run_node("Footprint GeoJSON", {{"file", Value::make(std::string("nowhere.geojson"))}}, {}, samples);
  EXPECT_NE(no_file.messages().find("nowhere.geojson"), std::string::npos) << no_file.messages();
}

// A graph whose one output is a Footprint GeoJSON node reading `file` (and
// the feature `id` when not empty).
Graph footprint_file_graph(const std::string& file, const std::string& id) {
  Graph g;
  const NodeId n = g.add_node("Footprint GeoJSON").value();
  EXPECT_TRUE(g.set_param(n, "file", Value::make(file)));
  if (!id.empty()) {
    EXPECT_TRUE(g.set_param(n, "id", Value::make(id)));
  }
  EXPECT_TRUE(g.add_output({"footprint", &value_type<Footprint>(), ""}));
  EXPECT_TRUE(g.connect(PortRef{n, 0}, PortRef{kGraphOutputs, 0}));
  return g;
}

// An edited GeoJSON file is read again: its size and time are in the node's cache key.
TEST(FootprintGeoJson, AnEditedFileChangesTheHash) {
  const test::ScratchDir dir("geojson_node");
  auto write = [&](double x) {
    std::ofstream(dir / "plan.geojson") << R"({"type": "FeatureCollection", "features": [{"type": "Feature",
      "properties": {}, "geometry": {"type": "Polygon", "coordinates": [[[0,0],[)" << x << R"(,0],[10,8],[0,8],[0,0]]]}}]})";
  };
  const Graph g = footprint_file_graph("plan.geojson", "");
  ResultCache cache(1 << 20);
  Evaluator ev(cache, "nodes test");
  EvalOptions options;
  options.folder = dir.path();
  write(10);
  const EvalResult first = ev.evaluate(g, {}, {}, options);
  ASSERT_TRUE(first.ok());
  write(12.5);  // a different size, whatever the clock's resolution
  const EvalResult second = ev.evaluate(g, {}, {}, options);
  ASSERT_TRUE(second.ok());
  EXPECT_NE(first.outputs[0].hash, second.outputs[0].hash);
  EXPECT_EQ(second.stats.computed(), 1u);
  EXPECT_EQ(second.output("footprint")->get<Footprint>().loops[0].points[1].x, 12.5);
}

// A Shapefile is read again when its .dbf or .prj is edited, not only its .shp:
// the feature asked for by id appears when the .dbf renames it, and a .prj in
// feet makes a footprint a third the size (GDAL's ogr2ogr writes the files).
TEST(FootprintGeoJson, AnEditedShapefileSidecarChangesTheHash) {
  namespace fs = std::filesystem;
  const test::ScratchDir dir("shapefile_node");
  fs::create_directories(dir / "a");
  fs::create_directories(dir / "b");
  for (const char* id : {"a", "b"}) {
    const fs::path geojson = dir / id / "plan.geojson";
    std::ofstream(geojson) << R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {"id": ")"
                           << id << R"("}, "geometry": {"type": "Polygon", "coordinates": [[[0,0],[12,0],[12,8],[0,8],[0,0]]]}}]})";
    const std::string command = "ogr2ogr -a_srs EPSG:32632 " + (dir / id / "plan.shp").string() + " " + geojson.string();
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
  }
  const Graph g = footprint_file_graph("a/plan.shp", "b");
  ResultCache cache(1 << 20);
  Evaluator ev(cache, "nodes test");
  EvalOptions options;
  options.folder = dir.path();
  EXPECT_FALSE(ev.evaluate(g, {}, {}, options).ok());  // a/plan.dbf names the feature "a"
  // Only the .dbf changes (the same size: one letter for another), a minute later.
  fs::copy_file(dir / "b" / "plan.dbf", dir / "a" / "plan.dbf", fs::copy_options::overwrite_existing);
  fs::last_write_time(dir / "a" / "plan.dbf", fs::last_write_time(dir / "a" / "plan.shp") + std::chrono::minutes(1));
  const EvalResult renamed = ev.evaluate(g, {}, {}, options);
  ASSERT_TRUE(renamed.ok());
  auto width = [](const EvalResult& r) {
    double low = 1e300, high = -1e300;
    for (const auto& p : r.output("footprint")->get<Footprint>().loops[0].points) low = std::min(low, p.x), high = std::max(high, p.x);
    return high - low;
  };
  EXPECT_EQ(width(renamed), 12.0);
  // Only the .prj changes: the same numbers are US survey feet now, projected to metres.
  const std::string prj = "gdalsrsinfo --single-line -o wkt_esri EPSG:2263 > " + (dir / "a" / "plan.prj").string();
  ASSERT_EQ(std::system(prj.c_str()), 0) << prj;
  fs::last_write_time(dir / "a" / "plan.prj", fs::last_write_time(dir / "a" / "plan.shp") + std::chrono::minutes(2));
  const EvalResult feet = ev.evaluate(g, {}, {}, options);
  ASSERT_TRUE(feet.ok());
  EXPECT_EQ(feet.stats.computed(), 1u);
  // 12 US feet, give or take the Lambert projection's scale this far (300 km) from the zone's centre.
  EXPECT_NEAR(width(feet), 12 * 0.3048006, 0.15);
}

TEST(Export, WritesTheMeshBesideTheRecipe) {
  const test::ScratchDir dir("export_node");
  const auto mesh = run_node("Extrude", {}, {{"footprint", rectangle(10, 6)}});
  const auto r = run_node("Export", {{"file", Value::make(std::string("roof.glb"))}}, {{"mesh", mesh.outputs[0]}}, dir.path());
  ASSERT_TRUE(r.ok()) << r.messages();
  EXPECT_EQ(r.outputs[0].get<std::string>(), (dir / "roof.glb").string());
  const auto meshes = read_glb(dir / "roof.glb");
  ASSERT_EQ(meshes.size(), 1u);
  EXPECT_EQ(meshes[0].primitives.size(), 2u);  // base and roof
  const auto bad = run_node("Export", {{"file", Value::make(std::string("roof.stl"))}}, {{"mesh", mesh.outputs[0]}}, dir.path());
  EXPECT_NE(bad.messages().find("does not end in .obj, .ply or .glb"), std::string::npos) << bad.messages();
}

}  // namespace
}  // namespace procex
