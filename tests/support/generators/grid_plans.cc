#include "tests/support/generators/grid_plans.h"

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

namespace procex::testing {
namespace {

// Filled cells of a w x h grid; cell (i, j) is the unit square from (i, j).
class Cells {
 public:
  Cells(int w, int h) : w_(w), h_(h), filled_(static_cast<std::size_t>(w * h), false) {}
  bool at(int i, int j) const { return i >= 0 && j >= 0 && i < w_ && j < h_ && filled_[index(i, j)]; }
  void fill(int i, int j) {
    if (i >= 0 && j >= 0 && i < w_ && j < h_) filled_[index(i, j)] = true;
  }
  void fill_rect(int x0, int y0, int x1, int y1) {
    for (int i = x0; i < x1; ++i)
      for (int j = y0; j < y1; ++j) fill(i, j);
  }
  void clear_rect(int x0, int y0, int x1, int y1) {
    for (int i = x0; i < x1; ++i)
      for (int j = y0; j < y1; ++j)
        if (at(i, j)) filled_[index(i, j)] = false;
  }

  // Fills the empty cells of every 2 x 2 window whose cells alternate
  // (filled cells meeting only at a corner, or holes doing so), until none is left.
  void fill_corner_contacts() {
    for (bool changed = true; changed;) {
      changed = false;
      for (int i = 0; i + 1 < w_; ++i)
        for (int j = 0; j + 1 < h_; ++j) {
          const bool a = at(i, j), b = at(i + 1, j), c = at(i, j + 1), d = at(i + 1, j + 1);
          if (a == d && b == c && a != b) {
            fill_rect(i, j, i + 2, j + 2);
            changed = true;
          }
        }
    }
  }

  // Boundary loops with the cells on their left, straight vertices removed.
  Plan outline() const {
    std::map<std::pair<int, int>, std::pair<int, int>> next;  // directed boundary edges
    for (int i = 0; i < w_; ++i)
      for (int j = 0; j < h_; ++j) {
        if (!at(i, j)) continue;
        if (!at(i, j - 1)) next[{i, j}] = {i + 1, j};
        if (!at(i + 1, j)) next[{i + 1, j}] = {i + 1, j + 1};
        if (!at(i, j + 1)) next[{i + 1, j + 1}] = {i, j + 1};
        if (!at(i - 1, j)) next[{i, j + 1}] = {i, j};
      }
    Plan loops;
    while (!next.empty()) {
      std::vector<std::pair<int, int>> chain;
      auto at_point = next.begin();
      const std::pair<int, int> start = at_point->first;
      std::pair<int, int> p = start;
      do {
        chain.push_back(p);
        const auto it = next.find(p);
        p = it->second;
        next.erase(it);
      } while (p != start);
      std::vector<glm::dvec2> loop;
      const std::size_t n = chain.size();
      for (std::size_t k = 0; k < n; ++k) {
        const auto a = chain[(k + n - 1) % n], b = chain[k], c = chain[(k + 1) % n];
        const bool straight = (a.first == b.first && b.first == c.first) || (a.second == b.second && b.second == c.second);
        if (!straight) loop.emplace_back(b.first, b.second);
      }
      loops.push_back(std::move(loop));
    }
    return loops;
  }

