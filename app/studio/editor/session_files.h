// session_files.h -- the studio's own files: the recent-files list and the
// autosaves that let a user recover edits after a crash.
//
// They live in $PROCEX_STUDIO_HOME, else $XDG_STATE_HOME/procex-studio, else
// ~/.local/state/procex-studio. An autosave is named after the recipe's path,
// so each recipe (and the untitled one) has its own.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string_view>
#include <vector>

namespace procex::studio {

std::filesystem::path studio_home();

class RecentFiles {
 public:
  explicit RecentFiles(std::filesystem::path file, std::size_t limit = 10);
  const std::vector<std::filesystem::path>& list() const { return list_; }
  // Moves `recipe` to the front and writes the list (best effort: a failed write is not an error).
  void add(const std::filesystem::path& recipe);

 private:
  std::filesystem::path file_;
  std::size_t limit_;
  std::vector<std::filesystem::path> list_;
};

// Where the autosave of `recipe` (empty: the untitled recipe) lives in `home`.
std::filesystem::path autosave_path(const std::filesystem::path& home, const std::filesystem::path& recipe);
// Writes atomically; throws std::runtime_error naming the file on failure.
void write_autosave(const std::filesystem::path& home, const std::filesystem::path& recipe, std::string_view text);
void remove_autosave(const std::filesystem::path& home, const std::filesystem::path& recipe);
// The autosave of `recipe` if one exists that is newer than the recipe file
// (edits that were never saved, e.g. because the studio crashed).
std::optional<std::filesystem::path> find_recovery(const std::filesystem::path& home, const std::filesystem::path& recipe);

}  // namespace procex::studio
