#include "core/placement/placement_error.h"

#include <charconv>

namespace procex {

std::string vector_text(const glm::dvec3& v) {
  std::string out = "(";
  for (int k = 0; k < 3; ++k) {
    char buf[32];
    out.append(buf, std::to_chars(buf, buf + sizeof buf, v[k]).ptr);
    out += k < 2 ? ", " : ")";
  }
  return out;
}

}  // namespace procex
