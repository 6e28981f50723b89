#include "app/studio/ui/inspector.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cstdint>
#include <limits>

#include <nlohmann/json.hpp>

#include "app/studio/editor/exposed_default.h"
#include "graph/expression_value.h"

namespace procex::studio {

namespace {

// "%.3f m": the unit follows the number in the widget.
std::string number_format(const ParamDecl& p, const char* conversion) {
  std::string f = conversion;
  if (!p.unit.empty()) f += " " + p.unit;
  return f;
}

std::string json_text(const Value& v) {
  if (v.empty() || !v.type()->has_json()) return "";
  nlohmann::json j;
  v.type()->to_json(v.raw(), j);
  return j.dump();
}

// The value as the inspector writes it: "4.500 m", "true", "gable".
std::string shown_value(const Value& v, const ParamDecl& p) {
  if (v.empty()) return "?";
  std::string text;
  if (v.is<double>()) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.3f", v.get<double>());
    text = buf;
  } else if (v.is<EnumValue>()) {
    text = v.get<EnumValue>().choice;
  } else {
    text = json_text(v);
  }
  return p.unit.empty() ? text : text + " " + p.unit;
}

std::string key_of(NodeId id, const ParamDecl& p) { return std::to_string(id) + "." + p.name; }

}  // namespace

