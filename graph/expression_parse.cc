// expression_parse.cc -- text to syntax tree, by recursive descent, one
// function per precedence level of the grammar in docs/expressions.md.
// Untrusted input: length and nesting are bounded, every refusal names a column.
#include <algorithm>
#include <charconv>
#include <cctype>
#include <utility>

#include "graph/expression.h"
#include "graph/expression_tree.h"

namespace procex {

namespace {

constexpr std::size_t kMaxText = 4096;
constexpr std::size_t kMaxDepth = 64;

struct Refusal {
  std::size_t column;
  std::string message;
};

class Parser {
 public:
  explicit Parser(std::string_view text) : s_(text) {}

  std::unique_ptr<ExprNode> whole() {
    auto e = expr();
    skip_space();
    if (i_ < s_.size()) refuse("unexpected '" + std::string(1, s_[i_]) + "'" + hint_after_value());
    return e;
  }

  std::vector<std::string> names;

 private:
  [[noreturn]] void refuse(std::string message, std::size_t at) const { throw Refusal{at + 1, std::move(message)}; }
  [[noreturn]] void refuse(std::string message) const { refuse(std::move(message), i_); }

  std::string hint_after_value() const {
    return s_[i_] == '=' ? " (compare with '==')" : " (an operator or the end was expected)";
  }

  void skip_space() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  // Consumes `op` if it comes next (and is not the start of a longer operator).
  bool take(std::string_view op) {
    skip_space();
    if (s_.substr(i_, op.size()) != op) return false;
    const char after = i_ + op.size() < s_.size() ? s_[i_ + op.size()] : '\0';
    if ((op == "<" || op == ">" || op == "!") && after == '=') return false;
    i_ += op.size();
    return true;
  }

  std::unique_ptr<ExprNode> make(ExprNode::Kind k, std::size_t at, std::string text = {}) {
    auto n = std::make_unique<ExprNode>();
    n->kind = k;
    n->column = at + 1;
    n->text = std::move(text);
    return n;
  }
  std::unique_ptr<ExprNode> binary(std::string op, std::size_t at, std::unique_ptr<ExprNode> a, std::unique_ptr<ExprNode> b) {
    auto n = make(ExprNode::kBinary, at, std::move(op));
    n->args.push_back(std::move(a));
    n->args.push_back(std::move(b));
    return n;
  }

  struct Deeper {
    explicit Deeper(Parser& p) : p_(p) {
      if (++p_.depth_ > kMaxDepth) p_.refuse("nested more than " + std::to_string(kMaxDepth) + " deep");
    }
    ~Deeper() { --p_.depth_; }
    Parser& p_;
  };

  std::unique_ptr<ExprNode> expr() {
    auto a = conjunction();
    for (;;) {
      skip_space();
      const std::size_t at = i_;
      if (!take("||")) return a;
      a = binary("||", at, std::move(a), conjunction());
    }
  }
  std::unique_ptr<ExprNode> conjunction() {
    auto a = comparison();
    for (;;) {
      skip_space();
      const std::size_t at = i_;
      if (!take("&&")) return a;
      a = binary("&&", at, std::move(a), comparison());
    }
  }
  std::unique_ptr<ExprNode> comparison() {
    auto a = sum();
    skip_space();
    const std::size_t at = i_;
    for (const char* op : {"==", "!=", "<=", ">=", "<", ">"})
      if (take(op)) {
        auto n = binary(op, at, std::move(a), sum());
        skip_space();
        for (std::string_view again : {"==", "!=", "<", ">"})
          if (s_.substr(i_, again.size()) == again) refuse("comparisons do not chain; join them with '&&'");
        return n;
      }
    return a;
  }
  std::unique_ptr<ExprNode> sum() {
    auto a = product();
    for (;;) {
      skip_space();
      const std::size_t at = i_;
      if (take("+")) a = binary("+", at, std::move(a), product());
      else if (take("-")) a = binary("-", at, std::move(a), product());
      else return a;
    }
  }
  std::unique_ptr<ExprNode> product() {
    auto a = unary();
    for (;;) {
      skip_space();
      const std::size_t at = i_;
      if (take("*")) a = binary("*", at, std::move(a), unary());
      else if (take("/")) a = binary("/", at, std::move(a), unary());
      else if (take("%")) a = binary("%", at, std::move(a), unary());
      else return a;
    }
  }
  std::unique_ptr<ExprNode> unary() {
    Deeper d(*this);
    skip_space();
    const std::size_t at = i_;
    for (const char* op : {"-", "!"})
      if (take(op)) {
        auto n = make(ExprNode::kUnary, at, op);
        n->args.push_back(unary());
        return n;
      }
    auto base = primary();
    skip_space();
    const std::size_t pow_at = i_;
    if (take("^")) return binary("^", pow_at, std::move(base), unary());  // right-associative: 2^3^2 = 2^9
    return base;
  }

