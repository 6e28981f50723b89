// expression.h -- a parameter that says what it means: `wall_height + 1.5`,
// `if(levels > 4, 3.2, 3.0) * levels`, `attr("building:levels", 2)`.
//
// The grammar (docs/expressions.md) is small enough for a hand-written
// recursive-descent parser; no Debian package offers one that reports columns
// and types the way the .pxg loader needs. An expression is parsed once, its
// names are typed against the graph that holds it (graph inputs and exposed
// parameters), and it is evaluated while the evaluator plans the graph, before
// any hash is taken: the resolved value is hashed like any parameter value, so
// caching stays exact.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "graph/status.h"

namespace procex {

enum class ExprType { kNumber, kBool, kString };
const char* to_string(ExprType t);

// What an expression evaluates to.
using ExprValue = std::variant<double, bool, std::string>;
ExprType type_of(const ExprValue& v);

// A failure while evaluating (division by zero, a name without a value); the
// message starts with "column N: ".
struct ExprError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct ExprNode;

class Expression {
 public:
  // Parses `text`. A refusal says "column N: what is wrong".
  static Result<std::shared_ptr<const Expression>> parse(std::string_view text);

  const std::string& text() const { return text_; }
  // The names the expression reads, each once, in order of first use.
  const std::vector<std::string>& names() const { return names_; }

  // The type of the whole, given the type of each name (nullopt: no such
  // name). A refusal says "column N: ...".
  using NameTypes = std::function<std::optional<ExprType>(std::string_view name)>;
  Result<ExprType> check(const NameTypes& type_of) const;

  // Values of names and per-feature attributes (null: the attribute is absent)
  // at evaluation (`name` throws ExprError, without a column, for a name it
  // cannot give; the column is added); `warn` hears of an attribute that does not read as its
  // default's type (the default is used). Throws ExprError.
  struct Env {
    std::function<ExprValue(std::string_view name)> name;
    std::function<const std::string*(std::string_view key)> attribute;
    std::function<void(std::string message)> warn;
  };
  ExprValue evaluate(const Env& env) const;

  ~Expression();
  Expression(const Expression&) = delete;
  Expression& operator=(const Expression&) = delete;

 private:
  Expression() = default;
  std::string text_;
  std::vector<std::string> names_;
  std::unique_ptr<ExprNode> root_;
};

}  // namespace procex
