// The physics fuzz target in every (sanitized) test run: the committed corpus and deterministic
// mutations of it build and step their worlds, or fail with one stride::Error line; nothing else
// (no other exception, no ODE assertion, no sanitizer report).
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "tests/fuzz_physics/physics_fuzz_target.hpp"
#include "tests/fuzz_support/corpus.hpp"

namespace stride {
namespace {

// Numbers pushed towards what once crashed the process: huge, tiny, negative, zero.
std::string mutate(std::string s, std::mt19937_64& rng) {
  static const char* kTokens[] = {"1e308", "1e-310", "-1",  "0", "1e19", "nan", "0 0 0",
                                  "1e7",   "-0.1",   "1e5", "2", "\"",   "<",   "/>"};
  const int edits = 1 + static_cast<int>(rng() % 3);
  for (int k = 0; k < edits && s.size() > 1; ++k) {
    const std::size_t at = 1 + rng() % (s.size() - 1);
    switch (rng() % 4) {
      case 0: {  // replace the number starting at or after `at`
        const auto b = s.find_first_of("0123456789", at);
        if (b == std::string::npos) break;
        const auto e = s.find_first_not_of("0123456789.e-", b);
        s.replace(b, (e == std::string::npos ? s.size() : e) - b, kTokens[rng() % 8]);
        break;
      }
      case 1:
        s.insert(at, kTokens[rng() % std::size(kTokens)]);
        break;
      case 2:
        s.erase(at, 1 + rng() % 8);
        break;
      case 3:
        s[at] = static_cast<char>(rng() % 256);
        break;
    }
  }
  return s;
}

TEST(PhysicsFuzz, CorpusAndMutationsBuildAndStepOrFailWithOneLine) {
  const auto seeds = test::read_corpus("tests/fuzz_physics/corpus");
  ASSERT_GE(seeds.size(), 8u);
  std::mt19937_64 rng(29);
  int errors = 0, stepped = 0;
  const int inputs = static_cast<int>(seeds.size()) + 120;
  for (int i = 0; i < inputs; ++i) {
    const std::string input =
        i < static_cast<int>(seeds.size()) ? seeds[i] : mutate(seeds[rng() % seeds.size()], rng);
    std::string msg;
    ASSERT_NO_THROW(msg = test::run_physics_fuzz_input(
                        reinterpret_cast<const std::uint8_t*>(input.data()), input.size()))
        << "input " << i;
    if (msg.empty()) {
      ++stepped;
      continue;
    }
    ++errors;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  }
  EXPECT_GT(errors, 20);
  EXPECT_GT(stepped, static_cast<int>(seeds.size()) / 2);
}

}  // namespace
}  // namespace stride