  std::unique_ptr<ExprNode> primary() {
    skip_space();
    const std::size_t at = i_;
    if (i_ >= s_.size()) refuse(at == 0 ? "the expression is empty" : "the expression ends too early");
    const char c = s_[i_];
    if (c == '(') {
      ++i_;
      auto e = expr();
      if (!take(")")) refuse("')' expected to close the '(' at column " + std::to_string(at + 1));
      return e;
    }
    if (c == '"' || c == '\'') return string_literal();
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') return number();
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      std::size_t end = i_;
      while (end < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[end])) || s_[end] == '_')) ++end;
      std::string word(s_.substr(i_, end - i_));
      i_ = end;
      if (word == "true" || word == "false") {
        auto n = make(ExprNode::kBool, at);
        n->boolean = word == "true";
        return n;
      }
      if (take("(")) return call(std::move(word), at);
      if (std::find(names.begin(), names.end(), word) == names.end()) names.push_back(word);
      return make(ExprNode::kName, at, std::move(word));
    }
    refuse("unexpected '" + std::string(1, c) + "'");
  }

  std::unique_ptr<ExprNode> call(std::string function, std::size_t at) {
    auto n = make(ExprNode::kCall, at, std::move(function));
    if (take(")")) return n;
    do n->args.push_back(expr());
    while (take(","));
    if (!take(")")) refuse("',' or ')' expected in the arguments of " + n->text + "()");
    return n;
  }

  std::unique_ptr<ExprNode> number() {
    const std::size_t at = i_;
    std::size_t end = i_;
    auto digits = [&] {
      while (end < s_.size() && std::isdigit(static_cast<unsigned char>(s_[end]))) ++end;
    };
    digits();
    if (end < s_.size() && s_[end] == '.') ++end, digits();
    if (end < s_.size() && (s_[end] == 'e' || s_[end] == 'E')) {
      std::size_t e = end + 1;
      if (e < s_.size() && (s_[e] == '+' || s_[e] == '-')) ++e;
      if (e < s_.size() && std::isdigit(static_cast<unsigned char>(s_[e]))) end = e, digits();
    }
    auto n = make(ExprNode::kNumber, at);
    const auto [p, ec] = std::from_chars(s_.data() + at, s_.data() + end, n->number);
    if (ec != std::errc() || p != s_.data() + end) refuse("'" + std::string(s_.substr(at, end - at)) + "' is not a number", at);
    if (end < s_.size() && (std::isalpha(static_cast<unsigned char>(s_[end])) || s_[end] == '_'))
      refuse("a number cannot run into a name (write '2 * x', not '2x')", end);
    i_ = end;
    return n;
  }

  std::unique_ptr<ExprNode> string_literal() {
    const std::size_t at = i_;
    const char quote = s_[i_++];
    std::string out;
    while (i_ < s_.size() && s_[i_] != quote) {
      if (s_[i_] == '\\' && i_ + 1 < s_.size() && (s_[i_ + 1] == quote || s_[i_ + 1] == '\\')) ++i_;
      out += s_[i_++];
    }
    if (i_ >= s_.size()) refuse("the string that starts here is not closed", at);
    ++i_;
    return make(ExprNode::kString, at, std::move(out));
  }

  std::string_view s_;
  std::size_t i_ = 0;
  std::size_t depth_ = 0;
};

}  // namespace

Expression::~Expression() = default;

Result<std::shared_ptr<const Expression>> Expression::parse(std::string_view text) {
  if (text.size() > kMaxText)
    return Status::error("the expression is longer than " + std::to_string(kMaxText) + " characters");
  Parser p(text);
  std::shared_ptr<Expression> e(new Expression());
  try {
    e->root_ = p.whole();
  } catch (const Refusal& r) {
    return Status::error("column " + std::to_string(r.column) + ": " + r.message);
  }
  e->text_ = std::string(text);
  e->names_ = std::move(p.names);
  return std::shared_ptr<const Expression>(std::move(e));
}

}  // namespace procex
