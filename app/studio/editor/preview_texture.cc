#include "app/studio/editor/preview_texture.h"

#include <stb_image.h>

#include <algorithm>
#include <climits>
#include <cstring>
#include <map>
#include <memory>

#include <glm/vec3.hpp>

namespace procex::studio {
namespace {

constexpr int kMaxSide = 8192;  // the largest texture the preview shows (a 256 MiB RGBA image)

}  // namespace

PreviewTexture decode_texture(std::string_view bytes, const glm::vec3& tint) {
  PreviewTexture t;
  if (bytes.size() > static_cast<std::size_t>(INT_MAX)) return t;
  int w = 0, h = 0, channels = 0;
  // The header first: a small hostile file may claim a vast image.
  if (!stbi_info_from_memory(reinterpret_cast<const unsigned char*>(bytes.data()), static_cast<int>(bytes.size()), &w, &h,
                             &channels) ||
      w <= 0 || h <= 0 || w > kMaxSide || h > kMaxSide)
    return t;
  const std::unique_ptr<unsigned char, void (*)(void*)> pixels(
      stbi_load_from_memory(reinterpret_cast<const unsigned char*>(bytes.data()), static_cast<int>(bytes.size()), &w, &h,
                            &channels, 4),
      stbi_image_free);
  if (!pixels || w <= 0 || h <= 0) return t;
  t.width = w;
  t.height = h;
  const std::size_t row = static_cast<std::size_t>(w) * 4;
  t.rgba.resize(row * static_cast<std::size_t>(h));
  for (int y = 0; y < h; ++y)  // flipped: stb_image gives the top row first
    std::memcpy(t.rgba.data() + static_cast<std::size_t>(h - 1 - y) * row, pixels.get() + static_cast<std::size_t>(y) * row, row);
  // Its mean (what it blends to seen from afar), then its colours counted at 5 bits a channel, so a
  // texture's shades of one colour count together.
  glm::dvec3 sum(0.0);
  for (std::size_t i = 0; i < t.rgba.size(); i += 4) sum += glm::dvec3(t.rgba[i], t.rgba[i + 1], t.rgba[i + 2]);
  t.palette.push_back(glm::vec3(sum / (255.0 * static_cast<double>(w) * h)) * tint);
  std::map<int, int> counts;
  for (std::size_t i = 0; i < t.rgba.size(); i += 4)
    ++counts[(t.rgba[i] >> 3) << 10 | (t.rgba[i + 1] >> 3) << 5 | (t.rgba[i + 2] >> 3)];
  std::vector<std::pair<int, int>> by_use(counts.begin(), counts.end());
  std::sort(by_use.begin(), by_use.end(), [](const auto& a, const auto& b) { return a.second > b.second || (a.second == b.second && a.first < b.first); });
  for (std::size_t i = 0; i < by_use.size() && t.palette.size() < PreviewTexture::kPaletteSize; ++i) {
    const int c = by_use[i].first;
    const glm::vec3 colour((static_cast<float>(c >> 10) + 0.5f) / 32.0f, (static_cast<float>((c >> 5) & 31) + 0.5f) / 32.0f,
                           (static_cast<float>(c & 31) + 0.5f) / 32.0f);
    t.palette.push_back(colour * tint);
  }
  return t;
}

}  // namespace procex::studio
