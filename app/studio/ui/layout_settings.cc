#include "app/studio/ui/layout_settings.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <string_view>
#include <system_error>

#include "base/atomic_write.h"
#include "base/read_file.h"

namespace procex::studio {

namespace fs = std::filesystem;

namespace {

LayoutSettings* owner(ImGuiSettingsHandler* handler) { return static_cast<LayoutSettings*>(handler->UserData); }

}  // namespace

LayoutSettings::LayoutSettings(fs::path file) : file_(std::move(file)) {
  ImGuiSettingsHandler h;
  h.TypeName = "Procex";
  h.TypeHash = ImHashStr("Procex");
  h.ReadOpenFn = [](ImGuiContext*, ImGuiSettingsHandler* handler, const char* name) -> void* {
    return std::string_view(name) == "Layout" ? handler->UserData : nullptr;
  };
  h.ReadLineFn = [](ImGuiContext*, ImGuiSettingsHandler* handler, void*, const char* line) { (void)owner(handler)->layout().read_line(line); };
  h.ApplyAllFn = [](ImGuiContext*, ImGuiSettingsHandler* handler) { owner(handler)->layout() = owner(handler)->layout().clamped(); };
  h.WriteAllFn = [](ImGuiContext*, ImGuiSettingsHandler* handler, ImGuiTextBuffer* out) {
    out->append("[Procex][Layout]\n");
    out->append(owner(handler)->layout().lines().c_str());
    out->append("\n");
  };
  h.UserData = this;
  ImGui::GetCurrentContext()->SettingsHandlers.push_back(h);
}

std::string LayoutSettings::load() {
  std::error_code ec;
  if (!fs::exists(file_, ec)) return {};
  try {
    const std::string text = read_file(file_, kMaxLayoutFileBytes);
    ImGui::LoadIniSettingsFromMemory(text.data(), text.size());
    return {};
  } catch (const std::exception& e) {
    layout_ = {};
    return std::string(e.what()) + " (the default panel layout is used; View > Reset layout writes a new file)";
  }
}

std::string LayoutSettings::save() {
  ImGui::GetIO().WantSaveIniSettings = false;
  try {
    std::size_t size = 0;
    const char* text = ImGui::SaveIniSettingsToMemory(&size);
    fs::create_directories(file_.parent_path());
    write_file_atomically(file_, std::string_view(text, size));
    return {};
  } catch (const std::exception& e) {
    return std::string("the panel layout was not saved: ") + e.what();
  }
}

void LayoutSettings::mark_changed() { ImGui::MarkIniSettingsDirty(); }

std::string LayoutSettings::reset() {
  layout_ = {};
  return save();
}

}  // namespace procex::studio
