// What the command tests share: a fresh folder per test (ScratchDirTest),
// captured output streams, whole-file reads, eval's options.
#pragma once

#include <filesystem>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "app/cli/eval_command.h"
#include "tests/support/scratch_dir.h"

namespace procex::test {

class CommandTest : public ScratchDirTest {
 protected:
  std::ostringstream out_, err_;
};

// `procex eval RECIPE -o OUTPUT [--set ...] [--preset PRESET]`, every other
// option at its default.
inline EvalCommandOptions eval_options(std::filesystem::path recipe, std::filesystem::path output,
                                       std::vector<std::string> settings = {}, std::string preset = {}) {
  EvalCommandOptions o;
  o.recipe = std::move(recipe);
  o.output = std::move(output);
  o.settings = std::move(settings);
  o.preset = std::move(preset);
  return o;
}

}  // namespace procex::test
