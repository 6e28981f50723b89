// procex_update_expected SAMPLES_DIR: rewrites samples/expected/<name>.json for
// every sample recipe and city.json from a batch of the city sample over
// samples/footprints/sample_block.geojson. Run by scripts/update-expected.sh
// after a deliberate change of the samples' output; review the diff.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "app/cli/batch_command.h"
#include "graph/pxg.h"
#include "tests/expected/sample_summaries.h"
#include "tests/nodes/node_runner.h"

namespace fs = std::filesystem;

int main(int argc, char** argv) {
  using namespace procex;
  if (argc != 2) {
    std::cerr << "usage: procex_update_expected SAMPLES_DIR\n";
    return 2;
  }
  const fs::path samples = argv[1], expected = samples / "expected";
  fs::create_directories(expected);
  int failed = 0;
  for (const std::string& name : test::sample_recipe_names(samples)) {
    const EvalResult r = test::evaluate_mesh(load_pxg(samples / (name + ".pxg")), samples);
    if (!r.ok()) {
      std::cerr << name << ": evaluation failed, summary left as it is\n";
      for (const Diagnostic& d : r.diagnostics) std::cerr << "  " << d.to_string() << "\n";
      ++failed;
      continue;
    }
    std::ofstream(expected / (name + ".json")) << test::summary_json(summarize(r.output("mesh")->get<MeshSet>())).dump(1) << "\n";
    std::cout << "wrote " << (expected / (name + ".json")).string() << "\n";
  }
  const fs::path dir = fs::temp_directory_path() / ("procex_update_expected_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  BatchCommandOptions o;
  o.recipe = samples / "city.pxg";
  o.footprints = samples / "footprints" / "sample_block.geojson";
  o.output = dir / "city.glb";
  o.report = dir / "city.json";
  o.progress = false;
  std::ostringstream out, err;
  if (run_batch(o, out, err) != 0) {
    std::cerr << "city: the batch failed, summary left as it is\n" << err.str();
    ++failed;
  } else {
    std::ifstream in(o.report);
    std::ofstream(expected / "city.json") << test::city_summary(nlohmann::ordered_json::parse(in)).dump(1) << "\n";
    std::cout << "wrote " << (expected / "city.json").string() << "\n";
  }
  fs::remove_all(dir);
  return failed == 0 ? 0 : 1;
}
