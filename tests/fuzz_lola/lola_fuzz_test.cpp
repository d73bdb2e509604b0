// LoLA's packet decoders under hostile input, in every (sanitized) test run: the committed corpus
// plus deterministic mutations of it must decode or fail with one stride::Error line.
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "tests/fuzz_lola/lola_fuzz_target.hpp"
#include "tests/fuzz_support/corpus.hpp"

namespace stride {
namespace {

// Byte flips, msgpack type tags dropped in, cuts and repeats: what a broken peer sends.
std::string mutate(std::string s, std::mt19937_64& rng) {
  static const unsigned char kTags[] = {0xc0, 0xc2, 0xca, 0xcb, 0xcc, 0xd0, 0xd9, 0xdc,
                                        0xdd, 0xde, 0xdf, 0x80, 0x90, 0xa0, 0xff, 0x7f};
  const int edits = 1 + static_cast<int>(rng() % 4);
  for (int k = 0; k < edits && s.size() > 1; ++k) {
    const std::size_t at = 1 + rng() % (s.size() - 1);  // byte 0 picks the decoder
    switch (rng() % 5) {
      case 0:
        s[at] = static_cast<char>(rng() % 256);
        break;
      case 1:
        s[at] = static_cast<char>(kTags[rng() % std::size(kTags)]);
        break;
      case 2:
        s.erase(at, 1 + rng() % 8);
        break;
      case 3:
        s.resize(at);
        break;
      default:
        s.insert(at, s.substr(at, 1 + rng() % 32));
        break;
    }
  }
  return s;
}

TEST(LolaFuzz, CorpusAndMutationsDecodeOrFailWithOneLine) {
  const auto seeds = test::read_corpus("tests/fuzz_lola/corpus");
  ASSERT_GE(seeds.size(), 6u);
  std::mt19937_64 rng(26);
  int errors = 0, decoded = 0;
  for (int i = 0; i < 4000; ++i) {
    const std::string input =
        i < static_cast<int>(seeds.size()) ? seeds[i] : mutate(seeds[rng() % seeds.size()], rng);
    std::string msg;
    ASSERT_NO_THROW(msg = test::decode_lola_fuzz_input(
                        reinterpret_cast<const std::uint8_t*>(input.data()), input.size()))
        << "input " << i;
    if (msg.empty()) {
      ++decoded;
      continue;
    }
    ++errors;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    EXPECT_TRUE(msg.starts_with("LoLA ") || msg.starts_with("stream: ")) << msg;
  }
  EXPECT_GT(errors, 1000);
  EXPECT_GE(decoded, 4);  // the good seeds
}

}  // namespace
}  // namespace stride
