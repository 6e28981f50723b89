// Footprint GeoJSON: one feature of a footprint file (core/io/footprint_read.h).
#include "core/io/footprint_read.h"
#include "core/io/io_error.h"
#include "graph/registry.h"
#include "nodes/values.h"

namespace procex {
namespace {

// Parameter handles, from the declaration.
struct Params {
  std::size_t file, id, index, angle;
};
Params par;

// An edited file is read again, a Shapefile's .dbf and .prj included.
void hash_file(const std::vector<Value>& params, const std::filesystem::path& folder, FileVersionMemo* versions,
               Hasher& h) {
  for (const std::filesystem::path& f : footprint_files(folder / params[par.file].get<std::string>()))
    hash_file_stamp(f, versions, h);
}

void declare(NodeDecl& d) {
  d.doc("One Polygon or MultiPolygon feature of a footprint file (GeoJSON, Shapefile, GeoPackage, FlatGeobuf, "
        "OSM buildings), chosen by id or, when the id is empty, by position. Coordinates in metres, or longitude/"
        "latitude projected to a transverse Mercator centred on the file's data (as `procex batch` does). Edge ids run 0, 1, 2... over the rings in file order. "
        "(For whole files use `procex batch`, which binds each feature to the graph input `footprint`.)")
      .category("Footprint");
  par.file = d.param<std::string>("file").default_value(std::string("footprints/sample_block.geojson"))
      .doc("path, relative to the recipe's folder").index();
  par.id = d.param<std::string>("id").default_value(std::string()).doc("the feature's id (empty: use index)").index();
  par.index = d.param<std::int64_t>("index").default_value<std::int64_t>(0).min(0).doc("position in the features array").index();
  par.angle = d.param<double>("angle").default_value(45.0).range(-90, 90).unit("deg")
      .doc("every edge's slope from the vertical, for edges that get no profile (0 = wall)").index();
  d.output<Footprint>("footprint");
  d.hash_extra(hash_file);
}

void evaluate(EvalContext& ctx) {
  const std::string& file = ctx.param<std::string>(par.file);
  const std::string& id = ctx.param<std::string>(par.id);
  const auto index = static_cast<std::size_t>(ctx.param<std::int64_t>(par.index));
  GeoJsonCollection collection;
  try {
    collection = read_footprints(ctx.file(file));
  } catch (const IoError& e) {
    return ctx.error(e.what());
  }
  for (const GeoJsonFeatureError& e : collection.errors)
    if (id.empty() ? e.index == index : e.id == id) return ctx.error(file + ": " + e.message);
  for (const GeoJsonFeature& f : collection.features)
    if (id.empty() ? f.index == index : f.id == id) return ctx.set_output(0, to_footprint(f, ctx.param<double>(par.angle)));
  ctx.error(file + ": no feature " + (id.empty() ? "at index " + std::to_string(index) : "with id '" + id + "'") +
            " (" + std::to_string(collection.features.size() + collection.errors.size()) + " features)");
}

}  // namespace
PROCEX_REGISTER_NODE("Footprint GeoJSON", 1, declare, evaluate);
}  // namespace procex
