#pragma once
// Deterministic mutations of a fuzz target's seed inputs for the in-suite fuzz tests: bytes
// changed, cut out, or tokens of the format put in.
#include <cstddef>
#include <random>
#include <span>
#include <string>

namespace stride::test {

// One to four edits of `s` after its first `keep` bytes (a selector byte stays as it is).
inline std::string mutate(std::string s, std::mt19937_64& rng, std::span<const char* const> tokens,
                          std::size_t keep = 0) {
  const int edits = 1 + static_cast<int>(rng() % 4);
  for (int k = 0; k < edits && s.size() > keep; ++k) {
    const std::size_t at = keep + rng() % (s.size() - keep);
    switch (rng() % 4) {
      case 0:
        s[at] = static_cast<char>(rng() % 256);
        break;
      case 1:
        s.erase(at, 1 + rng() % 16);
        break;
      case 2:
        s.insert(at, tokens[rng() % tokens.size()]);
        break;
      case 3:
        s.resize(at);
        break;
    }
  }
  return s;
}

}  // namespace stride::test
