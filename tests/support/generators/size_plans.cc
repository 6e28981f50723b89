#include "tests/support/generators/size_plans.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>

#include "core/geom/segment_intersections.h"

namespace procex::testing {
namespace {

NamedPlan polar(std::string name, const std::vector<double>& angles, const std::vector<double>& radii) {
  std::vector<glm::dvec2> loop;
  for (std::size_t i = 0; i < angles.size(); ++i)
    loop.emplace_back(radii[i] * std::cos(angles[i]), radii[i] * std::sin(angles[i]));
  return {std::move(name), {std::move(loop)}};
}

std::vector<double> even_angles(std::size_t n) {
  std::vector<double> a(n);
  for (std::size_t i = 0; i < n; ++i) a[i] = 2.0 * M_PI * static_cast<double>(i) / static_cast<double>(n);
  return a;
}

// The place of cell (x, y) along the Hilbert curve through a 2^16 x 2^16 grid.
std::uint64_t hilbert_index(std::uint32_t x, std::uint32_t y) {
  constexpr std::uint32_t kSide = 1u << 16;
  std::uint64_t d = 0;
  for (std::uint32_t s = kSide / 2; s > 0; s /= 2) {
    const std::uint32_t rx = (x & s) ? 1 : 0, ry = (y & s) ? 1 : 0;
    d += static_cast<std::uint64_t>(s) * s * ((3 * rx) ^ ry);
    if (ry == 0) {  // the quadrant turned so that the curve runs on through it
      if (rx == 1) x = kSide - 1 - x, y = kSide - 1 - y;
      std::swap(x, y);
    }
  }
  return d;
}

}  // namespace

NamedPlan regular_polygon(std::size_t n, double radius) {
  return polar("regular " + std::to_string(n) + "-gon of radius " + std::to_string(radius), even_angles(n),
               std::vector<double>(n, radius));
}

NamedPlan star(std::size_t n, double outer, double inner) {
  std::vector<double> radii(n);
  for (std::size_t i = 0; i < n; ++i) radii[i] = i % 2 == 0 ? outer : inner;
  return polar("star of " + std::to_string(n) + " vertices, radii " + std::to_string(outer) + "/" + std::to_string(inner),
               even_angles(n), radii);
}

NamedPlan jittered_star(std::size_t n, double outer, double inner, double jitter, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> moved(-jitter, jitter);
  std::vector<double> radii(n);
  for (std::size_t i = 0; i < n; ++i) radii[i] = (i % 2 == 0 ? outer : inner) + moved(rng);
  return polar("star of " + std::to_string(n) + " vertices, radii " + std::to_string(outer) + "/" +
                   std::to_string(inner) + " each moved by up to " + std::to_string(jitter),
               even_angles(n), radii);
}

NamedPlan random_star_shaped(std::size_t n, double radius, std::mt19937_64& rng) {
  // Angles jittered within their own slot keep order and a positive gap.
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> angles = even_angles(n), radii(n);
  for (std::size_t i = 0; i < n; ++i) {
    angles[i] += (0.1 + 0.8 * unit(rng)) * 2.0 * M_PI / static_cast<double>(n);
    radii[i] = radius * (0.3 + 0.7 * unit(rng));
  }
  return polar("random star-shaped polygon of " + std::to_string(n) + " vertices", angles, radii);
}

NamedPlan random_simple_polygon(std::size_t n, double size, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> coordinate(0.0, size);
  std::vector<std::pair<std::uint64_t, glm::dvec2>> placed(n);
  for (auto& [key, p] : placed) {
    p = {coordinate(rng), coordinate(rng)};
    const auto cell = [size](double v) {
      return static_cast<std::uint32_t>(std::min(v / size, 1.0 - 1e-12) * 65536.0);
    };
    key = hilbert_index(cell(p.x), cell(p.y));
  }
  std::sort(placed.begin(), placed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<glm::dvec2> loop(n);
  for (std::size_t i = 0; i < n; ++i) loop[i] = placed[i].second;
  // Each round undoes the crossings whose paths between do not overlap; a
  // reversal keeps every edge but the two it replaces, so the others found
  // in the round still cross.
  for (;;) {
    const LoopSegments segments = loop_segments({loop});
    const auto crossing = intersecting_segment_pairs(segments.segments, segments.next, n);
    if (crossing.empty()) break;
    std::vector<std::pair<std::size_t, std::size_t>> taken;  // [i, j + 1] of each reversal
    for (const auto& [i, j] : crossing) {
      const bool apart = std::none_of(taken.begin(), taken.end(), [&](const auto& t) {
        return !(j + 1 < t.first || t.second < i);
      });
      if (!apart) continue;
      std::reverse(loop.begin() + static_cast<std::ptrdiff_t>(i + 1),
                   loop.begin() + static_cast<std::ptrdiff_t>(j + 1));
      taken.emplace_back(i, j + 1);
    }
  }
  double area2 = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec2 &p = loop[i], &q = loop[(i + 1) % n];
    area2 += p.x * q.y - q.x * p.y;
  }
  if (area2 < 0.0) std::reverse(loop.begin(), loop.end());  // counter-clockwise, as an outer loop is
  return {"random simple polygon of " + std::to_string(n) + " vertices (2-opt) in a square of side " +
              std::to_string(size),
          {std::move(loop)}};
}

}  // namespace procex::testing
