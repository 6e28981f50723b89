// procex-studio's command line.
#include "app/studio/editor/options.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace procex::studio {
namespace {

TEST(Options, ParsesTheCommandLine) {
  const Options o = parse_options({"house.pxg", "--screenshot", "out.png", "--screenshot-info", "out.json", "--size", "800x600", "--autosave", "0"});
  EXPECT_EQ(o.recipe, "house.pxg");
  EXPECT_EQ(o.screenshot, "out.png");
  EXPECT_EQ(o.screenshot_info, "out.json");
  EXPECT_EQ(o.width, 800);
  EXPECT_EQ(o.height, 600);
  EXPECT_EQ(o.autosave_s, 0);
  EXPECT_TRUE(parse_options({"--help"}).help);
  EXPECT_EQ(parse_options({"city.pxg", "--footprints", "block.geojson"}).footprints, "block.geojson");
  const Options view = parse_options({"--view", "-60,-12.5"});
  ASSERT_TRUE(view.view);
  EXPECT_EQ((*view.view)[0], -60.0f);
  EXPECT_EQ((*view.view)[1], -12.5f);
}

TEST(Options, BadArgumentsAreNamed) {
  auto message = [](std::vector<std::string> args) {
    try {
      parse_options(args);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message({"--size", "800"}).find("WIDTHxHEIGHT"), std::string::npos);
  EXPECT_NE(message({"--size", "0x600"}).find("positive"), std::string::npos);
  EXPECT_NE(message({"--frobnicate"}).find("--frobnicate"), std::string::npos);
  EXPECT_NE(message({"a.pxg", "b.pxg"}).find("one recipe"), std::string::npos);
  EXPECT_NE(message({"--screenshot"}).find("needs a value"), std::string::npos);
  EXPECT_NE(message({"--screenshot-info", "x.json"}).find("--screenshot"), std::string::npos);
  EXPECT_NE(message({"--view", "30"}).find("YAW,PITCH"), std::string::npos);
  EXPECT_NE(message({"--view", "30,95"}).find("[-89, 89]"), std::string::npos);
  EXPECT_NE(message({"--view", "a,5"}).find("YAW,PITCH"), std::string::npos);
}

}  // namespace
}  // namespace procex::studio
