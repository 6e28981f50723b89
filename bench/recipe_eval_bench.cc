// What `procex eval` does in-process for a recipe, minus writing the file:
// evaluate its mesh outputs with an empty cache and gather the meshes. The
// reference bench/python_eval_bench.py compares the Python module with.
// Process CPU time (all threads), steadier than wall time on a loaded machine.
//   procex_recipe_eval_bench RECIPE.pxg [ITERATIONS]  ->  "median_ms <m>"
#include <algorithm>
#include <ctime>
#include <cstdlib>
#include <iostream>
#include <vector>

#include "app/cli/recipe_session.h"

int main(int argc, char** argv) {
  using namespace procex;
  if (argc < 2) {
    std::cerr << "usage: procex_recipe_eval_bench RECIPE.pxg [ITERATIONS]\n";
    return 2;
  }
  const int iterations = argc > 2 ? std::atoi(argv[2]) : 50;
  std::optional<MeshRecipe> recipe = open_mesh_recipe(argv[1], {}, {}, std::cerr);
  if (!recipe) return 2;
  std::vector<double> ms;
  std::size_t faces = 0;
  for (int i = 0; i < iterations + 1; ++i) {  // the first run warms the process up and is not counted
    const std::clock_t start = std::clock();
    ResultCache cache;
    Evaluator evaluator(cache, kEngineSalt);
    const EvalResult r = evaluator.evaluate(recipe->graph, recipe->bindings, recipe->outputs, recipe->options);
    const MeshSet meshes = gather_meshes(r);
    const double t = 1000.0 * static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
    if (!r.ok()) return 1;
    faces = meshes.parts.front().mesh->n_faces();
    if (i > 0) ms.push_back(t);
  }
  std::sort(ms.begin(), ms.end());
  std::cout << "median_ms " << ms[ms.size() / 2] << " faces " << faces << "\n";
  return 0;
}