void Inspector::draw(Document& doc, const EvalSnapshot* eval, std::string& status) {
  widgets_.clear();
  const NodeId id = doc.selected();
  if (id == 0) {
    ImGui::TextDisabled(doc.selection().empty() ? "Select a node to edit its parameters." : "%zu nodes selected.", doc.selection().size());
    return;
  }
  const Node& n = *doc.graph().node(id);
  const NodeDecl& decl = n.decl();
  ImGui::Text("%s  #%u", n.group.empty() ? n.type->name().c_str() : n.group.c_str(), id);
  if (!decl.doc().empty()) ImGui::TextWrapped("%s", decl.doc().c_str());
  ImGui::Separator();
  // One undo step per gesture: a drag starts a gesture, its release ends it.
  auto track = [&](const std::string& label) {
    if (ImGui::IsItemActivated()) doc.begin_gesture("set " + label);
    if (ImGui::IsItemDeactivated()) doc.end_gesture();
  };
  auto apply = [&](std::size_t i, Value v) {
    if (Status s = doc.set_param(id, i, std::move(v)); !s) status = s.message();
  };
  // Text is edited in a buffer and committed when the field loses focus.
  auto edit_text = [&](std::size_t i, const std::string& current, bool multiline, auto parse) {
    const ParamDecl& p = decl.params()[i];
    const std::string key = key_of(id, p);
    std::string& text = editing_.try_emplace(key, current).first->second;
    if (multiline) ImGui::InputTextMultiline(p.name.c_str(), &text, ImVec2(-80, ImGui::GetTextLineHeight() * 3));
    else ImGui::InputText(p.name.c_str(), &text);
    if (ImGui::IsItemDeactivatedAfterEdit()) {
      try {
        apply(i, parse(text));
      } catch (const std::exception& e) {
        status = p.name + ": " + e.what();
      }
    }
    if (!ImGui::IsItemActive()) editing_.erase(key);
  };
  for (std::size_t i = 0; i < decl.params().size(); ++i) {
    const ParamDecl& p = decl.params()[i];
    const Value& v = n.params[i];
    ImGui::PushID(static_cast<int>(i));
    const char* label = p.name.c_str();
    if (p.sets_port_count) {
      // Variadic ports: one more or one fewer, each an undo step; the graph refuses to drop a connected port.
      const std::size_t count = port_count_of(v);
      auto step = [&](const char* text, const char* key, std::size_t to) {
        if (ImGui::Button(text, ImVec2(ImGui::GetFrameHeight(), 0)))
          if (Status s = doc.set_port_count(id, i, to); !s) status = s.message();
        record(p.name + key);
        ImGui::SameLine();
      };
      if (count > 0) step("-", ".remove", count - 1);
      step("+", ".add", count + 1);
      ImGui::Text("%zu %s", count, count == 1 ? "port" : "ports");
      if (v.is<std::int64_t>()) {
        ImGui::SameLine();
        ImGui::TextDisabled("(%s)", label);
        if (ImGui::IsItemHovered() && !p.doc.empty()) ImGui::SetTooltip("%s", p.doc.c_str());
        ImGui::PopID();
        continue;
      }
    }
    const auto held = n.expressions.find(static_cast<std::uint32_t>(i));
    const bool has_expression = held != n.expressions.end();
    // An edit begun on what the recipe no longer holds (undone, redone, set back to a value) is dropped.
    if (auto e = expressions_.find(key_of(id, p)); e != expressions_.end() && e->second.held != (has_expression ? held->second->text() : ""))
      expressions_.erase(e);
    if (has_expression || expressions_.count(key_of(id, p))) {
      expression_field(doc, eval, id, i, status);
    } else if (!p.choices.empty()) {
      const std::string& cur = v.get<EnumValue>().choice;
      if (ImGui::BeginCombo(label, cur.c_str())) {
        for (const std::string& c : p.choices)
          if (ImGui::Selectable(c.c_str(), c == cur) && c != cur) apply(i, Value::make(EnumValue{c}));
        ImGui::EndCombo();
      }
    } else if (v.is<double>()) {
      double x = v.get<double>();
      const std::string fmt = number_format(p, "%.3f");
      bool changed;
      if (p.min && p.max) {
        const double lo = *p.min, hi = *p.max;
        changed = ImGui::SliderScalar(label, ImGuiDataType_Double, &x, &lo, &hi, fmt.c_str());
      } else {
        const double lo = p.min.value_or(-std::numeric_limits<double>::max()), hi = p.max.value_or(std::numeric_limits<double>::max());
        changed = ImGui::DragScalar(label, ImGuiDataType_Double, &x, 0.05f, &lo, &hi, fmt.c_str());
      }
      if (changed) apply(i, Value::make(x));
      track(p.name);
    } else if (v.is<std::int64_t>()) {
      std::int64_t x = v.get<std::int64_t>();
      const std::string fmt = number_format(p, "%lld");
      bool changed;
      if (p.min && p.max) {
        const std::int64_t lo = static_cast<std::int64_t>(*p.min), hi = static_cast<std::int64_t>(*p.max);
        changed = ImGui::SliderScalar(label, ImGuiDataType_S64, &x, &lo, &hi, fmt.c_str());
      } else {
        changed = ImGui::DragScalar(label, ImGuiDataType_S64, &x, 0.2f, nullptr, nullptr, fmt.c_str());
      }
      if (changed) apply(i, Value::make(x));
      track(p.name);
    } else if (v.is<bool>()) {
      bool b = v.get<bool>();
      if (ImGui::Checkbox(label, &b)) apply(i, Value::make(b));
    } else if (v.is<Vec2>() || v.is<Vec3>()) {
      double xyz[3] = {0, 0, 0};
      const int n = v.is<Vec2>() ? 2 : 3;
      if (n == 2) {
        xyz[0] = v.get<Vec2>().x;
        xyz[1] = v.get<Vec2>().y;
      } else {
        xyz[0] = v.get<Vec3>().x;
        xyz[1] = v.get<Vec3>().y;
        xyz[2] = v.get<Vec3>().z;
      }
      if (ImGui::DragScalarN(label, ImGuiDataType_Double, xyz, n, 0.05f, nullptr, nullptr, number_format(p, "%.3f").c_str()))
        apply(i, n == 2 ? Value::make(Vec2{xyz[0], xyz[1]}) : Value::make(Vec3{xyz[0], xyz[1], xyz[2]}));
      track(p.name);
    } else if (v.is<std::string>()) {
      edit_text(i, v.get<std::string>(), false, [](const std::string& t) { return Value::make(t); });
    } else if (v.type() && v.type()->has_json()) {
      // Lists and points: JSON text, checked by the type's own reader when committed.
      const ValueType* type = v.type();
      edit_text(i, json_text(v), true, [type](const std::string& t) { return type->from_json(nlohmann::json::parse(t)); });
    } else {
      ImGui::TextDisabled("%s: %s (not editable here)", label, v.type() ? v.type()->name().c_str() : "?");
    }
    if (ImGui::IsItemHovered() && !p.doc.empty()) ImGui::SetTooltip("%s", p.doc.c_str());
    record(p.name);
    // Right click: expose it on the recipe's interface, or take it off.
    if (ImGui::BeginPopupContextItem("param_menu")) {
      const auto& exposed = doc.graph().exposed_params();
      auto it = std::find_if(exposed.begin(), exposed.end(), [&](const ExposedParam& e) { return e.node == id && e.param == i; });
      if (it != exposed.end()) {
        const std::string name = it->name;
        if (ImGui::MenuItem(("Unexpose '" + name + "'").c_str()))
          if (Status s = doc.edit_recipe("unexpose " + name, [name](Graph& g) { return g.unexpose_param(name); }); !s) status = s.message();
      } else if (ImGui::MenuItem("Expose...")) {
        expose_ = {true, id, i, p.name, "", p.unit, v.is<double>(), p.min.value_or(0.0), p.max.value_or(0.0), v.is<double>() ? v.get<double>() : 0.0};
        if (expose_.numeric && !p.min && !p.max) expose_.max = expose_.min = expose_.value;
      }
      record("expose_menu");
      if (has_expression) {
        // Back to a value: the one the expression gave in the last evaluation, so the result stays as it is.
        const NodeStats* s = eval ? eval->result.stats.find(NodePath{id}) : nullptr;
        if (ImGui::MenuItem("Use value")) apply(i, s && i < s->params.size() ? s->params[i] : v);
        record("value_menu");
      } else if (expression_type(*p.type) && !p.sets_port_count && !expressions_.count(key_of(id, p))) {
        if (ImGui::MenuItem("Expression...")) {
          const std::string literal = expression_literal(to_expr_value(v));
          expressions_[key_of(id, p)] = {literal, "", literal, "", true};
        }
        record("expression_menu");
      }
      ImGui::EndPopup();
    }
    expression_error(id, p);
    if (const std::string note = exposed_default_note(doc, id, i); !note.empty()) {
      ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.55f, 0.75f, 1.0f, 1.0f));
      ImGui::TextWrapped("%s", note.c_str());
      ImGui::PopStyleColor();
      record(p.name + ".default_note");
    }
    ImGui::PopID();
  }
  expose_dialog(doc, status);
  if (!eval) return;
  ImGui::Separator();
  if (const NodeStats* s = eval->result.stats.find(NodePath{id}))
    ImGui::TextDisabled("last evaluation: %s, %.2f ms, %.1f KiB", to_string(s->outcome), static_cast<double>(s->time_ns) * 1e-6,
                        static_cast<double>(s->memory) / 1024.0);
  for (const Diagnostic& d : eval->result.diagnostics) {
    if (d.node.empty() || d.node[0] != id) continue;
    const ImVec4 col = d.severity == Severity::kError ? ImVec4(1.0f, 0.4f, 0.35f, 1.0f) : ImVec4(1.0f, 0.8f, 0.3f, 1.0f);
    ImGui::PushStyleColor(ImGuiCol_Text, col);
    ImGui::TextWrapped("%s", d.to_string().c_str());
    ImGui::PopStyleColor();
  }
}

