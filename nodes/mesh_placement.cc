// Mesh placement: a mesh from an OBJ file placed at a named anchor of a
// building (paper 3.6: windows, chimneys, pillars), once, in rows or grids,
// or stretched between two anchors (core/placement/place_mesh.h).
#include <chrono>
#include <filesystem>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <tuple>

#include "core/io/io_error.h"
#include "core/io/mesh_read.h"
#include "core/placement/face_cover.h"
#include "core/placement/frame_transform.h"
#include "core/placement/place_mesh.h"
#include "core/placement/placement_error.h"
#include "graph/registry.h"
#include "nodes/values.h"

namespace procex {
namespace {

namespace fs = std::filesystem;

// Parameter order, as declared.
enum Param : std::size_t {
  kFile, kName, kAnchor, kTopAnchor, kMode, kPivot, kScale, kOffset,
  kColumns, kColumnSpacing, kRounding, kFill, kLayout, kMarginStart, kMarginEnd,
  kRows, kRowSpacing, kZFrom, kZTo, kFit, kMargin, kTag, kUpright, kZToTop, kFloorFrom, kFloorTo,
};

// An edited mesh file is read again.
void hash_file(const std::vector<Value>& params, const fs::path& folder, Hasher& h) {
  hash_file_stamp(folder / params[kFile].get<std::string>(), h);
}

void declare(NodeDecl& d) {
  d.doc("Places a mesh read from an OBJ file (its faces tagged by their `usemtl` material, else by `name`) at the "
        "resolutions of the anchor `anchor` on every mesh of the input: `single` places one at each resolution "
        "(the pivot point of the mesh's bounds on the anchor, scaled, then offset along, up and out of the face), "
        "`row` a row across the face at the anchor's height, `grid` rows and columns up the face between z_from "
        "and z_to, `stretch` from `anchor` (the mesh's bottom) to `top_anchor` (its top) on the same edge. Rows "
        "and columns take `rows` / `columns` items, or one every `row_spacing` / `column_spacing` metres as the "
        "face allows (rounding, fill, layout and margins apply to both). Row and grid items whose mesh, "
        "seen along the face's normal, is not wholly on the anchor's face (above the roof line, across a set-back, "
        "past a corner) are dropped and counted in `dropped`. A grid's z_to may be an expression of the recipe's "
        "values (docs/expressions.md). `tiles` places one in every tile named `anchor` of a Facade Split, on the "
        "floors from floor_from to floor_to, fitted to the tile with `fit`, else at the pivot. The meshes "
        "stay instances: .glb files share one mesh between them, OBJ and PLY get them merged in. Where an anchor "
        "resolved as absent (its edge is gone at that height) nothing is placed and a warning says so.")
      .category("Geometry");
  d.input<MeshSet>("mesh").doc("buildings with resolved anchors (Extrude)");
  d.param<std::string>("file").default_value(std::string()).doc("the mesh to place: an .obj, relative to the recipe's folder");
  d.param<std::string>("name").default_value(std::string()).doc("tags the mesh's faces without a material (empty: the file's name)");
  d.param<std::string>("anchor").default_value(std::string("window")).doc("the anchor to place at (for stretch: the bottom)");
  d.param<std::string>("top_anchor").default_value(std::string()).doc("stretch: the anchor the mesh's top follows");
  d.param_enum("mode", {"single", "row", "grid", "stretch", "tiles"}).doc("how many and where");
  d.param<Vec3>("pivot").default_value(Vec3{0.5, 0.0, 0.0})
      .doc("the point of the mesh's bounds put on the anchor, as fractions of its size (x along, y up, z out)");
  d.param<Vec3>("scale").default_value(Vec3{1, 1, 1}).doc("the mesh's scale (single; row and grid without fit)");
  d.param<Vec3>("offset").default_value(Vec3{}).unit("m").doc("moves each placed mesh along, up and out of the face");
  d.param<std::int64_t>("columns").default_value<std::int64_t>(0).range(0, 10000)
      .doc("row and grid: items along the face (0: as many as `column_spacing` allows)");
  d.param<double>("column_spacing").default_value(2.0).range(0, 1000).unit("m").doc("row and grid: the pitch when columns is 0");
  d.param_enum("rounding", {"down", "nearest", "up"})
      .doc("a spacing's item count from the length: down never packs items closer than the spacing");
  d.param<bool>("fill").default_value(true).doc("a spacing's items spread over the whole length (else exactly spaced, centred)");
  d.param_enum("layout", {"cells", "ends"}).doc("items at the centres of equal cells, or from end to end");
  d.param<double>("margin_start").default_value(0.0).range(0, 1000).unit("m").doc("length kept free at the start of each row and column");
  d.param<double>("margin_end").default_value(0.0).range(0, 1000).unit("m").doc("length kept free at the end of each row and column");
  d.param<std::int64_t>("rows").default_value<std::int64_t>(0).range(0, 10000)
      .doc("grid: rows up the face (0: as many as `row_spacing` allows)");
  d.param<double>("row_spacing").default_value(3.0).range(0, 1000).unit("m").doc("grid: the pitch when rows is 0");
  d.param<double>("z_from").default_value(0.0).range(-1000, 10000).unit("m").doc("grid: the height its rows start");
  d.param<double>("z_to").default_value(0.0).range(-1000, 10000).unit("m").doc("grid: the height its rows end");
  d.param<bool>("fit").default_value(false)
      .doc("row and grid: scale each mesh to fill its cell (less margin); single: to fill each Facade Split tile");
  d.param<double>("margin").default_value(0.0).range(0, 1000).unit("m").doc("fit: the gap kept around each mesh in its cell");
  d.param<std::string>("tag").default_value(std::string()).doc("tags every face of the placed meshes (empty: their own tags)");
  d.param<bool>("upright").default_value(false)
      .doc("stand the mesh upright: its up is the world's, not the face's (a chimney on a roof slope)");
  d.param<bool>("z_to_top").default_value(false).doc("grid: the rows end at the top of each anchor's face (z_to is ignored)");
  d.param<std::int64_t>("floor_from").default_value<std::int64_t>(0).range(0, 10000).doc("tiles: the lowest floor placed in");
  d.param<std::int64_t>("floor_to").default_value<std::int64_t>(10000).range(0, 10000).doc("tiles: the highest floor placed in");
  d.output<MeshSet>("mesh");
  d.output<std::int64_t>("dropped").doc("row and grid items left out: not wholly on their face");
  d.hash_extra(hash_file);
}

// A mesh file is read once per version (path, size, time) and shared by every
// building that places it: a batch puts the same window on thousands.
struct SharedMesh {
  std::shared_ptr<const Mesh> mesh;
  std::vector<std::string> warnings;
};

SharedMesh read_shared(const fs::path& path) {
  std::error_code size_error, time_error;
  const auto size = fs::file_size(path, size_error);
  const auto time = fs::last_write_time(path, time_error);
  if (size_error || time_error) {  // read_mesh_file says what is wrong
    SharedMesh m;
    m.mesh = std::make_shared<const Mesh>(read_mesh_file(path, &m.warnings));
    return m;
  }
  using Key = std::tuple<std::string, std::uintmax_t, fs::file_time_type::rep>;
  static std::mutex mutex;
  static std::map<Key, SharedMesh> cache;
  const Key key{fs::absolute(path).string(), size, time.time_since_epoch().count()};
  std::lock_guard lock(mutex);
  if (const auto it = cache.find(key); it != cache.end()) return it->second;
  SharedMesh m;
  m.mesh = std::make_shared<const Mesh>(read_mesh_file(path, &m.warnings));
  if (cache.size() >= 64) cache.clear();  // edited files leave old versions behind
  return cache.emplace(key, std::move(m)).first->second;
}

glm::dvec3 vec(const Vec3& v) { return {v.x, v.y, v.z}; }

Repeat::Rounding rounding(const std::string& choice) {
  return choice == "nearest" ? Repeat::Rounding::Nearest : choice == "up" ? Repeat::Rounding::Up : Repeat::Rounding::Down;
}

MeshPlacementSpec spec_of(const EvalContext& ctx) {
  MeshPlacementSpec s;
  s.anchor = ctx.param<std::string>(kAnchor);
  s.top_anchor = ctx.param<std::string>(kTopAnchor);
  constexpr MeshPlacementSpec::Mode kModes[] = {MeshPlacementSpec::Mode::Single, MeshPlacementSpec::Mode::Row,
                                                MeshPlacementSpec::Mode::Grid, MeshPlacementSpec::Mode::Stretch,
                                                MeshPlacementSpec::Mode::Tiles};
  s.mode = kModes[ctx.choice_index(kMode)];
  s.pivot = vec(ctx.param<Vec3>(kPivot));
  s.scale = vec(ctx.param<Vec3>(kScale));
  s.offset = vec(ctx.param<Vec3>(kOffset));
  Repeat line;
  line.rounding = rounding(ctx.choice(kRounding));
  line.fill = ctx.param<bool>(kFill);
  line.layout = ctx.choice(kLayout) == "ends" ? Repeat::Layout::Ends : Repeat::Layout::Cells;
  line.margin_start = ctx.param<double>(kMarginStart);
  line.margin_end = ctx.param<double>(kMarginEnd);
  s.columns = s.rows = line;
  s.columns.count = static_cast<int>(ctx.param<std::int64_t>(kColumns));
  s.columns.spacing = ctx.param<double>(kColumnSpacing);
  s.rows.count = static_cast<int>(ctx.param<std::int64_t>(kRows));
  s.rows.spacing = ctx.param<double>(kRowSpacing);
  s.z_from = ctx.param<double>(kZFrom);
  s.z_to = ctx.param<double>(kZTo);
  s.z_to_top = ctx.param<bool>(kZToTop);
  s.floor_from = static_cast<int>(ctx.param<std::int64_t>(kFloorFrom));
  s.floor_to = static_cast<int>(ctx.param<std::int64_t>(kFloorTo));
  s.fit = ctx.param<bool>(kFit);
  s.margin = ctx.param<double>(kMargin);
  s.tag = ctx.param<std::string>(kTag);
  return s;
}

// The frames turned about their along axis until up is the world's up; along
// (the edge's direction, level) stays.
std::vector<ResolvedAnchor> stood_upright(std::vector<ResolvedAnchor> anchors) {
  for (ResolvedAnchor& a : anchors)
    if (a.present) a.frame = orthonormal_frame(a.frame.origin, a.frame.along, {0.0, 0.0, 1.0});
  return anchors;
}

bool carries(const TaggedMesh& part, const std::string& anchor, bool tiles) {
  if (tiles) return std::any_of(part.tiles.begin(), part.tiles.end(), [&](const FacadeTile& t) { return t.name == anchor; });
  return std::any_of(part.anchors.begin(), part.anchors.end(), [&](const ResolvedAnchor& a) { return a.name == anchor; });
}

void evaluate(EvalContext& ctx) {
  const std::string& file = ctx.param<std::string>(kFile);
  if (file.empty()) return ctx.error("file: no mesh file given (an .obj, relative to the recipe's folder)");
  fs::path path;
  SharedMesh read;
  try {
    path = ctx.file(file);
    read = read_shared(path);
  } catch (const IoError& e) {
    return ctx.error(e.what());
  }
  for (const std::string& w : read.warnings) ctx.warning(w);
  const std::string& name = ctx.param<std::string>(kName);
  const PlaceableMesh mesh{name.empty() ? fs::path(file).stem().string() : name, read.mesh};
  const MeshPlacementSpec spec = spec_of(ctx);

  MeshSet out = ctx.input<MeshSet>(0);
  std::set<std::string> names;  // of all anchors there are, for the error below
  const bool upright = ctx.param<bool>(kUpright);
  bool placed_any = false;
  std::int64_t dropped = 0;
  const bool tiles = spec.mode == MeshPlacementSpec::Mode::Tiles;
  for (TaggedMesh& part : out.parts) {
    if (tiles)
      for (const FacadeTile& t : part.tiles) names.insert(t.name);
    else
      for (const ResolvedAnchor& a : part.anchors) names.insert(a.name);
    if (!carries(part, spec.anchor, tiles)) continue;  // another building type's mesh
    placed_any = true;
    try {
      if (tiles) {
        place_in_tiles(part.placed, mesh, part.tiles, spec);
        continue;
      }
      const std::optional<FaceCover> cover =
          (spec.mode != MeshPlacementSpec::Mode::Row && spec.mode != MeshPlacementSpec::Mode::Grid) || upright ? std::nullopt : std::optional<FaceCover>(std::in_place, *part.mesh);
      const PlaceMeshReport report = place_mesh(part.placed, mesh, upright ? stood_upright(part.anchors) : part.anchors,
                                                spec, cover ? &*cover : nullptr);
      dropped += static_cast<std::int64_t>(report.dropped);
      for (const std::string& absent : report.absent)
        ctx.warning((part.building.empty() ? "" : "building " + part.building + ": ") + absent);
    } catch (const PlacementError& e) {
      return ctx.error(e.what());
    }
  }
  if (!placed_any) {
    if (names.empty()) {
      ctx.warning("anchor '" + spec.anchor + "': the input carries no " + (tiles ? "facade tiles" : "resolved anchors") +
                  ", nothing is placed");
    } else {
      std::string list;
      for (const std::string& n : names) list += (list.empty() ? "'" : ", '") + n + "'";
      return ctx.error("anchor: no " + std::string(tiles ? "tiles" : "anchor") + " named '" + spec.anchor +
                       "' on the input (there are " + list + ")");
    }
  }
  ctx.set_output(0, std::move(out));
  ctx.set_output(1, dropped);
}

}  // namespace
PROCEX_REGISTER_NODE("Mesh Placement", 1, declare, evaluate);
}  // namespace procex
