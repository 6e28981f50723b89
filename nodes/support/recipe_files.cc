#include "nodes/support/recipe_files.h"

#include <mutex>

namespace procex {
namespace {

std::mutex g_mutex;
std::filesystem::path& folder() {
  static std::filesystem::path f;
  return f;
}

}  // namespace

void set_recipe_folder(const std::filesystem::path& f) {
  std::lock_guard lock(g_mutex);
  folder() = f;
}

std::filesystem::path resolve_recipe_path(const std::filesystem::path& file) {
  if (file.is_absolute()) return file;
  std::lock_guard lock(g_mutex);
  return folder().empty() ? file : folder() / file;
}

}  // namespace procex
