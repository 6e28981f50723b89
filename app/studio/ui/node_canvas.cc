#include "app/studio/ui/node_canvas.h"

#include <imgui.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/studio/editor/preview_mesh.h"

namespace procex::studio {

namespace {

ImVec2 im(glm::vec2 v) { return ImVec2(v.x, v.y); }

ImU32 color_of(const glm::vec3& c, float alpha = 1.0f) { return ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, alpha)); }

// Ports are coloured by value type, headers by category: hues from the names.
ImU32 type_color(const ValueType* t) { return color_of(tag_color(t ? t->name() : "?")); }

bool contains_nocase(std::string_view hay, std::string_view needle) {
  return std::search(hay.begin(), hay.end(), needle.begin(), needle.end(), [](char a, char b) {
           return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b));
         }) != hay.end();
}

struct NodeMarks {
  std::vector<const Diagnostic*> errors, warnings;
  const NodeStats* stats = nullptr;
};

NodeMarks marks_of(const EvalSnapshot* eval, NodeId id) {
  NodeMarks m;
  if (!eval) return m;
  for (const Diagnostic& d : eval->result.diagnostics)
    if (!d.node.empty() && d.node[0] == id) (d.severity == Severity::kError ? m.errors : m.warnings).push_back(&d);
  m.stats = eval->result.stats.find(NodePath{id});
  return m;
}

// "computed, 1.25 ms": what the last evaluation did at a node and how long its own evaluate took.
std::string timing_label(const NodeStats& s, bool with_time) {
  if (!with_time || (s.outcome != NodeOutcome::kComputed && s.outcome != NodeOutcome::kFailed)) return to_string(s.outcome);
  char buf[96];
  std::snprintf(buf, sizeof buf, "%s, %.2f ms", to_string(s.outcome), static_cast<double>(s.time_ns) * 1e-6);
  return buf;
}

ImU32 outcome_color(NodeOutcome o) {
  switch (o) {
    case NodeOutcome::kCacheHit: return IM_COL32(120, 140, 170, 255);
    case NodeOutcome::kComputed: return IM_COL32(90, 220, 110, 255);
    case NodeOutcome::kPassThrough: return IM_COL32(90, 200, 220, 255);
    case NodeOutcome::kFailed: return IM_COL32(235, 70, 60, 255);
    case NodeOutcome::kInputFailed: return IM_COL32(230, 150, 60, 255);
    case NodeOutcome::kCancelled: return IM_COL32(150, 150, 150, 255);
  }
  return IM_COL32_WHITE;
}

void bezier(ImDrawList* dl, glm::vec2 a, glm::vec2 b, ImU32 col, float zoom) {
  const float dx = std::max(std::abs(b.x - a.x) * 0.5f, 30.0f * zoom);
  dl->AddBezierCubic(im(a), ImVec2(a.x + dx, a.y), ImVec2(b.x - dx, b.y), im(b), col, 2.5f * zoom);
}

// `s` cut to `width` pixels at `px`, with an ellipsis when cut.
std::string fit_text(ImFont* font, float px, const std::string& s, float width) {
  if (font->CalcTextSizeA(px, 1e9f, 0.0f, s.c_str()).x <= width) return s;
  for (std::size_t n = s.size(); n > 0; --n) {
    std::string cut = s.substr(0, n) + "..";
    if (font->CalcTextSizeA(px, 1e9f, 0.0f, cut.c_str()).x <= width) return cut;
  }
  return "";
}

std::string title_of(const Graph& g, NodeId id) {
  if (id == kGraphInputs) return "Graph inputs";
  if (id == kGraphOutputs) return "Graph outputs";
  const Node& n = *g.node(id);
  return (n.group.empty() ? n.type->name() : n.group) + "  #" + std::to_string(id);
}

// A value in a line or so: JSON for the types that have it, else its type.
std::string value_text(const Value& v) {
  if (v.empty()) return "(none)";
  if (!v.type()->has_json()) return "a " + v.type()->name();
  nlohmann::json j;
  v.type()->to_json(v.raw(), j);
  std::string t = j.dump();
  return t.size() > 80 ? t.substr(0, 77) + "..." : t;
}

