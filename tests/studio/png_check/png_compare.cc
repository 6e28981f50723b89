// studio_png_compare A.png B.png IGNORE_BOTTOM_ROWS [--preview INFO.json] [--allow PIXELS]
// -- checks two procex-studio screenshots are the same pixels, except the
// bottom rows (the status bar, which shows timings). Used to show that
// redrawing only what changed from frame to frame ends in the same image as
// drawing every frame in full. With --preview, only the 3D preview's
// rectangle (from what `procex-studio --screenshot-info` wrote beside A) is
// compared, and --allow lets that many pixels differ: the same building drawn
// at another place in the world rasterises a few edge pixels apart.
#include <stb_image.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>

#include <nlohmann/json.hpp>

int main(int argc, char** argv) {
  const char* usage = "usage: studio_png_compare A.png B.png IGNORE_BOTTOM_ROWS [--preview INFO.json] [--allow PIXELS]\n";
  if (argc < 4) {
    std::fprintf(stderr, "%s", usage);
    return 2;
  }
  const char* info_file = nullptr;
  long allowed = 0;
  for (int i = 4; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--preview") && i + 1 < argc) {
      info_file = argv[++i];
    } else if (!std::strcmp(argv[i], "--allow") && i + 1 < argc) {
      allowed = std::atol(argv[++i]);
    } else {
      std::fprintf(stderr, "%s", usage);
      return 2;
    }
  }
  int w[2] = {0, 0}, h[2] = {0, 0}, n = 0;
  unsigned char* px[2] = {stbi_load(argv[1], &w[0], &h[0], &n, 3), stbi_load(argv[2], &w[1], &h[1], &n, 3)};
  for (int i = 0; i < 2; ++i)
    if (!px[i]) {
      std::fprintf(stderr, "studio_png_compare: %s: %s\n", argv[1 + i], stbi_failure_reason());
      return 1;
    }
  if (w[0] != w[1] || h[0] != h[1]) {
    std::printf("FAILED: sizes differ: %dx%d and %dx%d\n", w[0], h[0], w[1], h[1]);
    return 1;
  }
  int x0 = 0, y0 = 0, x1 = w[0], y1 = h[0] - std::atoi(argv[3]);
  if (info_file) {
    try {
      std::ifstream in(info_file);
      const nlohmann::json r = nlohmann::json::parse(in).at("preview");
      x0 = std::max(0, static_cast<int>(r.at("x").get<double>()));
      y0 = std::max(0, static_cast<int>(r.at("y").get<double>()));
      x1 = std::min(x1, x0 + static_cast<int>(r.at("w").get<double>()));
      y1 = std::min(y1, y0 + static_cast<int>(r.at("h").get<double>()));
    } catch (const std::exception& e) {
      std::fprintf(stderr, "studio_png_compare: %s: no preview rectangle: %s\n", info_file, e.what());
      return 1;
    }
  }
  long differ = 0;
  int first_x = -1, first_y = -1;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      for (int c = 0; c < 3; ++c) {
        const std::size_t k = (static_cast<std::size_t>(y) * w[0] + x) * 3 + c;
        if (px[0][k] != px[1][k]) {
          if (differ++ == 0) first_x = x, first_y = y;
          break;
        }
      }
  stbi_image_free(px[0]);
  stbi_image_free(px[1]);
  if (differ > allowed) {
    std::printf("FAILED: %ld pixels differ (%ld allowed), the first at (%d, %d)\n", differ, allowed, first_x, first_y);
    return 1;
  }
  std::printf("ok: %ld of the %dx%d pixels from (%d, %d) differ (%ld allowed; bottom %s rows ignored)\n", differ, x1 - x0, y1 - y0,
              x0, y0, allowed, argv[3]);
  return 0;
}
