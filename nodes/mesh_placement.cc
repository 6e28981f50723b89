// Mesh placement: a mesh from an OBJ file placed at a named anchor of a
// building (paper 3.6: windows, chimneys, pillars), once, in rows or grids,
// or stretched between two anchors (core/placement/place_mesh.h).
#include <chrono>
#include <filesystem>
#include <map>
#include <mutex>
#include <optional>
#include <set>

#include "base/file_read_cache.h"
#include "base/file_version_memo.h"
#include "core/geom/error.h"
#include "core/io/io_error.h"
#include "core/io/mesh_read.h"
#include "core/mesh/validate.h"
#include "core/placement/cut_openings.h"
#include "core/placement/face_cover.h"
#include "core/placement/frame_transform.h"
#include "core/placement/place_mesh.h"
#include "core/placement/placement_error.h"
#include "graph/hash.h"
#include "graph/registry.h"
#include "nodes/values.h"

namespace procex {
namespace {

namespace fs = std::filesystem;

// Parameter and output handles, from the declaration.
struct Params {
  std::size_t file, name, anchor, top_anchor, mode, pivot, scale, offset, columns, column_spacing, rounding, fill, layout,
      margin_start, margin_end, rows, row_spacing, z_from, z_to, fit, margin, tag, upright, z_to_top, floor_from, floor_to,
      cut, cut_depth, reveal_tag;
  std::size_t mesh_out, dropped_out, cut_out;
};
Params par;

// The files `file` names, by what `names` finds in it, read once per version
// of the file (base/file_version.h): the graph is hashed for every building
// of a batch.
std::vector<fs::path> named_in(const fs::path& file, std::vector<fs::path> (*names)(const fs::path&),
                               FileVersionMemo* versions) {
  static FileReadCache<FileVersion, std::vector<fs::path>> cache;  // a file is an OBJ or a library, never both
  return cache.get(fs::absolute(file).string(), file_version(file, versions), [&] { return names(file); });
}

// The version of the mesh file and of every file it is read with (its
// material libraries, their textures): an edit to any of them reads the mesh
// again and makes a new key.
Hash128 mesh_files_stamp(const fs::path& obj, FileVersionMemo* versions) {
  Hasher h;
  hash_file_stamp(obj, versions, h);
  for (const fs::path& library : named_in(obj, obj_material_libraries, versions)) {
    hash_file_stamp(library, versions, h);
    for (const fs::path& texture : named_in(library, material_library_textures, versions))
      hash_file_stamp(texture, versions, h);
  }
  return h.result();
}

void hash_file(const std::vector<Value>& params, const fs::path& folder, FileVersionMemo* versions, Hasher& h) {
  h.hash(mesh_files_stamp(folder / params[par.file].get<std::string>(), versions));
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
        "floors from floor_from to floor_to, fitted to the tile with `fit`, else at the pivot (a building without "
        "such tiles gets none: a split keeps no tile where its walls are absent or too small; a name no Facade Split "
        "upstream gives is an error that lists the names they give). The meshes "
        "stay instances: .glb files share one mesh between them, OBJ and PLY get them merged in. The mesh keeps its own "
        "texture coordinates and normals (`vt`, `vn`) and its `mtllib` materials (colour `Kd`, texture `map_Kd`, a PNG "
        "or JPEG image; library and image confined to the recipe's folder as the mesh is): .glb files embed the image, "
        "OBJ's .mtl names it relative to the output. Where an anchor "
        "resolved as absent (its edge is gone at that height) nothing is placed and a warning says so. With `cut`, each "
        "placed mesh's outline becomes a hole in the face it stands on, lined by reveals `cut_depth` deep and closed "
        "behind, so the building stays closed (offset z = -cut_depth sets the mesh back into it); an outline not "
        "inside one face with wall around it, or whose recess would reach another face or recess, is not cut and a "
        "warning says so.")
      .category("Geometry")
      .detail_level(kFullDetail);  // windows and doors are LOD3: below it the buildings pass through unplaced
  d.input<MeshSet>("mesh").doc("buildings with resolved anchors (Extrude)");
  par.file = d.param<std::string>("file").default_value(std::string()).doc("the mesh to place: an .obj, relative to the recipe's folder").index();
  par.name = d.param<std::string>("name").default_value(std::string()).doc("tags the mesh's faces without a material (empty: the file's name)").index();
  par.anchor = d.param<std::string>("anchor").default_value(std::string("window")).doc("the anchor to place at (for stretch: the bottom)").index();
  par.top_anchor = d.param<std::string>("top_anchor").default_value(std::string()).doc("stretch: the anchor the mesh's top follows").index();
  par.mode = d.param_enum("mode", {"single", "row", "grid", "stretch", "tiles"}).doc("how many and where").index();
  par.pivot = d.param<Vec3>("pivot").default_value(Vec3{0.5, 0.0, 0.0})
      .doc("the point of the mesh's bounds put on the anchor, as fractions of its size (x along, y up, z out)").index();
  par.scale = d.param<Vec3>("scale").default_value(Vec3{1, 1, 1}).doc("the mesh's scale (single; row and grid without fit)").index();
  par.offset = d.param<Vec3>("offset").default_value(Vec3{}).unit("m").doc("moves each placed mesh along, up and out of the face").index();
  par.columns = d.param<std::int64_t>("columns").default_value<std::int64_t>(0).range(0, 10000)
      .doc("row and grid: items along the face (0: as many as `column_spacing` allows)").index();
  par.column_spacing = d.param<double>("column_spacing").default_value(2.0).range(0, 1000).unit("m").doc("row and grid: the pitch when columns is 0").index();
  par.rounding = d.param_enum("rounding", {"down", "nearest", "up"})
      .doc("a spacing's item count from the length: down never packs items closer than the spacing").index();
  par.fill = d.param<bool>("fill").default_value(true).doc("a spacing's items spread over the whole length (else exactly spaced, centred)").index();
  par.layout = d.param_enum("layout", {"cells", "ends"}).doc("items at the centres of equal cells, or from end to end").index();
  par.margin_start = d.param<double>("margin_start").default_value(0.0).range(0, 1000).unit("m").doc("length kept free at the start of each row and column").index();
  par.margin_end = d.param<double>("margin_end").default_value(0.0).range(0, 1000).unit("m").doc("length kept free at the end of each row and column").index();
  par.rows = d.param<std::int64_t>("rows").default_value<std::int64_t>(0).range(0, 10000)
      .doc("grid: rows up the face (0: as many as `row_spacing` allows)").index();
  par.row_spacing = d.param<double>("row_spacing").default_value(3.0).range(0, 1000).unit("m").doc("grid: the pitch when rows is 0").index();
  par.z_from = d.param<double>("z_from").default_value(0.0).range(-1000, 10000).unit("m").doc("grid: the height its rows start").index();
  par.z_to = d.param<double>("z_to").default_value(0.0).range(-1000, 10000).unit("m").doc("grid: the height its rows end").index();
  par.fit = d.param<bool>("fit").default_value(false)
      .doc("row and grid: scale each mesh to fill its cell (less margin); single: to fill each Facade Split tile").index();
  par.margin = d.param<double>("margin").default_value(0.0).range(0, 1000).unit("m").doc("fit: the gap kept around each mesh in its cell").index();
  par.tag = d.param<std::string>("tag").default_value(std::string()).doc("tags every face of the placed meshes (empty: their own tags)").index();
  par.upright = d.param<bool>("upright").default_value(false)
      .doc("stand the mesh upright: its up is the world's, not the face's (a chimney on a roof slope)").index();
  par.z_to_top = d.param<bool>("z_to_top").default_value(false).doc("grid: the rows end at the top of each anchor's face (z_to is ignored)").index();
  par.floor_from = d.param<std::int64_t>("floor_from").default_value<std::int64_t>(0).range(0, 10000).doc("tiles: the lowest floor placed in").index();
  par.floor_to = d.param<std::int64_t>("floor_to").default_value<std::int64_t>(10000).range(0, 10000).doc("tiles: the highest floor placed in").index();
  par.cut = d.param<bool>("cut").default_value(false)
      .doc("cut each placed mesh's outline (its bounds seen along the face's normal) into the face as a hole lined with reveals").index();
  par.cut_depth = d.param<double>("cut_depth").default_value(0.2).range(0.001, 100).unit("m").doc("cut: how deep the reveals run into the wall").index();
  par.reveal_tag = d.param<std::string>("reveal_tag").default_value(std::string("reveal")).doc("cut: the tag of the reveal and back faces").index();
  par.mesh_out = d.output<MeshSet>("mesh").index();
  par.dropped_out = d.output<std::int64_t>("dropped").doc("row and grid items left out: not wholly on their face").index();
  par.cut_out = d.output<std::int64_t>("cut").doc("openings cut into the walls, over every mesh").index();
  d.hash_extra(hash_file);
}

// A mesh file is read once per version (of it and the files it names:
// mesh_files_stamp) and shared by every building that places it: a batch puts
// the same window on thousands.
struct SharedMesh {
  std::shared_ptr<const Mesh> mesh;
  MaterialTable materials;  // from its .mtl
  std::vector<std::string> warnings;
};

SharedMesh read_mesh(const fs::path& path, const ReferencedFileResolver& resolve) {
  SharedMesh m;
  Materials materials;
  m.mesh = std::make_shared<const Mesh>(read_mesh_file(path, &m.warnings, resolve, &materials));
  m.materials = material_table(std::move(materials));
  return m;
}

// Files the OBJ names (its material library, textures) are confined as the
// recipe's own.
SharedMesh read_shared(const fs::path& path, const ReferencedFileResolver& resolve, FileVersionMemo* versions) {
  if (file_version(path, versions).content == 0) return read_mesh(path, resolve);  // read_mesh_file says what is wrong
  static FileReadCache<Hash128, SharedMesh> cache;
  return cache.get(fs::absolute(path).string(), mesh_files_stamp(path, versions), [&] { return read_mesh(path, resolve); });
}

glm::dvec3 vec(const Vec3& v) { return {v.x, v.y, v.z}; }

Repeat::Rounding rounding(const std::string& choice) {
  return choice == "nearest" ? Repeat::Rounding::Nearest : choice == "up" ? Repeat::Rounding::Up : Repeat::Rounding::Down;
}

MeshPlacementSpec spec_of(const EvalContext& ctx) {
  MeshPlacementSpec s;
  s.anchor = ctx.param<std::string>(par.anchor);
  s.top_anchor = ctx.param<std::string>(par.top_anchor);
  constexpr MeshPlacementSpec::Mode kModes[] = {MeshPlacementSpec::Mode::Single, MeshPlacementSpec::Mode::Row,
                                                MeshPlacementSpec::Mode::Grid, MeshPlacementSpec::Mode::Stretch,
                                                MeshPlacementSpec::Mode::Tiles};
  s.mode = kModes[ctx.choice_index(par.mode)];
  s.pivot = vec(ctx.param<Vec3>(par.pivot));
  s.scale = vec(ctx.param<Vec3>(par.scale));
  s.offset = vec(ctx.param<Vec3>(par.offset));
  Repeat line;
  line.rounding = rounding(ctx.choice(par.rounding));
  line.fill = ctx.param<bool>(par.fill);
  line.layout = ctx.choice(par.layout) == "ends" ? Repeat::Layout::Ends : Repeat::Layout::Cells;
  line.margin_start = ctx.param<double>(par.margin_start);
  line.margin_end = ctx.param<double>(par.margin_end);
  s.columns = s.rows = line;
  s.columns.count = static_cast<int>(ctx.param<std::int64_t>(par.columns));
  s.columns.spacing = ctx.param<double>(par.column_spacing);
  s.rows.count = static_cast<int>(ctx.param<std::int64_t>(par.rows));
  s.rows.spacing = ctx.param<double>(par.row_spacing);
  s.z_from = ctx.param<double>(par.z_from);
  s.z_to = ctx.param<double>(par.z_to);
  s.z_to_top = ctx.param<bool>(par.z_to_top);
  s.floor_from = static_cast<int>(ctx.param<std::int64_t>(par.floor_from));
  s.floor_to = static_cast<int>(ctx.param<std::int64_t>(par.floor_to));
  s.fit = ctx.param<bool>(par.fit);
  s.margin = ctx.param<double>(par.margin);
  s.tag = ctx.param<std::string>(par.tag);
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
  if (tiles) return std::any_of(tiles_of(part).begin(), tiles_of(part).end(), [&](const FacadeTile& t) { return t.name == anchor; });
  return std::any_of(part.anchors.begin(), part.anchors.end(), [&](const ResolvedAnchor& a) { return a.name == anchor; });
}

// The part with `outlines` cut into its faces; its tags follow the new faces.
CutReport cut_into(TaggedMesh& part, const std::vector<Opening>& outlines, const CutSpec& spec) {
  CutReport report;
  if (outlines.empty()) return report;
  std::vector<std::string> tags;
  tags.reserve(part.face_tags.size());
  for (std::size_t f = 0; f < part.face_tags.size(); ++f) tags.push_back(face_tag(part, f));
  auto mesh = std::make_shared<const Mesh>(cut_openings(*part.mesh, tags, outlines, spec, report));
  // Validated as Extrude validates its sweep: a cut must leave a closed 2-manifold.
  if (report.cut > 0)
    if (const ValidationReport v = validate(*mesh); !v.ok())
      throw MeshError("the mesh with its openings cut does not validate (" + std::to_string(v.problems.size()) +
                      " problems): " + (v.problems.empty() ? "no details" : v.problems.front()));
  part.mesh = std::move(mesh);
  face_tags_from_mesh(part);
  return report;
}

void evaluate(EvalContext& ctx) {
  const std::string& file = ctx.param<std::string>(par.file);
  if (file.empty()) return ctx.error("file: no mesh file given (an .obj, relative to the recipe's folder)");
  fs::path path;
  SharedMesh read;
  try {
    path = ctx.file(file);
    read = read_shared(path, [&](const fs::path& name) { return ctx.file(name.string()); }, ctx.file_versions());
  } catch (const IoError& e) {
    return ctx.error(e.what());
  }
  for (const std::string& w : read.warnings) ctx.warning(w);
  const std::string& name = ctx.param<std::string>(par.name);
  const PlaceableMesh mesh{name.empty() ? fs::path(file).stem().string() : name, read.mesh, read.materials};
  const MeshPlacementSpec spec = spec_of(ctx);

  MeshSet out = ctx.input<MeshSet>(0);
  std::set<std::string> names;  // of all anchors there are, for the error below
  const bool upright = ctx.param<bool>(par.upright);
  bool placed_any = false;
  std::int64_t dropped = 0, cut = 0;
  const bool cutting = ctx.param<bool>(par.cut);
  const CutSpec cut_spec{ctx.param<double>(par.cut_depth), ctx.param<std::string>(par.reveal_tag)};
  const bool tiles = spec.mode == MeshPlacementSpec::Mode::Tiles;
  for (TaggedMesh& part : out.parts) {
    if (tiles)
      names.insert(part.split_names.begin(), part.split_names.end());
    else
      for (const ResolvedAnchor& a : part.anchors) names.insert(a.name);
    if (!carries(part, spec.anchor, tiles)) continue;  // another building type's mesh
    placed_any = true;
    ctx.throw_if_cancelled();
    const std::string building = part.building.empty() ? "" : "building " + part.building + ": ";
    try {
      PlaceMeshReport report;
      if (tiles) {
        report = place_in_tiles(part.placed, mesh, tiles_of(part), spec);
      } else {
        const std::optional<FaceCover> cover =
            (spec.mode != MeshPlacementSpec::Mode::Row && spec.mode != MeshPlacementSpec::Mode::Grid) || upright ? std::nullopt : std::optional<FaceCover>(std::in_place, *part.mesh);
        report = place_mesh(part.placed, mesh, upright ? stood_upright(part.anchors) : part.anchors, spec,
                            cover ? &*cover : nullptr);
      }
      dropped += static_cast<std::int64_t>(report.dropped);
      for (const std::string& absent : report.absent) ctx.warning(building + absent);
      if (cutting && part.mesh) {
        const CutReport cuts = cut_into(part, report.outlines, cut_spec);
        cut += static_cast<std::int64_t>(cuts.cut);
        if (!cuts.skipped.empty())
          ctx.warning(building + std::to_string(cuts.skipped.size()) + " opening(s) not cut, the first: " + cuts.skipped[0]);
      }
    } catch (const PlacementError& e) {
      return ctx.error(e.what());
    } catch (const MeshError& e) {
      return ctx.error(building + e.what());
    }
  }
  // A split may keep no tile of its name on a building (no street front, walls too small): a name
  // that some split upstream gives is no misspelling, and nothing is placed.
  if (!placed_any && !(tiles && names.count(spec.anchor) > 0)) {
    if (names.empty()) {
      ctx.warning("anchor '" + spec.anchor + "': the input carries no " + (tiles ? "facade tiles" : "resolved anchors") +
                  ", nothing is placed");
    } else {
      std::string list;
      for (const std::string& n : names) list += (list.empty() ? "'" : ", '") + n + "'";
      return ctx.error(tiles ? "anchor: no Facade Split upstream makes tiles named '" + spec.anchor + "' (they make " + list + ")"
                             : "anchor: no anchor named '" + spec.anchor + "' on the input (there are " + list + ")");
    }
  }
  ctx.set_output(par.mesh_out, std::move(out));
  ctx.set_output(par.dropped_out, dropped);
  ctx.set_output(par.cut_out, cut);
}

}  // namespace
PROCEX_REGISTER_NODE("Mesh Placement", 1, declare, evaluate);
}  // namespace procex
