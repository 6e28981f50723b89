#include "app/studio/editor/auto_layout.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <set>

#include "app/studio/editor/canvas_layout.h"

namespace procex::studio {

namespace {

constexpr float kLayerGap = 90.0f;  // between a layer's right edge and the next one's left
constexpr float kRowGap = 30.0f;    // between boxes in one layer
constexpr float kDummyGap = 14.0f;  // around the points a long link passes through

// A box in one layer, or a point a link spanning several layers passes through.
struct Vertex {
  NodeId id = 0;  // 0 for a dummy point
  int layer = 0;
  float height = 0.0f;
  float y = 0.0f;
};

// A link between consecutive layers: from `a`'s pin at `a_pin` below its top to `b`'s at `b_pin`.
struct Segment {
  std::size_t a = 0, b = 0;
  float a_pin = 0.0f, b_pin = 0.0f;
};

struct Layered {
  std::vector<Vertex> vertices;
  std::vector<std::vector<std::size_t>> layers;  // vertex indices in order
  std::vector<Segment> segments;                 // a in layer l, b in layer l + 1
};

std::size_t inputs_of(const Node& n) { return n.decl().inputs().size(); }
std::size_t outputs_of(const Node& n) { return n.decl().outputs().size(); }

// Layers by longest path from the sources; a source then moves right up to
// its first user, so a constant sits beside what reads it.
Layered layer_nodes(const Graph& g, const std::set<NodeId>& subset) {
  Layered L;
  std::map<NodeId, std::size_t> index;
  for (NodeId id : subset) {
    const Node& n = *g.node(id);
    index[id] = L.vertices.size();
    L.vertices.push_back({id, 0, node_size(inputs_of(n), outputs_of(n)).y, 0.0f});
  }
  struct Edge {
    std::size_t a, b;
    std::uint32_t from_port, to_port;
  };
  std::vector<Edge> edges;
  for (const auto& [to, from] : g.links())
    if (index.count(from.node) && index.count(to.node)) edges.push_back({index[from.node], index[to.node], from.port, to.port});
  const std::size_t n = L.vertices.size();
  std::vector<std::vector<std::size_t>> succ(n), pred(n);
  for (const Edge& e : edges) {
    succ[e.a].push_back(e.b);
    pred[e.b].push_back(e.a);
  }
  // Kahn's order (the graph refuses cycles), lowest id first for determinism.
  std::vector<std::size_t> indegree(n), order;
  for (std::size_t v = 0; v < n; ++v) indegree[v] = pred[v].size();
  std::set<std::size_t> ready;
  for (std::size_t v = 0; v < n; ++v)
    if (!indegree[v]) ready.insert(v);
  while (!ready.empty()) {
    const std::size_t v = *ready.begin();
    ready.erase(ready.begin());
    order.push_back(v);
    for (std::size_t w : succ[v])
      if (--indegree[w] == 0) ready.insert(w);
  }
  for (std::size_t v : order)
    for (std::size_t w : succ[v]) L.vertices[w].layer = std::max(L.vertices[w].layer, L.vertices[v].layer + 1);
  for (auto it = order.rbegin(); it != order.rend(); ++it) {
    if (!pred[*it].empty() || succ[*it].empty()) continue;
    int first_use = std::numeric_limits<int>::max();
    for (std::size_t w : succ[*it]) first_use = std::min(first_use, L.vertices[w].layer);
    L.vertices[*it].layer = first_use - 1;
  }
  int layers = 0;
  for (const Vertex& v : L.vertices) layers = std::max(layers, v.layer + 1);
  L.layers.resize(static_cast<std::size_t>(layers));
  for (std::size_t v : order) L.layers[static_cast<std::size_t>(L.vertices[v].layer)].push_back(v);
  // Long links pass through one dummy point per layer they cross.
  for (const Edge& e : edges) {
    std::size_t a = e.a;
    float a_pin = pin_offset(e.from_port);
    for (int l = L.vertices[e.a].layer + 1; l < L.vertices[e.b].layer; ++l) {
      const std::size_t d = L.vertices.size();
      L.vertices.push_back({0, l, 0.0f, 0.0f});
      L.layers[static_cast<std::size_t>(l)].push_back(d);
      L.segments.push_back({a, d, a_pin, 0.0f});
      a = d;
      a_pin = 0.0f;
    }
    L.segments.push_back({a, e.b, a_pin, pin_offset(e.to_port)});
  }
  return L;
}

// Position of a pin within its layer's order: the rank, plus the pin's place down the box.
float pin_rank(const Layered& L, const std::vector<float>& rank, std::size_t v, float pin) {
  const float h = L.vertices[v].height;
  return rank[v] + (h > 0.0f ? 0.8f * pin / h : 0.0f);
}

std::size_t count_crossings(const Layered& L, const std::vector<float>& rank) {
  std::vector<std::vector<std::pair<float, float>>> by_layer(L.layers.size());
  for (const Segment& s : L.segments)
    by_layer[static_cast<std::size_t>(L.vertices[s.a].layer)].push_back({pin_rank(L, rank, s.a, s.a_pin), pin_rank(L, rank, s.b, s.b_pin)});
  std::size_t count = 0;
  for (const auto& segs : by_layer)
    for (std::size_t i = 0; i < segs.size(); ++i)
      for (std::size_t j = i + 1; j < segs.size(); ++j)
        count += (segs[i].first - segs[j].first) * (segs[i].second - segs[j].second) < 0.0f;
  return count;
}

std::vector<float> ranks_of(const Layered& L) {
  std::vector<float> rank(L.vertices.size());
  for (const auto& layer : L.layers)
    for (std::size_t i = 0; i < layer.size(); ++i) rank[layer[i]] = static_cast<float>(i);
  return rank;
}

// Barycenter sweeps, down and up, keeping the order with the fewest crossings.
void reduce_crossings(Layered& L) {
  std::vector<std::vector<std::size_t>> best = L.layers;
  std::size_t best_count = count_crossings(L, ranks_of(L));
  for (int round = 0; round < 12 && best_count > 0; ++round) {
    const bool down = round % 2 == 0;
    std::vector<float> rank = ranks_of(L);
    const int last = static_cast<int>(L.layers.size()) - 1;
    for (int step = 1; step <= last; ++step) {
      const std::size_t l = static_cast<std::size_t>(down ? step : last - step);
      std::map<std::size_t, std::pair<float, int>> sum;  // vertex -> (sum of neighbour pin ranks, count)
      for (const Segment& s : L.segments) {
        if (down && static_cast<std::size_t>(L.vertices[s.b].layer) == l) {
          auto& [total, count] = sum[s.b];
          total += pin_rank(L, rank, s.a, s.a_pin);
          ++count;
        } else if (!down && static_cast<std::size_t>(L.vertices[s.a].layer) == l) {
          auto& [total, count] = sum[s.a];
          total += pin_rank(L, rank, s.b, s.b_pin);
          ++count;
        }
      }
      std::vector<std::pair<float, std::size_t>> keyed;
      for (std::size_t v : L.layers[l]) {
        auto it = sum.find(v);
        keyed.push_back({it == sum.end() ? rank[v] : it->second.first / static_cast<float>(it->second.second), v});
      }
      std::stable_sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
      for (std::size_t i = 0; i < keyed.size(); ++i) {
        L.layers[l][i] = keyed[i].second;
        rank[keyed[i].second] = static_cast<float>(i);
      }
    }
    if (const std::size_t c = count_crossings(L, rank); c < best_count) {
      best_count = c;
      best = L.layers;
    }
  }
  L.layers = std::move(best);
}

float gap_after(const Vertex& v) { return v.id ? kRowGap : kDummyGap; }

// Tops as close as possible (least squares, weighted) to `wanted`, in order and without overlaps:
// with offsets taken out, the constraint is tops non-decreasing, which pooling adjacent violators solves.
void place_layer(Layered& L, const std::vector<std::size_t>& layer, const std::vector<float>& wanted, const std::vector<float>& weight) {
  struct Block {
    float value, weight;
    std::size_t count;
  };
  std::vector<float> offset(layer.size(), 0.0f);
  for (std::size_t i = 1; i < layer.size(); ++i) offset[i] = offset[i - 1] + L.vertices[layer[i - 1]].height + gap_after(L.vertices[layer[i - 1]]);
  std::vector<Block> blocks;
  for (std::size_t i = 0; i < layer.size(); ++i) {
    blocks.push_back({wanted[i] - offset[i], weight[i], 1});
    while (blocks.size() > 1 && blocks[blocks.size() - 2].value > blocks.back().value) {
      const Block b = blocks.back();
      blocks.pop_back();
      Block& a = blocks.back();
      a.value = (a.value * a.weight + b.value * b.weight) / (a.weight + b.weight);
      a.weight += b.weight;
      a.count += b.count;
    }
  }
  std::size_t i = 0;
  for (const Block& b : blocks)
    for (std::size_t k = 0; k < b.count; ++k, ++i) L.vertices[layer[i]].y = b.value + offset[i];
}

// Rows: stacked in order, then aligned with the pins they connect to, sweeping down and up.
void assign_rows(Layered& L) {
  for (const auto& layer : L.layers) {
    float y = 0.0f;
    for (std::size_t v : layer) {
      L.vertices[v].y = y;
      y += L.vertices[v].height + gap_after(L.vertices[v]);
    }
  }
  for (int round = 0; round < 8; ++round) {
    const bool down = round % 2 == 0;
    const int last = static_cast<int>(L.layers.size()) - 1;
    for (int step = 0; step <= last; ++step) {
      const std::size_t l = static_cast<std::size_t>(down ? step : last - step);
      const auto& layer = L.layers[l];
      std::map<std::size_t, std::pair<float, int>> sum;
      for (const Segment& s : L.segments) {
        if (down && static_cast<std::size_t>(L.vertices[s.b].layer) == l) {
          sum[s.b].first += L.vertices[s.a].y + s.a_pin - s.b_pin;
          ++sum[s.b].second;
        } else if (!down && static_cast<std::size_t>(L.vertices[s.a].layer) == l) {
          sum[s.a].first += L.vertices[s.b].y + s.b_pin - s.a_pin;
          ++sum[s.a].second;
        }
      }
      std::vector<float> wanted, weight;
      for (std::size_t v : layer) {
        auto it = sum.find(v);
        const bool linked = it != sum.end();
        wanted.push_back(linked ? it->second.first / static_cast<float>(it->second.second) : L.vertices[v].y);
        weight.push_back(linked ? static_cast<float>(it->second.second) : 0.1f);
      }
      place_layer(L, layer, wanted, weight);
    }
  }
}

std::map<NodeId, glm::vec2> layout_subset(const Graph& g, const std::set<NodeId>& subset) {
  std::map<NodeId, glm::vec2> out;
  if (subset.empty()) return out;
  Layered L = layer_nodes(g, subset);
  reduce_crossings(L);
  assign_rows(L);
  float top = std::numeric_limits<float>::max();
  for (const Vertex& v : L.vertices) top = std::min(top, v.y);
  for (const Vertex& v : L.vertices)
    if (v.id) out[v.id] = {static_cast<float>(v.layer) * (kNodeWidth + kLayerGap), std::round(v.y - top)};
  return out;
}

}  // namespace

std::map<NodeId, glm::vec2> layered_layout(const Graph& g) {
  std::set<NodeId> all;
  for (const auto& [id, n] : g.nodes()) all.insert(id);
  return layout_subset(g, all);
}

std::size_t crossings(const Graph& g, const std::map<NodeId, glm::vec2>& corners) {
  struct Seg {
    glm::vec2 a, b;
  };
  std::vector<Seg> segs;
  for (const auto& [to, from] : g.links()) {
    auto a = corners.find(from.node), b = corners.find(to.node);
    if (a == corners.end() || b == corners.end()) continue;
    segs.push_back({a->second + glm::vec2(kNodeWidth, pin_offset(from.port)), b->second + glm::vec2(0.0f, pin_offset(to.port))});
  }
  auto side = [](glm::vec2 p, glm::vec2 q, glm::vec2 r) {
    const float c = (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
    return (c > 1e-3f) - (c < -1e-3f);
  };
  std::size_t count = 0;
  for (std::size_t i = 0; i < segs.size(); ++i)
    for (std::size_t j = i + 1; j < segs.size(); ++j) {
      const Seg &s = segs[i], &t = segs[j];
      // Links sharing a pin meet there; they do not cross.
      if (s.a == t.a || s.b == t.b) continue;
      const int d1 = side(s.a, s.b, t.a), d2 = side(s.a, s.b, t.b), d3 = side(t.a, t.b, s.a), d4 = side(t.a, t.b, s.b);
      count += d1 * d2 < 0 && d3 * d4 < 0;
    }
  return count;
}

std::vector<NodeId> stacked_nodes(const Graph& g) {
  std::map<std::pair<double, double>, std::vector<NodeId>> at;
  for (const auto& [id, n] : g.nodes()) at[{n.editor.x, n.editor.y}].push_back(id);
  std::vector<NodeId> out;
  for (const auto& [pos, ids] : at)
    if (ids.size() > 1) out.insert(out.end(), ids.begin(), ids.end());
  std::sort(out.begin(), out.end());
  return out;
}

std::size_t place_stacked_nodes(Graph& g) {
  std::vector<NodeId> stacked = stacked_nodes(g);
  // The first node on each spot may have been put there: the others need places.
  std::set<std::pair<double, double>> kept;
  std::erase_if(stacked, [&](NodeId id) { return kept.insert({g.node(id)->editor.x, g.node(id)->editor.y}).second; });
  if (stacked.empty()) return 0;
  std::map<NodeId, glm::vec2> corners;
  if (stacked.size() * 2 > g.nodes().size()) {
    corners = layered_layout(g);
  } else {
    // Below the nodes that have places, so none of those moves.
    float left = std::numeric_limits<float>::max(), bottom = std::numeric_limits<float>::lowest();
    for (const auto& [id, n] : g.nodes()) {
      if (std::binary_search(stacked.begin(), stacked.end(), id)) continue;
      left = std::min(left, static_cast<float>(n.editor.x));
      bottom = std::max(bottom, static_cast<float>(n.editor.y) + node_size(inputs_of(n), outputs_of(n)).y);
    }
    corners = layout_subset(g, std::set<NodeId>(stacked.begin(), stacked.end()));
    for (auto& [id, c] : corners) c += glm::vec2(left, bottom + 2.0f * kRowGap);
  }
  for (const auto& [id, c] : corners) {
    EditorState e = g.node(id)->editor;
    e.x = c.x;
    e.y = c.y;
    (void)g.set_editor_state(id, std::move(e));
  }
  return corners.size();
}

}  // namespace procex::studio
