#include "app/studio/editor/session_files.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <system_error>

#include "graph/pxg.h"

namespace procex::studio {

namespace fs = std::filesystem;

fs::path studio_home() {
  if (const char* h = std::getenv("PROCEX_STUDIO_HOME"); h && *h) return h;
  if (const char* s = std::getenv("XDG_STATE_HOME"); s && *s) return fs::path(s) / "procex-studio";
  if (const char* home = std::getenv("HOME"); home && *home) return fs::path(home) / ".local/state/procex-studio";
  return fs::temp_directory_path() / "procex-studio";
}

RecentFiles::RecentFiles(fs::path file, std::size_t limit) : file_(std::move(file)), limit_(limit) {
  std::ifstream in(file_);
  for (std::string line; std::getline(in, line) && list_.size() < limit_;)
    if (!line.empty()) list_.emplace_back(line);
}

void RecentFiles::add(const fs::path& recipe) {
  std::error_code ec;
  fs::path p = fs::weakly_canonical(recipe, ec);
  if (ec) p = recipe;
  std::erase(list_, p);
  list_.insert(list_.begin(), p);
  if (list_.size() > limit_) list_.resize(limit_);
  std::string text;
  for (const fs::path& f : list_) text += f.string() + "\n";
  try {
    fs::create_directories(file_.parent_path());
    write_file_atomically(file_, text);
  } catch (const std::exception&) {
    // The list is a convenience; the studio works without it.
  }
}

fs::path autosave_path(const fs::path& home, const fs::path& recipe) {
  if (recipe.empty()) return home / "autosave" / "untitled.pxg";
  std::error_code ec;
  fs::path abs = fs::weakly_canonical(recipe, ec);
  if (ec) abs = fs::absolute(recipe);
  std::uint64_t h = 14695981039346656037ull;  // FNV-1a of the absolute path: one autosave per recipe
  for (char c : abs.string()) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return home / "autosave" / (recipe.stem().string() + "-" + hex + ".pxg");
}

void write_autosave(const fs::path& home, const fs::path& recipe, std::string_view text) {
  const fs::path p = autosave_path(home, recipe);
  fs::create_directories(p.parent_path());
  write_file_atomically(p, text);
}

void remove_autosave(const fs::path& home, const fs::path& recipe) {
  std::error_code ec;
  fs::remove(autosave_path(home, recipe), ec);
}

std::optional<fs::path> find_recovery(const fs::path& home, const fs::path& recipe) {
  const fs::path p = autosave_path(home, recipe);
  std::error_code ec;
  if (!fs::exists(p, ec)) return std::nullopt;
  if (!recipe.empty() && fs::exists(recipe, ec) && fs::last_write_time(p, ec) < fs::last_write_time(recipe, ec)) return std::nullopt;
  return p;
}

}  // namespace procex::studio
