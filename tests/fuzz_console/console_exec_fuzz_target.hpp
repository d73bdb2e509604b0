#pragma once
// One console fuzz input: script text executed statement by statement against the controlled NAO
// scene (loaded fresh for each input), through the real Interpreter and LocalTarget. A
// stride::Error is a refused command; anything else escaping (another exception, an ODE
// assertion, a sanitizer report) is a bug. The simulation may advance at most kStepBudget steps
// per input, and files are written only as plain names in a scratch directory (the current
// directory, set here), so neither a long run nor an absolute path can harm the machine.
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "console/interpreter/interpreter.hpp"
#include "console/interpreter/tokenizer.hpp"
#include "robot/core/error.hpp"
#include "tests/fuzz_console/budget_target.hpp"

namespace stride::test {

inline constexpr std::uint64_t kStepBudget = 40;

// The scratch directory (current directory from now on) with the scenes an input may load.
inline const std::filesystem::path& console_fuzz_dir() {
  static const std::filesystem::path dir =
      [] {
        namespace fs = std::filesystem;
        const fs::path d =
            fs::temp_directory_path() / ("stride_console_fuzz_" + std::to_string(getpid()));
        fs::create_directories(d);
        const fs::path src(STRIDE_SOURCE_DIR);
        const std::string nao = (src / "scenes/robots/nao").string();
        std::ofstream(d / "stand.xml")
            << "<scene><physics seed=\"2\"/><robot name=\"nao\" urdf=\"" << nao << "/nao.urdf\" "
            << "devices=\"" << nao << "/nao.devices.xml\"><joints LKneePitch=\"0.6\" "
            << "RKneePitch=\"0.6\" LHipPitch=\"-0.3\" RHipPitch=\"-0.3\" LAnklePitch=\"-0.3\" "
            << "RAnklePitch=\"-0.3\"/><controller><provider representation=\"JointRequest\" "
            << "module=\"Stand\"/></controller></robot></scene>\n";
        std::ofstream(d / "two.xml")
            << "<scene><robot name=\"a\" urdf=\"" << nao << "/nao.urdf\" devices=\"" << nao
            << "/nao.devices.xml\" xyz=\"0 0.4 auto\"/><robot name=\"b\" urdf=\"" << nao
            << "/nao.urdf\" xyz=\"0 -0.4 auto\" fixed=\"true\"/><box size=\"0.2 0.2 0.2\" "
            << "xyz=\"1 0 0.1\"/></scene>\n";
        fs::current_path(d);
        return d;
      }();
  return dir;
}

// Statements that would write outside the scratch directory, pace the run by the wall clock, or
// open network connections (connect, serve).
inline bool allowed_statement(const std::string& statement) {
  std::vector<std::string> w;
  try {
    w = console::tokenize(statement);
  } catch (const Error&) {
    return true;  // the interpreter refuses it itself
  }
  if (w.empty()) return true;
  if (w[0] == "realtime" || w[0] == "connect" || w[0] == "serve") return false;
  const auto plain = [](const std::string& p) {
    return !p.empty() && p.find('/') == std::string::npos && p != "." && p != "..";
  };
  if (w[0] == "report" && w.size() > 1) return plain(w[1]);
  if (w[0] == "log" && w.size() > 2 && w[1] == "save") return plain(w[2]);
  if (w[0] == "plot")
    for (std::size_t i = 1; i + 1 < w.size(); ++i)
      if (w[i] == "to") return plain(w[i + 1]);
  return true;
}

// Returns how many statements failed with a stride::Error.
inline int run_console_fuzz_input(const std::uint8_t* data, std::size_t size) {
  namespace fs = std::filesystem;
  const fs::path& dir = console_fuzz_dir();
  for (const auto& e : fs::directory_iterator(dir))  // what the previous input wrote
    if (e.path().filename() != "stand.xml" && e.path().filename() != "two.xml")
      fs::remove_all(e.path());
  const std::string text(reinterpret_cast<const char*>(data), size);
  BudgetTarget target(kStepBudget);
  std::ostringstream out;
  int refused = 0;
  {
    console::Interpreter in(target, out);
    in.execute("load stand.xml");
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line) && !in.quit_requested();) {
      std::vector<std::string> statements;
      try {
        statements = console::split_statements(line);
      } catch (const Error&) {
        ++refused;
        continue;
      }
      for (const std::string& s : statements)
        if (allowed_statement(s) && !in.execute_reporting(s)) ++refused;
    }
  }  // the interpreter's destructor writes a pending plot
  return refused;
}

}  // namespace stride::test
