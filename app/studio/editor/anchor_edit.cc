#include "app/studio/editor/anchor_edit.h"

#include <algorithm>
#include <charconv>
#include <set>

#include "app/studio/editor/downstream.h"

namespace procex::studio {

namespace {

constexpr const char* kAnchorType = "Anchor";
constexpr const char* kExtrudeType = "Extrude";
constexpr const char* kAnchorInputPrefix = "anchor_";

template <class T>
T param_or(const Node& n, std::string_view name, T fallback) {
  const auto i = n.decl().param_index(name);
  return i && n.params[*i].is<T>() ? n.params[*i].get<T>() : fallback;
}

std::vector<std::int32_t> edge_ids(const std::string& text) {
  std::vector<std::int32_t> ids;
  const char* p = text.data();
  const char* end = p + text.size();
  while (p < end) {
    while (p < end && (*p == ' ' || *p == ',' || *p == '\t')) ++p;
    std::int32_t id = 0;
    const auto [next, ec] = std::from_chars(p, end, id);
    if (ec != std::errc()) return {};  // the node reports the bad text; the editor shows every edge
    ids.push_back(id);
    p = next;
  }
  return ids;
}

}  // namespace

std::optional<NodeId> extrude_downstream(const Graph& g, NodeId from) {
  const std::vector<NodeId> found = downstream_of_type(g, from, kExtrudeType);
  return found.empty() ? std::nullopt : std::optional<NodeId>(found.front());
}

std::vector<AnchorNode> anchors_into(const Graph& g, NodeId extrude) {
  std::vector<AnchorNode> out;
  const Node* e = g.node(extrude);
  if (!e) return out;
  for (std::uint32_t i = 0; i < e->decl().inputs().size(); ++i) {
    const auto from = g.source(PortRef{extrude, i});
    const Node* a = from ? g.node(from->node) : nullptr;
    if (!a || a->type->name() != kAnchorType) continue;
    AnchorNode an;
    an.node = a->id;
    an.name = param_or<std::string>(*a, "name", "");
    an.mode = param_or<EnumValue>(*a, "mode", EnumValue{"fraction"}).choice;
    an.position = param_or<double>(*a, "position", 0.5);
    an.profile = param_or<std::string>(*a, "profile", "");
    an.edges = edge_ids(param_or<std::string>(*a, "edges", ""));
    out.push_back(std::move(an));
  }
  return out;
}

double edge_fraction(const std::string& mode, double position, double length) {
  const double t = mode == "fraction" ? position : length <= 0 ? 0.0 : mode == "from_end" ? 1.0 - position / length : position / length;
  return std::clamp(t, 0.0, 1.0);
}

double anchor_position(const std::string& mode, double fraction, double length) {
  const double t = std::clamp(fraction, 0.0, 1.0);
  return mode == "fraction" ? t : mode == "from_end" ? (1.0 - t) * length : t * length;
}

Result<NodeId> place_anchor(Document& doc, NodeId footprint_node, std::int32_t edge_id, double fraction) {
  const Graph& g = doc.graph();
  const Node* fp = g.node(footprint_node);
  if (!fp) return Status::error("no node " + std::to_string(footprint_node));
  const auto extrude = extrude_downstream(g, footprint_node);
  if (!extrude) return Status::error("no Extrude downstream of " + fp->type->name() + " #" + std::to_string(footprint_node) + " to resolve an anchor on");
  const Node* ex = g.node(*extrude);
  const auto count_param = ex->decl().param_index("anchors");
  if (!count_param || !ex->params[*count_param].is<std::int64_t>())
    return Status::error("Extrude #" + std::to_string(*extrude) + " takes no anchors");
  // A name no Anchor node uses yet.
  std::set<std::string> names;
  for (const auto& [id, n] : g.nodes())
    if (n.type->name() == kAnchorType) names.insert(param_or<std::string>(n, "name", ""));
  std::string name;
  for (int k = 1; name.empty() || names.count(name); ++k) name = "anchor" + std::to_string(k);

  doc.begin_gesture("place anchor");
  auto fail = [&](const Status& s) -> Result<NodeId> {
    doc.abort_gesture();
    doc.select_only(footprint_node);
    return s;
  };
  Result<NodeId> added = doc.add_node(kAnchorType, fp->editor.x, fp->editor.y + 140);
  if (!added) return fail(added.status());
  const NodeId id = *added;
  const Node* a = doc.graph().node(id);
  const std::pair<const char*, Value> params[] = {
      {"name", Value::make(name)},
      {"mode", Value::make(EnumValue{"fraction"})},
      {"position", Value::make(std::clamp(fraction, 0.0, 1.0))},
      {"edges", Value::make(std::to_string(edge_id))},
  };
  for (const auto& [pname, v] : params) {
    const auto i = a->decl().param_index(pname);
    if (!i) return fail(Status::error(std::string("the Anchor node has no parameter '") + pname + "'"));
    if (Status s = doc.set_param(id, *i, v); !s) return fail(s);
  }
  // A free anchor input, else one more.
  auto free_input = [&]() -> std::optional<std::uint32_t> {
    const Node* e = doc.graph().node(*extrude);
    for (std::uint32_t i = 0; i < e->decl().inputs().size(); ++i)
      if (e->decl().inputs()[i].name.starts_with(kAnchorInputPrefix) && !doc.graph().source(PortRef{*extrude, i})) return i;
    return std::nullopt;
  };
  auto input = free_input();
  if (!input) {
    const auto count = static_cast<std::size_t>(doc.graph().node(*extrude)->params[*count_param].get<std::int64_t>());
    if (Status s = doc.set_port_count(*extrude, *count_param, count + 1); !s) return fail(s);
    input = free_input();
    if (!input) return fail(Status::error("Extrude #" + std::to_string(*extrude) + " has no free anchor input"));
  }
  if (Status s = doc.connect(PortRef{id, 0}, PortRef{*extrude, *input}); !s) return fail(s);
  doc.end_gesture();
  doc.select_only(footprint_node);
  return id;
}

}  // namespace procex::studio
