#include "app/cli/feature_binding.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <functional>
#include <map>
#include <ostream>
#include <utility>

#include "app/cli/recipe_session.h"
#include "core/geom/error.h"
#include "core/geom/party_walls.h"
#include "core/geom/plan_tiles.h"
#include "core/geom/street_edges.h"
#include "core/geom/prepare.h"
#include "core/io/io_error.h"
#include "nodes/support/errors.h"

namespace procex {
namespace {

bool names_setting(const Graph& graph, const std::string& key) {
  return graph.input_index(key).has_value() ||
         std::any_of(graph.exposed_params().begin(), graph.exposed_params().end(),
                     [&](const ExposedParam& p) { return p.name == key; });
}

}  // namespace

std::string setting_name(const std::string& property) {
  std::string out;
  for (unsigned char c : property) out += std::isalnum(c) ? static_cast<char>(std::tolower(c)) : '_';
  return out;
}

namespace {

// The JSON list of ids.
std::string id_list(const std::vector<std::int32_t>& ids) {
  std::string list = "[";
  for (const std::int32_t id : ids) {
    if (list.size() > 1) list += ',';
    list += std::to_string(id);
  }
  list += ']';
  return list;
}

using Labels = std::vector<std::pair<std::string, std::string>>;

// Footprints per tile of the edge search: many, so that few are searched
// again as another tile's neighbours; few, so that a tile takes little memory.
constexpr std::size_t kFootprintsPerTile = 4096;

}  // namespace

EdgeLabelsRead edge_labels_read(const Graph& recipe) {
  return {names_setting(recipe, std::string(kPartyEdgesProperty)), names_setting(recipe, std::string(kStreetEdgesProperty))};
}

namespace {

// The labels of `count` footprints, wherever they are held: loops_of(i) gives
// the i-th one's loops, label(i, labels) is called once for each footprint
// with its lists (those the recipe reads), which it keeps where the footprint
// has no property of that name.
void label_edges(EdgeLabelsRead read, std::size_t count, const std::vector<StreetLine>& lines,
                 const std::function<PlanLoops(std::size_t)>& loops_of,
                 const std::function<void(std::size_t, const Labels&)>& label) {
  // Tile by tile (core/geom/plan_tiles.h): the edges and search grid of
  // every footprint of a large file at once take far more memory than the
  // footprints. A footprint's labels depend only on what lies within the
  // search distance of it, so they are those one search over all would give.
  std::vector<PlanBox> boxes;
  boxes.reserve(count);
  for (std::size_t i = 0; i < count; ++i) boxes.push_back(plan_box(loops_of(i)));
  std::vector<PlanBox> line_boxes;
  for (const StreetLine& line : lines) line_boxes.push_back(plan_box({line}));
  std::vector<bool> labelled(count, false);
  for_each_plan_tile(boxes, kPartyWallDistance, kFootprintsPerTile, [&](const PlanTile& tile) {
    std::vector<PlanLoops> plans;
    for (const std::size_t i : tile.plans) plans.push_back(loops_of(i));
    std::vector<Labels> own(tile.own);
    if (read.party) {
      const auto ids = party_edges(plans, kPartyWallDistance);
      for (std::size_t k = 0; k < tile.own; ++k) own[k].emplace_back(kPartyEdgesProperty, id_list(ids[k]));
    }
    if (read.street) {
      plans.resize(tile.own);
      std::vector<StreetLine> near;
      for (std::size_t l = 0; l < lines.size(); ++l)
        if (within(line_boxes[l], tile.extent, kStreetDistance)) near.push_back(lines[l]);
      const auto ids = street_edges(plans, near, kStreetDistance);
      for (std::size_t k = 0; k < tile.own; ++k) own[k].emplace_back(kStreetEdgesProperty, id_list(ids[k]));
    }
    for (std::size_t k = 0; k < tile.own; ++k) label(tile.plans[k], own[k]), labelled[tile.plans[k]] = true;
  });
  // A footprint without points is in no tile: none of its edges runs along anything.
  Labels none;
  if (read.party) none.emplace_back(kPartyEdgesProperty, "[]");
  if (read.street) none.emplace_back(kStreetEdgesProperty, "[]");
  for (std::size_t i = 0; i < count; ++i)
    if (!labelled[i]) label(i, none);
}

}  // namespace

void add_edge_labels(const Graph& recipe, GeoJsonCollection& collection) {
  const EdgeLabelsRead read = edge_labels_read(recipe);
  if (!read.party && !read.street) return;
  label_edges(
      read, collection.features.size(), collection.lines, [&](std::size_t i) { return collection.features[i].loops; },
      [&](std::size_t i, const Labels& labels) {
        for (const auto& [name, list] : labels) collection.features[i].properties.try_emplace(name, list);
      });
}

void add_edge_labels(const Graph& recipe, FeatureSpool& footprints, const std::vector<StreetLine>& lines) {
  const EdgeLabelsRead read = edge_labels_read(recipe);
  if (!read.party && !read.street) return;
  label_edges(
      read, footprints.size(), lines, [&](std::size_t i) { return footprints.at(i).loops; },
      [&](std::size_t i, const Labels& labels) { footprints.add_properties(i, labels); });
}

Status check_footprint_input(const Graph& recipe, const std::filesystem::path& recipe_file) {
  const auto i = recipe.input_index("footprint");
  if (!i || recipe.inputs()[*i].type != &value_type<Footprint>())
    return Status::error(recipe_file.string() + ": the recipe needs a graph input named 'footprint' of type footprint");
  return Status::ok();
}

std::optional<GeoJsonCollection> open_footprints(const Graph& recipe, const std::filesystem::path& recipe_file,
                                                 const std::filesystem::path& footprints,
                                                 const FootprintReadOptions& read, const std::string& command,
                                                 std::ostream& err, FeatureSpool* spool) {
  if (const Status s = check_footprint_input(recipe, recipe_file); !s) {
    err << s.message() << "\n";
    return std::nullopt;
  }
  try {
    if (spool) {
      GeoJsonCollection collection = read_footprints(footprints, read, *spool);
      add_edge_labels(recipe, *spool, collection.lines);
      return collection;
    }
    GeoJsonCollection collection = read_footprints(footprints, read);
    add_edge_labels(recipe, collection);
    return collection;
  } catch (const IoError& e) {
    err << "procex " << command << ": " << e.what() << "\n";
    return std::nullopt;
  }
}

std::vector<std::string> bind_feature(Graph& graph, Bindings& bindings, EvalOptions& options, const GeoJsonFeature& f) {
  std::vector<std::string> problems;
  options.attributes.clear();
  for (const auto& [name, json_text] : f.properties)
    if (json_text != "null") options.attributes.emplace(name, *f.property_text(name));
  const Footprint plan = to_footprint(f, 45.0);
  try {
    prepare_footprint(plan);  // as procex roof checks it: a plan no recipe can use is refused, not failed
  } catch (const InputError& e) {
    problems.push_back(describe(e));
  }
  bindings["footprint"] = Value::make(plan);
  if (graph.input_index("building_id")) bindings["building_id"] = Value::make(f.id);
  std::map<std::string, std::string> property_of;  // setting -> the property that set it
  for (const auto& [name, json_text] : f.properties) {
    const std::string key = setting_name(name);
    if (key == "footprint" || key == "building_id" || !names_setting(graph, key)) continue;
    if (const auto [it, first] = property_of.try_emplace(key, name); !first) {
      problems.push_back("properties '" + it->second + "' and '" + name + "' both set '" + key +
                         "': keep one of them in the footprint file");
      continue;
    }
    Status s = apply_setting(graph, bindings, key, *f.property_text(name));
    if (const auto number = f.property_number(name); !s && number) {  // "12 m", "40 ft" for a number parameter
      char text[32];
      std::snprintf(text, sizeof text, "%.17g", *number);
      s = apply_setting(graph, bindings, key, text);
    }
    if (!s)
      problems.push_back("property " + name + ": " + s.message() +
                         " (numbers take a unit of m, ft or ' at most: fix the value in the footprint file)");
  }
  return problems;
}

std::string FeatureEvaluation::status() const { return ok ? "ok" : binding_problems.empty() ? "failed" : "refused"; }

std::vector<std::string> FeatureEvaluation::warnings() const {
  std::vector<std::string> out;
  for (const Diagnostic& d : diagnostics)
    if (d.severity == Severity::kWarning) out.push_back(d.to_string());
  return out;
}

std::string FeatureEvaluation::reason() const {
  std::string out;
  for (const std::string& p : binding_problems) out += (out.empty() ? "" : "; ") + p;
  for (const Diagnostic& d : diagnostics)
    if (d.severity == Severity::kError) out += (out.empty() ? "" : "; ") + d.to_string();
  return out.empty() && !ok ? "an output is missing" : out;
}

FeatureEvaluation evaluate_feature(const MeshRecipe& recipe, Evaluator& evaluator, const GeoJsonFeature& f,
                                   bool parallel) {
  FeatureEvaluation out;
  Graph graph = recipe.graph;
  Bindings bindings = recipe.bindings;
  EvalOptions options = recipe.options;
  out.binding_problems = bind_feature(graph, bindings, options, f);
  if (!out.binding_problems.empty()) return out;
  options.parallel = parallel;
  EvalResult r = evaluator.evaluate(graph, bindings, recipe.outputs, options);
  out.ok = r.ok();
  out.diagnostics = std::move(r.diagnostics);
  out.stats = std::move(r.stats);
  if (out.ok) {
    out.meshes = gather_meshes(r);
    label_parts(out.meshes, f);
    label_parameters(out.meshes, graph);
  }
  return out;
}

Result<const GeoJsonFeature*> find_feature(const GeoJsonCollection& collection, const std::string& id_or_index,
                                           const std::string& file) {
  auto refused = [&](const GeoJsonFeatureError& e) -> Result<const GeoJsonFeature*> {
    return Status::error(file + ": feature " + e.id + " (index " + std::to_string(e.index) + "): " + e.message);
  };
  for (const GeoJsonFeature& f : collection.features)
    if (f.id == id_or_index) return &f;
  for (const GeoJsonFeatureError& e : collection.errors)
    if (e.id == id_or_index) return refused(e);
  std::size_t index = 0;
  const char* end = id_or_index.data() + id_or_index.size();
  if (auto [p, ec] = std::from_chars(id_or_index.data(), end, index); ec == std::errc() && p == end && !id_or_index.empty()) {
    for (const GeoJsonFeature& f : collection.features)
      if (f.index == index) return &f;
    for (const GeoJsonFeatureError& e : collection.errors)
      if (e.index == index) return refused(e);
  }
  return Status::error(file + ": no feature with id or index '" + id_or_index + "' (" +
                       std::to_string(collection.features.size() + collection.errors.size()) + " features)");
}

}  // namespace procex
