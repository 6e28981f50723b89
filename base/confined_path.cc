#include "base/confined_path.h"

#include <algorithm>
#include <string>

namespace procex {

namespace fs = std::filesystem;

namespace {

bool inside(const fs::path& folder, const fs::path& target) {
  std::error_code ec;
  const fs::path resolved = fs::weakly_canonical(fs::absolute(folder, ec), ec);
  if (ec) return false;
  // A trailing separator leaves an empty last element: ignore it.
  auto end = resolved.end();
  if (end != resolved.begin() && std::prev(end)->empty()) --end;
  return std::mismatch(resolved.begin(), end, target.begin(), target.end()).first == end;
}

}  // namespace

fs::path confined_path(const fs::path& root, std::string_view name, std::span<const fs::path> allowed) {
  const std::string text(name);
  const fs::path folder = root.empty() ? fs::current_path() : root;
  if (text.empty()) throw IoError("no file name given (a path relative to the recipe's folder " + folder.string() + ")", text);
  std::error_code ec;
  const fs::path target = fs::weakly_canonical(fs::absolute(folder / fs::path(text), ec), ec);
  if (ec) throw IoError("cannot resolve '" + text + "': " + ec.message(), text);
  if (inside(folder, target)) return target;
  if (std::any_of(allowed.begin(), allowed.end(), [&](const fs::path& a) { return inside(a, target); })) return target;
  throw IoError("'" + text + "' lies outside the recipe's folder " + folder.string() +
                    " (after following symlinks); a shared recipe may only name files inside its folder. "
                    "Move the file there, or allow its folder with --allow-path DIR if you trust the recipe",
                text);
}

}  // namespace procex
