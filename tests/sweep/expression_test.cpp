// The sweep files' expressions: arithmetic and logic with the usual precedence, texts compared,
// names bound once, and one-line errors that say where the text went wrong.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "console/sweep/expression.hpp"
#include "tests/error_text.hpp"

namespace stride::sweep {
namespace {

using test_support::error_of;

// Names a..d are slots 0..3.
const Expression::Resolver kNames = [](std::string_view n) -> int {
  if (n.size() == 1 && n[0] >= 'a' && n[0] <= 'd') return n[0] - 'a';
  throw Error("unknown name '" + std::string(n) + "'");
};

Cell eval(const std::string& text, std::vector<Cell> slots = {2.0, 3.0, std::string("x"), 0.5}) {
  return Expression(text, kNames).evaluate(slots);
}
double number(const std::string& text) {
  return std::get<double>(eval(text));
}

TEST(Expression, ArithmeticAndPrecedence) {
  EXPECT_EQ(number("1 + 2 * 3"), 7);
  EXPECT_EQ(number("(1 + 2) * 3"), 9);
  EXPECT_EQ(number("a * b - d / 0.25"), 4);
  EXPECT_EQ(number("-a + -(-b)"), 1);
  EXPECT_EQ(number("8 - 4 - 2"), 2);  // left to right
  EXPECT_EQ(number("2e-3 * 1000"), 2);
}

TEST(Expression, ComparisonsLogicAndTexts) {
  EXPECT_EQ(number("a < b and b <= 3"), 1);
  EXPECT_EQ(number("a > b or not (d == 0.5)"), 0);
  EXPECT_EQ(number("c == 'x' and c != 'y'"), 1);
  EXPECT_EQ(number("c == 1"), 0);  // a text is never equal to a number
  EXPECT_EQ(std::get<std::string>(eval("if(a > 1, 'big', 'small')")), "big");
  EXPECT_EQ(number("if(a > 5, c, 7)"), 7);  // the text branch is not taken
}

TEST(Expression, Functions) {
  EXPECT_EQ(number("max(-a, b, 1)"), 3);
  EXPECT_EQ(number("min(a, b)"), 2);
  EXPECT_EQ(number("abs(-d) + sqrt(16) + hypot(3, 4)"), 9.5);
  EXPECT_EQ(number("isnan(nan) + isnan(1)"), 1);
  EXPECT_TRUE(std::isinf(number("inf")));
}

TEST(Expression, ReadsEachSlotOnceAndSaysWhetherItGivesText) {
  const Expression e("a + a * b", kNames);
  EXPECT_EQ(e.slots(), (std::vector<int>{0, 1}));
  const auto text_slot = [](int s) { return s == 2; };
  EXPECT_FALSE(e.yields_text(text_slot));
  EXPECT_TRUE(Expression("c", kNames).yields_text(text_slot));
  EXPECT_TRUE(Expression("if(a, 'y', 'n')", kNames).yields_text(text_slot));
}

TEST(Expression, ErrorsNameTheTextAndColumn) {
  const auto error = [](const std::string& text) {
    return error_of([&] { Expression(text, kNames); });
  };
  EXPECT_EQ(error("a +"), "expression 'a +': expected a value at column 4");
  EXPECT_EQ(error("a b"), "expression 'a b': unexpected 'b' at column 3");
  EXPECT_EQ(error("(a"), "expression '(a': expected ')' at column 3");
  EXPECT_EQ(error("zz * 2"), "expression 'zz * 2': unknown name 'zz'");
  EXPECT_EQ(error("'abc"), "expression ''abc': unterminated text at column 1");
  EXPECT_EQ(error("foo(a)"),
            "expression 'foo(a)': unknown function 'foo' (abs, min, max, sqrt, hypot, isnan, if) "
            "at column 4");
  EXPECT_EQ(error("hypot(a)"), "expression 'hypot(a)': hypot() takes 2 argument(s) at column 9");
  EXPECT_EQ(error_of([] { eval("c + 1"); }),
            "expression 'c + 1': expected a number, got the text 'x'");
}

}  // namespace
}  // namespace stride::sweep
