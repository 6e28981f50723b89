// Blender itself (headless, Debian's blender, scripts/install-deps.sh) imports
// what `procex batch` writes, .glb and .obj, with its importers' defaults, as
// a technical artist would (tools/blender_import.py reports what it made):
// every building stands upright (its ridge above its eaves in Blender's Z),
// is one object named by its id, has a UV map and materials named by tag, and
// measures what the batch report says to the millimetre; from the .glb it has
// its feature's attributes as custom properties.
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <map>
#include <set>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/cli/batch_command.h"
#include "app/cli/eval_command.h"
#include "tests/app/command_test.h"
#include "tests/app/sample_block.h"

namespace procex {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

const fs::path& kRoot = test::kRepository;

class BlenderImport : public test::CommandTest {
 protected:
  // The sample city as one file in `format`, and its report.
  void batch(const std::string& format) {
    BatchCommandOptions o;
    o.recipe = kRoot / "samples" / "city.pxg";
    o.footprints = test::kSampleBlock;
    o.output = dir_ / ("city." + format);
    o.report = dir_ / ("city_" + format + ".json");
    o.progress = false;
    o.lod = 2;  // the buildings alone, not their placed windows and doors
    ASSERT_EQ(run_batch(o, out_, err_), 0) << err_.str();
  }
};

TEST_F(BlenderImport, BuildingsStandUprightNamedTexturedAndToTheMillimetre) {
  batch("glb");
  batch("obj");
  const fs::path report_file = dir_ / "blender.json";
  const fs::path log = dir_ / "blender.log";
  const int status = std::system(("blender -b --factory-startup --python " + (kRoot / "tools" / "blender_import.py").string() +
                                  " -- " + report_file.string() + " " + (dir_ / "city.glb").string() + " " +
                                  (dir_ / "city.obj").string() + " > " + log.string() + " 2>&1")
                                     .c_str());
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0)
      << "blender (scripts/install-deps.sh installs it) failed:\n" << test::read_text(log);
  const json blender = json::parse(test::read_text(report_file));
  const json procex = json::parse(test::read_text(dir_ / "city_glb.json"));

  std::map<std::string, json> want;  // building id -> its entry in the batch report
  for (const json& b : procex["buildings"]) want[b["id"].get<std::string>()] = b;
  ASSERT_EQ(want.size(), 18u);
  const json block = json::parse(test::read_text(test::kSampleBlock));
  std::map<std::string, json> features;  // building id -> its feature's GeoJSON properties
  for (const json& f : block["features"]) features[f["id"].get<std::string>()] = f["properties"];

