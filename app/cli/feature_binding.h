// One GeoJSON feature bound to a recipe: what `procex batch` does for every
// feature and `procex eval --footprints F --feature ID` for one. The feature
// becomes the graph input `footprint`, its id the input `building_id` (if the
// recipe has one), and each property sets the exposed parameter or graph input
// of the same name (characters other than a-z, 0-9 and _ become _, so
// building:levels sets building_levels).
#pragma once

#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/geom/street_edges.h"  // StreetLine
#include "core/io/feature_spool.h"
#include "core/io/footprint_read.h"
#include "graph/evaluator.h"
#include "graph/graph.h"
#include "graph/status.h"
#include "nodes/support/mesh_labels.h"  // label_parts
#include "nodes/values.h"

namespace procex {

// A recipe with a graph input (or an exposed parameter) named party_edges
// gets, per feature, the ids of its edges that run along another footprint of the
// same file (within kPartyWallDistance metres, at least half their length):
// Assign Profiles' label `party`. A feature's own party_edges property wins.
inline constexpr std::string_view kPartyEdgesProperty = "party_edges";
inline constexpr double kPartyWallDistance = 0.3;

// Likewise street_edges: the ids of a feature's edges that face a street line
// of collection.lines within kStreetDistance metres, over at least half their
// length (core/geom/street_edges.h): Assign Profiles' label `street`.
inline constexpr std::string_view kStreetEdgesProperty = "street_edges";
inline constexpr double kStreetDistance = 20.0;

// Adds the properties party_edges and street_edges to every feature of
// `collection` that lacks them, when `recipe` reads them.
void add_edge_labels(const Graph& recipe, GeoJsonCollection& collection);
// The same for footprints spooled on disk (a batch's), with the collection's street lines.
void add_edge_labels(const Graph& recipe, FeatureSpool& footprints, const std::vector<StreetLine>& lines);
// Which of those two `recipe` reads (a graph input or exposed parameter of that name): what
// add_edge_labels' result depends on, so a caller knows when another recipe needs them made again.
struct EdgeLabelsRead {
  bool party = false, street = false;
  bool operator==(const EdgeLabelsRead&) const = default;
};
EdgeLabelsRead edge_labels_read(const Graph& recipe);

// Ok, or why features cannot be bound to the recipe (no graph input named
// `footprint` of type footprint), naming recipe_file.
Status check_footprint_input(const Graph& recipe, const std::filesystem::path& recipe_file);

// The features a recipe loaded from recipe_file is to be evaluated for: checks
// that it has a graph input named `footprint` of type footprint, then reads
// `footprints` (any file read_footprints reads, in the CRS `read` says), with
// party_edges and street_edges added when the recipe reads them. With a
// spool the footprints go there (labelled there), not to the collection's features.
// nullopt after writing the problem to err ("procex <command>: ...").
std::optional<GeoJsonCollection> open_footprints(const Graph& recipe, const std::filesystem::path& recipe_file,
                                                 const std::filesystem::path& footprints,
                                                 const FootprintReadOptions& read, const std::string& command,
                                                 std::ostream& err, FeatureSpool* spool = nullptr);

// Binds f to graph (a copy of the recipe) and bindings, and its properties
// (by their own names) to the attributes expressions read with attr(). Returns
// why the feature cannot be evaluated as given, one line per problem: a plan
// that prepare_footprint refuses (a bow-tie, fewer than 3 distinct vertices;
// in the words procex roof uses), a property that names a parameter but whose
// value does not fit it (read strictly: "3,5", "3 storeys" or "0x3" are not
// 3), or two properties that name the same one (max_height and MAX_HEIGHT). The caller refuses such a
// feature rather than evaluate it with the recipe's defaults. Properties that
// name nothing in the recipe are ignored.
std::vector<std::string> bind_feature(Graph& graph, Bindings& bindings, EvalOptions& options, const GeoJsonFeature& f);
// The parameter or graph input name a feature property sets, if the recipe has
// one of that name: the property's name lower-cased, other than [a-z0-9] as '_'.
std::string setting_name(const std::string& property);

struct MeshRecipe;

// The recipe evaluated for one feature (a building of a batch).
struct FeatureEvaluation {
  bool ok = false;                           // every mesh output present, no error diagnostics
  std::vector<std::string> binding_problems;  // why bind_feature refused the feature (then not evaluated)
  std::vector<Diagnostic> diagnostics;       // the evaluation's
  MeshSet meshes;  // when ok: labelled with the feature (label_parts) and the parameters as bound (label_parameters)
  EvalStats stats;                           // what the evaluation did per node (empty when not evaluated)

  // A batch report's status: "ok", "refused" (the feature could not be
  // bound) or "failed" (the evaluation).
  std::string status() const;
  // The warning diagnostics (Diagnostic::to_string).
  std::vector<std::string> warnings() const;
  // The binding problems, then the error diagnostics, joined by "; " (a batch
  // report's reason); for an evaluation that failed without saying why, "an
  // output is missing".
  std::string reason() const;
};
// Binds f to a copy of the recipe and evaluates its mesh outputs; `parallel`
// as EvalOptions::parallel (off when buildings already run in parallel).
FeatureEvaluation evaluate_feature(const MeshRecipe& recipe, Evaluator& evaluator, const GeoJsonFeature& f,
                                   bool parallel);

// The feature whose id is `id_or_index`, else (if it is a number) the one at
// that position. The message names the file, the feature and, for a feature
// that could not be read, why.
Result<const GeoJsonFeature*> find_feature(const GeoJsonCollection& collection, const std::string& id_or_index,
                                           const std::string& file);

}  // namespace procex
