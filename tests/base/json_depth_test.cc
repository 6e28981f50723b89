// json_too_deep_at: the nesting limit every JSON reader applies before parsing.
#include <string>

#include <gtest/gtest.h>

#include "base/json_depth.h"

namespace procex {
namespace {

TEST(JsonDepth, FindsTheFirstBracketTooDeep) {
  EXPECT_EQ(json_too_deep_at(R"({"a": [[1], {"b": [2]}]})", 4), std::nullopt);
  EXPECT_EQ(json_too_deep_at(R"({"a": [[1], {"b": [2]}]})", 3), std::size_t{18});
  EXPECT_EQ(json_too_deep_at(R"({"a": [[1], {"b": [2]}]})", 2), std::size_t{7});
  // Brackets in strings, escaped quotes included, do not count.
  EXPECT_EQ(json_too_deep_at(R"({"a": "[[[[\"[[[["})", 1), std::nullopt);
  const std::string deep = std::string(80000, '[') + std::string(80000, ']');
  EXPECT_EQ(json_too_deep_at(deep), kMaxJsonDepth);
}

}  // namespace
}  // namespace procex
