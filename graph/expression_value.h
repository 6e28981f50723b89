// expression_value.h -- between parameter Values and expression values: which
// parameter types an expression can fill, and the conversions both ways.
#pragma once

#include <optional>
#include <string>

#include "graph/expression.h"
#include "graph/value.h"

namespace procex {

// float and int: number; bool; string and enum: string. Others: nullopt.
std::optional<ExprType> expression_type(const ValueType& t);

// A Value of one of those types as an expression value.
ExprValue to_expr_value(const Value& v);

// An expression's result as a Value of type t: an int must be a whole number,
// an enum takes the choice's name. The refusal says why.
Result<Value> from_expr_value(const ExprValue& v, const ValueType& t);

// The expression text that gives `v`: `4.5`, `true`, `"gable"` (quotes and
// backslashes escaped), so an editor can turn a value into an expression to edit.
std::string expression_literal(const ExprValue& v);

}  // namespace procex
