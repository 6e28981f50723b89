#include "app/studio/ui/recipe_panel.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <vector>

namespace procex::studio {

void RecipePanel::record(const std::string& name) { record_item(widgets_, name); }

void RecipePanel::draw(Document& doc, std::string& status, const std::function<void(const std::filesystem::path&)>& take_thumbnail) {
  widgets_.clear();
  ImGui::BeginChild("recipe");
  metadata(doc, status, take_thumbnail);
  interface(doc, status);
  presets(doc, status);
  ImGui::EndChild();
}

void RecipePanel::metadata(Document& doc, std::string& status, const std::function<void(const std::filesystem::path&)>& take_thumbnail) {
  ImGui::TextDisabled("recipe");
  // Text is edited in a buffer and committed (one undo step) when the field loses focus.
  auto field = [&](const char* label, std::string GraphMetadata::*member, bool multiline) {
    const std::string& now = doc.graph().metadata.*member;
    std::string& text = editing_.try_emplace(label, now).first->second;
    if (multiline) ImGui::InputTextMultiline(label, &text, ImVec2(-80, ImGui::GetTextLineHeight() * 3));
    else ImGui::InputText(label, &text);
    record(std::string("metadata.") + label);
    if (ImGui::IsItemDeactivatedAfterEdit() && text != now) {
      const std::string value = text;
      if (Status s = doc.edit_recipe(std::string("set ") + label, [member, value](Graph& g) {
            g.metadata.*member = value;
            return Status::ok();
          });
          !s)
        status = s.message();
    }
    if (!ImGui::IsItemActive()) editing_.erase(label);
  };
  field("title", &GraphMetadata::name, false);
  field("author", &GraphMetadata::author, false);
  field("licence", &GraphMetadata::licence, false);
  field("description", &GraphMetadata::description, true);
  const bool shoot = ImGui::Button("Thumbnail from the preview");
  record("thumbnail");
  if (!doc.graph().metadata.thumbnail.empty()) {
    ImGui::SameLine();
    ImGui::TextDisabled("%s", doc.graph().metadata.thumbnail.c_str());
  }
  if (shoot) {
    if (doc.path().empty()) {
      status = "save the recipe first: its thumbnail is a PNG beside it";
    } else {
      const std::filesystem::path png = std::filesystem::path(doc.path()).replace_extension(".png");
      try {
        take_thumbnail(png);
        const std::string name = png.filename().string();
        if (Status s = doc.edit_recipe("set thumbnail", [name](Graph& g) {
              g.metadata.thumbnail = name;
              return Status::ok();
            });
            !s)
          status = s.message();
        else status = "thumbnail written to " + png.string();
      } catch (const std::exception& e) {
        status = e.what();
      }
    }
  }
}

void RecipePanel::interface(Document& doc, std::string& status) {
  const Graph& g = doc.graph();
  ImGui::Separator();
  ImGui::TextDisabled("graph inputs and outputs (the node's ports when used as a group)");
  auto remove = [&](const std::string& what, const std::string& name, bool output) {
    ImGui::SameLine();
    ImGui::PushID((what + name).c_str());
    const bool clicked = ImGui::SmallButton("x");
    record("remove_" + what + "." + name);
    ImGui::PopID();
    if (!clicked) return;
    if (Status s = doc.edit_recipe("remove " + what + " " + name,
                                   [name, output](Graph& graph) { return output ? graph.remove_output(name) : graph.remove_input(name); });
        !s)
      status = s.message();
  };
  for (const GraphInput& in : g.inputs()) {
    ImGui::BulletText("input %s : %s", in.name.c_str(), in.type->name().c_str());
    remove("input", in.name, false);
  }
  for (const GraphOutput& out : g.outputs()) {
    ImGui::BulletText("output %s : %s", out.name.c_str(), out.type->name().c_str());
    remove("output", out.name, true);
  }
  const std::vector<const ValueType*> types = ValueTypeRegistry::global().all();
  ImGui::SetNextItemWidth(120);
  ImGui::InputTextWithHint("##port_name", "name", &new_name_);
  record("port_name");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(120);
  if (ImGui::BeginCombo("##port_type", types.empty() ? "" : types[static_cast<std::size_t>(new_type_) % types.size()]->name().c_str())) {
    for (std::size_t i = 0; i < types.size(); ++i)
      if (ImGui::Selectable(types[i]->name().c_str(), static_cast<int>(i) == new_type_)) new_type_ = static_cast<int>(i);
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  ImGui::Checkbox("output", &new_is_output_);
  ImGui::SameLine();
  const bool add = ImGui::Button("Add");
  record("add_port");
  if (add && !types.empty()) {
    const ValueType* type = types[static_cast<std::size_t>(new_type_) % types.size()];
    const std::string name = new_name_;
    const bool output = new_is_output_;
    if (Status s = doc.edit_recipe("add " + std::string(output ? "output " : "input ") + name,
                                   [=](Graph& graph) { return output ? graph.add_output({name, type, ""}) : graph.add_input({name, type, "", {}}); });
        !s)
      status = s.message();
    else new_name_.clear();
  }

  ImGui::Separator();
  ImGui::TextDisabled("exposed parameters (right click a parameter in the inspector to expose it)");
  for (const ExposedParam& e : g.exposed_params()) {
    const Node& n = *g.node(e.node);
    const ParamDecl& p = n.decl().params()[e.param];
    std::string range;
    if (e.min || p.min) range = " [" + std::to_string(e.min ? *e.min : *p.min) + ", " + std::to_string(e.max ? *e.max : p.max.value_or(0.0)) + "]";
    ImGui::BulletText("%s%s%s <- #%u %s%s %s", e.name.c_str(), e.label.empty() ? "" : " \"", e.label.empty() ? "" : (e.label + "\"").c_str(), e.node,
                      p.name.c_str(), range.c_str(), (e.unit.empty() ? p.unit : e.unit).c_str());
    const std::string name = e.name;
    ImGui::SameLine();
    ImGui::PushID(("unexpose" + name).c_str());
    const bool clicked = ImGui::SmallButton("x");
    ImGui::PopID();
    if (clicked)
      if (Status s = doc.edit_recipe("unexpose " + name, [name](Graph& graph) { return graph.unexpose_param(name); }); !s) status = s.message();
  }
}

void RecipePanel::presets(Document& doc, std::string& status) {
  ImGui::Separator();
  ImGui::TextDisabled("presets: named sets of the exposed values (procex eval --preset NAME)");
  for (const Preset& p : doc.graph().presets()) {
    const std::string name = p.name;
    ImGui::PushID(("preset" + name).c_str());
    const bool apply = ImGui::Button(name.c_str());
    record("preset." + name);
    ImGui::SameLine();
    const bool drop = ImGui::SmallButton("x");
    ImGui::PopID();
    if (apply)
      if (Status s = doc.apply_preset(name); !s) status = s.message();
    if (drop)
      if (Status s = doc.edit_recipe("remove preset " + name, [name](Graph& g) { return g.remove_preset(name); }); !s) status = s.message();
  }
  ImGui::SetNextItemWidth(160);
  ImGui::InputTextWithHint("##preset_name", "preset name", &new_preset_);
  record("preset_name");
  ImGui::SameLine();
  const bool save = ImGui::Button("Save preset");
  record("save_preset");
  if (save) {
    if (Status s = doc.save_preset(new_preset_); !s) status = s.message();
    else status = "saved preset " + new_preset_;
  }
}

}  // namespace procex::studio