// The name drawn beside a pin. Pseudo nodes: graph inputs are the outputs of
// kGraphInputs, graph outputs the inputs of kGraphOutputs.
std::string port_label(const Graph& g, PortRef p, bool is_output) {
  if (p.node == kGraphInputs) return g.inputs()[p.port].name;
  if (p.node == kGraphOutputs) return g.outputs()[p.port].name;
  const NodeDecl& d = g.node(p.node)->decl();
  if (is_output) return d.outputs()[p.port].name;
  return d.inputs()[p.port].name + (d.inputs()[p.port].optional ? "?" : "");
}

std::string port_tooltip(const Graph& g, PortRef p, bool is_output, const EvalSnapshot* eval) {
  const ValueType* type = is_output ? g.output_type(p) : g.input_type(p);
  std::string doc;
  if (p.node == kGraphInputs) doc = g.inputs()[p.port].doc;
  else if (p.node == kGraphOutputs) doc = g.outputs()[p.port].doc;
  else doc = (is_output ? g.node(p.node)->decl().outputs() : g.node(p.node)->decl().inputs())[p.port].doc;
  std::string t = (is_output ? "output " : "input ") + port_label(g, p, is_output) + " : " + (type ? type->name() : "?");
  if (!doc.empty()) t += "\n" + doc;
  // The value there: an output's own, an input's from its source.
  std::optional<PortRef> at = is_output ? std::optional<PortRef>(p) : g.source(p);
  if (eval && at)
    if (auto it = eval->values.find(*at); it != eval->values.end()) t += "\nvalue: " + value_text(it->second);
  return t;
}

std::string node_tooltip(const Graph& g, NodeId id, const EvalSnapshot* eval) {
  std::string t = title_of(g, id);
  if (id > kMaxNodeId) return t;
  const Node& n = *g.node(id);
  for (std::size_t i = 0; i < n.params.size(); ++i) {
    const ParamDecl& p = n.decl().params()[i];
    t += "\n  " + p.name + " = " + value_text(n.params[i]) + (p.unit.empty() ? "" : " " + p.unit);
  }
  if (const NodeMarks m = marks_of(eval, id); m.stats) t += std::string("\n") + to_string(m.stats->outcome);
  return t;
}

}  // namespace

float NodeCanvas::legible_zoom() { return kMinTextPx / ImGui::GetFontSize(); }

void NodeCanvas::breadcrumb(Document& doc) {
  const std::vector<std::string> names = doc.breadcrumb();
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) {
      ImGui::SameLine();
      ImGui::TextDisabled(">");
      ImGui::SameLine();
    }
    ImGui::PushID(static_cast<int>(i));
    // Every step but the last (the graph shown) backs out to its level.
    const bool up = i + 1 < names.size() && ImGui::Button(names[i].c_str());
    if (i + 1 == names.size()) ImGui::TextUnformatted(names[i].c_str());
    crumbs_on_screen_.push_back(Rect{{ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y}, {ImGui::GetItemRectMax().x, ImGui::GetItemRectMax().y}});
    ImGui::PopID();
    if (up) doc.leave_group(i);
  }
}

void NodeCanvas::open_group(Document& doc, NodeId id, std::string& status) {
  if (Status s = doc.enter_group(id); !s) status = s.message();
}

