#pragma once
// Output that arrives while the readline prompt is on screen (watch lines and debug output of a
// background run) is written above the prompt, and the prompt with the half-typed line is drawn
// again below it. Output of a command the user just entered is written straight through.
#include <streambuf>
#include <string>

namespace stride::console {

class TerminalOutput final : public std::streambuf {
 public:
  explicit TerminalOutput(std::streambuf* terminal) : terminal_(terminal) {}
  // Whether readline's prompt is on screen (between commands) or not (a command is running).
  void set_prompt_shown(bool shown);

 protected:
  int overflow(int c) override;
  std::streamsize xsputn(const char* s, std::streamsize n) override;
  int sync() override;

 private:
  void write_lines(bool all);  // complete lines only, or everything (sync)

  std::streambuf* terminal_;
  std::string pending_;
  bool prompt_shown_ = false;
};

}  // namespace stride::console