void Inspector::expression_field(Document& doc, const EvalSnapshot* eval, NodeId id, std::size_t i, std::string& status) {
  const Node& n = *doc.graph().node(id);
  const ParamDecl& p = n.decl().params()[i];
  const std::string key = key_of(id, p);
  const auto held_it = n.expressions.find(static_cast<std::uint32_t>(i));
  const std::string held = held_it == n.expressions.end() ? "" : held_it->second->text();
  auto found = expressions_.find(key);
  ExpressionEdit& edit = found != expressions_.end() ? found->second : expressions_[key];
  if (found == expressions_.end()) edit = {held, held, held, "", false};
  // The value beside the text: what the expression gave in the last evaluation of this node.
  std::string label = p.name;
  if (!held.empty()) {
    const NodeStats* s = eval ? eval->result.stats.find(NodePath{id}) : nullptr;
    label += s && i < s->params.size() ? " = " + shown_value(s->params[i], p) : " = (not evaluated)";
  } else {
    label += " (new expression)";
  }
  label += "###expression";
  if (edit.focus) {
    ImGui::SetKeyboardFocusHere();
    edit.focus = false;
  }
  ImGui::PushStyleColor(ImGuiCol_FrameBg, ImVec4(0.30f, 0.20f, 0.45f, 1.0f));
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.55f);
  ImGui::InputText(label.c_str(), &edit.text, ImGuiInputTextFlags_AutoSelectAll);
  ImGui::PopStyleColor();
  record(p.name + ".expression");
  const bool active = ImGui::IsItemActive();
  if (ImGui::IsItemDeactivated()) {
    // Escape leaves the recipe as it is: the field shows its expression again, or its value widget.
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape)) || (held.empty() && edit.text == edit.initial)) {
      expressions_.erase(key);
      return;
    }
    if (Status s = doc.set_expression(id, i, edit.text); !s) {
      edit.error = s.message();
      status = s.message();
      return;
    }
    expressions_.erase(key);
    return;
  }
  if (edit.error.empty() && !active && !held.empty() && !edit.focus)
    expressions_.erase(key);  // nothing being edited: the next frame shows the recipe's text again
}

