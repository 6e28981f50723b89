// panel_layout.h -- where the studio's panels meet, as the user left them.
//
// The window is split in four: the node canvas and the inspector on the left,
// the preview and the evaluation panels on the right. Two fractions of the
// window say where: `split_x` (the left column's share of the width) and
// `split_y` (the upper row's share of the height). They are kept per user in
// the XDG config folder, as a section of the studio's ImGui .ini file.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace procex::studio {

struct PanelLayout {
  static constexpr double kDefaultSplitX = 0.5, kDefaultSplitY = 0.62;
  // A panel never shrinks below this share of the window, so a bad file or a wild drag cannot hide one.
  static constexpr double kMinShare = 0.15;
  double split_x = kDefaultSplitX, split_y = kDefaultSplitY;

  // Within [kMinShare, 1 - kMinShare]; a value that is not a number goes back to its default.
  PanelLayout clamped() const;
  // One line of the .ini section ("SplitX=0.55"); false if it is not one of ours or not a number.
  bool read_line(std::string_view line);
  // The section's lines, as read_line reads them.
  std::string lines() const;
  bool operator==(const PanelLayout&) const = default;
};

// $XDG_CONFIG_HOME/procex-studio/imgui.ini, else ~/.config/procex-studio/imgui.ini.
std::filesystem::path layout_settings_path();

// Largest settings file read: the studio writes a few hundred bytes, so anything bigger is not its file.
inline constexpr std::size_t kMaxLayoutFileBytes = 64 * 1024;

}  // namespace procex::studio
