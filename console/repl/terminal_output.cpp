#include "console/repl/terminal_output.hpp"

#include <cstdio>
#include <cstdlib>

#include <readline/readline.h>

namespace stride::console {

void TerminalOutput::set_prompt_shown(bool shown) {
  write_lines(true);
  prompt_shown_ = shown;
}

int TerminalOutput::overflow(int c) {
  if (c == traits_type::eof()) return traits_type::not_eof(c);
  pending_.push_back(static_cast<char>(c));
  if (c == '\n') write_lines(false);
  return c;
}

std::streamsize TerminalOutput::xsputn(const char* s, std::streamsize n) {
  pending_.append(s, static_cast<std::size_t>(n));
  if (pending_.find('\n') != std::string::npos) write_lines(false);
  return n;
}

int TerminalOutput::sync() {
  write_lines(!prompt_shown_);  // a partial line waits for its end while the prompt is shown
  return terminal_->pubsync();
}

void TerminalOutput::write_lines(bool all) {
  const std::size_t end = all ? pending_.size() : pending_.rfind('\n') + 1;
  if (end == 0 || pending_.empty()) return;
  if (!prompt_shown_) {
    terminal_->sputn(pending_.data(), static_cast<std::streamsize>(end));
    terminal_->pubsync();
    pending_.erase(0, end);
    return;
  }
  // Clear the prompt line, print, then draw the prompt and what was typed so far again.
  const int point = rl_point;
  char* typed = rl_copy_text(0, rl_end);
  rl_save_prompt();
  rl_replace_line("", 0);
  rl_redisplay();
  terminal_->sputn(pending_.data(), static_cast<std::streamsize>(end));
  terminal_->pubsync();
  std::fflush(stdout);
  pending_.erase(0, end);
  rl_restore_prompt();
  rl_replace_line(typed, 0);
  rl_point = point;
  rl_redisplay();
  std::free(typed);
}

}  // namespace stride::console
