// write_glb with placed meshes at city scale (figures in BENCHMARKS.md,
// "Batch"): every building a box with windows instanced on it, joined the way
// `procex batch` joins them (one scene per building, then append_scene), then
// written once. Prints the time of each phase and the file's size.
// Usage: procex_glb_instances_bench [BUILDINGS] [WINDOWS_PER_BUILDING] [OUT.glb]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "core/io/gltf_write.h"
#include "core/io/mesh_read.h"
#include "core/placement/frame_transform.h"
#include "core/placement/placement_gltf.h"

int main(int argc, char** argv) {
  using namespace procex;
  namespace fs = std::filesystem;
  const int buildings = argc > 1 ? std::atoi(argv[1]) : 9491;
  const int windows = argc > 2 ? std::atoi(argv[2]) : 20;
  const fs::path out = argc > 3 ? fs::path(argv[3]) : fs::temp_directory_path() / "procex_glb_instances_bench.glb";
  const fs::path data = fs::path(PROCEX_TEST_DATA);
  const auto window = std::make_shared<const Mesh>(read_mesh_file(data / "mesh_window_frame.obj"));
  const auto box = std::make_shared<const Mesh>(read_mesh_file(data / "mesh_dormer_box.obj"));
  using Clock = std::chrono::steady_clock;
  const auto ms = [](Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); };

  const auto start = Clock::now();
  GltfScene city;
  for (int b = 0; b < buildings; ++b) {
    PlacementResult r;
    r.building = box;
    const std::size_t w = r.add_mesh({"window", window});
    for (int k = 0; k < windows; ++k) {
      Frame f;
      f.origin = {20.0 * b + k, 0, 1};
      r.add_instance({w, place_at(f), "", -1});
    }
    GltfSceneBuilder one;
    one.add(r, std::string("b").append(std::to_string(b)), b);
    append_scene(city, std::move(one).take());
  }
  const auto built = Clock::now();
  write_glb(out, city);
  const auto written = Clock::now();
  std::printf("%d buildings, %d windows each: scenes built and joined %.0f ms (serial), write_glb %.0f ms, %.1f MB -> %s\n",
              buildings, windows, ms(start, built), ms(built, written), static_cast<double>(fs::file_size(out)) / 1e6,
              out.string().c_str());
}
