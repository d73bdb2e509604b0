// Offending input in error messages: quoted whole up to about 80 characters, longer text cut
// around "..." with its length, one line always; and the one number reader's messages.
#include <gtest/gtest.h>

#include <string>

#include "robot/core/error.hpp"
#include "robot/core/number_text.hpp"
#include "robot/core/one_line.hpp"
#include "robot/core/quote.hpp"
#include "robot/core/utf8.hpp"
#include "robot/framework/enum_names.hpp"
#include "robot/framework/reflect.hpp"
#include "tests/error_text.hpp"

namespace stride {
namespace {

using test_support::error_of;

TEST(Quote, ShortTextWhole) {
  EXPECT_EQ(quote("fast"), "'fast'");
  EXPECT_EQ(quote(""), "''");
  EXPECT_EQ(quote(std::string(80, 'x')), "'" + std::string(80, 'x') + "'");
}

TEST(Quote, LongTextKeepsStartAndEndAndSaysHowLong) {
  std::string text = "start" + std::string(500, '-') + "the end";
  const std::string q = quote(text);
  EXPECT_EQ(q, "'start" + std::string(51, '-') + "...---------the end' (512 characters)");
  EXPECT_LE(q.size(), 100u);
}

TEST(Quote, ControlCharactersEscapedSoTheMessageStaysOneLine) {
  EXPECT_EQ(quote("a\nb\tc\x01"), "'a\\nb\\tc\\x01'");
}

TEST(Quote, NeverCutsInsideAUtf8Character) {
  std::string text;
  for (int i = 0; i < 60; ++i) text += "\xc3\xa4";  // a-umlaut, 2 bytes each: 120 bytes
  const std::string q = quote(text);
  // Head of 56 bytes = 28 whole characters, tail of 16 bytes = 8 whole characters.
  std::string expected = "'";
  for (int i = 0; i < 28; ++i) expected += "\xc3\xa4";
  expected += "...";
  for (int i = 0; i < 8; ++i) expected += "\xc3\xa4";
  EXPECT_EQ(q, expected + "' (120 characters)");
}

TEST(Quote, BytesThatAreNotUtf8AreEscapedSoTheMessageIsUtf8) {
  // A lone byte, a cut sequence, an overlong '/', a surrogate, a code point above U+10FFFF.
  EXPECT_EQ(one_line("a\xff"
                     "b\xc3"
                     "c\xc0\xaf"
                     "d\xed\xa0\x80"
                     "e\xf4\x90\x80\x80"),
            "a\\xffb\\xc3c\\xc0\\xafd\\xed\\xa0\\x80e\\xf4\\x90\\x80\\x80");
  EXPECT_EQ(quote("\xc3\xa4\xe2\x82\xac\xf0\x9f\x98\x80"),
            "'\xc3\xa4\xe2\x82\xac\xf0\x9f\x98\x80'");
  EXPECT_EQ(utf8_escaped("ok\n\xfe"), "ok\n\\xfe");  // control characters kept, for texts
}

TEST(Utf8, WellFormedAsRfc3629Says) {
  for (const std::string good :
       {"", "plain", "\xc2\x80", "\xdf\xbf", "\xe0\xa0\x80", "\xed\x9f\xbf", "\xef\xbf\xbf",
        "\xf0\x90\x80\x80", "\xf4\x8f\xbf\xbf"})
    EXPECT_TRUE(valid_utf8(good)) << one_line(good);
  for (const std::string bad :
       {"\x80", "\xc1\xbf", "\xc2", "\xe0\x9f\xbf", "\xed\xa0\x80", "\xf0\x8f\xbf\xbf",
        "\xf4\x90\x80\x80", "\xf5\x80\x80\x80", "\xe2\x82", "a\xff" "b"})
    EXPECT_FALSE(valid_utf8(bad)) << one_line(bad);
  EXPECT_EQ(utf8_char_length("\xe2\x82\xac!", 0), 3u);
  EXPECT_EQ(utf8_char_length("\xe2\x82\xac!", 3), 1u);
  EXPECT_EQ(utf8_char_length("\xe2\x82\xac!", 1), 0u);  // inside a character
  EXPECT_EQ(utf8_char_length("x", 1), 0u);              // past the end
}

TEST(NumberText, OneReaderOneMessage) {
  EXPECT_EQ(parse_number("+2.5", "x"), 2.5);
  EXPECT_EQ(parse_number("-1e-3", "x"), -1e-3);
  EXPECT_EQ(error_of([] { parse_number("2.5s", "--seconds"); }),
            "--seconds: expected a number, got '2.5s'");
  EXPECT_EQ(error_of([] { parse_number("nan", "--seconds"); }),
            "--seconds: expected a number, got 'nan'");
  EXPECT_EQ(error_of([] { parse_number("inf", "x"); }), "x: expected a number, got 'inf'");
  EXPECT_EQ(error_of([] { parse_integer("7", "fps", 1, 5); }), "fps: 7 is outside [1, 5]");
  EXPECT_EQ(parse_unsigned("18446744073709551615", "--seed"), 18446744073709551615ull);
  EXPECT_EQ(error_of([] { parse_unsigned("-1", "--seed"); }),
            "--seed: expected a non-negative integer, got '-1'");
  // A pasted 10 kB value is quoted in under 100 characters.
  const std::string paste(10000, '7');
  const std::string e = error_of([&] { parse_number(paste + "x", "--dt"); });
  EXPECT_LT(e.size(), 130u) << e;
  EXPECT_NE(e.find("(10001 characters)"), std::string::npos) << e;
}

enum class Shade { red, green, blue };

}  // namespace

template <>
struct EnumNames<Shade> {
  static constexpr std::string_view type_name = "Shade";
  static constexpr std::array<std::string_view, 3> names{"red", "green", "blue"};
};

namespace {

TEST(EnumNames, NameAndBackAgain) {
  static_assert(enum_name(Shade::green) == "green");
  EXPECT_EQ(enum_name(static_cast<Shade>(7)), "?");
  EXPECT_EQ(enum_from_name<Shade>("blue"), Shade::blue);
  EXPECT_EQ(enum_from_name<Shade>("Blue"), std::nullopt);
}

}  // namespace
}  // namespace stride
