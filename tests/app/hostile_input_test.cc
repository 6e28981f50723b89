// The commands on inputs made to crash them: folders where files belong,
// merge reports with wrong types, numbers beyond double range or nesting deep
// enough to overflow a stack, and names that are not UTF-8. Each ends with
// exit 2 and a message naming the file, or, for names, a report written with
// the bytes replaced.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/cli/batch_command.h"
#include "app/cli/merge_command.h"
#include "app/cli/roof_command.h"
#include "tests/app/command_test.h"
#include "tests/app/sample_block.h"

namespace procex {
namespace {

namespace fs = std::filesystem;
using test::read_text;

const fs::path kSamples = PROCEX_SAMPLES;
const fs::path& kBlock = test::kSampleBlock;

class HostileInput : public test::CommandTest {
 protected:
  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name, std::ios::binary) << text;
    return dir_ / name;
  }
  // A batch shard of the sample block, and its report.
  MergeCommandOptions shard_pair() {
    BatchCommandOptions b;
    b.recipe = kSamples / "city.pxg";
    b.footprints = kBlock;
    b.output = dir_ / "part.glb";
    b.report = dir_ / "part.json";
    b.progress = false;
    EXPECT_EQ(run_batch(b, out_, err_), 0) << err_.str();
    return {{b.output, b.report}, dir_ / "merged.glb", dir_ / "merged.json"};
  }
};

TEST_F(HostileInput, FoldersWhereFilesBelong) {
  fs::create_directories(dir_ / "dir.geojson");
  fs::create_directories(dir_ / "dir.glb");
  RoofOptions roof;
  roof.input = dir_ / "dir.geojson";
  roof.output = dir_ / "out.obj";
  roof.report = dir_ / "report.json";
  EXPECT_EQ(run_roof(roof, out_, err_), 2);
  BatchCommandOptions batch;
  batch.recipe = kSamples / "city.pxg";
  batch.footprints = dir_ / "dir.geojson";
  batch.output = dir_ / "out.glb";
  batch.progress = false;
  EXPECT_EQ(run_batch(batch, out_, err_), 2);
  MergeCommandOptions merge{{dir_ / "dir.glb"}, dir_ / "merged.glb", {}};
  EXPECT_EQ(run_merge(merge, out_, err_), 2);
  const std::string said = err_.str();
  EXPECT_NE(said.find((dir_ / "dir.geojson").string() + "': it is a folder, not a file"), std::string::npos) << said;
  EXPECT_NE(said.find((dir_ / "dir.glb").string() + "': it is a folder, not a file"), std::string::npos) << said;
}

TEST_F(HostileInput, MergeReportsThatAreNotReports) {
  MergeCommandOptions merge = shard_pair();
  const std::string deep = std::string(80000, '[') + std::string(80000, ']');
  for (const std::string& text :
       {std::string(R"({"buildings": [{"index": 0, "status": 7}]})"), std::string(R"({"recipe": 3, "buildings": []})"),
        std::string(R"({"buildings": [{"index": 0, "ms": 1e400}]})"), std::string(R"({"buildings": [)") + deep + "]}",
        std::string(R"({"buildings": [3]})"), std::string("[1, 2]")}) {
    merge.parts[1] = write("part.json", text);
    err_.str("");
    EXPECT_EQ(run_merge(merge, out_, err_), 2) << text.substr(0, 60);
    EXPECT_NE(err_.str().find("part.json"), std::string::npos) << err_.str();
  }
  EXPECT_FALSE(fs::exists(merge.report));
}

TEST_F(HostileInput, NamesThatAreNotUtf8StillGetAReport) {
  const fs::path odd = dir_ / std::string("caf\xe9\xff.geojson");
  fs::copy_file(kBlock, odd);
  RoofOptions roof;
  roof.input = odd;
  roof.output = dir_ / "out.obj";
  roof.report = dir_ / "report.json";
  roof.angles_property = "\xfe";
  EXPECT_EQ(run_roof(roof, out_, err_), 0) << err_.str();
  const nlohmann::json report = nlohmann::json::parse(read_text(roof.report));
  EXPECT_NE(report["input"].get<std::string>().find("caf\xef\xbf\xbd"), std::string::npos);  // U+FFFD
  BatchCommandOptions batch;
  batch.recipe = kSamples / "city.pxg";
  batch.footprints = odd;
  batch.output = dir_ / "out.glb";
  batch.report = dir_ / "batch.json";
  batch.progress = false;
  EXPECT_EQ(run_batch(batch, out_, err_), 0) << err_.str();
  EXPECT_TRUE(nlohmann::json::accept(read_text(batch.report)));
}

