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

}  // namespace

void NodeCanvas::draw(Document& doc, const EvalSnapshot* eval, std::string& status) {
  ImGuiIO& io = ImGui::GetIO();
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
    if (!boxes.empty()) view_.frame(bounds(boxes), size);
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

  // Nodes.
  std::string hover_text;
  for (const NodeBox& b : boxes) {
    if (!b.rect.overlaps(visible)) continue;
    const glm::vec2 a = view_.to_screen(b.rect.min), c = view_.to_screen(b.rect.max);
    const bool pseudo = b.id > kMaxNodeId;
    const Node* n = pseudo ? nullptr : g.node(b.id);
    std::string title;
    if (pseudo) title = b.id == kGraphInputs ? "Graph inputs" : "Graph outputs";
    else title = (n->group.empty() ? n->type->name() : n->group) + "  #" + std::to_string(b.id);
    const std::string& category = n ? n->decl().category() : title;
    dl->AddRectFilled(im(a), im(c), IM_COL32(46, 48, 56, 235), 6.0f * zoom);
    dl->AddRectFilled(im(a), ImVec2(c.x, a.y + kHeaderHeight * zoom), color_of(tag_color(category) * 0.6f), 6.0f * zoom,
                      ImDrawFlags_RoundCornersTop);
    const bool selected = doc.selection().count(b.id) > 0;
    dl->AddRect(im(a), im(c), selected ? IM_COL32(255, 170, 40, 255) : IM_COL32(80, 82, 92, 255), 6.0f * zoom, 0,
                selected ? 2.5f : 1.0f);
    dl->AddText(font, font_size, ImVec2(a.x + 16.0f * zoom, a.y + 5.0f * zoom), IM_COL32(240, 240, 240, 255), title.c_str());
    // Ports with their names.
    for (std::uint32_t i = 0; i < b.inputs.size(); ++i) {
      const PortRef p{b.id, i};
      const glm::vec2 s = view_.to_screen(b.inputs[i]);
      const std::string name = pseudo ? g.outputs()[i].name : n->decl().inputs()[i].name + (n->decl().inputs()[i].optional ? "?" : "");
      dl->AddCircleFilled(im(s), kPinRadius * zoom, type_color(g.input_type(p)));
      dl->AddText(font, font_size, ImVec2(s.x + 9.0f * zoom, s.y - font_size * 0.5f), IM_COL32(200, 200, 205, 255), name.c_str());
    }
    for (std::uint32_t i = 0; i < b.outputs.size(); ++i) {
      const PortRef p{b.id, i};
      const glm::vec2 s = view_.to_screen(b.outputs[i]);
      const std::string name = pseudo ? g.inputs()[i].name : n->decl().outputs()[i].name;
      dl->AddCircleFilled(im(s), kPinRadius * zoom, type_color(g.output_type(p)));
      const float w = font->CalcTextSizeA(font_size, 1e9f, 0.0f, name.c_str()).x;
      dl->AddText(font, font_size, ImVec2(s.x - 9.0f * zoom - w, s.y - font_size * 0.5f), IM_COL32(200, 200, 205, 255), name.c_str());
    }
    if (pseudo) continue;
    // Evaluation marks: a dot for cached / computed, a badge for errors and warnings.
    const NodeMarks m = marks_of(eval, b.id);
    if (m.stats) {
      const glm::vec2 dot(a.x + 8.0f * zoom, a.y + kHeaderHeight * zoom * 0.5f);
      dl->AddCircleFilled(im(dot), 4.0f * zoom, outcome_color(m.stats->outcome));
      if (glm::distance(mouse_s, dot) < 7.0f * zoom) {
        char buf[96];
        std::snprintf(buf, sizeof buf, "%s, %.2f ms", to_string(m.stats->outcome), static_cast<double>(m.stats->time_ns) * 1e-6);
        hover_text = buf;
      }
    }
    if (!m.errors.empty() || !m.warnings.empty()) {
      const glm::vec2 badge(c.x - 10.0f * zoom, a.y + kHeaderHeight * zoom * 0.5f);
      dl->AddCircleFilled(im(badge), 8.0f * zoom, m.errors.empty() ? IM_COL32(230, 190, 40, 255) : IM_COL32(220, 50, 45, 255));
      dl->AddText(font, font_size, ImVec2(badge.x - 2.5f * zoom, badge.y - font_size * 0.5f), IM_COL32(20, 20, 20, 255), "!");
      if (glm::distance(mouse_s, badge) < 10.0f * zoom) {
        for (const auto* list : {&m.errors, &m.warnings})
          for (const Diagnostic* d : *list) {
            if (!hover_text.empty()) hover_text += '\n';
            hover_text += d->to_string();
          }
      }
    }
  }

  // Gestures.
  const float pick = std::max(kPinRadius * 2.0f, 9.0f / zoom);
  const bool ctrl = io.KeyCtrl, shift = io.KeyShift;
  if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && drag_ == Drag::kNone) {
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
    ImGui::OpenPopup("add_node");
  }
  if (ImGui::IsWindowFocused() && !io.WantTextInput) {
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Tab))) {
      add_at_ = hovered ? mouse : view_.to_canvas(view_.origin + size * 0.5f);
      ImGui::OpenPopup("add_node");
    }
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Delete)) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Backspace)))
      if (Status s = doc.remove_selection(); !s) status = s.message();
    if (!ctrl && ImGui::IsKeyPressed('F')) {
      const std::vector<NodeId> sel(doc.selection().begin(), doc.selection().end());
      if (!boxes.empty()) view_.frame(bounds(boxes, sel), size);
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
    if (ctrl && ImGui::IsKeyPressed('G'))
      if (auto r = doc.group_selection(); !r) status = r.message();
  }
  draw_add_menu(doc, status);
}