 private:
  std::size_t index(int i, int j) const { return static_cast<std::size_t>(j * w_ + i); }
  int w_, h_;
  std::vector<bool> filled_;
};

std::size_t vertex_count(const Plan& plan) {
  std::size_t n = 0;
  for (const auto& loop : plan) n += loop.size();
  return n;
}

template <class T>
T pick(std::mt19937_64& rng, std::initializer_list<T> values) {
  return *(values.begin() + std::uniform_int_distribution<std::size_t>(0, values.size() - 1)(rng));
}

}  // namespace

NamedPlan polyomino_plan(std::mt19937_64& rng, std::size_t max_vertices) {
  for (;;) {
    const int w = std::uniform_int_distribution<int>(2, 24)(rng), h = std::uniform_int_distribution<int>(2, 24)(rng);
    const int target = std::uniform_int_distribution<int>(1, std::max(1, w * h * 2 / 3))(rng);
    Cells cells(w, h);
    std::vector<std::pair<int, int>> grown{{w / 2, h / 2}};
    cells.fill(w / 2, h / 2);
    // Grow from random filled cells into random free neighbours.
    for (int tries = 0; static_cast<int>(grown.size()) < target && tries < 20 * target; ++tries) {
      const auto [i, j] = grown[std::uniform_int_distribution<std::size_t>(0, grown.size() - 1)(rng)];
      static constexpr int kStep[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
      const int* d = kStep[std::uniform_int_distribution<int>(0, 3)(rng)];
      const int ni = i + d[0], nj = j + d[1];
      if (ni < 0 || nj < 0 || ni >= w || nj >= h || cells.at(ni, nj)) continue;
      cells.fill(ni, nj);
      grown.emplace_back(ni, nj);
    }
    cells.fill_corner_contacts();
    Plan plan = cells.outline();
    const std::size_t n = vertex_count(plan);
    if (n >= 4 && n <= max_vertices)
      return {"polyomino of " + std::to_string(grown.size()) + " cells in " + std::to_string(w) + " x " +
                  std::to_string(h) + ", " + std::to_string(plan.size()) + " loops",
              std::move(plan)};
  }
}

NamedPlan letter_plan(std::mt19937_64& rng) {
  // Wings from one small set, lengths from another: coincident widths and
  // equal distances between parallel edges are the point.
  const int w = pick(rng, {2, 4, 8}), v = pick(rng, {2, 4, 8});
  const int l = pick(rng, {12, 16, 24}), m = pick(rng, {12, 16, 24});
  const std::string kinds[] = {"rectangle", "L", "T", "U", "H", "E", "F", "plus", "comb", "stairs", "courtyard", "court grid"};
  const std::string kind = kinds[std::uniform_int_distribution<std::size_t>(0, std::size(kinds) - 1)(rng)];
  Cells c(64, 64);
  if (kind == "rectangle") {
    c.fill_rect(0, 0, l, w);
  } else if (kind == "L") {
    c.fill_rect(0, 0, w, m);
    c.fill_rect(0, 0, l, v);
  } else if (kind == "T") {
    c.fill_rect(0, m - v, l + w, m);
    c.fill_rect(l / 2, 0, l / 2 + w, m);
  } else if (kind == "U") {
    c.fill_rect(0, 0, w, m);
    c.fill_rect(l + w, 0, l + 2 * w, m);
    c.fill_rect(0, 0, l + 2 * w, v);
  } else if (kind == "H") {
    c.fill_rect(0, 0, w, m);
    c.fill_rect(l + w, 0, l + 2 * w, m);
    c.fill_rect(0, m / 2 - v / 2, l + 2 * w, m / 2 - v / 2 + v);
  } else if (kind == "E" || kind == "F") {
    c.fill_rect(0, 0, w, 2 * m);
    c.fill_rect(0, 2 * m - v, l, 2 * m);
    c.fill_rect(0, m - v / 2, l, m - v / 2 + v);
    if (kind == "E") c.fill_rect(0, 0, l, v);
  } else if (kind == "plus") {
    c.fill_rect(0, m / 2, l + w, m / 2 + v);
    c.fill_rect(l / 2, 0, l / 2 + w, m + v);
  } else if (kind == "comb") {
    const int teeth = std::uniform_int_distribution<int>(2, 8)(rng), t = pick(rng, {1, 2});
    c.fill_rect(0, 0, (2 * teeth - 1) * t, v);
    for (int k = 0; k < teeth; ++k) c.fill_rect(2 * k * t, 0, 2 * k * t + t, v + m / 2);
  } else if (kind == "stairs") {
    const int steps = std::uniform_int_distribution<int>(2, 8)(rng);
    for (int k = 0; k < steps; ++k) c.fill_rect(k * w, 0, (k + 1) * w, (steps - k) * v);
  } else if (kind == "court grid") {  // k x k square courts of side v, placed symmetrically, walls w
    const int k = std::uniform_int_distribution<int>(1, 4)(rng);
    c.fill_rect(0, 0, k * (v + w) + w, k * (v + w) + w);
    for (int a = 0; a < k; ++a)
      for (int b = 0; b < k; ++b) c.clear_rect(w + a * (v + w), w + b * (v + w), (a + 1) * (v + w), (b + 1) * (v + w));
  } else {  // courtyard: a ring of wall width w, sometimes with a cross wall splitting the court
    c.fill_rect(0, 0, l + 2 * w, m + 2 * w);
    c.clear_rect(w, w, l + w, m + w);
    if (std::uniform_int_distribution<int>(0, 1)(rng) == 1) c.fill_rect(w + (l - w) / 2, w, w + (l - w) / 2 + w, m + w);
  }
  return {kind + " wings " + std::to_string(w) + "/" + std::to_string(v) + ", lengths " + std::to_string(l) + "/" +
              std::to_string(m),
          c.outline()};
}

NamedPlan with_collinear_vertices(NamedPlan plan, std::mt19937_64& rng) {
  std::size_t added = 0;
  for (auto& loop : plan.loops) {
    std::vector<glm::dvec2> out;
    for (std::size_t i = 0; i < loop.size(); ++i) {
      out.push_back(loop[i]);
      const glm::dvec2 a = loop[i], b = loop[(i + 1) % loop.size()];
      const int length = static_cast<int>(std::abs(b.x - a.x) + std::abs(b.y - a.y));
      if (length < 2 || std::uniform_int_distribution<int>(0, 2)(rng) != 0) continue;
      // Distinct interior grid points, in order along the edge.
      std::vector<int> at;
      for (int k = std::uniform_int_distribution<int>(1, 3)(rng); k > 0; --k)
        at.push_back(std::uniform_int_distribution<int>(1, length - 1)(rng));
      std::sort(at.begin(), at.end());
      at.erase(std::unique(at.begin(), at.end()), at.end());
      for (int k : at) out.push_back(a + (b - a) * (static_cast<double>(k) / length));
      added += at.size();
    }
    loop = std::move(out);
  }
  plan.name += ", " + std::to_string(added) + " collinear vertices added";
  return plan;
}

}  // namespace procex::testing
