#include "graph/expression_value.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>

namespace procex {

std::optional<ExprType> expression_type(const ValueType& t) {
  if (&t == &value_type<double>() || &t == &value_type<std::int64_t>()) return ExprType::kNumber;
  if (&t == &value_type<bool>()) return ExprType::kBool;
  if (&t == &value_type<std::string>() || &t == &value_type<EnumValue>()) return ExprType::kString;
  return std::nullopt;
}

ExprValue to_expr_value(const Value& v) {
  if (v.is<double>()) return v.get<double>();
  if (v.is<std::int64_t>()) return static_cast<double>(v.get<std::int64_t>());
  if (v.is<bool>()) return v.get<bool>();
  if (v.is<EnumValue>()) return v.get<EnumValue>().choice;
  return v.get<std::string>();
}

Result<Value> from_expr_value(const ExprValue& v, const ValueType& t) {
  if (&t == &value_type<double>()) return Value::make(std::get<double>(v));
  if (&t == &value_type<std::int64_t>()) {
    const double d = std::get<double>(v);
    if (d != std::floor(d) || std::abs(d) > 9.0e15)
      return Status::error("the expression gives " + std::to_string(d) + ", not a whole number (use round())");
    return Value::make(static_cast<std::int64_t>(d));
  }
  if (&t == &value_type<bool>()) return Value::make(std::get<bool>(v));
  if (&t == &value_type<EnumValue>()) return Value::make(EnumValue{std::get<std::string>(v)});
  return Value::make(std::get<std::string>(v));
}

std::string expression_literal(const ExprValue& v) {
  if (const double* d = std::get_if<double>(&v)) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, *d);  // shortest text that reads back the same
    return std::string(buf, r.ptr);
  }
  if (const bool* b = std::get_if<bool>(&v)) return *b ? "true" : "false";
  std::string text = "\"";
  for (const char c : std::get<std::string>(v)) {
    if (c == '"' || c == '\\') text += '\\';
    text += c;
  }
  return text + "\"";
}

}  // namespace procex
