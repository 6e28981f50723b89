// Export: writes a mesh to a file from inside a recipe.
#include "core/io/io_error.h"
#include "graph/registry.h"
#include "nodes/support/mesh_export.h"
#include "nodes/values.h"

namespace procex {
namespace {

// Parameter handles, from the declaration.
struct Params {
  std::size_t file;
};
Params par;

void declare(NodeDecl& d) {
  d.doc("Writes the mesh to `file` (relative to the recipe's folder) when the node is evaluated, atomically: "
        ".obj with a group per mesh and a material per face tag (plus a .mtl), .ply, or .glb (glTF binary, a "
        "primitive per tag, tags and building ids in extras). Outputs the path written. `procex eval -o` "
        "writes graph outputs without this node.")
      .category("Output");
  d.input<MeshSet>("mesh");
  par.file = d.param<std::string>("file").default_value(std::string("out/model.glb")).doc(".obj, .ply or .glb").index();
  d.output<std::string>("written");
}

void evaluate(EvalContext& ctx) {
  const std::string& file = ctx.param<std::string>(par.file);
  if (!is_mesh_file(file)) return ctx.error("file: '" + file + "' does not end in .obj, .ply or .glb");
  std::filesystem::path path;
  try {
    path = ctx.file(file);
    write_mesh_set(path, ctx.input<MeshSet>(0));
  } catch (const IoError& e) {
    return ctx.error(e.what());
  }
  ctx.set_output(0, path.string());
}

}  // namespace
PROCEX_REGISTER_NODE("Export", 1, declare, evaluate);
}  // namespace procex
