// layout_settings.h -- the studio's panel layout kept in ImGui's .ini text:
// a [Procex][Layout] section beside ImGui's own window and table entries,
// read at start and written atomically (ImGui's own saving writes in place).
#pragma once

#include <filesystem>
#include <string>

#include "app/studio/editor/panel_layout.h"

namespace procex::studio {

class LayoutSettings {
 public:
  // Registers the section with the current ImGui context; reads nothing yet.
  explicit LayoutSettings(std::filesystem::path file);
  LayoutSettings(const LayoutSettings&) = delete;
  LayoutSettings& operator=(const LayoutSettings&) = delete;

  const std::filesystem::path& file() const { return file_; }
  PanelLayout& layout() { return layout_; }
  // Reads the file if there is one. A file that cannot be read keeps the
  // default layout; the message (naming the file) is returned, empty if none.
  std::string load();
  // Writes every ImGui setting and the layout; the message on failure, else empty.
  std::string save();
  // The layout changed: ImGui asks for a save (io.WantSaveIniSettings) a few seconds later.
  void mark_changed();
  // Back to the default layout, written at once.
  std::string reset();

 private:
  std::filesystem::path file_;
  PanelLayout layout_;
};

}  // namespace procex::studio
