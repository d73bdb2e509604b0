// The sweep-file parser, the --resume CSV reader and the worker-row decoder under hostile input,
// in every (sanitized) test run: the committed corpus plus deterministic mutations of it must be
// accepted or fail with one stride::Error line.
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/fuzz_support/corpus.hpp"
#include "tests/fuzz_support/mutation.hpp"
#include "tests/fuzz_sweep/sweep_fuzz_target.hpp"

namespace stride {
namespace {

std::string mutate(const std::string& s, std::mt19937_64& rng) {
  static const char* const kTokens[] = {"<",  ">",     "/>",        "\"",      "=", "nan",
                                        "-1", "1e308", "{",         "}",       "(", "'",
                                        ":",  ",",     "walk_end+", "<factor", "\0"};
  return test::mutate(s, rng, kTokens, 1);  // the selector byte stays
}

TEST(SweepFuzz, CorpusAndMutationsAreAcceptedOrFailWithOneLine) {
  const auto seeds = test::read_corpus("tests/fuzz_sweep/corpus");
  ASSERT_GE(seeds.size(), 3u);
  std::mt19937_64 rng(11);
  int errors = 0, accepted = 0;
  for (int i = 0; i < 3000; ++i) {
    const std::string input =
        i < static_cast<int>(seeds.size()) ? seeds[i] : mutate(seeds[rng() % seeds.size()], rng);
    std::string msg;
    ASSERT_NO_THROW(msg = test::sweep_fuzz_input(
                        reinterpret_cast<const std::uint8_t*>(input.data()), input.size()))
        << "input " << i;
    if (msg.empty()) {
      ++accepted;
      continue;
    }
    ++errors;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  }
  EXPECT_GT(errors, 100);
  EXPECT_GT(accepted, 3);
}

}  // namespace
}  // namespace stride
