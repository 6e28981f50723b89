// studio_png_check IMAGE.png INFO.json [--require-tag NAME]... [--require-texture NAME]... [--require-anchors] --
// checks a procex-studio screenshot:
// the image is not blank, and the 3D preview shows the geometry: enough
// pixels differ from the preview's background, most of them carry a tag's
// (lit) colour (a textured tag's: its texture's mean or commonest colours),
// and the tags seen cover most of the mesh's coloured area
// (some faces may hide behind others), and each required tag is clearly
// visible (a soffit seen from below the eaves), each required texture is
// drawn (two of its colours of clearly different hue each cover many
// pixels: a face of one flat colour cannot), and with --require-anchors
// that the anchors have markers (pixels of the marker colour). INFO.json is
// what `procex-studio --screenshot-info` wrote beside the image. The node
// canvas's text must be legible (at least 10 px) and its framing zoom no lower
// than the legible one.
#include <stb_image.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace {

struct Rgb {
  float r, g, b;
};

// Lighting scales a tag's colour, so compare chromaticities (colour / sum).
bool same_chroma(Rgb p, Rgb c) {
  const float sp = p.r + p.g + p.b, sc = c.r + c.g + c.b;
  if (sp < 0.15f || sc <= 0) return false;
  return std::fabs(p.r / sp - c.r / sc) + std::fabs(p.g / sp - c.g / sc) + std::fabs(p.b / sp - c.b / sc) < 0.05f;
}

bool chromatic(Rgb c) { return std::max({c.r, c.g, c.b}) - std::min({c.r, c.g, c.b}) > 0.1f; }

int failures = 0;
void check(bool ok, const std::string& what) {
  std::printf("%s: %s\n", ok ? "ok" : "FAILED", what.c_str());
  failures += !ok;
}

}  // namespace

