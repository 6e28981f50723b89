// widget_rects.h -- where ImGui items are on screen, by name, for the
// --ui-map (window tests click widgets there).
#pragma once

#include <array>
#include <map>
#include <string>

namespace procex::studio {

using WidgetRects = std::map<std::string, std::array<float, 4>>;  // x, y, width, height in window pixels

// Records the last item under `name`; not in its window's first frame: a
// menu or dialog that appears sizes and places itself then (drawn hidden),
// so a test clicks a widget only where it stays.
void record_item(WidgetRects& into, const std::string& name);

}  // namespace procex::studio
