// Where the sweep's split candidates come from, measured on one plan: every
// live plane (the event queue's lists and their PlaneIndex, what sweep()
// uses) or the spans facing a corner across a kinetic triangulation of the
// cross-section (core/sweep/kinetic_triangulation.h, not used by sweep() yet).
// One source per process, so that the peak memory is its own; the event loop
// alone (loading the plan, its events, the surface), at the first clustering
// scale sweep() tries and with every edge at 45 degrees; then the mesh is
// validated as `procex roof` validates it.
//
//   procex_split_source_bench listed|triangulated PLAN.json
//
// Prints one line: the source, n, CPU seconds of the event loop, splits
// worked out, the triangulation's counts (and whether it was kept to the
// end), the roof's vertices, whether it validates, and the peak RSS.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include "bench/process_usage.h"
#include "core/geom/nesting.h"
#include "core/geom/prepare.h"
#include "core/io/polyjson.h"
#include "core/mesh/mesh.h"
#include "core/mesh/validate.h"
#include "core/sweep/driver.h"
#include "core/sweep/event_queue.h"
#include "core/sweep/profile_event.h"
#include "core/sweep/surface_output.h"

namespace {

using namespace procex;

int run(bool triangulated, const char* path) {
  const std::vector<PolyShape> shapes = read_polyjson_file(path);
  if (shapes.empty()) {
    std::fprintf(stderr, "%s: no shape in the file\n", path);
    return 1;
  }
  const Footprint footprint = prepare_footprint(to_footprint(shapes.front(), 45.0)).footprint;
  if (footprint.loops.size() != 1) {
    std::fprintf(stderr, "%s: %zu loops; this bench takes one\n", path, footprint.loops.size());
    return 1;
  }
  std::vector<glm::dvec2> points = footprint.loops[0].points;
  if (twice_signed_area(points) < 0.0) std::reverse(points.begin(), points.end());
  glm::dvec2 lo = points[0], hi = points[0];
  for (const glm::dvec2& p : points) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const engine::Tolerances tol{std::max(hi.x - lo.x, hi.y - lo.y), engine::Tolerances::retry_relative[0]};

  const double start = bench::cpu_seconds();
  engine::State st(tol, SweepOptions{});
  engine::FaceGroup base;
  base.kind = FaceKind::Base;
  base.outward = {0.0, 0.0, -1.0};
  st.base_face = 0;
  st.faces.push_back(base);
  for (std::size_t j = 0; j < points.size(); ++j) st.sources.push_back(engine::Source{static_cast<std::int32_t>(j)});
  engine::load_loop(st, points, std::vector<double>(points.size(), 1.0), std::vector<std::string>(points.size()), 0, 0);
  engine::EventQueue queue(engine::EventQueue::kIndexedFrom, triangulated ? 0 : SIZE_MAX);
  engine::ProfileEvents profiles;
  engine::schedule_all(st, queue);
  engine::run_events(st, queue, profiles);
  Surface surface = engine::build_surface(st);
  const double cpu = bench::cpu_seconds() - start;
  const auto& w = queue.triangulation().work();
  std::string valid = "valid";
  try {
    engine::close_surface(surface, st.plan_position);
    const ValidationReport report = validate(build_mesh(surface), roof_validation(surface));
    if (!report.ok()) valid = "INVALID: " + (report.problems.empty() ? std::string("?") : report.problems[0]);
  } catch (const std::exception& e) {
    valid = std::string("INVALID: ") + e.what();
  }
  std::printf("%s n=%zu cpu=%.3f s worked=%zu kept=%s flips=%zu updates=%zu cavity=%zu widenings=%zu tangled=%zu "
              "walked=%zu repairs=%zu rebuilds=%zu vertices=%zu %s peak=%.0f MB\n",
              triangulated ? "triangulated" : "listed", points.size(), cpu, queue.worked(),
              queue.triangulated() ? "yes" : "no", w.flips, w.updates, w.cavity_triangles, w.widenings, w.tangled,
              w.walked, w.repairs, w.rebuilds, surface.vertices.size(), valid.c_str(), bench::peak_rss_mb());
  return valid == "valid" ? 0 : 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3 || (std::strcmp(argv[1], "listed") != 0 && std::strcmp(argv[1], "triangulated") != 0)) {
    std::fprintf(stderr, "usage: %s listed|triangulated PLAN.json\n", argv[0]);
    return 64;
  }
  try {
    return run(std::strcmp(argv[1], "triangulated") == 0, argv[2]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", argv[2], e.what());
    return 1;
  }
}
