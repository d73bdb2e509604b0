// The console execution fuzz target in every (sanitized) test run: the committed corpus and
// deterministic mutations of it run against the controlled NAO; every statement either works or
// is refused with a stride::Error, nothing else escapes.
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "tests/fuzz_console/console_exec_fuzz_target.hpp"
#include "tests/fuzz_support/corpus.hpp"

namespace stride {
namespace {

// Lines of two seeds spliced, words swapped in, numbers made absurd.
std::string mutate(const std::vector<std::string>& seeds, std::mt19937_64& rng) {
  static const char* kWords[] = {
      "1e308", "-1e308", "nan", "inf", "0", "-0", "1e-320",          "99999",
      "torso", "\"",     ";",   "#",   "?", "on", "representation:", "module:Stand"};
  std::string s = seeds[rng() % seeds.size()];
  const std::string& other = seeds[rng() % seeds.size()];
  const auto cut = other.find('\n', rng() % std::max<std::size_t>(1, other.size()));
  if (cut != std::string::npos) s += other.substr(cut + 1);
  for (int k = 0, n = 1 + static_cast<int>(rng() % 4); k < n && !s.empty(); ++k) {
    const std::size_t at = rng() % s.size();
    const auto word_end = s.find_first_of(" \n;", at);
    const std::size_t len = (word_end == std::string::npos ? s.size() : word_end) - at;
    s.replace(at, rng() % 2 ? len : 0, kWords[rng() % std::size(kWords)]);
  }
  return s;
}

TEST(ConsoleExecFuzz, CorpusAndMutationsRunOrAreRefused) {
  const auto seeds = test::read_corpus("tests/fuzz_console/corpus");
  ASSERT_GE(seeds.size(), 10u);
  std::mt19937_64 rng(29);
  int refused = 0;
  const int inputs = static_cast<int>(seeds.size()) + 40;
  for (int i = 0; i < inputs; ++i) {
    const std::string input = i < static_cast<int>(seeds.size()) ? seeds[i] : mutate(seeds, rng);
    ASSERT_NO_THROW(refused += test::run_console_fuzz_input(
                        reinterpret_cast<const std::uint8_t*>(input.data()), input.size()))
        << "input " << i << ":\n"
        << input;
  }
  EXPECT_GT(refused, 20);  // the mutations do reach the checks
}

}  // namespace
}  // namespace stride
