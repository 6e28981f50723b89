// Messages for core/ exceptions that carry a location (loop, vertex, height,
// edge ids), so a node's error says where the footprint went wrong.
#pragma once

#include <exception>
#include <string>

namespace procex {

// e.what() followed by the location InputError / SweepError carry, if any.
std::string describe(const std::exception& e);

}  // namespace procex
