#include "app/studio/editor/panel_layout.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace procex::studio {

namespace fs = std::filesystem;

namespace {

double clamp_share(double v, double fallback) {
  if (!std::isfinite(v)) return fallback;
  return std::clamp(v, PanelLayout::kMinShare, 1.0 - PanelLayout::kMinShare);
}

}  // namespace

PanelLayout PanelLayout::clamped() const { return {clamp_share(split_x, kDefaultSplitX), clamp_share(split_y, kDefaultSplitY)}; }

bool PanelLayout::read_line(std::string_view line) {
  const std::size_t eq = line.find('=');
  if (eq == std::string_view::npos) return false;
  const std::string_view key = line.substr(0, eq), text = line.substr(eq + 1);
  double* field = key == "SplitX" ? &split_x : key == "SplitY" ? &split_y : nullptr;
  if (!field) return false;
  double v = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size()) return false;
  *field = v;
  return true;
}

std::string PanelLayout::lines() const {
  char buf[64];
  std::snprintf(buf, sizeof buf, "SplitX=%.4f\nSplitY=%.4f\n", split_x, split_y);
  return buf;
}

fs::path layout_settings_path() {
  if (const char* c = std::getenv("XDG_CONFIG_HOME"); c && *c) return fs::path(c) / "procex-studio" / "imgui.ini";
  if (const char* home = std::getenv("HOME"); home && *home) return fs::path(home) / ".config" / "procex-studio" / "imgui.ini";
  return fs::temp_directory_path() / "procex-studio" / "imgui.ini";
}

}  // namespace procex::studio
