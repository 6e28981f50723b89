// Fuzzes what `procex merge` reads: a .glb shard. Any input must either give
// a scene whose instances name its placed meshes, or throw IoError; offsets
// and lengths in the file never read outside it (ASan watches the copies).
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "core/io/glb_read.h"
#include "core/io/gltf_write.h"
#include "core/io/io_error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    procex::GltfScene merged;
    procex::append_scene(merged, procex::parse_glb_scene(bytes, "fuzz.glb"));
    for (const procex::GltfMeshData& building : merged.meshes)
      for (const procex::GltfInstanceData& instance : building.instances)
        if (instance.prototype >= merged.prototypes.size()) std::abort();
  } catch (const procex::IoError&) {
  }
  return 0;
}
