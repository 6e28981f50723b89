// studio_png_compare A.png B.png IGNORE_BOTTOM_ROWS -- checks two procex-studio
// screenshots are the same pixels, except the bottom rows (the status bar,
// which shows timings). Used to show that redrawing only what changed from
// frame to frame ends in the same image as drawing every frame in full.
#include <stb_image.h>

#include <cstdio>
#include <cstdlib>

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: studio_png_compare A.png B.png IGNORE_BOTTOM_ROWS\n");
    return 2;
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
  const int rows = h[0] - std::atoi(argv[3]);
  long differ = 0;
  int first_x = -1, first_y = -1;
  for (int y = 0; y < rows; ++y)
    for (int x = 0; x < w[0]; ++x)
      for (int c = 0; c < 3; ++c) {
        const std::size_t k = (static_cast<std::size_t>(y) * w[0] + x) * 3 + c;
        if (px[0][k] != px[1][k]) {
          if (differ++ == 0) first_x = x, first_y = y;
          break;
        }
      }
  stbi_image_free(px[0]);
  stbi_image_free(px[1]);
  if (differ) {
    std::printf("FAILED: %ld pixels differ, the first at (%d, %d)\n", differ, first_x, first_y);
    return 1;
  }
  std::printf("ok: the same %dx%d pixels (bottom %s rows ignored)\n", w[0], rows, argv[3]);
  return 0;
}
