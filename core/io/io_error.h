// IoError lives in base/ (write_file_atomically, shared with graph, throws it).
#pragma once

#include "base/io_error.h"
