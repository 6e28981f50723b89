// Fuzzes parse_pxg: any input must either load or throw PxgError, and a graph
// that loads must save and load again to the same bytes.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "graph/pxg.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  procex::PxgOptions options;
  options.limits.max_file_bytes = 1 << 20;
  try {
    const procex::Graph g = procex::parse_pxg(text, "/nonexistent/fuzz/input.pxg", options);
    const std::string saved = procex::to_pxg(g);
    const std::string again = procex::to_pxg(procex::parse_pxg(saved, "/nonexistent/fuzz/input.pxg", options));
    if (saved != again) {
      std::fprintf(stderr, "round trip not byte-identical\n");
      std::abort();
    }
  } catch (const procex::PxgError&) {
  }
  return 0;
}
