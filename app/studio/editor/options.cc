#include "app/studio/editor/options.h"

#include <algorithm>
#include <charconv>
#include <stdexcept>

namespace procex::studio {

std::string usage() {
  return "usage: procex-studio [RECIPE.pxg | FILE.glb] [options]\n"
         "  --screenshot OUT.png        render the window once the recipe is evaluated, save it, exit\n"
         "  --screenshot-info OUT.json  with --screenshot: also describe the preview (area, tags)\n"
         "  --size WxH                  window size in pixels (default 1280x800)\n"
         "  --timeout SECONDS           --screenshot: longest wait for the evaluation (default 60)\n"
         "  --autosave SECONDS          autosave interval for crash recovery (default 30, 0: off)\n"
         "  --report-frames FILE        on exit, write frame and evaluation timings as JSON\n"
         "  --bench-edits N             benchmark: make N parameter edits, time each to the screen, exit\n"
         "  --select NODE               select this node id at start\n"
         "  --footprints FILE           preview the recipe on every feature of this footprint file, as if dropped\n"
         "  --view YAW,PITCH            the 3D preview's direction in degrees (pitch below 0: from below)\n"
         "  --full-redraw               draw the whole window every frame, not only what changed\n"
         "  --ui-map FILE               keep a JSON map of the pins and widgets on screen (for input-driving tests)\n"
         "  -h, --help                  this text\n";
}

namespace {

int parse_int(std::string_view s, const std::string& what) {
  int v = 0;
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || v <= 0)
    throw std::invalid_argument(what + ": '" + std::string(s) + "' is not a positive whole number");
  return v;
}

}  // namespace

Options parse_options(const std::vector<std::string>& args) {
  Options o;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&]() -> const std::string& {
      if (i + 1 >= args.size()) throw std::invalid_argument(a + " needs a value");
      return args[++i];
    };
    if (a == "-h" || a == "--help") {
      o.help = true;
    } else if (a == "--screenshot") {
      o.screenshot = value();
    } else if (a == "--screenshot-info") {
      o.screenshot_info = value();
    } else if (a == "--select") {
      o.select = static_cast<unsigned>(parse_int(value(), "--select"));
    } else if (a == "--ui-map") {
      o.ui_map = value();
    } else if (a == "--footprints") {
      o.footprints = value();
    } else if (a == "--report-frames") {
      o.frame_report = value();
    } else if (a == "--size") {
      const std::string& v = value();
      const auto x = v.find('x');
      if (x == std::string::npos) throw std::invalid_argument("--size: '" + v + "' is not WIDTHxHEIGHT");
      o.width = parse_int(std::string_view(v).substr(0, x), "--size");
      o.height = parse_int(std::string_view(v).substr(x + 1), "--size");
    } else if (a == "--autosave") {
      o.autosave_s = value() == "0" ? 0 : parse_int(args[i], "--autosave");
    } else if (a == "--bench-edits") {
      o.bench_edits = parse_int(value(), "--bench-edits");
    } else if (a == "--full-redraw") {
      o.full_redraw = true;
    } else if (a == "--view") {
      const std::string& v = value();
      float yaw = 0, pitch = 0;
      const auto comma = v.find(',');
      const char* end = v.data() + v.size();
      auto [yaw_end, yaw_ec] = std::from_chars(v.data(), v.data() + std::min(comma, v.size()), yaw);
      if (comma == std::string::npos || yaw_ec != std::errc() || yaw_end != v.data() + comma)
        throw std::invalid_argument("--view: '" + v + "' is not YAW,PITCH in degrees");
      auto [pitch_end, pitch_ec] = std::from_chars(v.data() + comma + 1, end, pitch);
      if (pitch_ec != std::errc() || pitch_end != end || pitch < -89 || pitch > 89)
        throw std::invalid_argument("--view: '" + v + "' is not YAW,PITCH in degrees with PITCH in [-89, 89]");
      o.view = std::array<float, 2>{yaw, pitch};
    } else if (a == "--timeout") {
      o.timeout_s = parse_int(value(), "--timeout");
    } else if (!a.empty() && a[0] == '-') {
      throw std::invalid_argument("unknown option '" + a + "'");
    } else if (o.recipe.empty()) {
      o.recipe = a;
    } else {
      throw std::invalid_argument("one recipe at a time: '" + o.recipe.string() + "' and '" + a + "'");
    }
  }
  if (!o.screenshot_info.empty() && o.screenshot.empty()) throw std::invalid_argument("--screenshot-info needs --screenshot");
  return o;
}

}  // namespace procex::studio
