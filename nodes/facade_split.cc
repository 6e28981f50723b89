// Facade split: the walls of every mesh divided into floors and bays, each
// tile an anchor for Mesh Placement (core/placement/facade_split.h).
#include <memory>
#include <set>
#include <utility>
#include <vector>

#include "core/placement/facade_split.h"
#include "core/placement/placement_error.h"
#include "graph/registry.h"
#include "nodes/values.h"

namespace procex {
namespace {

// Parameter and output handles, from the declaration.
struct Handles {
  std::size_t mesh_in, edges_in, name, tag, which_edges, floors, bays, floor_height, bay_width, z_from;
  std::size_t mesh_out, tiles_out, dropped_out;
};
Handles h;

void declare(NodeDecl& d) {
  d.doc("Divides the vertical faces of every mesh (those tagged `tag`) into floors and bays, as CGA's split does, "
        "and adds one tile named `name` per cell for Mesh Placement's `tiles` mode: at its bottom centre, with the "
        "face's axes, its width and height, floor index (from z_from up) and bay index (from the face's start). Each plane of an edge's "
        "faces is split on its own (the wall above a set-back is another plane); floors count from the same "
        "height on every plane. Only tiles the faces cover wholly are kept: none above the roof line, across a "
        "set-back or past a corner; `dropped` counts the others. Sizes: `3` metres, `~3` flexible (the flexible "
        "cells stretch to fill the length), `_1` a gap that is no tile (a margin, a plinth), `{...}*` a group "
        "repeated as often as it fits, `{...}*4` exactly four times; `floor_height` and `bay_width` name the sizes of those parameters (`{floor_height}*`, "
        "`_floor_height {~bay_width}*`), so an expression or an exposed parameter sets them as numbers. `which_edges` with the `edges` input splits only "
        "the street fronts (listed) or every other wall (unlisted).")
      .category("Geometry");
  h.mesh_in = d.input<MeshSet>("mesh").doc("buildings (Extrude)").index();
  h.edges_in = d.input<std::vector<std::int64_t>>("edges").optional()
      .doc("footprint edge ids `which_edges` selects by (street_edges: the street fronts)").index();
  h.name = d.param<std::string>("name").default_value(std::string("tile")).doc("the tiles' name, for Mesh Placement").index();
  h.tag = d.param<std::string>("tag").default_value(std::string("wall")).doc("the faces to split (empty: every vertical face)").index();
  h.which_edges = d.param_enum("which_edges", {"all", "listed", "unlisted"})
      .doc("whose faces are split: every edge's, only the edges on the `edges` input, or every edge but those").index();
  h.floors = d.param<std::string>("floors").default_value(std::string("{floor_height}*")).doc("floor heights, up from z_from").index();
  h.bays = d.param<std::string>("bays").default_value(std::string("_0.5 {~bay_width}* _0.5")).doc("bay widths, across each face").index();
  h.floor_height = d.param<double>("floor_height").default_value(3.0).range(0.1, 100).unit("m")
      .doc("the size `floor_height` stands for in the split specs").index();
  h.bay_width = d.param<double>("bay_width").default_value(3.0).range(0.1, 100).unit("m")
      .doc("the size `bay_width` stands for in the split specs").index();
  h.z_from = d.param<double>("z_from").default_value(0.0).range(-1000, 10000).unit("m").doc("the height the first floor starts").index();
  h.mesh_out = d.output<MeshSet>("mesh").index();
  h.tiles_out = d.output<std::int64_t>("tiles").doc("tiles kept, over every mesh").index();
  h.dropped_out = d.output<std::int64_t>("dropped").doc("tiles not wholly on a face, over every mesh").index();
}

void evaluate(EvalContext& ctx) {
  FacadeSplitSpec spec;
  spec.name = ctx.param<std::string>(h.name);
  spec.z_from = ctx.param<double>(h.z_from);
  const SplitNames names{{"floor_height", ctx.param<double>(h.floor_height)}, {"bay_width", ctx.param<double>(h.bay_width)}};
  try {
    spec.floors = parse_split(ctx.param<std::string>(h.floors), names);
    spec.bays = parse_split(ctx.param<std::string>(h.bays), names);
  } catch (const PlacementError& e) {
    return ctx.error(e.what());
  }
  const std::string& tag = ctx.param<std::string>(h.tag);
  const std::string& which = ctx.choice(h.which_edges);
  std::set<std::int32_t> listed;
  if (ctx.has_input(h.edges_in))
    for (const std::int64_t id : ctx.input<std::vector<std::int64_t>>(h.edges_in)) listed.insert(static_cast<std::int32_t>(id));
  MeshSet out = ctx.input<MeshSet>(h.mesh_in);
  std::int64_t tiles = 0, dropped = 0;
  for (TaggedMesh& part : out.parts) {
    ctx.throw_if_cancelled();
    if (!part.mesh) continue;
    const auto edge_of = source_edge_property(*part.mesh);
    const auto wall = [&](Mesh::FaceHandle f) {
      const auto i = static_cast<std::size_t>(f.idx());
      if (!tag.empty() && !(i < part.face_tags.size() && part.tags[part.face_tags[i]] == tag)) return false;
      return which == "all" || (listed.count(part.mesh->property(edge_of, f)) > 0) == (which == "listed");
    };
    try {
      FacadeTiles split = split_facades(*part.mesh, wall, spec);
      tiles += static_cast<std::int64_t>(split.tiles.size());
      dropped += static_cast<std::int64_t>(split.dropped);
      if (!split.tiles.empty()) {  // the input's tiles are shared: added to, they are new ones
        std::vector<FacadeTile> tiles = tiles_of(part);
        tiles.insert(tiles.end(), split.tiles.begin(), split.tiles.end());
        part.tiles = std::make_shared<const std::vector<FacadeTile>>(std::move(tiles));
      }
      part.split_names.insert(spec.name);
    } catch (const PlacementError& e) {
      return ctx.error((part.building.empty() ? "" : "building " + part.building + ": ") + e.what());
    }
  }
  ctx.set_output(h.mesh_out, std::move(out));
  ctx.set_output(h.tiles_out, tiles);
  ctx.set_output(h.dropped_out, dropped);
}

}  // namespace
PROCEX_REGISTER_NODE("Facade Split", 1, declare, evaluate);
}  // namespace procex