int main(int argc, char** argv) {
  const char* usage = "usage: studio_png_check IMAGE.png INFO.json [--require-tag NAME]... [--require-texture NAME]... [--require-anchors]\n";
  std::vector<std::string> required, required_textures;
  bool require_anchors = false;
  for (int i = 3; i < argc; ++i) {
    if (std::string(argv[i]) == "--require-anchors") {
      require_anchors = true;
    } else if (std::string(argv[i]) == "--require-tag" && i + 1 < argc) {
      required.push_back(argv[++i]);
    } else if (std::string(argv[i]) == "--require-texture" && i + 1 < argc) {
      required_textures.push_back(argv[++i]);
    } else {
      std::fprintf(stderr, "%s", usage);
      return 2;
    }
  }
  if (argc < 3) {
    std::fprintf(stderr, "%s", usage);
    return 2;
  }
  int w = 0, h = 0, n = 0;
  unsigned char* data = stbi_load(argv[1], &w, &h, &n, 3);
  if (!data) {
    std::fprintf(stderr, "studio_png_check: %s: %s\n", argv[1], stbi_failure_reason());
    return 1;
  }
  nlohmann::json info;
  try {
    std::ifstream in(argv[2]);
    info = nlohmann::json::parse(in);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "studio_png_check: %s: %s\n", argv[2], e.what());
    return 1;
  }
  auto at = [&](int x, int y) {
    const unsigned char* p = data + (static_cast<std::size_t>(y) * w + x) * 3;
    return Rgb{p[0] / 255.0f, p[1] / 255.0f, p[2] / 255.0f};
  };
  check(w == info["width"].get<int>() && h == info["height"].get<int>(), "image size " + std::to_string(w) + "x" + std::to_string(h));
  check(info["errors"].get<int>() == 0, "the recipe evaluated without errors");

  // Not blank: many distinct colours over the whole window.
  std::set<int> colours;
  for (int y = 0; y < h; y += 2)
    for (int x = 0; x < w; x += 2) {
      const unsigned char* p = data + (static_cast<std::size_t>(y) * w + x) * 3;
      colours.insert((p[0] >> 3) << 10 | (p[1] >> 3) << 5 | (p[2] >> 3));
    }
  check(colours.size() >= 20, std::to_string(colours.size()) + " distinct colours in the window");

  // The preview: pixels that are neither its background nor its grey grid.
  const auto& r = info["preview"];
  const int x0 = static_cast<int>(r["x"].get<double>()), y0 = static_cast<int>(r["y"].get<double>());
  const int x1 = std::min(w, x0 + static_cast<int>(r["w"].get<double>())), y1 = std::min(h, y0 + static_cast<int>(r["h"].get<double>()));
  const Rgb background = at(x0 + 1, y0 + 1);
  std::vector<Rgb> tag_colours;
  std::vector<std::string> tag_names;
  std::vector<double> tag_areas;
  std::vector<std::vector<Rgb>> texture_colours;  // per tag: its texture's colours, none if untextured
  for (const auto& t : info["tags"]) {
    tag_colours.push_back({t["color"][0].get<float>(), t["color"][1].get<float>(), t["color"][2].get<float>()});
    tag_names.push_back(t["name"].get<std::string>());
    tag_areas.push_back(t["area"].get<double>());
    texture_colours.emplace_back();
    if (t.contains("texture_colours"))
      for (const auto& c : t["texture_colours"]) texture_colours.back().push_back({c[0].get<float>(), c[1].get<float>(), c[2].get<float>()});
  }
  std::vector<long> tag_pixels(tag_colours.size(), 0);
  std::vector<std::vector<long>> texture_pixels(texture_colours.size());
  for (std::size_t i = 0; i < texture_colours.size(); ++i) texture_pixels[i].assign(texture_colours[i].size(), 0);
  const auto& ac = info["anchor_color"];
  const Rgb anchor_colour{ac[0].get<float>(), ac[1].get<float>(), ac[2].get<float>()};
  long geometry = 0, area = 0, anchor_pixels = 0, tagged_pixels = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      ++area;
      const Rgb p = at(x, y);
      const bool grey = std::max({p.r, p.g, p.b}) - std::min({p.r, p.g, p.b}) < 0.03f;
      const bool is_background = std::fabs(p.r - background.r) + std::fabs(p.g - background.g) + std::fabs(p.b - background.b) < 0.03f;
      if (is_background || (grey && p.r < 0.35f)) continue;  // background or grid line
      ++geometry;
      anchor_pixels += same_chroma(p, anchor_colour);
      bool any = false;  // tags that share a texture both match its pixels: each pixel counts once below
      for (std::size_t i = 0; i < tag_colours.size(); ++i) {
        bool seen = chromatic(tag_colours[i]) && same_chroma(p, tag_colours[i]);
        for (std::size_t k = 0; k < texture_colours[i].size(); ++k)
          if (chromatic(texture_colours[i][k]) && same_chroma(p, texture_colours[i][k])) ++texture_pixels[i][k], seen = true;
        tag_pixels[i] += seen;
        any = any || seen;
      }
      tagged_pixels += any;
    }
  check(area > 10000, "preview area " + std::to_string(area) + " pixels");
  check(geometry > area / 50, "geometry covers " + std::to_string(100.0 * geometry / std::max(area, 1L)) + "% of the preview");
  double coloured_area = 0, seen_area = 0;
  for (std::size_t i = 0; i < tag_colours.size(); ++i) {
    if (!chromatic(tag_colours[i]) && texture_colours[i].empty()) continue;
    coloured_area += tag_areas[i];
    if (tag_pixels[i] >= 50) seen_area += tag_areas[i];
    std::printf("     tag '%s': %ld pixels, %.1f m2\n", tag_names[i].c_str(), tag_pixels[i], tag_areas[i]);
  }
  check(coloured_area > 0 && seen_area >= 0.5 * coloured_area, "the tags seen cover " + std::to_string(100.0 * seen_area / std::max(coloured_area, 1e-9)) + "% of the coloured mesh area");
  for (const std::string& name : required) {
    const auto it = std::find(tag_names.begin(), tag_names.end(), name);
    const long pixels = it == tag_names.end() ? 0 : tag_pixels[static_cast<std::size_t>(it - tag_names.begin())];
    check(pixels >= 200, "required tag '" + name + "' " + (it == tag_names.end() ? "is not in the mesh" : "covers " + std::to_string(pixels) + " pixels (at least 200)"));
  }
  for (const std::string& name : required_textures) {
    const auto it = std::find(tag_names.begin(), tag_names.end(), name);
    const std::size_t i = static_cast<std::size_t>(it - tag_names.begin());
    // Two of its colours, each on many pixels, whose hues differ as a texture's parts do.
    bool two = false;
    if (it != tag_names.end())
      for (std::size_t a = 0; a < texture_colours[i].size(); ++a)
        for (std::size_t b = a + 1; b < texture_colours[i].size(); ++b) {
          const Rgb ca = texture_colours[i][a], cb = texture_colours[i][b];
          const float sa = ca.r + ca.g + ca.b, sb = cb.r + cb.g + cb.b;
          const bool apart = std::fabs(ca.r / sa - cb.r / sb) + std::fabs(ca.g / sa - cb.g / sb) + std::fabs(ca.b / sa - cb.b / sb) > 0.2f;
          two = two || (apart && texture_pixels[i][a] >= 200 && texture_pixels[i][b] >= 200);
        }
    std::string counts;
    if (it != tag_names.end())
      for (long n : texture_pixels[i]) counts.append(1, ' ').append(std::to_string(n));
    check(two, "required texture of '" + name + "' " +
                   (it == tag_names.end() ? "is not in the mesh"
                    : texture_colours[i].empty() ? "is missing: the tag has no texture"
                                                 : "shows two of its colours on 200 pixels each (pixels per colour:" + counts + ")"));
  }
  if (require_anchors) {
    const long present = info["anchors_present"].get<long>();
    check(present > 0 && anchor_pixels >= 40 * present,
          std::to_string(anchor_pixels) + " pixels of anchor markers for " + std::to_string(present) + " present anchors (at least 40 each)");
  }
  // Readable node canvas: whatever text it drew is at least the legible size, and a
  // graph framed at open uses a zoom no lower than the one that keeps text that size.
  if (info.contains("canvas")) {
    const double min_px = info["canvas"]["min_text_px"].get<double>(), zoom = info["canvas"]["zoom"].get<double>();
    const double legible = info["canvas"]["legible_zoom"].get<double>();
    check(min_px == 0.0 || min_px >= 10.0 - 1e-3, "the smallest text on the node canvas is " + std::to_string(min_px) + " px (at least 10)");
    check(zoom >= legible - 1e-4, "the node canvas opened at zoom " + std::to_string(zoom) + " (legible from " + std::to_string(legible) + ")");
  } else {
    check(false, "INFO.json says how the node canvas was drawn");
  }
  check(tagged_pixels > geometry / 2, std::to_string(tagged_pixels) + " of " + std::to_string(geometry) + " geometry pixels have a tag colour");
  stbi_image_free(data);
  std::printf("%d failed\n", failures);
  return failures == 0 ? 0 : 1;
}