  for (const char* file : {"city.glb", "city.obj"}) {
    SCOPED_TRACE(file);
    const json& objects = blender.at((dir_ / file).string());
    std::set<std::string> seen;
    for (const json& o : objects) {
      const std::string name = o["name"];
      if (!want.count(name)) continue;  // e.g. a placed mesh's own object
      SCOPED_TRACE(name);
      seen.insert(name);
      const json& bounds = want[name]["bounds"];
      // procex's x east, y north, z up is Blender's own frame: both importers
      // turn the files' +Y up back into Blender's Z up.
      for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(o["min"][k].get<double>(), bounds["min"][k].get<double>(), 1e-3) << "axis " << k;
        EXPECT_NEAR(o["max"][k].get<double>(), bounds["max"][k].get<double>(), 1e-3) << "axis " << k;
      }
      EXPECT_FALSE(o["uv_maps"].empty());
      std::set<std::string> materials;
      for (const json& m : o["materials"]) materials.insert(m.get<std::string>());
      std::set<std::string> tags;
      for (const auto& [tag, count] : want[name]["faces_per_tag"].items()) tags.insert(tag);
      EXPECT_EQ(materials, tags);
      // Upright: the footprint at the bottom, the walls above it, a roof above them.
      const json& top = o["top_by_material"];
      ASSERT_TRUE(top.contains("base") && top.contains("wall")) << top.dump();
      EXPECT_NEAR(top["base"].get<double>(), bounds["min"][2].get<double>(), 1e-3);
      EXPECT_GT(top["wall"].get<double>(), top["base"].get<double>() + 2.0);
      if (top.contains("roof")) {
        EXPECT_GT(top["roof"].get<double>(), top["wall"].get<double>() + 0.5);
      }
      // Its attributes: the .glb node's extras are the object's custom
      // properties, its feature's GeoJSON properties among them (Blender
      // keeps a boolean as 0 or 1); an .obj has none to give.
      if (std::string(file) == "city.glb") {
        const json& p = o["properties"];
        EXPECT_EQ(p.value("building", ""), name) << p.dump();
        ASSERT_TRUE(p.contains("properties") && features.count(name)) << p.dump();
        for (const auto& [key, value] : features.at(name).items()) {
          SCOPED_TRACE(key);
          ASSERT_TRUE(p["properties"].contains(key)) << p["properties"].dump();
          EXPECT_EQ(p["properties"][key], value.is_boolean() ? json(value.get<bool>() ? 1 : 0) : value);
        }
        EXPECT_FALSE(p.value("parameters", json::object()).empty()) << "the recipe's exposed values";
      }
    }
    EXPECT_EQ(seen.size(), want.size()) << "one object per building, named by its id";
  }
}

// The dimensions a recipe gives, to the millimetre, in Blender: samples whose
// stored summaries (samples/expected, reviewed against the recipes: e.g.
// gallery_overhang's 20 x 10 m walls with 0.5 m eaves, 21 x 11 m, ridge at
// 8.5 m) bound what procex eval writes as .glb and .obj, imported upright.
TEST_F(BlenderImport, SamplesMeasureWhatTheirRecipesSay) {
  const std::vector<std::string> samples = {"gallery_overhang", "gallery_gambrel", "house"};
  const auto written = [&](const std::string& name, const char* extension) { return (dir_ / name).concat(extension); };
  std::string files;
  for (const std::string& name : samples)
    for (const char* extension : {".glb", ".obj"}) {
      EvalCommandOptions o;
      o.recipe = (kRoot / "samples" / name).concat(".pxg");
      o.output = written(name, extension);
      ASSERT_EQ(run_eval(o, out_, err_), 0) << err_.str();
      files.append(" ").append(o.output.string());
    }
  const fs::path report_file = dir_ / "blender.json", log = dir_ / "blender.log";
  const int status = std::system(("blender -b --factory-startup --python " + (kRoot / "tools" / "blender_import.py").string() +
                                  " -- " + report_file.string() + files + " > " + log.string() + " 2>&1")
                                     .c_str());
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0)
      << "blender (scripts/install-deps.sh installs it) failed:\n" << test::read_text(log);
  const json blender = json::parse(test::read_text(report_file));
  for (const std::string& name : samples) {
    const json expected = json::parse(test::read_text((kRoot / "samples" / "expected" / name).concat(".json")))["bounds"];
    for (const char* extension : {".glb", ".obj"}) {
      SCOPED_TRACE(written(name, extension).filename().string());
      const json& objects = blender.at(written(name, extension).string());
      ASSERT_FALSE(objects.empty());
      std::array<double, 3> low{1e300, 1e300, 1e300}, high{-1e300, -1e300, -1e300};
      for (const json& o : objects)
        for (int k = 0; k < 3; ++k)
          low[k] = std::min(low[k], o["min"][k].get<double>()), high[k] = std::max(high[k], o["max"][k].get<double>());
      for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(low[k], expected["min"][k].get<double>(), 1e-3) << "axis " << k;
        EXPECT_NEAR(high[k], expected["max"][k].get<double>(), 1e-3) << "axis " << k;
      }
    }
  }
}

}  // namespace
}  // namespace procex
