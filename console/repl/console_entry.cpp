#include "console/repl/console_entry.hpp"

#include <ostream>

#include "console/cli/exit_codes.hpp"
#include "console/interpreter/interpreter.hpp"
#include "console/repl/repl.hpp"
#include "console/target/local_target.hpp"
#include "robot/core/error.hpp"
#include "robot/core/quote.hpp"
#include "robot/debug/auth.hpp"

namespace stride::console {

namespace {
struct ConsoleArgs {
  std::string script;
  std::string inline_commands;
  bool has_inline = false;
  std::string scene;
  std::string connect;     // host:port of a robot to act on
  std::string token_file;  // its token (else STRIDE_TOKEN)
};

ConsoleArgs read_args(const std::vector<std::string>& args) {
  ConsoleArgs c;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--script" || a == "-c" || a == "--connect" || a == "--token-file") {
      if (i + 1 >= args.size()) throw UsageError("stride: " + a + ": expected a value");
      (a == "--script"    ? c.script
       : a == "-c"        ? c.inline_commands
       : a == "--connect" ? c.connect
                          : c.token_file) = args[++i];
      if (a == "-c") c.has_inline = true;
    } else if (a.starts_with("-")) {
      throw UsageError("stride: unknown flag " + quote(a) + " (see stride --help)");
    } else if (c.scene.empty()) {
      c.scene = a;
    } else {
      throw UsageError("stride: unexpected argument " + quote(a) + " (one scene at most)");
    }
  }
  if (!c.script.empty() && c.has_inline) throw UsageError("stride: give --script or -c, not both");
  if (!c.token_file.empty() && c.connect.empty())
    throw UsageError("stride: --token-file is for --connect");
  return c;
}

std::string quoted_word(const std::string& s) {
  std::string q = "\"";
  for (char ch : s) {
    if (ch == '"' || ch == '\\') q += '\\';
    q += ch;
  }
  return q + "\"";
}
}  // namespace

std::string console_usage() {
  return "  stride [scene.xml]: interactive console (REPL)\n"
         "  stride --script file.con [scene.xml]: run a script; exit 1 on the first failure\n"
         "  stride -c \"cmd; cmd\" [scene.xml]: run commands; exit 1 on the first failure\n"
         "  ... --connect host:port [--token-file f]: the same against a robot's debug server\n";
}

int console_main(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  ConsoleArgs c;
  try {
    c = read_args(args);
  } catch (const Error& e) {
    return cli::report_error(e, err);
  }
  LocalTarget target;
  Interpreter interpreter(target, out);
  const bool batch = !c.script.empty() || c.has_inline;
  bool connecting = false;  // a failed --connect is an error, never a local console instead
  try {
    if (!c.scene.empty()) interpreter.execute("load " + quoted_word(c.scene));
    if (!c.connect.empty()) {
      connecting = true;
      const std::string token =
          c.token_file.empty() ? "" : debug::read_token_file(c.token_file).front().secret;
      interpreter.execute("connect " + quoted_word(c.connect) +
                          (token.empty() ? std::string() : " " + quoted_word(token)));
      connecting = false;
    }
    if (!c.script.empty()) interpreter.run_script(c.script);
    if (c.has_inline) interpreter.run_inline(c.inline_commands);
    if (batch) interpreter.finish();
  } catch (const Error& e) {
    out.flush();
    const int code = cli::report_error(e, err);
    if (batch || connecting) return code;
  }
  return batch ? 0 : run_repl(interpreter);
}

}  // namespace stride::console
