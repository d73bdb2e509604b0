#include "console/cli/help.hpp"

#include <ostream>
#include <vector>

#include "console/cli/exit_codes.hpp"
#include "console/interpreter/command_table.hpp"
#include "console/interpreter/help_search.hpp"
#include "console/interpreter/help_topics.hpp"
#include "console/repl/console_entry.hpp"
#include "robot/core/data_dir.hpp"

namespace stride::cli {

namespace {

constexpr const char* kExitCodes =
    "exit codes: 0 done; 1 it ran and failed (an expect, a run, a study); 2 wrong command line; "
    "3 a file or command text that cannot be read or parsed\n";

void print_subcommand(const Subcommand& s, std::ostream& out) {
  out << "  stride " << s.summary << "\n";
}

void print_console_command(const console::CommandSpec& c, std::ostream& out) {
  out << "  " << c.usage << "\n      " << c.summary << "\n";
}

void print_everything(std::ostream& out) {
  out << "usage: stride <command> [arguments]   (stride <command> --help, stride help <word>)\n";
  out << "commands:\n";
  for (const auto& s : subcommands()) print_subcommand(s, out);
  out << console::console_usage();
  out << "console commands (in the REPL, scripts and -c; help <word> there too):\n";
  for (const auto& c : console::command_table()) print_console_command(c, out);
  out << console::help_text("keys");
  out << console::help_topic_list() << kExitCodes << data_dir_line() << "\n";
}

}  // namespace

int help_main(Args args, std::ostream& out) {
  if (args.empty()) {
    print_everything(out);
    return kExitOk;
  }
  const std::string& word = args[0];
  if (word == "--help" || word == "-h") {  // `stride help --help`
    out << "usage: stride help [word]: everything, or what a word finds\n";
    print_command_help("help", out);
    return kExitOk;
  }
  // One search over everything, so a whole-word match anywhere outranks a part of a word.
  std::vector<console::HelpEntry> entries;
  for (const auto& s : subcommands())
    entries.push_back({std::string(s.name), std::string(s.summary)});
  const std::size_t first_console = entries.size();
  const auto console_entries = console::help_entries();
  entries.insert(entries.end(), console_entries.begin(), console_entries.end());
  const auto found = console::find_help(entries, word);
  const std::string topic = console::help_topic_text(word);  // the answer first, then commands
  out << topic;
  if (found.empty() && topic.empty()) out << "nothing matches '" << word << "'\n";
  std::vector<std::size_t> in_console;
  for (const std::size_t i : found) {
    if (i >= first_console) {
      in_console.push_back(i - first_console);
      continue;
    }
    if (i == found.front()) out << "commands:\n";
    print_subcommand(subcommands()[i], out);
  }
  if (!in_console.empty()) out << "console:\n" << console::help_listing(in_console);
  return kExitOk;
}

bool print_command_help(const std::string& name, std::ostream& out) {
  bool known = false;
  for (const auto& s : subcommands())
    if (s.name == name) {
      out << "usage: stride " << s.summary << "\n";
      known = true;
    }
  if (const console::CommandSpec* c = console::find_command(name)) {
    out << (known ? "console command " : "console command (in the REPL, a script or stride -c):\n")
        << (known ? "" : "  ") << c->usage << "\n      " << c->summary << "\n";
    known = true;
  }
  return known;
}

}  // namespace stride::cli
