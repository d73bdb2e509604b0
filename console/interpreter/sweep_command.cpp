#include "console/interpreter/sweep_command.hpp"

#include <algorithm>
#include <filesystem>
#include <iostream>

#include "console/interpreter/sweep_arguments.hpp"
#include "console/sweep/run_plan.hpp"
#include "console/sweep/sweep_request.hpp"
#include "robot/core/error.hpp"

namespace stride::console {

struct SweepState {
  sweep::SweepResult result;
};

SweepCommand::SweepCommand() = default;
SweepCommand::~SweepCommand() = default;

void SweepCommand::run(const std::vector<std::string>& args, const std::string& file,
                       std::ostream& out, bool interactive) {
  const SweepArguments words = parse_sweep_arguments(args);
  sweep::SweepRequest r;
  r.jobs = words.jobs;
  r.seeds = words.seeds;
  r.options.out_dir = words.out;
  r.options.resume = words.resume;
  r.options.overwrite = words.overwrite;
  r.quiet = words.quiet;
  r.file = file;
  if (!interactive) r.quiet = true;
  if (r.options.out_dir.empty())
    r.options.out_dir = std::filesystem::path(file).stem().string() + "-sweep";
  r.options.command = "console: sweep " + file;
  const auto result = sweep::run_sweep_request(r, out, std::cerr);
  if (!result) return;
  auto state = std::make_unique<SweepState>();
  state->result = *result;
  last_ = std::move(state);
  if (!result->complete)
    throw Error("sweep: interrupted; continue with: sweep " + file + " resume");
}

std::string SweepCommand::value(const std::string& key) const {
  if (!last_) throw Error(key + ": no sweep has run yet (sweep <file>)");
  const sweep::SweepResult& r = last_->result;
  if (key == "sweep.runs") return std::to_string(r.rows.size());
  if (key == "sweep.failed") return std::to_string(r.failed);
  if (key == "sweep.complete") return r.complete ? "true" : "false";
  // sweep.<tally>.<column>[<group>]
  const std::string rest = key.substr(6);
  const std::size_t dot = rest.find('.'), open = rest.rfind('[');
  if (dot == std::string::npos || open == std::string::npos || open < dot || rest.back() != ']')
    throw Error("'" + key +
                "': expected sweep.runs, sweep.failed, sweep.complete or "
                "sweep.<tally>.<column>[<group>]");
  const std::string tally = rest.substr(0, dot), column = rest.substr(dot + 1, open - dot - 1),
                    group = rest.substr(open + 1, rest.size() - open - 2);
  for (const sweep::TallyTable& t : r.tallies) {
    if (t.name != tally) continue;
    const auto c = std::find(t.columns.begin(), t.columns.end(), column);
    if (c == t.columns.end())
      throw Error("'" + key + "': tally '" + tally + "' has no column '" + column + "'");
    for (std::size_t r = 0; r < t.texts.size(); ++r) {
      std::string g;
      for (std::size_t k = 0; k < t.by; ++k) g += (k ? "/" : "") + t.texts[r][k];
      if (g != group) continue;
      // The value itself, not its printed form (a mean's "+-sd", rounded decimals).
      const sweep::Cell& v = t.rows[r][static_cast<std::size_t>(c - t.columns.begin())];
      if (const double* d = std::get_if<double>(&v)) return sweep::number_text(*d);
      return std::get<std::string>(v);
    }
    throw Error("'" + key + "': no group [" + group + "] in tally '" + tally + "'");
  }
  throw Error("'" + key + "': no tally '" + tally + "'");
}

}  // namespace stride::console
