// The expression grammar of docs/expressions.md: values, precedence, every
// function, and refusals that name the column.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "graph/expression.h"

namespace procex {
namespace {

// Evaluates `text` with no names; attributes from `attrs`.
ExprValue eval(const std::string& text, const std::map<std::string, std::string, std::less<>>& attrs = {},
               std::vector<std::string>* warnings = nullptr) {
  auto e = Expression::parse(text);
  EXPECT_TRUE(e) << text << ": " << e.message();
  auto type = (*e)->check([](std::string_view) { return std::optional<ExprType>(); });
  EXPECT_TRUE(type) << text << ": " << type.message();
  Expression::Env env;
  env.attribute = [&](std::string_view k) -> const std::string* {
    auto it = attrs.find(k);
    return it == attrs.end() ? nullptr : &it->second;
  };
  env.warn = [&](std::string m) {
    if (warnings) warnings->push_back(std::move(m));
  };
  const ExprValue v = (*e)->evaluate(env);
  EXPECT_EQ(type_of(v), *type) << text;
  return v;
}

double number(const std::string& text) { return std::get<double>(eval(text)); }

// The refusal of parse or check, with `x` a number and `on` a bool.
std::string refusal(const std::string& text) {
  auto e = Expression::parse(text);
  if (!e) return e.message();
  auto type = (*e)->check([](std::string_view n) -> std::optional<ExprType> {
    if (n == "x") return ExprType::kNumber;
    if (n == "on") return ExprType::kBool;
    return std::nullopt;
  });
  return type ? std::string("accepted as ") + to_string(*type) : type.message();
}

TEST(Expression, ArithmeticFollowsTheUsualPrecedence) {
  EXPECT_DOUBLE_EQ(number("1 + 2 * 3"), 7);
  EXPECT_DOUBLE_EQ(number("(1 + 2) * 3"), 9);
  EXPECT_DOUBLE_EQ(number("10 - 4 - 3"), 3);   // left to right
  EXPECT_DOUBLE_EQ(number("2 ^ 3 ^ 2"), 512);  // right to left
  EXPECT_DOUBLE_EQ(number("-2 ^ 2"), -4);
  EXPECT_DOUBLE_EQ(number("7 % 4 + 1 / 4"), 3.25);
  EXPECT_DOUBLE_EQ(number("--3"), 3);
  EXPECT_DOUBLE_EQ(number("1e3 + .5 + 2.5E-1"), 1000.75);
}

TEST(Expression, FunctionsTakeDegreesAndRoundHalfAwayFromZero) {
  EXPECT_DOUBLE_EQ(number("min(3, 1, 2) + max(4, 9)"), 10);
  EXPECT_DOUBLE_EQ(number("clamp(5, 0, 3) + clamp(-1, 0, 3)"), 3);
  EXPECT_DOUBLE_EQ(number("floor(2.7) + ceil(2.1) + round(2.5) + round(-2.5)"), 5);
  EXPECT_DOUBLE_EQ(number("abs(-3) + sqrt(16)"), 7);
  EXPECT_NEAR(number("sin(90) + cos(60) + tan(45)"), 2.5, 1e-12);
  EXPECT_DOUBLE_EQ(number("pow(2, 10)"), 1024);
  EXPECT_DOUBLE_EQ(number("if(2 > 1, 10, 20) + if(false, 1, 2)"), 12);
}

TEST(Expression, ComparisonsLogicAndStrings) {
  EXPECT_EQ(eval("1 < 2 && 3 >= 3"), ExprValue(true));
  EXPECT_EQ(eval("!(1 == 1) || 2 != 2"), ExprValue(false));
  EXPECT_EQ(eval("'ab' + \"c\""), ExprValue(std::string("abc")));
  EXPECT_EQ(eval("'a\\'b' == \"a'b\""), ExprValue(true));
  EXPECT_EQ(eval("if(1 <= 0, 'flat', 'hip')"), ExprValue(std::string("hip")));
}

TEST(Expression, RandIsDeterministicAndInTheUnitInterval) {
  const double a = number("rand(7)");
  EXPECT_EQ(a, number("rand(7)"));
  EXPECT_NE(a, number("rand(8)"));
  EXPECT_NE(number("rand(7, 'w1')"), number("rand(7, 'w2')"));
  double sum = 0;
  for (int i = 0; i < 1000; ++i) {
    const double r = number("rand(" + std::to_string(i) + ", 'facade')");
    ASSERT_GE(r, 0.0);
    ASSERT_LT(r, 1.0);
    sum += r;
  }
  EXPECT_NEAR(sum / 1000, 0.5, 0.05);
}

TEST(Expression, AttrReadsAFeaturesAttributeOrItsDefault) {
  const std::map<std::string, std::string, std::less<>> attrs = {
      {"building:levels", "5"}, {"roof:shape", "gabled"}, {"junk", "3;4"}, {"flag", "yes"}};
  EXPECT_EQ(eval("attr('building:levels', 2) * 3", attrs), ExprValue(15.0));
  EXPECT_EQ(eval("attr('height', 9)", attrs), ExprValue(9.0));
  EXPECT_EQ(eval("attr('roof:shape', 'flat')", attrs), ExprValue(std::string("gabled")));
  EXPECT_EQ(eval("attr('flag', false)", attrs), ExprValue(true));
  std::vector<std::string> warnings;
  EXPECT_EQ(eval("attr('junk', 2)", attrs, &warnings), ExprValue(2.0));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], "column 1: attribute 'junk' is '3;4', not a number; its default is used");
}