void Inspector::expression_error(NodeId id, const ParamDecl& p) {
  auto e = expressions_.find(key_of(id, p));
  if (e == expressions_.end() || e->second.error.empty()) return;
  ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.4f, 0.35f, 1.0f));
  ImGui::TextWrapped("%s", e->second.error.c_str());
  ImGui::PopStyleColor();
  record(p.name + ".error");
}

void Inspector::record(const std::string& name) { record_item(widgets_, name); }

void Inspector::expose_dialog(Document& doc, std::string& status) {
  if (expose_.open_requested) {
    ImGui::OpenPopup("Expose parameter");
    expose_.open_requested = false;
  }
  if (!ImGui::BeginPopupModal("Expose parameter", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  ImGui::TextDisabled("shown on the recipe's interface, set with --set NAME=VALUE");
  ImGui::InputText("name", &expose_.name);
  record("expose.name");
  ImGui::InputText("label", &expose_.label);
  record("expose.label");
  ImGui::InputText("unit", &expose_.unit);
  if (expose_.numeric) {
    ImGui::InputDouble("min", &expose_.min);
    record("expose.min");
    ImGui::InputDouble("max", &expose_.max);
    record("expose.max");
    ImGui::InputDouble("default", &expose_.value);
    record("expose.default");
  }
  const bool ok = ImGui::Button("Expose");
  record("expose.ok");
  ImGui::SameLine();
  if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
  if (ok) {
    ExposedParam p;
    p.name = expose_.name;
    p.label = expose_.label;
    p.unit = expose_.unit;
    // A range of one value is no range: the inner parameter's own stays.
    if (expose_.numeric && expose_.min < expose_.max) {
      p.min = expose_.min;
      p.max = expose_.max;
    }
    if (Status s = doc.expose(expose_.node, expose_.param, p, expose_.numeric ? Value::make(expose_.value) : Value()); !s) status = "cannot expose: " + s.message();
    else status = "exposed " + p.name;
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

}  // namespace procex::studio
