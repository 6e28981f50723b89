#include "app/studio/ui/widget_rects.h"

#include <imgui.h>

namespace procex::studio {

void record_item(WidgetRects& into, const std::string& name) {
  if (ImGui::IsWindowAppearing()) return;
  const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
  into[name] = {lo.x, lo.y, hi.x - lo.x, hi.y - lo.y};
}

}  // namespace procex::studio
