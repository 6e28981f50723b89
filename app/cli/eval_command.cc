#include "app/cli/eval_command.h"

#include <ostream>

#include "app/cli/feature_binding.h"
#include "app/cli/output_crs.h"
#include "app/cli/output_paths.h"
#include "app/cli/recipe_session.h"
#include "core/io/geojson.h"
#include "core/io/io_error.h"
#include "nodes/support/mesh_export.h"

namespace procex {

int run_eval(const EvalCommandOptions& options, std::ostream& out, std::ostream& err) {
  if (!is_mesh_file(options.output) && !is_gis_file(options.output)) {
    err << "procex eval: " << options.output.string() << ": the output must end in .obj, .ply, .glb, .gpkg or .json (CityJSON)\n";
    return kExitUnusableInput;
  }
  if (const auto clash = output_clash({options.recipe, options.footprints, options.streets}, {options.output})) {
    err << "procex eval: " << *clash << "\n";
    return kExitUnusableInput;
  }
  std::optional<MeshRecipe> recipe = open_mesh_recipe(options.recipe, options.settings, options.allowed_paths, err, options.preset,
                                                        options.budget);
  if (!recipe) return kExitUnusableInput;
  recipe->options.lod = options.lod;
  std::optional<GeoJsonCollection> collection;
  const GeoJsonFeature* feature = nullptr;
  if (!options.footprints.empty()) {
    FootprintReadOptions read;
    read.crs = options.export_options.crs, read.target_crs = options.target_crs, read.layer = options.layer;
    read.streets = options.streets, read.streets_layer = options.streets_layer;
    collection = open_footprints(recipe->graph, options.recipe, options.footprints, read, "eval", err);
    if (!collection) return kExitUnusableInput;
    const Result<const GeoJsonFeature*> found = find_feature(*collection, options.feature, options.footprints.string());
    if (!found) {
      err << "procex eval: " << found.message() << "\n";
      return kExitUnusableInput;
    }
    feature = *found;
    const std::vector<std::string> problems = bind_feature(recipe->graph, recipe->bindings, recipe->options, *feature);
    for (const std::string& p : problems)
      err << "procex eval: " << options.footprints.string() << ": feature " << feature->id << ": refused: " << p << "\n";
    if (!problems.empty()) return kExitUnusableInput;
  }
  ExportOptions export_options = options.export_options;
  if (const auto problem = settle_output_crs(options.output, collection ? &*collection : nullptr, export_options)) {
    err << "procex eval: " << options.output.string() << ": " << *problem << "\n";
    return kExitUnusableInput;
  }
  ResultCache cache;
  Evaluator evaluator(cache, kEngineSalt);
  const EvalResult r = evaluator.evaluate(recipe->graph, recipe->bindings, recipe->outputs, recipe->options);
  print_diagnostics(r, options.recipe, err);
  if (!r.ok()) {
    err << "procex eval: " << options.recipe.string() << ": evaluation failed, nothing written\n";
    return kExitEvaluationFailed;
  }
  MeshSet meshes = gather_meshes(r);
  if (feature) label_parts(meshes, *feature);
  label_parameters(meshes, recipe->graph);
  try {
    write_mesh_set(options.output, meshes, export_options);
  } catch (const IoError& e) {
    err << "procex eval: " << e.what() << "\n";
    return kExitUnusableInput;
  }
  std::size_t faces = 0, placed = 0;
  for (const TaggedMesh& p : meshes.parts) {
    faces += p.mesh->n_faces();
    placed += p.placed.instances.size();
  }
  out << "procex eval: " << meshes.parts.size() << " meshes, " << faces << " faces";
  if (placed > 0) out << ", " << placed << " placed meshes";
  out << " -> " << options.output.string() << "\n";
  return 0;
}

}  // namespace procex