void NodeCanvas::draw(Document& doc, const EvalSnapshot* eval, std::string& status) {
  ImGuiIO& io = ImGui::GetIO();
  crumbs_on_screen_.clear();
  if (!doc.scope().empty()) breadcrumb(doc);
  if (doc.scope() != drawn_scope_) {  // another graph: frame it
    drawn_scope_ = doc.scope();
    frame_pending_ = true;
    drag_ = Drag::kNone;
  }
  const Graph& g = doc.graph();
  const ImVec2 p0 = ImGui::GetCursorScreenPos();
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const glm::vec2 size(std::max(avail.x, 50.0f), std::max(avail.y, 50.0f));
  view_.origin = {p0.x, p0.y};
  ImGui::InvisibleButton("canvas", im(size), ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight | ImGuiButtonFlags_MouseButtonMiddle);
  const bool hovered = ImGui::IsItemHovered();
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImVec2 p1(p0.x + size.x, p0.y + size.y);
  dl->PushClipRect(p0, p1, true);
  dl->AddRectFilled(p0, p1, IM_COL32(28, 29, 34, 255));
  const float grid = 32.0f * view_.zoom;
  const glm::vec2 phase = glm::mod(view_.pan * view_.zoom, glm::vec2(grid));
  for (float x = p0.x + phase.x; x < p1.x; x += grid) dl->AddLine(ImVec2(x, p0.y), ImVec2(x, p1.y), IM_COL32(45, 46, 54, 255));
  for (float y = p0.y + phase.y; y < p1.y; y += grid) dl->AddLine(ImVec2(p0.x, y), ImVec2(p1.x, y), IM_COL32(45, 46, 54, 255));

  std::vector<NodeBox> boxes = layout(g);
  if (frame_pending_) {
    if (!boxes.empty()) view_.frame(bounds(boxes), size, legible_zoom());
    frame_pending_ = false;
  }
  const glm::vec2 mouse_s(io.MousePos.x, io.MousePos.y);
  const glm::vec2 mouse = view_.to_canvas(mouse_s);
  if (drag_ == Drag::kNodes) {
    for (NodeBox& b : boxes) {
      if (!doc.selection().count(b.id)) continue;
      b.rect.min += drag_offset_;
      b.rect.max += drag_offset_;
      for (glm::vec2& p : b.inputs) p += drag_offset_;
      for (glm::vec2& p : b.outputs) p += drag_offset_;
    }
  }
  const float zoom = view_.zoom;
  ImFont* font = ImGui::GetFont();
  const float font_size = ImGui::GetFontSize() * zoom;

  screen_rect_ = Rect{view_.origin, view_.origin + size};
  pins_on_screen_.clear();
  timings_on_screen_.clear();
  for (const NodeBox& b : boxes) {
    for (std::uint32_t i = 0; i < b.inputs.size(); ++i) pins_on_screen_.push_back({{b.id, i}, false, view_.to_screen(b.inputs[i])});
    for (std::uint32_t i = 0; i < b.outputs.size(); ++i) pins_on_screen_.push_back({{b.id, i}, true, view_.to_screen(b.outputs[i])});
  }

  // Only what is in view is drawn: big graphs stay cheap to draw.
  const Rect visible{view_.to_canvas(view_.origin), view_.to_canvas(view_.origin + size)};
  std::map<NodeId, const NodeBox*> by_id;
  for (const NodeBox& b : boxes) by_id[b.id] = &b;

  // Links under the nodes.
  for (const auto& [to, from] : g.links()) {
    const NodeBox* fb = by_id.count(from.node) ? by_id[from.node] : nullptr;
    const NodeBox* tb = by_id.count(to.node) ? by_id[to.node] : nullptr;
    if (!fb || !tb || from.port >= fb->outputs.size() || to.port >= tb->inputs.size()) continue;
    const Rect span{glm::min(fb->rect.min, tb->rect.min), glm::max(fb->rect.max, tb->rect.max)};
    if (!span.overlaps(visible)) continue;
    bezier(dl, view_.to_screen(fb->outputs[from.port]), view_.to_screen(tb->inputs[to.port]), type_color(g.output_type(from)), zoom);
  }

  // Nodes. Text never below kMinTextPx: port names only when they are that
  // big, titles held at that size while the box is wide enough, then boxes only.
  const bool port_text = font_size >= kMinTextPx;
  const float title_size = std::max(font_size, kMinTextPx);
  const bool title_text = zoom >= kTitleMinZoom;
  min_text_px_ = 0.0f;
  auto text = [&](float px, ImVec2 at, ImU32 col, const std::string& s) {
    dl->AddText(font, px, at, col, s.c_str());
    min_text_px_ = min_text_px_ == 0.0f ? px : std::min(min_text_px_, px);
  };
  std::string hover_text;
  const bool idle = drag_ == Drag::kNone && hovered;
  const float pick = std::max(kPinRadius * 2.0f, 9.0f / zoom);  // pins are easy to hit at any zoom
  const std::optional<PinHit> hover_pin = idle ? pin_at(boxes, mouse, pick) : std::nullopt;
  for (const NodeBox& b : boxes) {
    if (!b.rect.overlaps(visible)) continue;
    const glm::vec2 a = view_.to_screen(b.rect.min), c = view_.to_screen(b.rect.max);
    const bool pseudo = b.id > kMaxNodeId;
    const Node* n = pseudo ? nullptr : g.node(b.id);
    const std::string title = title_of(g, b.id);
    const std::string& category = n ? n->decl().category() : title;
    dl->AddRectFilled(im(a), im(c), IM_COL32(46, 48, 56, 235), 6.0f * zoom);
    dl->AddRectFilled(im(a), ImVec2(c.x, a.y + kHeaderHeight * zoom), color_of(tag_color(category) * 0.6f), 6.0f * zoom,
                      ImDrawFlags_RoundCornersTop);
    const bool selected = doc.selection().count(b.id) > 0;
    dl->AddRect(im(a), im(c), selected ? IM_COL32(255, 170, 40, 255) : IM_COL32(80, 82, 92, 255), 6.0f * zoom, 0,
                selected ? 2.5f : 1.0f);
    if (title_text) {
      const float inset = (port_text ? 16.0f : 4.0f) * zoom;
      const std::string shown = fit_text(font, title_size, title, c.x - a.x - inset - 4.0f);
      text(title_size, ImVec2(a.x + inset, a.y + std::max(5.0f * zoom, (kHeaderHeight * zoom - title_size) * 0.5f)), IM_COL32(240, 240, 240, 255), shown);
    }
    // Ports, with their names when legible.
    for (std::uint32_t i = 0; i < b.inputs.size(); ++i) {
      const glm::vec2 s = view_.to_screen(b.inputs[i]);
      dl->AddCircleFilled(im(s), std::max(kPinRadius * zoom, 2.0f), type_color(g.input_type({b.id, i})));
      if (port_text) text(font_size, ImVec2(s.x + 9.0f * zoom, s.y - font_size * 0.5f), IM_COL32(200, 200, 205, 255), port_label(g, {b.id, i}, false));
    }
    for (std::uint32_t i = 0; i < b.outputs.size(); ++i) {
      const glm::vec2 s = view_.to_screen(b.outputs[i]);
      dl->AddCircleFilled(im(s), std::max(kPinRadius * zoom, 2.0f), type_color(g.output_type({b.id, i})));
      if (!port_text) continue;
      const std::string name = port_label(g, {b.id, i}, true);
      const float w = font->CalcTextSizeA(font_size, 1e9f, 0.0f, name.c_str()).x;
      text(font_size, ImVec2(s.x - 9.0f * zoom - w, s.y - font_size * 0.5f), IM_COL32(200, 200, 205, 255), name);
    }
    if (pseudo) continue;
    // Evaluation marks: a dot for cached / computed, a badge for errors and warnings (never too small to see or hover).
    const NodeMarks m = marks_of(eval, b.id);
    if (m.stats) {
      const glm::vec2 dot(a.x + 8.0f * zoom, a.y + kHeaderHeight * zoom * 0.5f);
      dl->AddCircleFilled(im(dot), std::max(4.0f * zoom, 2.0f), outcome_color(m.stats->outcome));
      const std::string timing = timing_label(*m.stats, show_times_);
      if (port_text && glm::distance(mouse_s, dot) < 7.0f * zoom) hover_text = timing;
      // Under the box, where a slow node shows at a glance (legible sizes only, like port names).
      if (port_text) {
        const ImVec2 at(a.x + 4.0f * zoom, c.y + 3.0f * zoom);
        text(font_size, at, outcome_color(m.stats->outcome), timing);
        const float w = font->CalcTextSizeA(font_size, 1e9f, 0.0f, timing.c_str()).x;
        timings_on_screen_.push_back({b.id, m.stats->outcome, static_cast<double>(m.stats->time_ns) * 1e-6,
                                      Rect{{at.x, at.y}, {at.x + w, at.y + font_size}}});
      }
    }
    if (!m.errors.empty() || !m.warnings.empty()) {
      const float r = std::max(8.0f * zoom, 5.0f);
      const glm::vec2 badge(c.x - r - 2.0f * zoom, a.y + kHeaderHeight * zoom * 0.5f);
      dl->AddCircleFilled(im(badge), r, m.errors.empty() ? IM_COL32(230, 190, 40, 255) : IM_COL32(220, 50, 45, 255));
      if (port_text) text(font_size, ImVec2(badge.x - 2.5f * zoom, badge.y - font_size * 0.5f), IM_COL32(20, 20, 20, 255), "!");
      if (glm::distance(mouse_s, badge) < r + 2.0f) {
        for (const auto* list : {&m.errors, &m.warnings})
          for (const Diagnostic* d : *list) {
            if (!hover_text.empty()) hover_text += '\n';
            hover_text += d->to_string();
          }
      }
    }
  }
  // Hover: a pin names its port, type, doc and the value last computed there;
  // a node shows its title and parameters (all that its box may be too small to say).
  if (hover_text.empty() && hover_pin) {
    hover_text = port_tooltip(g, hover_pin->port, hover_pin->is_output, eval);
  } else if (hover_text.empty() && idle) {
    for (auto b = boxes.rbegin(); b != boxes.rend(); ++b)
      if (b->rect.contains(mouse)) {
        if (!port_text || mouse.y < b->rect.min.y + kHeaderHeight) hover_text = node_tooltip(g, b->id, eval);
        break;
      }
  }

  // Gestures.
  const bool ctrl = io.KeyCtrl, shift = io.KeyShift;
  const NodeId double_clicked = hovered && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left) && !pin_at(boxes, mouse, pick) ? node_at(boxes, mouse) : 0;
  if (double_clicked && double_clicked <= kMaxNodeId && !g.node(double_clicked)->group.empty()) {
    open_group(doc, double_clicked, status);
  } else if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && drag_ == Drag::kNone) {
    if (auto pin = pin_at(boxes, mouse, pick)) {
      drag_ = Drag::kLink;
      link_from_ = *pin;
      if (!pin->is_output) {
        if (auto src = g.source(pin->port)) {
          // Picking up a connected input detaches its link; dropping it elsewhere reconnects.
          if (Status s = doc.disconnect(pin->port); !s) status = s.message();
          link_from_ = PinHit{*src, true};
        }
      }
    } else if (NodeId id = node_at(boxes, mouse)) {
      if (ctrl) doc.toggle(id);
      else if (shift) doc.select({id}, true);
      else if (!doc.selection().count(id)) doc.select_only(id);
      drag_ = Drag::kNodes;
      drag_start_ = mouse;
      drag_offset_ = glm::vec2(0.0f);
    } else {
      if (!ctrl && !shift) doc.clear_selection();
      drag_ = Drag::kBand;
      drag_start_ = mouse;
    }
  }
  if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Middle) && drag_ == Drag::kNone) drag_ = Drag::kPan;
  if (hovered && io.MouseWheel != 0) view_.zoom_at(mouse_s, std::pow(1.1f, io.MouseWheel));

  switch (drag_) {
    case Drag::kNone: break;
    case Drag::kPan:
      view_.pan += glm::vec2(io.MouseDelta.x, io.MouseDelta.y) / zoom;
      if (!ImGui::IsMouseDown(ImGuiMouseButton_Middle)) drag_ = Drag::kNone;
      break;
    case Drag::kNodes:
      drag_offset_ = mouse - drag_start_;
      if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        if (Status s = doc.move_selection(drag_offset_.x, drag_offset_.y); !s) status = s.message();
        drag_ = Drag::kNone;
      }
      break;
    case Drag::kBand: {
      const Rect band{glm::min(drag_start_, mouse), glm::max(drag_start_, mouse)};
      dl->AddRectFilled(im(view_.to_screen(band.min)), im(view_.to_screen(band.max)), IM_COL32(255, 170, 40, 40));
      dl->AddRect(im(view_.to_screen(band.min)), im(view_.to_screen(band.max)), IM_COL32(255, 170, 40, 160));
      if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        if (band.size().x > 2.0f || band.size().y > 2.0f) doc.select(nodes_in(boxes, band), ctrl || shift);
        drag_ = Drag::kNone;
      }
      break;
    }
    case Drag::kLink: {
      const NodeBox* fb = find_box(boxes, link_from_.port.node);
      if (!fb) {
        drag_ = Drag::kNone;
        break;
      }
      const glm::vec2 start = view_.to_screen(link_from_.is_output ? fb->outputs[link_from_.port.port] : fb->inputs[link_from_.port.port]);
      std::optional<PinHit> target = pin_at(boxes, mouse, pick);
      Status ok = Status::error("");
      if (target && target->is_output != link_from_.is_output) {
        const PortRef from = link_from_.is_output ? link_from_.port : target->port;
        const PortRef to = link_from_.is_output ? target->port : link_from_.port;
        ok = g.can_connect(from, to);
        hover_text = ok ? "connect " + g.port_name(from, true) + " -> " + g.port_name(to, false) : "cannot connect: " + ok.message();
      }
      const ImU32 col = target ? (ok ? IM_COL32(90, 220, 110, 255) : IM_COL32(235, 70, 60, 255)) : IM_COL32(220, 220, 220, 200);
      if (link_from_.is_output) bezier(dl, start, mouse_s, col, zoom);
      else bezier(dl, mouse_s, start, col, zoom);
      if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        if (target && target->is_output != link_from_.is_output) {
          const PortRef from = link_from_.is_output ? link_from_.port : target->port;
          const PortRef to = link_from_.is_output ? target->port : link_from_.port;
          if (Status s = doc.connect(from, to); !s) status = "cannot connect: " + s.message();
        }
        drag_ = Drag::kNone;
      }
      break;
    }
  }
  dl->PopClipRect();
  if (!hover_text.empty()) ImGui::SetTooltip("%s", hover_text.c_str());

  // Context menu and keys.
  if (hovered && ImGui::IsMouseReleased(ImGuiMouseButton_Right) && ImGui::GetMouseDragDelta(ImGuiMouseButton_Right).x == 0 &&
      ImGui::GetMouseDragDelta(ImGuiMouseButton_Right).y == 0) {
    add_at_ = mouse;
    wire_from_ = doc.selected();
    ImGui::OpenPopup("add_node");
  }
  if (ImGui::IsWindowFocused() && !io.WantTextInput) {
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Tab))) {
      add_at_ = hovered ? mouse : view_.to_canvas(view_.origin + size * 0.5f);
      wire_from_ = doc.selected();
      ImGui::OpenPopup("add_node");
    }
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Delete)) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Backspace)))
      if (Status s = doc.remove_selection(); !s) status = s.message();
    if (!ctrl && ImGui::IsKeyPressed('F')) {
      const std::vector<NodeId> sel(doc.selection().begin(), doc.selection().end());
      if (!boxes.empty()) view_.frame(bounds(boxes, sel), size, legible_zoom());
    }
    if (ctrl && (ImGui::IsKeyPressed('C') || ImGui::IsKeyPressed('X')) && !doc.selection().empty()) {
      ImGui::SetClipboardText(doc.copy_selection().c_str());
      if (ImGui::IsKeyPressed('X'))
        if (Status s = doc.remove_selection(); !s) status = s.message();
    }
    if (ctrl && ImGui::IsKeyPressed('V')) {
      const char* text = ImGui::GetClipboardText();
      if (auto r = doc.paste(text ? text : "", 40.0, 40.0); !r) status = r.message();
    }
    if (!ctrl && ImGui::IsKeyPressed('L'))
      if (Status s = doc.tidy_layout(); !s) status = s.message();
    if (ctrl && ImGui::IsKeyPressed('G'))
      if (auto r = doc.group_selection(); !r) status = r.message();
    const Node* selected = g.node(doc.selected());
    if (selected && !selected->group.empty() && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter))) open_group(doc, selected->id, status);
    if (!ctrl && ImGui::IsKeyPressed('U') && !doc.scope().empty()) doc.leave_group(doc.scope().size() - 1);
  }
  draw_add_menu(doc, status);
}

