#include "core/io/gltf_crs.h"

#include <nlohmann/json.hpp>

#include "core/io/io_error.h"
#include "core/io/output_crs.h"

namespace procex {

void set_gltf_crs(GltfScene& scene, const std::string& crs, const std::filesystem::path& path) {
  if (crs.empty()) return;
  OutputCrsText text = output_crs_wkt2(crs);
  if (text.problem) throw IoError("cannot write '" + path.string() + "': " + *text.problem, path.string());
  scene.extras[kGltfCrsKey] = nlohmann::json(std::move(text.wkt2)).dump();
}

}  // namespace procex
