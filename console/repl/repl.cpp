#include "console/repl/repl.hpp"

#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>

#include <readline/history.h>
#include <readline/readline.h>

#include "console/interpreter/tokenizer.hpp"
#include "console/repl/completion.hpp"
#include "robot/core/error.hpp"

namespace stride::console {

namespace {

// readline's C callbacks and the signal handler take no user data, so the session they serve
// is reachable only from here, set for the duration of run_repl.
Target* g_completion_target = nullptr;
std::atomic<bool> g_interrupt{false};
std::vector<std::string> g_matches;

void on_interrupt(int) {
  g_interrupt = true;
}

char* match_generator(const char*, int state) {
  if (static_cast<std::size_t>(state) >= g_matches.size()) return nullptr;
  return strdup(g_matches[state].c_str());
}

char** attempt_completion(const char* text, int start, int) {
  rl_attempted_completion_over = 1;  // no fallback to readline's own file names
  std::vector<std::string> before;
  try {
    before = tokenize(std::string_view(rl_line_buffer, static_cast<std::size_t>(start)));
  } catch (const Error&) {
    return nullptr;
  }
  g_matches = complete(before, text, *g_completion_target);
  if (g_matches.empty()) return nullptr;
  // Keys and paths continue ("module:Stand" + ".knee_pitch"): no space after a unique match.
  const std::string& only = g_matches.front();
  rl_completion_suppress_append =
      g_matches.size() == 1 && (only.find_first_of(":./=") != std::string::npos);
  return rl_completion_matches(text, match_generator);
}

std::string history_path() {
  const char* home = std::getenv("HOME");
  return std::string(home ? home : ".") + "/.stride_history";
}

int plain_loop(Interpreter& interpreter) {
  std::string line;
  while (!interpreter.quit_requested() && std::getline(std::cin, line)) {
    g_interrupt = false;
    interpreter.execute_reporting(line);
  }
  return 0;
}

}  // namespace

int run_repl(Interpreter& interpreter) {
  g_completion_target = &interpreter.target();
  interpreter.set_interactive(&g_interrupt);
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  struct sigaction previous {};
  sigaction(SIGINT, &action, &previous);
  if (!isatty(STDIN_FILENO)) {
    const int rc = plain_loop(interpreter);
    sigaction(SIGINT, &previous, nullptr);
    return rc;
  }
  rl_readline_name = "stride";
  rl_completer_word_break_characters = const_cast<char*>(" \t");
  rl_attempted_completion_function = attempt_completion;
  const std::string history = history_path();
  using_history();
  if (read_history(history.c_str()) != 0) write_history(history.c_str());  // create it
  std::cout << "stride console on " << interpreter.target().name()
            << " (help lists commands, Tab completes, quit leaves)\n";
  while (!interpreter.quit_requested()) {
    char* raw = readline("stride> ");
    if (!raw) break;  // Ctrl-D
    const std::string line(raw);
    std::free(raw);
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    add_history(line.c_str());
    append_history(1, history.c_str());
    g_interrupt = false;
    interpreter.execute_reporting(line);
    std::cout.flush();
  }
  history_truncate_file(history.c_str(), 1000);
  std::cout << "\n";
  sigaction(SIGINT, &previous, nullptr);
  g_completion_target = nullptr;
  return 0;
}

}  // namespace stride::console
