// write_file_atomically lives in base/ (graph writes .pxg files with it too).
#pragma once

#include "base/atomic_write.h"
