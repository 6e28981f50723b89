#include "app/studio/ui/shape_editor.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <typeindex>
#include <vector>

#include "app/studio/editor/anchor_edit.h"
#include "app/studio/editor/downstream.h"
#include "app/studio/editor/offset_edit.h"
#include "app/studio/editor/polyline_edit.h"
#include "app/studio/editor/preview_mesh.h"
#include "core/geom/footprint.h"
#include "core/geom/profile.h"

namespace procex::studio {

namespace {

template <class T>
std::optional<std::uint32_t> output_of_type(const NodeDecl& decl) {
  for (std::uint32_t i = 0; i < decl.outputs().size(); ++i)
    if (decl.outputs()[i].type->cpp_type() == std::type_index(typeid(T))) return i;
  return std::nullopt;
}

std::optional<std::size_t> param_of_type(const Node& n, std::string_view name, const std::type_info& t) {
  auto i = n.decl().param_index(name);
  if (i && n.params[*i].type()->cpp_type() == std::type_index(t)) return i;
  return std::nullopt;
}

ImU32 tag_color_u32(const std::string& tag) {
  const glm::vec3 c = tag_color(tag.empty() ? "untagged" : tag);
  return ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, 1.0f));
}

// World (plan metres, y up) to screen, fitted to a rectangle.
struct Fit {
  ImVec2 origin;
  double scale = 1, min_x = 0, min_y = 0, height = 0;
  ImVec2 to_screen(double x, double y) const {
    return ImVec2(origin.x + static_cast<float>((x - min_x) * scale), origin.y + static_cast<float>(height - (y - min_y) * scale));
  }
  Vec2 to_world(ImVec2 s) const { return {(s.x - origin.x) / scale + min_x, (height - (s.y - origin.y)) / scale + min_y}; }
};

Fit fit(const std::vector<Vec2>& pts, ImVec2 corner, ImVec2 size) {
  double x0 = 0, y0 = 0, x1 = 1, y1 = 1;
  if (!pts.empty()) {
    x0 = x1 = pts[0].x;
    y0 = y1 = pts[0].y;
  }
  for (const Vec2& p : pts) {
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  }
  const double pad = 0.15 * std::max({x1 - x0, y1 - y0, 1.0});
  x0 -= pad, x1 += pad, y0 -= pad, y1 += pad;
  Fit f;
  f.scale = std::min(size.x / (x1 - x0), size.y / (y1 - y0));
  f.min_x = x0;
  f.min_y = y0;
  f.height = size.y;
  // Centre horizontally.
  f.origin = ImVec2(corner.x + static_cast<float>((size.x - (x1 - x0) * f.scale) / 2), corner.y);
  return f;
}

}  // namespace

