// recipe_panel.h -- the recipe as an asset: its metadata (title, author,
// licence, description, thumbnail), its graph inputs and outputs, its exposed
// parameters and its presets, each edit one undo step.
#pragma once

#include <array>
#include <functional>
#include <map>
#include <string>

#include "app/studio/editor/document.h"
#include "app/studio/ui/widget_rects.h"

namespace procex::studio {

class RecipePanel {
 public:
  // `take_thumbnail` saves the preview's image to a file (a path beside the recipe).
  void draw(Document& doc, std::string& status, const std::function<void(const std::filesystem::path&)>& take_thumbnail);
  // Widget rectangles of the last frame (window pixels), for the --ui-map.
  const WidgetRects& widgets() const { return widgets_; }

 private:
  void record(const std::string& name);
  void metadata(Document& doc, std::string& status, const std::function<void(const std::filesystem::path&)>& take_thumbnail);
  void interface(Document& doc, std::string& status);
  void presets(Document& doc, std::string& status);

  WidgetRects widgets_;
  std::map<std::string, std::string> editing_;  // metadata text until committed
  std::string new_name_, new_preset_;
  int new_type_ = 0;
  bool new_is_output_ = false;
};

}  // namespace procex::studio
