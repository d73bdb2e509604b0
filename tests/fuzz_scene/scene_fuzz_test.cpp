// The scene and URDF parsers under hostile input, in every (sanitized) test run: the committed
// corpus plus deterministic mutations of it must parse or fail with one stride::Error line.
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/fuzz_scene/scene_fuzz_target.hpp"
#include "tests/fuzz_support/corpus.hpp"
#include "tests/fuzz_support/mutation.hpp"

namespace stride {
namespace {

std::string mutate(const std::string& s, std::mt19937_64& rng) {
  static const char* const kTokens[] = {
      "<",     ">",   "/>", "\"", "=", "nan", "-1", "1e308", "<robot", "<include file=\"x.xml\"/>",
      "&amp;", "deg", "mm", " ",  "\0"};
  return test::mutate(s, rng, kTokens);
}

TEST(SceneFuzz, CorpusAndMutationsParseOrFailWithOneLine) {
  const auto seeds = test::read_corpus("tests/fuzz_scene/corpus");
  ASSERT_GE(seeds.size(), 4u);
  std::mt19937_64 rng(7);
  int errors = 0, parsed = 0;
  for (int i = 0; i < 3000; ++i) {
    const std::string input =
        i < static_cast<int>(seeds.size()) ? seeds[i] : mutate(seeds[rng() % seeds.size()], rng);
    std::string msg;
    ASSERT_NO_THROW(msg = test::parse_fuzz_input(
                        reinterpret_cast<const std::uint8_t*>(input.data()), input.size()))
        << "input " << i;
    if (msg.empty()) {
      ++parsed;
      continue;
    }
    ++errors;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    const bool setting = msg.rfind("physics setting", 0) == 0;  // names the setting instead
    EXPECT_TRUE(setting || msg.find("fuzz.") != std::string::npos) << "names the file: " << msg;
  }
  EXPECT_GT(errors, 100);
  EXPECT_GT(parsed, 4);
}

}  // namespace
}  // namespace stride
