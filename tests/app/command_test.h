// What the command tests share: a fresh folder per test (ScratchDirTest),
// captured output streams, whole-file reads.
#pragma once

#include <sstream>

#include "tests/support/scratch_dir.h"

namespace procex::test {

class CommandTest : public ScratchDirTest {
 protected:
  std::ostringstream out_, err_;
};

}  // namespace procex::test