TEST(Expression, SyntaxErrorsNameTheColumn) {
  EXPECT_EQ(refusal(""), "column 1: the expression is empty");
  EXPECT_EQ(refusal("1 +"), "column 4: the expression ends too early");
  EXPECT_EQ(refusal("x = 2"), "column 3: unexpected '=' (compare with '==')");
  EXPECT_EQ(refusal("(1 + 2"), "column 7: ')' expected to close the '(' at column 1");
  EXPECT_EQ(refusal("min(1 2)"), "column 7: ',' or ')' expected in the arguments of min()");
  EXPECT_EQ(refusal("1 < x < 3"), "column 7: comparisons do not chain; join them with '&&'");
  EXPECT_EQ(refusal("3 * 'abc"), "column 5: the string that starts here is not closed");
  EXPECT_EQ(refusal("2x"), "column 2: a number cannot run into a name (write '2 * x', not '2x')");
  EXPECT_EQ(refusal("x # 2"), "column 3: unexpected '#' (an operator or the end was expected)");
  EXPECT_EQ(refusal(std::string(100, '(') + "1" + std::string(100, ')')), "column 65: nested more than 64 deep");
  EXPECT_EQ(refusal(std::string(5000, '1')), "the expression is longer than 4096 characters");
}

TEST(Expression, TypeErrorsNameTheColumn) {
  EXPECT_EQ(refusal("x + 1"), "accepted as number");
  EXPECT_EQ(refusal("on && x > 2"), "accepted as bool");
  EXPECT_EQ(refusal("width * 2"), "column 1: unknown name 'width' (names are the graph's inputs and exposed parameters)");
  EXPECT_EQ(refusal("x + on"), "column 5: '+' takes a number here, not a bool");
  EXPECT_EQ(refusal("if(x, 1, 2)"), "column 4: 'if()' takes a bool here, not a number");
  EXPECT_EQ(refusal("if(on, 1, 'a')"), "column 11: if() gives a number one way and a string the other");
  EXPECT_EQ(refusal("x == 'a'"), "column 3: '==' compares a number with a string");
  EXPECT_EQ(refusal("sqrt(1, 2)"), "column 1: sqrt() takes 1 argument, not 2");
  EXPECT_EQ(refusal("min(1)"), "column 1: min() takes at least 2 arguments, not 1");
  EXPECT_EQ(refusal("attr(x, 2)"), "column 6: attr() takes the attribute's name as a quoted string, e.g. attr(\"building:levels\", 2)");
  EXPECT_EQ(refusal("lerp(1, 2, 3)"), "column 1: unknown function 'lerp' (functions: min, max, clamp, floor, ceil, round, "
                                      "abs, sqrt, sin, cos, tan, pow, if, rand, attr)");
}

TEST(Expression, EvaluationErrorsNameTheColumn) {
  auto failure = [](const std::string& text) {
    auto e = Expression::parse(text);
    EXPECT_TRUE(e);
    try {
      (*e)->evaluate({});
    } catch (const ExprError& err) {
      return std::string(err.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(failure("1 + 1 / (2 - 2)"), "column 7: division by zero");
  EXPECT_EQ(failure("sqrt(1 - 2)"), "column 1: square root of a negative number");
  EXPECT_EQ(failure("clamp(1, 3, 2)"), "column 1: clamp(x, low, high) with low above high");
  EXPECT_EQ(failure("10 ^ 400"), "column 4: the power is not a finite number");
}

TEST(Expression, NamesAreListedOnceInOrderOfUse) {
  auto e = Expression::parse("b + a * b + min(c, a)");
  ASSERT_TRUE(e);
  EXPECT_EQ((*e)->names(), (std::vector<std::string>{"b", "a", "c"}));
}

}  // namespace
}  // namespace procex