void NodeCanvas::draw_add_menu(Document& doc, std::string& status) {
  if (!ImGui::BeginPopup("add_node")) return;
  if (ImGui::IsWindowAppearing()) {
    search_[0] = '\0';
    highlight_ = 0;
    ImGui::SetKeyboardFocusHere();
  }
  ImGui::SetNextItemWidth(280);
  const bool enter = ImGui::InputTextWithHint("##search", "search nodes", search_, sizeof search_, ImGuiInputTextFlags_EnterReturnsTrue);
  if (ImGui::IsItemEdited()) highlight_ = 0;
  // Best matches first: the name starting with the text, containing it, then category, then docs.
  struct Entry {
    std::string name, category;
    const NodeDecl* decl;
    bool group;
    int score;
  };
  std::vector<Entry> entries;
  auto score = [&](const std::string& name, const std::string& category, const std::string& docs) {
    const std::string_view q = search_;
    if (q.empty()) return 0;
    if (name.size() >= q.size() && contains_nocase(name.substr(0, q.size()), q)) return 0;
    if (contains_nocase(name, q)) return 1;
    if (contains_nocase(category, q)) return 2;
    if (contains_nocase(docs, q)) return 3;
    return -1;
  };
  for (const auto& t : NodeRegistry::global().all())
    entries.push_back({t->name(), t->decl.category(), &t->decl, false, score(t->name(), t->decl.category(), t->decl.doc())});
  for (const auto& [name, def] : doc.graph().groups())
    entries.push_back({name, "Groups", &def.type->decl, true, score(name, "Groups", def.type->decl.doc())});
  std::erase_if(entries, [](const Entry& e) { return e.score < 0; });
  std::stable_sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    return a.score != b.score ? a.score < b.score : a.category < b.category;
  });
  const int count = static_cast<int>(entries.size());
  if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_DownArrow))) highlight_ = std::min(highlight_ + 1, count - 1);
  if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_UpArrow))) highlight_ = std::max(highlight_ - 1, 0);
  highlight_ = std::clamp(highlight_, 0, std::max(count - 1, 0));
  const Entry* pick = enter && count > 0 ? &entries[static_cast<std::size_t>(highlight_)] : nullptr;
  ImGui::BeginChild("entries", ImVec2(280, 300));
  std::string category = "\x01";
  for (int i = 0; i < count; ++i) {
    const Entry& e = entries[static_cast<std::size_t>(i)];
    if (e.category != category && !search_[0]) {
      category = e.category;
      ImGui::TextDisabled("%s", category.empty() ? "Other" : category.c_str());
    }
    ImGui::Indent();
    if (ImGui::Selectable(e.name.c_str(), i == highlight_)) pick = &e;
    if (i == highlight_ && (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_DownArrow)) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_UpArrow))))
      ImGui::SetScrollHereY();
    if (ImGui::IsItemHovered()) highlight_ = i;
    ImGui::Unindent();
  }
  if (entries.empty()) ImGui::TextDisabled("no node type matches");
  ImGui::EndChild();
  // The highlighted type's documentation, as `procex nodes` prints it.
  ImGui::SameLine();
  ImGui::BeginChild("docs", ImVec2(340, 300), true);
  if (count > 0) {
    const Entry& e = entries[static_cast<std::size_t>(highlight_)];
    ImGui::TextUnformatted(e.name.c_str());
    ImGui::TextDisabled("%s", e.category.c_str());
    ImGui::Separator();
    if (!e.decl->doc().empty()) ImGui::TextWrapped("%s", e.decl->doc().c_str());
    auto ports = [](const char* what, const std::vector<PortDecl>& list) {
      if (list.empty()) return;
      ImGui::Spacing();
      ImGui::TextDisabled("%s", what);
      for (const PortDecl& p : list) ImGui::BulletText("%s : %s%s", p.name.c_str(), p.type ? p.type->name().c_str() : "?", p.optional ? " (optional)" : "");
    };
    ports("inputs", e.decl->inputs());
    ports("outputs", e.decl->outputs());
    if (!e.decl->params().empty()) {
      ImGui::Spacing();
      ImGui::TextDisabled("parameters");
      for (const ParamDecl& p : e.decl->params()) ImGui::BulletText("%s%s%s", p.name.c_str(), p.unit.empty() ? "" : " / ", p.unit.c_str());
    }
  }
  ImGui::EndChild();
  if (pick) {
    auto r = doc.add_node_wired(pick->name, pick->group, add_at_.x, add_at_.y, wire_from_);
    if (!r) status = r.message();
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

}  // namespace procex::studio