// A batch whose buildings would hold more than its budget is refused as a
// whole, whatever order they ran in, and writes nothing.
TEST_F(HostileInput, ABatchHasABudget) {
  BatchCommandOptions b;
  b.recipe = kSamples / "city.pxg";
  b.footprints = kBlock;
  b.output = dir_ / "out.obj";
  b.report = dir_ / "report.json";
  b.progress = false;
  b.max_faces = 50;
  EXPECT_EQ(run_batch(b, out_, err_), 2);
  EXPECT_NE(err_.str().find("refused: the buildings would hold more than 50 faces"), std::string::npos) << err_.str();
  EXPECT_FALSE(fs::exists(b.output));
  EXPECT_FALSE(fs::exists(b.report));
}

// A property that names a parameter is read strictly: a value that does not
// fit, or two properties naming the same parameter, refuse the building
// (said on stderr and in the report) instead of keeping the recipe's value.
TEST_F(HostileInput, PropertiesAreReadStrictly) {
  std::string text = read_text(kSamples / "gallery_hipped.pxg");
  auto replace = [&text](const std::string& from, const std::string& to) { text.replace(text.find(from), from.size(), to); };
  replace("\"from\": \"1.footprint\"", "\"from\": \"@footprint\"");
  replace("\"inputs\": []", "\"inputs\": [{\"doc\": \"\", \"name\": \"footprint\", \"type\": \"footprint\"}]");
  write("pitched.pxg", text);
  auto feature = [](const std::string& id, const std::string& properties) {
    return R"({"type": "Feature", "id": ")" + id + R"(", "properties": {)" + properties +
           R"(}, "geometry": {"type": "Polygon", "coordinates": [[[0,0],[10,0],[10,10],[0,10],[0,0]]]}})";
  };
  const fs::path in = write("props.geojson", R"({"type": "FeatureCollection", "features": [)" +
                                                 feature("comma", R"("pitch": "3,5")") + "," + feature("hex", R"("pitch": "0x3")") + "," +
                                                 feature("words", R"("pitch": "30 storeys")") + "," +
                                                 feature("twice", R"("pitch": 30, "PITCH": 40)") + "," +
                                                 feature("fine", R"("pitch": "30")") + "]}");
  BatchCommandOptions b;
  b.recipe = dir_ / "pitched.pxg";
  b.footprints = in;
  b.output = dir_ / "out.glb";
  b.report = dir_ / "report.json";
  b.progress = false;
  EXPECT_EQ(run_batch(b, out_, err_), 0) << err_.str();
  const nlohmann::json report = nlohmann::json::parse(read_text(b.report));
  ASSERT_EQ(report["buildings"].size(), 5u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(report["buildings"][i]["status"], "refused") << report["buildings"][i];
    EXPECT_NE(err_.str().find("feature " + report["buildings"][i]["id"].get<std::string>() + " "), std::string::npos) << err_.str();
  }
  EXPECT_NE(report["buildings"][3]["reason"].get<std::string>().find("both set 'pitch'"), std::string::npos);
  EXPECT_EQ(report["buildings"][4]["status"], "ok");
}

// An open roof is blamed on what caused it: vertical walls rise forever
// (the recipe's doing), a needle whose edges all lean inward is too thin for
// the sweep (rounding's). It said "edges rise forever" for both.
TEST_F(HostileInput, AnOpenRoofNamesItsCause) {
  struct Case {
    std::string ring;
    double angle;
    std::string said;
  };
  for (const Case& c : std::vector<Case>{
           {"[0,0],[10,0],[5,1e-7],[0,0]", 45.0, "although every edge leans inward"},
           {"[0,0],[10,0],[10,10],[0,10],[0,0]", 0.0, "vertical or outward-leaning edges rise forever"}}) {
    RoofOptions roof;
    roof.input = write("open.geojson", R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {},
        "geometry": {"type": "Polygon", "coordinates": [[)" + c.ring + "]]}}]}");
    roof.output = dir_ / "open.obj";
    roof.report = dir_ / "open.json";
    roof.angle_deg = c.angle;
    EXPECT_EQ(run_roof(roof, out_, err_), kExitFeatureFailed) << c.ring;
    const std::string reason = nlohmann::json::parse(read_text(roof.report))["features"][0]["reason"];
    EXPECT_EQ(reason.rfind("sweep: the roof does not close", 0), 0u) << reason;
    EXPECT_NE(reason.find(c.said), std::string::npos) << reason;
  }
}

}  // namespace
}  // namespace procex
