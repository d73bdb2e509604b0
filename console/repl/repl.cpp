#include "console/repl/repl.hpp"

#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <utility>

#include <readline/history.h>
#include <readline/readline.h>

#include "console/interpreter/tokenizer.hpp"
#include "console/repl/completion.hpp"
#include "console/repl/terminal_output.hpp"
#include "robot/core/error.hpp"

namespace stride::console {

namespace {

using Clock = std::chrono::steady_clock;
// A background run steps this long between looks at the keyboard.
constexpr auto kSlice = std::chrono::milliseconds(20);
// Between frames or keys the console looks after its connections this often (keep-alives, `serve`
// clients of a paused simulation).
constexpr int kIdleMs = 100;

// readline's C callbacks and the signal handler take no user data, so the session they serve
// is reachable only from here, set for the duration of run_repl.
Interpreter* g_interpreter = nullptr;
std::atomic<bool> g_interrupt{false};
std::vector<std::string> g_matches;
struct TerminalSession {
  Interpreter* interpreter = nullptr;
  TerminalOutput* output = nullptr;
  std::string history;
  bool ended = false;  // Ctrl-D
};
TerminalSession* g_terminal = nullptr;

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
  g_matches = complete(before, text, g_interpreter->target(), g_interpreter->robot_names());
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

// Waits for input on stdin until it arrives, `timeout` passes (negative: forever) or a signal.
bool input_ready(int timeout_ms) {
  pollfd p{STDIN_FILENO, POLLIN, 0};
  return ::poll(&p, 1, timeout_ms) > 0;
}

int milliseconds_until(Clock::duration wait) {
  return static_cast<int>(std::chrono::ceil<std::chrono::milliseconds>(wait).count());
}

// The loop both inputs share: read what has arrived (each complete line runs as a command,
// between frames), step a background run a slice at a time, pause it on Ctrl-C.
template <class Input>
void event_loop(Interpreter& interpreter, Input& input) {
  Clock::duration wait = Clock::duration::zero();
  while (!interpreter.quit_requested() && !input.ended()) {
    const bool ready = input_ready(interpreter.running() ? milliseconds_until(wait) : kIdleMs);
    if (g_interrupt.exchange(false)) {
      if (interpreter.running())
        interpreter.pause_run();
      else
        input.cancel_line();
    }
    if (ready) input.read();
    if (!interpreter.running()) {
      interpreter.idle();
      std::cout.flush();
      continue;
    }
    try {
      wait = interpreter.run_slice(kSlice);
    } catch (const Error& e) {
      std::cout << "error: " << e.what() << "\n";
    }
    std::cout.flush();
  }
}

// Lines from a pipe or file: no prompt, no editing.
class PipeInput {
 public:
  explicit PipeInput(Interpreter& interpreter) : interpreter_(interpreter) {}
  bool ended() const { return ended_; }
  void cancel_line() {}
  void read() {
    char chunk[4096];
    const ssize_t n = ::read(STDIN_FILENO, chunk, sizeof chunk);
    if (n < 0 && errno == EINTR) return;
    if (n <= 0) {
      ended_ = true;
      if (!buffer_.empty()) run(std::exchange(buffer_, std::string()));
      return;
    }
    buffer_.append(chunk, static_cast<std::size_t>(n));
    for (auto end = buffer_.find('\n'); end != std::string::npos && !interpreter_.quit_requested();
         end = buffer_.find('\n')) {
      const std::string line = buffer_.substr(0, end);
      buffer_.erase(0, end + 1);
      run(line);
    }
  }

 private:
  void run(const std::string& line) {
    interpreter_.execute_reporting(line);
    std::cout.flush();
  }
  Interpreter& interpreter_;
  std::string buffer_;
  bool ended_ = false;
};

// The prompt says when runs go as fast as possible, so a walk over in a blink is no surprise.
const char* prompt_of(const Interpreter& interpreter) {
  return interpreter.realtime() ? "stride> " : "stride (fast)> ";
}

void on_terminal_line(char* raw) {
  TerminalSession& s = *g_terminal;
  if (!raw) {
    s.ended = true;  // Ctrl-D
    return;
  }
  const std::string line(raw);
  std::free(raw);
  if (line.find_first_not_of(" \t") == std::string::npos) return;
  add_history(line.c_str());
  append_history(1, s.history.c_str());
  s.output->set_prompt_shown(false);
  s.interpreter->execute_reporting(line);
  std::cout.flush();
  rl_set_prompt(prompt_of(*s.interpreter));
  s.output->set_prompt_shown(true);
}

// The keyboard through readline's callback interface, so reading never blocks a running
// simulation.
class TerminalInput {
 public:
  explicit TerminalInput(TerminalSession& session) : session_(session) {
    rl_callback_handler_install(prompt_of(*session_.interpreter), on_terminal_line);
    session_.output->set_prompt_shown(true);
  }
  ~TerminalInput() {
    session_.output->set_prompt_shown(false);
    rl_callback_handler_remove();
  }
  bool ended() const { return session_.ended; }
  void read() { rl_callback_read_char(); }
  void cancel_line() {  // Ctrl-C at the prompt: drop the typed line, as a shell does
    session_.output->set_prompt_shown(false);
    rl_callback_sigcleanup();
    rl_replace_line("", 0);
    std::fputs("^C\n", stdout);
    rl_on_new_line();
    rl_redisplay();
    session_.output->set_prompt_shown(true);
  }

 private:
  TerminalSession& session_;
};

void terminal_loop(Interpreter& interpreter) {
  rl_readline_name = "stride";
  rl_catch_signals = 0;  // Ctrl-C is ours: it pauses a run or drops the typed line
  rl_completer_word_break_characters = const_cast<char*>(" \t");
  rl_attempted_completion_function = attempt_completion;
  TerminalOutput output(std::cout.rdbuf());
  std::streambuf* const previous = std::cout.rdbuf(&output);
  TerminalSession session{&interpreter, &output, history_path()};
  g_terminal = &session;
  using_history();
  if (read_history(session.history.c_str()) != 0) write_history(session.history.c_str());
  std::cout << "stride console on " << interpreter.target().name()
            << " (help lists commands, Tab completes, quit leaves)\n";
  {
    TerminalInput input(session);
    event_loop(interpreter, input);
  }
  history_truncate_file(session.history.c_str(), 1000);
  std::cout << "\n";
  std::cout.flush();
  std::cout.rdbuf(previous);
  g_terminal = nullptr;
}

}  // namespace

int run_repl(Interpreter& interpreter) {
  g_interpreter = &interpreter;
  interpreter.set_interactive(&g_interrupt);
  struct sigaction action {};
  action.sa_handler = on_interrupt;  // no SA_RESTART: Ctrl-C wakes the wait for input
  sigemptyset(&action.sa_mask);
  struct sigaction previous {};
  sigaction(SIGINT, &action, &previous);
  if (isatty(STDIN_FILENO)) {
    interpreter.set_realtime(true);  // a person typing sees the walk at its pace
    terminal_loop(interpreter);
  } else {
    PipeInput input(interpreter);
    event_loop(interpreter, input);
  }
  sigaction(SIGINT, &previous, nullptr);
  g_interpreter = nullptr;
  return 0;
}

}  // namespace stride::console
