// expression.cc -- typing and evaluating a parsed expression. The functions
// and their signatures live in one table so the checker and the evaluator
// cannot disagree.
#include "graph/expression.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>

#include "graph/expression_tree.h"
#include "graph/hash.h"

namespace procex {

const char* to_string(ExprType t) {
  switch (t) {
    case ExprType::kNumber: return "number";
    case ExprType::kBool: return "bool";
    case ExprType::kString: return "string";
  }
  return "?";
}

ExprType type_of(const ExprValue& v) { return static_cast<ExprType>(v.index()); }

namespace {

struct Failure {
  std::size_t column;
  std::string message;
};

[[noreturn]] void fail(const ExprNode& n, std::string message) { throw Failure{n.column, std::move(message)}; }

// Functions of numbers to a number, and how many arguments they take.
struct NumberFunction {
  const char* name;
  std::size_t min_args, max_args;  // max 0: any number
};
constexpr NumberFunction kNumberFunctions[] = {
    {"min", 2, 0}, {"max", 2, 0}, {"clamp", 3, 3}, {"floor", 1, 1}, {"ceil", 1, 1}, {"round", 1, 1},
    {"abs", 1, 1}, {"sqrt", 1, 1}, {"sin", 1, 1},  {"cos", 1, 1},   {"tan", 1, 1},  {"pow", 2, 2},
};

const NumberFunction* number_function(const std::string& name) {
  for (const NumberFunction& f : kNumberFunctions)
    if (name == f.name) return &f;
  return nullptr;
}

std::string function_list() {
  std::string out;
  for (const NumberFunction& f : kNumberFunctions) out += std::string(f.name) + ", ";
  return out + "if, rand, attr";
}

class Checker {
 public:
  explicit Checker(const Expression::NameTypes& names) : names_(names) {}

  ExprType type(const ExprNode& n) const {
    switch (n.kind) {
      case ExprNode::kNumber: return ExprType::kNumber;
      case ExprNode::kBool: return ExprType::kBool;
      case ExprNode::kString: return ExprType::kString;
      case ExprNode::kName: {
        if (auto t = names_(n.text)) return *t;
        fail(n, "unknown name '" + n.text + "' (names are the graph's inputs and exposed parameters)");
      }
      case ExprNode::kUnary: return want(*n.args[0], n.text == "-" ? ExprType::kNumber : ExprType::kBool, n.text);
      case ExprNode::kBinary: return binary(n);
      case ExprNode::kCall: return call(n);
    }
    fail(n, "unknown expression");
  }

 private:
  ExprType want(const ExprNode& n, ExprType t, const std::string& what) const {
    const ExprType got = type(n);
    if (got != t) fail(n, "'" + what + "' takes a " + to_string(t) + " here, not a " + to_string(got));
    return t;
  }

  ExprType binary(const ExprNode& n) const {
    const std::string& op = n.text;
    const ExprType a = type(*n.args[0]), b = type(*n.args[1]);
    if (op == "&&" || op == "||") {
      want(*n.args[0], ExprType::kBool, op);
      want(*n.args[1], ExprType::kBool, op);
      return ExprType::kBool;
    }
    if (op == "==" || op == "!=") {
      if (a != b) fail(n, "'" + op + "' compares a " + to_string(a) + " with a " + to_string(b));
      return ExprType::kBool;
    }
    if (op == "+" && a == ExprType::kString && b == ExprType::kString) return ExprType::kString;
    want(*n.args[0], ExprType::kNumber, op);
    want(*n.args[1], ExprType::kNumber, op);
    const bool ordering = op == "<" || op == "<=" || op == ">" || op == ">=";
    return ordering ? ExprType::kBool : ExprType::kNumber;
  }

  void arity(const ExprNode& n, std::size_t min, std::size_t max) const {
    const std::size_t k = n.args.size();
    if (k < min || (max && k > max)) {
      const std::string count = min == max ? std::to_string(min) : max ? std::to_string(min) + " to " + std::to_string(max)
                                                                      : "at least " + std::to_string(min);
      fail(n, n.text + "() takes " + count + " argument" + (min == 1 && max == 1 ? "" : "s") + ", not " + std::to_string(k));
    }
  }

  ExprType call(const ExprNode& n) const {
    if (const NumberFunction* f = number_function(n.text)) {
      arity(n, f->min_args, f->max_args);
      for (const auto& a : n.args) want(*a, ExprType::kNumber, n.text + "()");
      return ExprType::kNumber;
    }
    if (n.text == "if") {
      arity(n, 3, 3);
      want(*n.args[0], ExprType::kBool, "if()");
      const ExprType a = type(*n.args[1]), b = type(*n.args[2]);
      if (a != b) fail(*n.args[2], "if() gives a " + std::string(to_string(a)) + " one way and a " + to_string(b) + " the other");
      return a;
    }
    if (n.text == "rand") {
      arity(n, 1, 0);
      for (const auto& a : n.args) type(*a);
      return ExprType::kNumber;
    }
    if (n.text == "attr") {
      arity(n, 2, 2);
      if (n.args[0]->kind != ExprNode::kString)
        fail(*n.args[0], "attr() takes the attribute's name as a quoted string, e.g. attr(\"building:levels\", 2)");
      return type(*n.args[1]);
    }
    fail(n, "unknown function '" + n.text + "' (functions: " + function_list() + ")");
  }

