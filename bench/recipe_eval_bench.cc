// What `procex eval` does in-process for a recipe, minus writing the file:
// open the recipe (not timed), evaluate its mesh outputs with an empty cache
// and gather the meshes. The reference bench/python_eval_bench.py compares
// the Python module with. Medians of wall time and of process CPU time (all
// threads; it also counts TBB's workers spinning after the evaluation).
//   procex_recipe_eval_bench RECIPE.pxg [ITERATIONS]  ->  "wall_ms <m> cpu_ms <m> faces <n>"
#include <algorithm>
#include <chrono>
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
  std::vector<double> wall, cpu;
  std::size_t faces = 0;
  for (int i = 0; i < iterations + 1; ++i) {  // the first run warms the process up and is not counted
    std::optional<MeshRecipe> recipe = open_mesh_recipe(argv[1], {}, {}, std::cerr);  // as procex eval: loaded, then evaluated once
    if (!recipe) return 2;
    const auto wall_start = std::chrono::steady_clock::now();
    const std::clock_t start = std::clock();
    ResultCache cache;
    Evaluator evaluator(cache, kEngineSalt);
    const EvalResult r = evaluator.evaluate(recipe->graph, recipe->bindings, recipe->outputs, recipe->options);
    const MeshSet meshes = gather_meshes(r);
    const double t = 1000.0 * static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
    const double w = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - wall_start).count();
    if (!r.ok()) return 1;
    faces = meshes.parts.front().mesh->n_faces();
    if (i > 0) wall.push_back(w), cpu.push_back(t);
  }
  const auto median = [](std::vector<double>& v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  };
  std::cout << "wall_ms " << median(wall) << " cpu_ms " << median(cpu) << " faces " << faces << "\n";
  return 0;
}
