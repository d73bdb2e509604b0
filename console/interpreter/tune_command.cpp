#include "console/interpreter/tune_command.hpp"

#include <filesystem>
#include <iostream>

#include "console/interpreter/sweep_arguments.hpp"
#include "console/sweep/run_plan.hpp"
#include "console/tune/tune_run.hpp"
#include "robot/core/error.hpp"

namespace stride::console {

struct TuneState {
  tune::TuneResult result;
  std::vector<std::string> params;  // names, in the file's order
};

TuneCommand::TuneCommand() = default;
TuneCommand::~TuneCommand() = default;

void TuneCommand::run(const std::vector<std::string>& args, const std::string& file,
                      std::ostream& out, bool interactive) {
  const SweepArguments words = parse_sweep_arguments(args, "tune");
  tune::TuneRequest r;
  r.file = file;
  r.jobs = words.jobs;
  r.out_dir = words.out.empty() ? std::filesystem::path(file).stem().string() + "-tune" : words.out;
  r.resume = words.resume;
  r.overwrite = words.overwrite;
  r.quiet = words.quiet || !interactive;
  r.command = "console: tune " + file;
  const auto result = tune::run_tune(r, out, std::cerr);
  if (!result) return;
  auto state = std::make_unique<TuneState>();
  state->result = *result;
  for (const tune::TuneParam& p : tune::request_tune_spec(r).params)
    state->params.push_back(p.name);
  last_ = std::move(state);
  if (!result->complete) throw Error("tune: interrupted; continue with: tune " + file + " resume");
}

std::string TuneCommand::value(const std::string& key) const {
  if (!last_) throw Error(key + ": no search has run yet (tune <file>)");
  const tune::TuneResult& r = last_->result;
  const auto number = [](double v) { return sweep::number_text(v); };
  if (key == "tune.generations") return std::to_string(r.generations);
  if (key == "tune.walks") return std::to_string(r.walks);
  if (key == "tune.failed") return std::to_string(r.failed);
  if (key == "tune.complete") return r.complete ? "true" : "false";
  if (key == "tune.best") return number(r.best.score.objective);
  if (key == "tune.heldout.thesis") return number(r.heldout_thesis.objective);
  if (key == "tune.heldout.tuned") return number(r.heldout_tuned.objective);
  if (key == "tune.heldout.thesis_sd") return number(r.heldout_thesis.sd);
  if (key == "tune.heldout.tuned_sd") return number(r.heldout_tuned.sd);
  if (key.starts_with("tune.param."))
    for (std::size_t p = 0; p < last_->params.size() && p < r.best.values.size(); ++p)
      if (key.substr(11) == last_->params[p]) return number(r.best.values[p]);
  throw Error("'" + key +
              "': expected tune.generations, tune.walks, tune.failed, tune.complete, tune.best, "
              "tune.heldout.thesis|tuned[_sd] or tune.param.<name>");
}

}  // namespace stride::console