  const Expression::NameTypes& names_;
};

// An attribute's text as a value of type t; nullopt if it does not read as one.
std::optional<ExprValue> attribute_as(const std::string& text, ExprType t) {
  std::string_view s = text;
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  switch (t) {
    case ExprType::kString: return ExprValue(text);
    case ExprType::kNumber: {
      double v = 0;
      const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
      if (ec != std::errc() || p != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
      return ExprValue(v);
    }
    case ExprType::kBool:
      if (s == "true" || s == "yes" || s == "1") return ExprValue(true);
      if (s == "false" || s == "no" || s == "0") return ExprValue(false);
      return std::nullopt;
  }
  return std::nullopt;
}

class Evaluator {
 public:
  explicit Evaluator(const Expression::Env& env) : env_(env) {}

  ExprValue value(const ExprNode& n) const {
    switch (n.kind) {
      case ExprNode::kNumber: return n.number;
      case ExprNode::kBool: return n.boolean;
      case ExprNode::kString: return n.text;
      case ExprNode::kName:
        try {
          return env_.name(n.text);
        } catch (const ExprError& e) {
          fail(n, e.what());
        }
      case ExprNode::kUnary:
        if (n.text == "-") return -number(*n.args[0]);
        return !boolean(*n.args[0]);
      case ExprNode::kBinary: return binary(n);
      case ExprNode::kCall: return call(n);
    }
    fail(n, "unknown expression");
  }

 private:
  double number(const ExprNode& n) const { return std::get<double>(value(n)); }
  bool boolean(const ExprNode& n) const { return std::get<bool>(value(n)); }

  static double finite(const ExprNode& n, double v, const char* why) {
    if (!std::isfinite(v)) fail(n, why);
    return v;
  }

  ExprValue binary(const ExprNode& n) const {
    const std::string& op = n.text;
    const ExprNode &l = *n.args[0], &r = *n.args[1];
    if (op == "&&") return boolean(l) && boolean(r);
    if (op == "||") return boolean(l) || boolean(r);
    if (op == "==") return value(l) == value(r);
    if (op == "!=") return value(l) != value(r);
    ExprValue a = value(l);
    if (op == "+" && std::holds_alternative<std::string>(a)) return std::get<std::string>(a) + std::get<std::string>(value(r));
    const double x = std::get<double>(a), y = number(r);
    if (op == "<") return x < y;
    if (op == "<=") return x <= y;
    if (op == ">") return x > y;
    if (op == ">=") return x >= y;
    if (op == "+") return finite(n, x + y, "the sum is too large");
    if (op == "-") return finite(n, x - y, "the difference is too large");
    if (op == "*") return finite(n, x * y, "the product is too large");
    if (op == "/") return finite(n, y == 0 ? HUGE_VAL : x / y, "division by zero");
    if (op == "%") return finite(n, y == 0 ? HUGE_VAL : std::fmod(x, y), "remainder of a division by zero");
    return finite(n, std::pow(x, y), "the power is not a finite number");
  }

  ExprValue call(const ExprNode& n) const {
    const std::string& f = n.text;
    if (f == "if") return boolean(*n.args[0]) ? value(*n.args[1]) : value(*n.args[2]);
    if (f == "attr") {
      const std::string& key = n.args[0]->text;
      const std::string* text = env_.attribute ? env_.attribute(key) : nullptr;
      ExprValue fallback = value(*n.args[1]);
      if (!text) return fallback;
      if (auto v = attribute_as(*text, type_of(fallback))) return *v;
      if (env_.warn)
        env_.warn("column " + std::to_string(n.column) + ": attribute '" + key + "' is '" + *text + "', not a " +
                  to_string(type_of(fallback)) + "; its default is used");
      return fallback;
    }
    if (f == "rand") {  // the same arguments give the same number in [0, 1), on every machine
      Hasher h;
      h.str("rand");
      for (const auto& a : n.args) {
        const ExprValue v = value(*a);
        h.u64(v.index());
        if (auto* d = std::get_if<double>(&v)) h.f64(*d);
        else if (auto* b = std::get_if<bool>(&v)) h.boolean(*b);
        else h.str(std::get<std::string>(v));
      }
      return static_cast<double>(h.result().lo >> 11) * 0x1.0p-53;
    }
    std::vector<double> x;
    for (const auto& a : n.args) x.push_back(number(*a));
    constexpr double kDeg = std::numbers::pi / 180.0;
    if (f == "min") return *std::min_element(x.begin(), x.end());
    if (f == "max") return *std::max_element(x.begin(), x.end());
    if (f == "clamp") {
      if (x[1] > x[2]) fail(n, "clamp(x, low, high) with low above high");
      return std::clamp(x[0], x[1], x[2]);
    }
    if (f == "floor") return std::floor(x[0]);
    if (f == "ceil") return std::ceil(x[0]);
    if (f == "round") return std::round(x[0]);
    if (f == "abs") return std::abs(x[0]);
    if (f == "sqrt") {
      if (x[0] < 0) fail(n, "square root of a negative number");
      return std::sqrt(x[0]);
    }
    if (f == "sin") return std::sin(x[0] * kDeg);
    if (f == "cos") return std::cos(x[0] * kDeg);
    if (f == "tan") return finite(n, std::tan(x[0] * kDeg), "tan() of a right angle");
    return finite(n, std::pow(x[0], x[1]), "pow() is not a finite number");
  }

  const Expression::Env& env_;
};

}  // namespace

Result<ExprType> Expression::check(const NameTypes& type_of) const {
  try {
    return Checker(type_of).type(*root_);
  } catch (const Failure& f) {
    return Status::error("column " + std::to_string(f.column) + ": " + f.message);
  }
}

ExprValue Expression::evaluate(const Env& env) const {
  try {
    return Evaluator(env).value(*root_);
  } catch (const Failure& f) {
    throw ExprError("column " + std::to_string(f.column) + ": " + f.message);
  }
}

}  // namespace procex
