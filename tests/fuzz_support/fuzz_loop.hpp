#pragma once
// The in-suite fuzz loop: a target's committed seeds, then deterministic mutations of them, each
// of which must be accepted or fail with one line (an exception other than stride::Error, or a
// message with a line break, fails the test).
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace stride::test {

struct FuzzOutcomes {
  int accepted = 0, errors = 0;
};

// `target(input)` returns "" or the error's message; `mutate(seed, rng)` a mutated input.
template <class Target, class Mutate>
FuzzOutcomes fuzz_seeds_and_mutations(const std::vector<std::string>& seeds, int inputs,
                                      std::uint64_t rng_seed, Target&& target, Mutate&& mutate) {
  std::mt19937_64 rng(rng_seed);
  FuzzOutcomes n;
  for (int i = 0; i < inputs && !seeds.empty(); ++i) {
    const std::string input =
        i < static_cast<int>(seeds.size()) ? seeds[i] : mutate(seeds[rng() % seeds.size()], rng);
    std::string msg;
    EXPECT_NO_THROW(msg = target(input)) << "input " << i;
    if (msg.empty()) {
      ++n.accepted;
      continue;
    }
    ++n.errors;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  }
  return n;
}

}  // namespace stride::test