void NodeCanvas::draw_add_menu(Document& doc, std::string& status) {
  if (!ImGui::BeginPopup("add_node")) return;
  if (ImGui::IsWindowAppearing()) {
    search_[0] = '\0';
    ImGui::SetKeyboardFocusHere();
  }
  const bool enter = ImGui::InputTextWithHint("##search", "search nodes", search_, sizeof search_, ImGuiInputTextFlags_EnterReturnsTrue);
  struct Entry {
    std::string name, category, doc;
    bool group;
  };
  std::vector<Entry> entries;
  for (const auto& t : NodeRegistry::global().all()) entries.push_back({t->name(), t->decl.category(), t->decl.doc(), false});
  for (const auto& [name, def] : doc.graph().groups()) entries.push_back({name, "Groups", def.type->decl.doc(), true});
  std::erase_if(entries, [&](const Entry& e) { return !contains_nocase(e.name, search_) && !contains_nocase(e.category, search_); });
  std::stable_sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.category < b.category; });
  const Entry* pick = enter && !entries.empty() ? &entries.front() : nullptr;
  ImGui::BeginChild("entries", ImVec2(280, 260));
  std::string category = "\x01";
  for (const Entry& e : entries) {
    if (e.category != category) {
      category = e.category;
      ImGui::TextDisabled("%s", category.empty() ? "Other" : category.c_str());
    }
    ImGui::Indent();
    if (ImGui::Selectable(e.name.c_str())) pick = &e;
    ImGui::Unindent();
    if (ImGui::IsItemHovered() && !e.doc.empty()) ImGui::SetTooltip("%s", e.doc.c_str());
  }
  if (entries.empty()) ImGui::TextDisabled("no node type matches");
  ImGui::EndChild();
  if (pick) {
    auto r = pick->group ? doc.add_group_node(pick->name, add_at_.x, add_at_.y) : doc.add_node(pick->name, add_at_.x, add_at_.y);
    if (!r) status = r.message();
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

}  // namespace procex::studio
