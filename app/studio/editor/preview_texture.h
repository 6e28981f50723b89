// preview_texture.h -- a material's image decoded for the 3D preview, on the
// evaluation thread, so the UI thread only uploads it.
#pragma once

#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

namespace procex::studio {

struct PreviewTexture {
  int width = 0, height = 0;
  // RGBA, 8 bits a channel, the image's bottom row first (OpenGL's order:
  // texture coordinate v = 0 at the bottom, as OBJ's and procex's run).
  std::vector<unsigned char> rgba;
  // Its mean colour, then its commonest (0..1, at most kPaletteSize in all,
  // most used first), times the material's colour: what a screenshot check
  // looks for.
  std::vector<glm::vec3> palette;
  static constexpr std::size_t kPaletteSize = 8;
};

// The PNG or JPEG image in `bytes`, its palette tinted by `tint`; an empty
// texture (width 0) if stb_image cannot decode it (the writers checked the
// signature only) or it is wider or taller than 8192 pixels.
PreviewTexture decode_texture(std::string_view bytes, const glm::vec3& tint);

}  // namespace procex::studio
