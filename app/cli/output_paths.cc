#include "app/cli/output_paths.h"

namespace procex {

namespace fs = std::filesystem;

std::optional<std::string> output_clash(const std::vector<fs::path>& inputs, const std::vector<fs::path>& outputs) {
  auto resolved = [](const fs::path& p) {
    std::error_code ec;
    const fs::path r = fs::weakly_canonical(fs::absolute(p, ec), ec);
    return ec ? p : r;
  };
  struct Seen {
    fs::path resolved, given;
    bool input;
  };
  std::vector<Seen> seen;
  for (const fs::path& in : inputs)
    if (!in.empty()) seen.push_back({resolved(in), in, true});
  for (const fs::path& given : outputs) {
    if (given.empty()) continue;
    std::vector<fs::path> written = {given};
    if (given.extension() == ".obj") written.push_back(fs::path(given).replace_extension(".mtl"));
    for (const fs::path& out : written) {
      const fs::path r = resolved(out);
      for (const Seen& s : seen)
        if (s.resolved == r)
          // (Built with append: g++ 12 warns falsely on "'" + path.string().)
          return std::string("'").append(out.string()).append("' would overwrite '").append(s.given.string()) +
                 "', which this run " + (s.input ? "reads" : "also writes") + ": give each output its own path";
      seen.push_back({r, out, false});
    }
  }
  return std::nullopt;
}

}  // namespace procex
