// expression_tree.h -- the syntax tree shared by the parser and the evaluator
// (graph/ internal; users see only Expression).
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace procex {

struct ExprNode {
  enum Kind { kNumber, kBool, kString, kName, kUnary, kBinary, kCall } kind = kNumber;
  std::size_t column = 1;  // 1-based, in the expression's text
  double number = 0;
  bool boolean = false;
  std::string text;  // string literal, name, operator or function name
  std::vector<std::unique_ptr<ExprNode>> args;
};

}  // namespace procex
