// CI's share of the fuzzing: the committed libFuzzer corpus plus seeded random mutations of it go
// through the parser; every input parses to a command within its table's arity or is rejected
// with stride::Error, and nothing else escapes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "console/interpreter/command_parser.hpp"
#include "console/interpreter/command_table.hpp"
#include "console/interpreter/tokenizer.hpp"
#include "robot/core/error.hpp"

namespace stride::console {
namespace {

std::vector<std::string> corpus() {
  std::vector<std::string> out;
  for (const auto& e :
       std::filesystem::directory_iterator(STRIDE_SOURCE_DIR "/tests/fuzz_parser/corpus")) {
    std::ifstream in(e.path(), std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    out.push_back(s.str());
  }
  return out;
}

// Parses every statement; returns how many were accepted. Fails the test if the result breaks
// the table's arity or an exception other than stride::Error escapes.
int parse_all(const std::string& text) {
  int accepted = 0;
  std::vector<std::string> statements;
  try {
    statements = split_statements(text);
  } catch (const Error&) {
    return 0;
  }
  for (const auto& s : statements) {
    try {
      const Command c = parse_command(s);
      if (c.name.empty()) continue;
      const CommandSpec* spec = find_command(c.name);
      EXPECT_NE(spec, nullptr) << s;
      if (!spec) continue;
      const int n = static_cast<int>(c.args.size());
      EXPECT_GE(n, spec->min_args) << s;
      if (spec->max_args >= 0) {
        EXPECT_LE(n, spec->max_args) << s;
      }
      ++accepted;
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos)
          << "multi-line error: " << e.what();
    }
  }
  return accepted;
}

std::string mutate(std::string s, std::mt19937& rng) {
  const std::string alphabet = " \t\"#;=.:?[]0123456789-+eEabcdefghijklmnopqrstuvwxyz\\\n";
  std::uniform_int_distribution<int> kind(0, 3);
  const int edits = 1 + static_cast<int>(rng() % 4);
  for (int i = 0; i < edits; ++i) {
    const std::size_t at = s.empty() ? 0 : rng() % (s.size() + 1);
    switch (kind(rng)) {
      case 0:
        s.insert(at, 1, alphabet[rng() % alphabet.size()]);
        break;
      case 1:
        if (at < s.size()) s.erase(at, 1 + rng() % 3);
        break;
      case 2:
        if (at < s.size()) s[at] = static_cast<char>(rng() % 256);
        break;
      case 3:
        s.insert(at, s.substr(0, rng() % (s.size() + 1)));
        break;
    }
  }
  return s;
}

TEST(ParserFuzz, CommittedCorpusParses) {
  const auto inputs = corpus();
  ASSERT_GE(inputs.size(), 30u);
  int accepted = 0;
  for (const auto& text : inputs) accepted += parse_all(text);
  // Every seed is a valid command (some files hold two): the corpus exercises the accept paths.
  EXPECT_GE(accepted, static_cast<int>(inputs.size()) - 2);
}

TEST(ParserFuzz, RandomMutationsParseOrFailCleanly) {
  const auto inputs = corpus();
  std::mt19937 rng(20240601);
  int accepted = 0, total = 0;
  for (int round = 0; round < 40; ++round)
    for (const auto& text : inputs) {
      accepted += parse_all(mutate(text, rng));
      ++total;
    }
  // Mutations keep some commands valid and break others: both paths run.
  EXPECT_GT(accepted, 0);
  EXPECT_LT(accepted, total);
}

}  // namespace
}  // namespace stride::console