void ShapeEditor::draw(Document& doc, const EvalSnapshot* eval, std::string& status) {
  const NodeId id = doc.selected();
  buttons_.clear();
  if (id != node_) {
    node_ = id;
    dragging_.reset();
    selected_edges_.clear();
    issue_.reset();
    check_revision_ = 0;
    selected_segment_.reset();
    dragging_anchor_.reset();
    dragging_offset_.reset();
    anchor_tool_ = false;
  }
  const Node* n = id ? doc.graph().node(id) : nullptr;
  if (!n) {
    ImGui::TextDisabled("Select a footprint or profile node.");
    return;
  }
  const auto plan_out = output_of_type<Footprint>(n->decl());
  const bool is_profile = output_of_type<Profile>(n->decl()).has_value();
  if (!plan_out && !is_profile) {
    ImGui::TextDisabled("%s makes no footprint or profile.", n->type->name().c_str());
    return;
  }
  const PolylineRules rules = is_profile ? kProfileRules : kPlanRules;
  const auto points_param = param_of_type(*n, "points", typeid(std::vector<Vec2>));
  std::vector<Vec2> pts = points_param ? n->params[*points_param].get<std::vector<Vec2>>() : std::vector<Vec2>{};
  // A plain index, not an optional: g++ 12 wrongly warns an optional's value may be uninitialised here.
  const std::size_t holes_param = plan_out ? param_of_type(*n, "holes", typeid(PlanLoops)).value_or(SIZE_MAX) : SIZE_MAX;
  const bool has_holes_param = holes_param != SIZE_MAX;
  const PlanLoops holes = has_holes_param ? n->params[holes_param].get<PlanLoops>() : PlanLoops{};
  if (active_hole_ >= holes.size()) active_hole_ = holes.empty() ? 0 : holes.size() - 1;

  // The evaluated plan (all loops, with edge ids, angles and profiles).
  const Footprint* fp = nullptr;
  if (plan_out && eval)
    if (auto it = eval->values.find(PortRef{id, *plan_out}); it != eval->values.end()) fp = &it->second.get<Footprint>();
  std::vector<Vec2> extent = pts;
  // The Profile Offsets this profile feeds: a handle at each one's step.
  struct OffsetHandle {
    NodeId node;
    std::size_t distance_param, height_param;
    Vec2 at;
  };
  std::vector<OffsetHandle> offsets;
  if (is_profile)
    for (NodeId o : downstream_of_type(doc.graph(), id, "Profile Offset")) {
      const Node& on = *doc.graph().node(o);
      const auto d = param_of_type(on, "distance", typeid(double));
      const auto h = param_of_type(on, "height", typeid(double));
      if (!d || !h) continue;
      offsets.push_back({o, *d, *h, offset_handle(pts, on.params[*d].get<double>(), on.params[*h].get<double>())});
      extent.push_back(offsets.back().at);
    }
  if (fp)
    for (const Loop& l : fp->loops)
      for (const auto& p : l.points) extent.push_back({p.x, p.y});
  if (extent.empty()) {
    ImGui::TextDisabled("Nothing evaluated yet.");
    return;
  }
  if (has_holes_param && points_param) {
    auto record = [&](const char* name) {
      const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
      buttons_[name] = {lo.x, lo.y, hi.x - lo.x, hi.y - lo.y};
    };
    if (ImGui::SmallButton("Add hole")) {
      PlanLoops next = holes;
      next.push_back(hole_inside(pts, holes));
      if (next.back().empty()) status = "no room for another hole inside the outer loop";
      else if (Status s = doc.set_param(id, holes_param, Value::make(std::move(next))); !s) status = s.message();
      else active_hole_ = holes.size();
    }
    record("add_hole");
    ImGui::SameLine();
    if (!holes.empty()) {
      // The hole whose corner was grabbed last (else the newest).
      const std::string label = "Delete hole " + std::to_string(active_hole_ + 1);
      if (ImGui::SmallButton(label.c_str())) {
        PlanLoops next = holes;
        next.erase(next.begin() + static_cast<std::ptrdiff_t>(active_hole_));
        if (Status s = doc.set_param(id, holes_param, Value::make(std::move(next))); !s) status = s.message();
      }
      record("delete_hole");
      ImGui::SameLine();
    }
  }
  // Anchors feeding the Extrude this plan reaches: drawn on the plan, dragged along their edges.
  const std::optional<NodeId> extrude = plan_out ? extrude_downstream(doc.graph(), id) : std::nullopt;
  const std::vector<AnchorNode> anchor_nodes = extrude ? anchors_into(doc.graph(), *extrude) : std::vector<AnchorNode>{};
  if (extrude && fp) {
    if (anchor_tool_) ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.85f, 0.35f, 0.75f, 1.0f));
    const bool toggled = ImGui::SmallButton("Place anchor");
    if (anchor_tool_) ImGui::PopStyleColor();
    if (toggled) anchor_tool_ = !anchor_tool_;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Then click an edge: an Anchor node there, wired into Extrude #%u.", static_cast<unsigned>(*extrude));
    const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
    buttons_["anchor_tool"] = {lo.x, lo.y, hi.x - lo.x, hi.y - lo.y};
    ImGui::SameLine();
  }
  if (anchor_tool_) ImGui::TextDisabled("Click an edge to place an anchor there; drag anchors along their edges.");
  else ImGui::TextDisabled(is_profile ? "Profile: drag points (kept monotone, snapped level or plumb; Alt: free), double-click a segment to add, right-click to delete."
                      : points_param ? "Plan: drag corners, double-click an edge to add one, right-click a corner to delete, click edges to select."
                                     : "Plan: click edges to select them.");
  const std::size_t tags_param = is_profile ? param_of_type(*n, "tags", typeid(std::vector<std::string>)).value_or(SIZE_MAX) : SIZE_MAX;
  const std::vector<std::string> tags = tags_param != SIZE_MAX ? n->params[tags_param].get<std::vector<std::string>>() : std::vector<std::string>{};
  const std::size_t profile_segments = is_profile && pts.size() >= 2 ? pts.size() - 1 : 0;
  if (selected_segment_ && (*selected_segment_ >= profile_segments || tags.size() != profile_segments)) selected_segment_.reset();
  // A selected segment's tag, edited in a row above the view (not over it: the view would take the clicks).
  if (selected_segment_ && tags.size() == profile_segments) {
    constexpr float kFieldWidth = 140.0f;
    ImGui::SetNextItemWidth(kFieldWidth);
    const std::size_t e = *selected_segment_;
    if (segment_tag_edit_ != e) segment_tag_ = tags[e];
    segment_tag_edit_ = e;
    const std::string label = "tag of segment " + std::to_string(e) + (pts[e].y == pts[e + 1].y ? " (horizontal)" : "");
    ImGui::InputText(label.c_str(), &segment_tag_);
    const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
    buttons_["segment_tag"] = {lo.x, lo.y, kFieldWidth, hi.y - lo.y};  // the text field, not its label
    if (ImGui::IsItemDeactivatedAfterEdit() && segment_tag_ != tags[e]) {
      std::vector<std::string> next = tags;
      next[e] = segment_tag_;
      if (Status s = doc.set_param(id, tags_param, Value::make(std::move(next))); !s) status = s.message();
    }
    if (!ImGui::IsItemActive()) segment_tag_ = tags[e];
  } else if (profile_segments > 0 && tags.size() == profile_segments) {
    ImGui::TextDisabled("Click a segment to edit its tag.");  // the row stays: the view does not jump
  }
  const ImVec2 corner = ImGui::GetCursorScreenPos();
  const ImVec2 size(std::max(ImGui::GetContentRegionAvail().x, 50.0f), std::max(ImGui::GetContentRegionAvail().y - 4, 50.0f));
  ImGui::InvisibleButton("shape", size, ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
  const bool hovered = ImGui::IsItemHovered();
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->PushClipRect(corner, ImVec2(corner.x + size.x, corner.y + size.y), true);
  dl->AddRectFilled(corner, ImVec2(corner.x + size.x, corner.y + size.y), IM_COL32(24, 25, 30, 255));
  const Fit f = fit(extent, corner, size);
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  const Vec2 mw = f.to_world(mouse);
  const double tol = 8.0 / f.scale;
  if (is_profile) {  // the ground line and the wall line through (0, 0)
    dl->AddLine(f.to_screen(f.min_x, 0), f.to_screen(f.min_x + size.x / f.scale, 0), IM_COL32(90, 90, 90, 255));
    dl->AddLine(f.to_screen(0, f.min_y), f.to_screen(0, f.min_y + size.y / f.scale), IM_COL32(60, 60, 60, 255));
  }

  // Evaluated plan edges, labelled; hovered and selected ones highlighted.
  std::optional<std::int32_t> hover_edge;
  std::optional<std::pair<Vec2, Vec2>> hover_segment;  // the hovered edge's ends
  if (fp) {
    for (const Loop& l : fp->loops) {
      const std::size_t m = l.points.size();
      std::vector<Vec2> loop;
      for (const auto& p : l.points) loop.push_back({p.x, p.y});
      // SIZE_MAX: no edge near the mouse.
      const std::size_t near = hovered && !dragging_ ? nearest_edge(loop, mw, tol, true).value_or(SIZE_MAX) : SIZE_MAX;
      for (std::size_t e = 0; e < m; ++e) {
        const auto& a = l.points[e];
        const auto& b = l.points[(e + 1) % m];
        const EdgeSpec& spec = l.edges[e];
        const bool sel = selected_edges_.count(spec.id) > 0;
        if (near == e) hover_edge = spec.id;
        dl->AddLine(f.to_screen(a.x, a.y), f.to_screen(b.x, b.y), sel ? IM_COL32(255, 170, 40, 255) : near == e ? IM_COL32(255, 255, 255, 255) : IM_COL32(120, 190, 255, 255),
                    sel || near == e ? 3.0f : 2.0f);
        char label[64];
        if (spec.profile >= 0 && static_cast<std::size_t>(spec.profile) < fp->profiles.size())
          std::snprintf(label, sizeof label, "e%d %s", spec.id, fp->profiles[static_cast<std::size_t>(spec.profile)].name.c_str());
        else
          std::snprintf(label, sizeof label, "e%d %.0f deg", spec.id, spec.angle_deg);
        const ImVec2 mid = f.to_screen((a.x + b.x) / 2, (a.y + b.y) / 2);
        dl->AddText(ImVec2(mid.x + 4, mid.y - 14), IM_COL32(200, 200, 210, 255), label);
        buttons_["edge_" + std::to_string(spec.id)] = {mid.x, mid.y, 0.0f, 0.0f};  // where tests click an edge
        if (near == e) hover_segment = {{a.x, a.y}, {b.x, b.y}};
      }
    }
  }
  // Anchor nodes' points on the edges they select (the fraction at the footprint; the sweep keeps it up the face).
  struct AnchorMark {
    std::size_t anchor;  // index into anchor_nodes
    Vec2 a, b;           // the edge
    ImVec2 at;
  };
  std::vector<AnchorMark> marks;
  if (fp)
    for (std::size_t k = 0; k < anchor_nodes.size(); ++k) {
      const AnchorNode& an = anchor_nodes[k];
      for (const Loop& l : fp->loops)
        for (std::size_t e = 0; e < l.points.size(); ++e) {
          const EdgeSpec& spec = l.edges[e];
          if (!an.edges.empty() && std::find(an.edges.begin(), an.edges.end(), spec.id) == an.edges.end()) continue;
          if (!an.profile.empty() && (spec.profile < 0 || static_cast<std::size_t>(spec.profile) >= fp->profiles.size() ||
                                      fp->profiles[static_cast<std::size_t>(spec.profile)].name != an.profile))
            continue;
          const Vec2 a{l.points[e].x, l.points[e].y};
          const Vec2 b{l.points[(e + 1) % l.points.size()].x, l.points[(e + 1) % l.points.size()].y};
          const double t = edge_fraction(an.mode, an.position, std::hypot(b.x - a.x, b.y - a.y));
          const ImVec2 at = f.to_screen(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y));
          marks.push_back({k, a, b, at});
          buttons_["anchor_" + std::to_string(an.node) + "_e" + std::to_string(spec.id)] = {at.x, at.y, 0.0f, 0.0f};
        }
    }
  std::optional<std::size_t> near_mark;  // index into marks
  if (hovered && !dragging_)
    for (std::size_t i = 0; i < marks.size() && !near_mark; ++i)
      if (std::hypot(marks[i].at.x - mouse.x, marks[i].at.y - mouse.y) < 8.0) near_mark = i;
  const glm::vec3 anchor_rgb = PreviewMesh::kAnchorColor;  // as the preview's markers
  const ImU32 anchor_u32 = ImGui::ColorConvertFloat4ToU32(ImVec4(anchor_rgb.r, anchor_rgb.g, anchor_rgb.b, 1.0f));
  for (std::size_t i = 0; i < marks.size(); ++i) {
    const AnchorMark& m = marks[i];
    const bool hot = near_mark == i || (dragging_anchor_ && dragging_anchor_->node == anchor_nodes[m.anchor].node);
    const float r = hot ? 7.0f : 5.5f;
    dl->AddQuadFilled(ImVec2(m.at.x, m.at.y - r), ImVec2(m.at.x + r, m.at.y), ImVec2(m.at.x, m.at.y + r), ImVec2(m.at.x - r, m.at.y),
                      anchor_u32);
    dl->AddText(ImVec2(m.at.x + 8, m.at.y + 2), IM_COL32(255, 230, 140, 255), anchor_nodes[m.anchor].name.c_str());
  }
  // The editable polylines: the points, and a Footprint Polygon's holes (loop k: hole k, from 1, as check_plan counts).
  std::vector<std::vector<Vec2>> loops;
  if (points_param) {
    loops.push_back(pts);
    loops.insert(loops.end(), holes.begin(), holes.end());
  }
  if (plan_out && points_param && check_revision_ != doc.revision()) {
    check_revision_ = doc.revision();
    issue_ = check_plan(pts, holes);
  }
  for (std::size_t k = 1; k < loops.size(); ++k) {  // each hole named at its centre (hole_K in the ui map), the one Delete hole removes highlighted
    Vec2 c{0, 0};
    for (const Vec2& p : loops[k]) c.x += p.x / static_cast<double>(loops[k].size()), c.y += p.y / static_cast<double>(loops[k].size());
    const ImVec2 at = f.to_screen(c.x, c.y);
    const std::string name = "hole " + std::to_string(k);
    const ImVec2 size_text = ImGui::CalcTextSize(name.c_str());
    const ImVec2 lo(at.x - size_text.x / 2, at.y - size_text.y / 2);
    // Clicking the name picks the hole for Delete hole, as grabbing one of its corners does.
    if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && mouse.x >= lo.x && mouse.x <= lo.x + size_text.x && mouse.y >= lo.y &&
        mouse.y <= lo.y + size_text.y)
      active_hole_ = k - 1;
    dl->AddText(lo, k - 1 == active_hole_ ? IM_COL32(255, 170, 40, 255) : IM_COL32(150, 150, 160, 255), name.c_str());
    buttons_["hole_" + std::to_string(k)] = {lo.x, lo.y, size_text.x, size_text.y};
  }
  std::optional<Grab> near_point;
  for (std::size_t k = 0; k < loops.size(); ++k) {
    const std::vector<Vec2>& lp = loops[k];
    const std::size_t segs = rules.closed ? lp.size() : (lp.empty() ? 0 : lp.size() - 1);
    for (std::size_t e = 0; e < segs && !fp; ++e) {
      const Vec2 a = lp[e], b = lp[(e + 1) % lp.size()];
      if (is_profile && selected_segment_ == e) dl->AddLine(f.to_screen(a.x, a.y), f.to_screen(b.x, b.y), IM_COL32(255, 170, 40, 255), 6.0f);
      dl->AddLine(f.to_screen(a.x, a.y), f.to_screen(b.x, b.y), tag_color_u32(e < tags.size() ? tags[e] : ""), 2.5f);
      const ImVec2 mid = f.to_screen((a.x + b.x) / 2, (a.y + b.y) / 2);
      if (is_profile) buttons_["segment_" + std::to_string(e)] = {mid.x, mid.y, 0.0f, 0.0f};  // where tests click a segment
      if (e < tags.size()) {
        dl->AddText(ImVec2(mid.x + 6, mid.y - 7), IM_COL32(220, 220, 220, 255), tags[e].c_str());
      }
    }
    if (hovered && !near_point)
      if (auto i = nearest_point(lp, mw, tol)) near_point = Grab{k, *i};
  }
  for (std::size_t k = 0; k < loops.size(); ++k)
    for (std::size_t i = 0; i < loops[k].size(); ++i) {
      const Grab here{k, i};
      const bool hot = dragging_ == here || near_point == here;
      const bool bad = issue_ && issue_->loop == static_cast<int>(k) && issue_->vertex == static_cast<int>(i);
      const ImVec2 at = f.to_screen(loops[k][i].x, loops[k][i].y);
      if (bad) dl->AddCircle(at, 10.0f, IM_COL32(235, 70, 60, 255), 0, 2.5f);
      dl->AddCircleFilled(at, hot ? 6.0f : 4.5f, hot ? IM_COL32(255, 170, 40, 255) : bad ? IM_COL32(235, 70, 60, 255) : IM_COL32(240, 240, 240, 255));
    }
  auto apply = [&](std::size_t k, std::vector<Vec2> v) {
    Status s = Status::ok();
    if (k == 0) {
      s = doc.set_param(id, *points_param, Value::make(std::move(v)));
    } else {
      PlanLoops next = holes;
      next[k - 1] = std::move(v);
      s = doc.set_param(id, holes_param, Value::make(std::move(next)));
    }
    if (!s) status = s.message();
  };
  // A profile's points and its tags (one per segment) change together, as one undo step.
  auto apply_with_tags = [&](std::size_t k, std::vector<Vec2> v, std::vector<std::string> t, const char* label) {
    if (tags_param == SIZE_MAX || t == tags) return apply(k, std::move(v));
    doc.begin_gesture(label);
    apply(k, std::move(v));
    if (Status s = doc.set_param(id, tags_param, Value::make(std::move(t))); !s) status = s.message();
    doc.end_gesture();
  };
  // Along an edge from a to b, the fraction nearest the mouse.
  auto fraction_at = [&](Vec2 a, Vec2 b) {
    const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
    return len2 > 0 ? std::clamp(((mw.x - a.x) * dx + (mw.y - a.y) * dy) / len2, 0.0, 1.0) : 0.0;
  };
  bool click_taken = false;  // by an anchor or an offset handle: no vertex drag, edge selection or segment under it
  // Profile Offset handles: the step drawn from the profile out to the handle.
  std::optional<std::size_t> near_offset;
  for (std::size_t i = 0; i < offsets.size(); ++i) {
    const OffsetHandle& o = offsets[i];
    const ImVec2 at = f.to_screen(o.at.x, o.at.y);
    const ImVec2 from = f.to_screen(profile_offset_at(pts, o.at.y), o.at.y);
    if (hovered && !dragging_ && !near_offset && std::hypot(at.x - mouse.x, at.y - mouse.y) < 8.0) near_offset = i;
    const bool hot = near_offset == i || dragging_offset_ == o.node;
    dl->AddLine(from, at, IM_COL32(120, 220, 160, 255), 2.0f);
    dl->AddRectFilled(ImVec2(at.x - 5, at.y - 5), ImVec2(at.x + 5, at.y + 5), hot ? IM_COL32(255, 170, 40, 255) : IM_COL32(120, 220, 160, 255));
    const std::string label = "offset #" + std::to_string(o.node);
    dl->AddText(ImVec2(at.x + 8, at.y - 16), IM_COL32(170, 230, 190, 255), label.c_str());
    buttons_["offset_" + std::to_string(o.node)] = {at.x, at.y, 0.0f, 0.0f};
  }
  if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && near_offset) {
    dragging_offset_ = offsets[*near_offset].node;
    doc.begin_gesture("move profile offset");
    click_taken = true;
  }
  if (dragging_offset_) {
    const auto it = std::find_if(offsets.begin(), offsets.end(), [&](const OffsetHandle& o) { return o.node == *dragging_offset_; });
    if (ImGui::IsMouseDown(ImGuiMouseButton_Left) && it != offsets.end()) {
      const OffsetParams p = offset_params(pts, mw, *doc.graph().node(it->node));
      for (const auto& [param, v] : {std::pair{it->distance_param, p.distance}, std::pair{it->height_param, p.height}})
        if (Status st = doc.set_param(it->node, param, Value::make(v)); !st) status = st.message();
    } else {
      dragging_offset_.reset();
      doc.end_gesture();
    }
    click_taken = true;
  }
  if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && near_mark && !click_taken) {
    const AnchorMark& m = marks[*near_mark];
    dragging_anchor_ = AnchorDrag{anchor_nodes[m.anchor].node, m.a, m.b};
    doc.begin_gesture("move anchor");
    click_taken = true;
  } else if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && anchor_tool_ && hover_edge && hover_segment && !click_taken) {
    const auto [a, b] = *hover_segment;
    if (Result<NodeId> r = place_anchor(doc, id, *hover_edge, fraction_at(a, b)); !r) status = r.message();
    else status = "placed an anchor on edge " + std::to_string(*hover_edge) + " (Anchor #" + std::to_string(*r) + ")";
    click_taken = true;
  }
  if (dragging_anchor_) {
    const Node* an = doc.graph().node(dragging_anchor_->node);
    const auto position = an ? an->decl().param_index("position") : std::nullopt;
    const auto it = std::find_if(anchor_nodes.begin(), anchor_nodes.end(), [&](const AnchorNode& x) { return x.node == dragging_anchor_->node; });
    if (ImGui::IsMouseDown(ImGuiMouseButton_Left) && position && it != anchor_nodes.end()) {
      const Vec2 a = dragging_anchor_->a, b = dragging_anchor_->b;
      const double p = anchor_position(it->mode, fraction_at(a, b), std::hypot(b.x - a.x, b.y - a.y));
      if (Status st = doc.set_param(dragging_anchor_->node, *position, Value::make(p)); !st) status = st.message();
    } else {
      dragging_anchor_.reset();
      doc.end_gesture();
    }
    click_taken = true;
  }
  if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && near_point && !click_taken) {
    dragging_ = near_point;
    if (near_point->loop > 0) active_hole_ = near_point->loop - 1;
    doc.begin_gesture(is_profile ? "edit profile" : "edit plan");
  }
  if (dragging_ && dragging_->loop < loops.size()) {
    if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
      const std::vector<Vec2>& lp = loops[dragging_->loop];
      // Alt drags freely; otherwise a point snaps level with (or plumb above) its neighbours.
      const Vec2 to = ImGui::GetIO().KeyAlt ? mw : snap_to_neighbours(lp, dragging_->point, mw, tol, rules.closed);
      apply(dragging_->loop, move_point(lp, dragging_->point, to, rules));
    } else {
      dragging_.reset();
      doc.end_gesture();
    }
  }
  if (hovered && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left) && !near_point && !click_taken && !anchor_tool_)
    for (std::size_t k = 0; k < loops.size(); ++k)
      if (auto e = nearest_edge(loops[k], mw, tol, rules.closed)) {
        apply_with_tags(k, insert_point(loops[k], *e, mw, rules), tags_after_insert(tags, profile_segments, *e), "insert point");
        break;
      }
  if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Right) && near_point) {
    auto r = remove_point(loops[near_point->loop], near_point->point, rules);
    if (r) apply_with_tags(near_point->loop, r.value(), tags_after_remove(tags, profile_segments, near_point->point), "delete point");
    else if (near_point->loop > 0) {
      active_hole_ = near_point->loop - 1;
      status = "hole " + std::to_string(near_point->loop) + ": " + r.message() + " (Delete hole " + std::to_string(near_point->loop) + " removes it)";
    } else status = r.message();
  }
  // A profile segment clicked: its tag is edited in the row above the view.
  if (profile_segments > 0 && tags.size() == profile_segments && hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && !near_point && !click_taken)
    selected_segment_ = nearest_edge(pts, mw, tol, false);  // the field appears next frame
  // Edge selection (plan only), e.g. for Assign Profiles' `selection`.
  if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && !dragging_ && hover_edge && !click_taken) {
    if (!ImGui::GetIO().KeyCtrl && !ImGui::GetIO().KeyShift) selected_edges_.clear();
    if (!selected_edges_.erase(*hover_edge)) selected_edges_.insert(*hover_edge);
  }
  dl->PopClipRect();
  if (issue_) {  // at the bottom of the view, over a dark band so the plan does not hide it
    const float wrap = size.x - 12;
    const ImVec2 text = ImGui::CalcTextSize(issue_->message.c_str(), nullptr, false, wrap);
    const ImVec2 at(corner.x + 6, corner.y + size.y - text.y - 6);
    dl->AddRectFilled(ImVec2(corner.x, at.y - 3), ImVec2(corner.x + size.x, corner.y + size.y), IM_COL32(24, 25, 30, 220));
    dl->AddText(ImGui::GetFont(), ImGui::GetFontSize(), at, IM_COL32(255, 102, 90, 255), issue_->message.c_str(), nullptr, wrap);
  }
  if (!selected_edges_.empty()) {
    ImGui::SetCursorScreenPos(ImVec2(corner.x + 6, corner.y + 6));
    std::string text = "selected edges:";
    for (std::int32_t e : selected_edges_) {
      text += ' ';
      text += std::to_string(e);
    }
    ImGui::TextUnformatted(text.c_str());
    if (auto sel = param_of_type(*n, "selection", typeid(std::vector<std::int64_t>))) {
      if (ImGui::SmallButton("Use as the node's selection"))
        if (Status s = doc.set_param(id, *sel, Value::make(std::vector<std::int64_t>(selected_edges_.begin(), selected_edges_.end()))); !s)
          status = s.message();
    }
  }
}

}  // namespace procex::studio
