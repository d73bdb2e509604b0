// The view's message decoder under hostile input, in every (sanitized) test run: the committed
// corpus (every op, wrong types, deep nesting, bad UTF-8) plus deterministic mutations of it must
// decode or fail with one "ws message: ..." line.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "tests/fuzz_support/corpus.hpp"
#include "tests/fuzz_support/mutation.hpp"
#include "tests/fuzz_view/view_fuzz_target.hpp"

namespace stride {
namespace {

TEST(ViewMessageFuzz, CorpusAndMutationsDecodeOrFailWithOneLine) {
  const auto seeds = test::read_corpus("tests/fuzz_view/corpus");
  ASSERT_GE(seeds.size(), 20u);
  static const char* const kTokens[] = {"{",     "[",    "\"",      "\\u0000", "\xff",
                                        "1e999", "null", "\"op\":", "\"cmd\"", ","};
  std::mt19937_64 rng(5);
  std::size_t decoded = 0, refused = 0;
  for (int i = 0; i < 20000; ++i) {
    const std::string input = i < static_cast<int>(seeds.size())
                                  ? seeds[i]
                                  : test::mutate(seeds[rng() % seeds.size()], rng, kTokens);
    std::string error;
    ASSERT_NO_THROW(error = test::fuzz_view_input(
                        reinterpret_cast<const std::uint8_t*>(input.data()), input.size()))
        << "input " << i;
    if (error.empty()) {
      ++decoded;
      continue;
    }
    ++refused;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    EXPECT_TRUE(error.starts_with("ws message: ")) << error;
  }
  EXPECT_GT(decoded, 5u);
  EXPECT_GT(refused, 10000u);
}

TEST(ViewMessage, DecodesEveryOpAndNamesWhatIsWrong) {
  using view::decode_view_message;
  const auto cmd = std::get<view::CmdRequest>(
      decode_view_message(R"({"op":"cmd","id":7,"line":"set module:PatternWalk T_stride=0.5"})"));
  EXPECT_EQ(cmd.id, 7);
  EXPECT_EQ(cmd.line, "set module:PatternWalk T_stride=0.5");
  const auto w = std::get<view::WatchRequest>(
      decode_view_message(R"({"op":"watch","keys":["a","representation:X.y"]})"));
  EXPECT_EQ(w.keys, (std::vector<std::string>{"a", "representation:X.y"}));
  EXPECT_TRUE(std::holds_alternative<view::TreeRequest>(decode_view_message(R"({"op":"tree"})")));
  const auto g =
      std::get<view::GetRequest>(decode_view_message(R"({"op":"get","id":3,"key":"k"})"));
  EXPECT_EQ(g.id, 3);
  EXPECT_EQ(g.key, "k");
  const std::string hex64(64, 'a');
  const auto a = std::get<view::AuthRequest>(decode_view_message(
      R"({"op":"auth","nonce":")" + hex64 + R"(","proof":")" + hex64 + R"("})"));
  EXPECT_EQ(a.proof, hex64);
  const auto error = [](const std::string& text) {
    try {
      decode_view_message(text);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("decoded");
  };
  EXPECT_EQ(error("nope"), "ws message: not JSON (expected one object)");
  EXPECT_EQ(error("[1]"), "ws message: expected a JSON object");
  EXPECT_EQ(error(R"({"op":"cmd","line":"x"})"), "ws message: expected \"id\"");
  EXPECT_EQ(error(R"({"op":"cmd","id":"1","line":"x"})"),
            "ws message: \"id\" should be an integer");
  EXPECT_EQ(error(R"({"op":"cmd","id":1,"line":"a\nb"})"),
            "ws message: \"line\" holds a control character");
  EXPECT_TRUE(std::get<view::TimesRequest>(decode_view_message(R"({"op":"times","on":true})")).on);
  EXPECT_FALSE(
      std::get<view::TimesRequest>(decode_view_message(R"({"op":"times","on":false})")).on);
  EXPECT_EQ(error(R"({"op":"times","on":1})"), "ws message: \"on\" should be true or false");
  EXPECT_EQ(error(R"({"op":"times"})"), "ws message: \"on\" should be true or false");
  EXPECT_EQ(error(R"({"op":"fly"})"),
            "ws message: unknown op \"fly\" (expected cmd, watch, tree, get, times, auth)");
  EXPECT_EQ(error(std::string(20, '[') + std::string(20, ']')),
            "ws message: nested deeper than 16");
  std::string many = R"({"op":"watch","keys":[)";
  for (int i = 0; i < 65; ++i) many += std::string(i ? "," : "") + "\"k\"";
  EXPECT_EQ(error(many + "]}"), "ws message: more than 64 keys");
}

}  // namespace
}  // namespace stride
