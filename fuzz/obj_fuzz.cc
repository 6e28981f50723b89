// Fuzzes the OBJ reader for meshes to place: any input must either give a
// mesh with a tag per face or throw IoError.
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "core/io/io_error.h"
#include "core/io/mesh_read.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    std::vector<std::string> warnings;
    const procex::Mesh mesh = procex::parse_obj_mesh(text, "fuzz.obj", &warnings);
    if (mesh.n_faces() == 0) std::abort();  // a mesh without faces must have been refused
  } catch (const procex::IoError&) {
  }
  return 0;
}
