#include "app/studio/editor/polyline_edit.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace procex::studio {

namespace {

double distance(Vec2 a, Vec2 b) { return std::hypot(a.x - b.x, a.y - b.y); }

// Closest point to p on segment ab, as a parameter in [0, 1].
double segment_param(Vec2 a, Vec2 b, Vec2 p) {
  const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
  if (len2 == 0) return 0;
  return std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0);
}

}  // namespace

std::vector<Vec2> move_point(std::vector<Vec2> pts, std::size_t i, Vec2 to, const PolylineRules& rules) {
  if (i >= pts.size() || (rules.pinned_start && i == 0)) return pts;
  if (rules.monotone) {
    const double lo = i > 0 ? pts[i - 1].y : -INFINITY;
    const double hi = i + 1 < pts.size() ? pts[i + 1].y : INFINITY;
    to.y = std::clamp(to.y, lo, hi);
  }
  pts[i] = to;
  return pts;
}

Vec2 snap_to_neighbours(const std::vector<Vec2>& pts, std::size_t i, Vec2 to, double tolerance, bool closed) {
  const std::size_t n = pts.size();
  if (i >= n) return to;
  std::vector<Vec2> neighbours;
  if (i > 0 || (closed && n > 1)) neighbours.push_back(pts[(i + n - 1) % n]);
  if (i + 1 < n || (closed && n > 1)) neighbours.push_back(pts[(i + 1) % n]);
  double best_x = tolerance, best_y = tolerance;
  Vec2 out = to;
  for (const Vec2& q : neighbours) {
    if (const double d = std::abs(q.x - to.x); d <= best_x) best_x = d, out.x = q.x;
    if (const double d = std::abs(q.y - to.y); d <= best_y) best_y = d, out.y = q.y;
  }
  // Both snapped onto one neighbour would merge the two points: keep the closer snap only.
  for (const Vec2& q : neighbours)
    if (out.x == q.x && out.y == q.y) (best_x <= best_y ? out.y : out.x) = best_x <= best_y ? to.y : to.x;
  return out;
}

std::vector<Vec2> insert_point(std::vector<Vec2> pts, std::size_t e, Vec2 at, const PolylineRules& rules) {
  const std::size_t n = pts.size();
  if (n == 0 || e >= (rules.closed ? n : n - 1)) return pts;
  const Vec2 a = pts[e], b = pts[(e + 1) % n];
  const double t = segment_param(a, b, at);
  // On the edge itself: a point between two monotone neighbours is monotone.
  pts.insert(pts.begin() + static_cast<std::ptrdiff_t>(e + 1), Vec2{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)});
  return pts;
}

Result<std::vector<Vec2>> remove_point(std::vector<Vec2> pts, std::size_t i, const PolylineRules& rules) {
  if (i >= pts.size()) return Status::error("no point " + std::to_string(i));
  if (rules.pinned_start && i == 0) return Status::error("the first point is fixed at (0, 0)");
  if (pts.size() <= rules.min_points) return Status::error("needs at least " + std::to_string(rules.min_points) + " points");
  pts.erase(pts.begin() + static_cast<std::ptrdiff_t>(i));
  return pts;
}

std::vector<std::string> tags_after_insert(std::vector<std::string> tags, std::size_t segments, std::size_t e) {
  if (tags.size() != segments || e >= segments) return tags;
  tags.insert(tags.begin() + static_cast<std::ptrdiff_t>(e), tags[e]);
  return tags;
}

std::vector<std::string> tags_after_remove(std::vector<std::string> tags, std::size_t segments, std::size_t i) {
  if (tags.size() != segments || segments == 0 || i > segments) return tags;
  // Point i ends segment i - 1 and starts segment i: segment i's tag goes (the last point's: the last segment's).
  const std::size_t drop = std::min(i, segments - 1);
  tags.erase(tags.begin() + static_cast<std::ptrdiff_t>(drop));
  return tags;
}

std::optional<std::size_t> nearest_point(const std::vector<Vec2>& pts, Vec2 p, double tolerance) {
  std::optional<std::size_t> best;
  double best_d = tolerance;
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (const double d = distance(pts[i], p); d <= best_d) {
      best = i;
      best_d = d;
    }
  return best;
}

std::optional<std::size_t> nearest_edge(const std::vector<Vec2>& pts, Vec2 p, double tolerance, bool closed) {
  std::optional<std::size_t> best;
  double best_d = tolerance;
  const std::size_t n = pts.size(), edges = closed ? n : (n > 0 ? n - 1 : 0);
  for (std::size_t e = 0; e < edges && n >= 2; ++e) {
    const Vec2 a = pts[e], b = pts[(e + 1) % n];
    const double t = segment_param(a, b, p);
    if (const double d = distance(p, Vec2{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)}); d <= best_d) {
      best = e;
      best_d = d;
    }
  }
  return best;
}

}  // namespace procex::studio
