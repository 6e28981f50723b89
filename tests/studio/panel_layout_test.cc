#include "app/studio/editor/panel_layout.h"

#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>

#include <gtest/gtest.h>

namespace procex::studio {
namespace {

TEST(PanelLayout, ReadsTheLinesItWrites) {
  PanelLayout a{0.3125, 0.7};
  PanelLayout b;
  std::string text = a.lines();
  for (std::size_t start = 0, nl; (nl = text.find('\n', start)) != std::string::npos; start = nl + 1)
    EXPECT_TRUE(b.read_line(std::string_view(text).substr(start, nl - start)));
  EXPECT_EQ(a, b);
}

TEST(PanelLayout, RefusesLinesThatAreNotItsOwn) {
  PanelLayout l;
  EXPECT_FALSE(l.read_line("SplitZ=0.3"));
  EXPECT_FALSE(l.read_line("SplitX"));
  EXPECT_FALSE(l.read_line("SplitX=0.3px"));
  EXPECT_FALSE(l.read_line("SplitX="));
  EXPECT_EQ(l, PanelLayout{});
}

TEST(PanelLayout, ClampsSoNoPanelVanishes) {
  EXPECT_EQ((PanelLayout{7, -1}.clamped()), (PanelLayout{1 - PanelLayout::kMinShare, PanelLayout::kMinShare}));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ((PanelLayout{nan, std::numeric_limits<double>::infinity()}.clamped()), PanelLayout{});
}

TEST(PanelLayout, LivesInTheXdgConfigFolder) {
  setenv("XDG_CONFIG_HOME", "/tmp/procex_cfg", 1);
  EXPECT_EQ(layout_settings_path(), std::filesystem::path("/tmp/procex_cfg/procex-studio/imgui.ini"));
  unsetenv("XDG_CONFIG_HOME");
  const std::string home = std::getenv("HOME") ? std::getenv("HOME") : "";
  setenv("HOME", "/home/someone", 1);
  EXPECT_EQ(layout_settings_path(), std::filesystem::path("/home/someone/.config/procex-studio/imgui.ini"));
  setenv("HOME", home.c_str(), 1);
}

}  // namespace
}  // namespace procex::studio
