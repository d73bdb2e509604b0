#include "console/tune/tune_run.hpp"

#include <chrono>
#include <memory>
#include <ostream>

#include "console/sweep/mpi_executor.hpp"
#include "console/sweep/run_progress.hpp"
#include "console/sweep/sweep_engine.hpp"
#include "console/sweep/sweep_output.hpp"
#include "console/tune/optimiser.hpp"
#include "console/tune/tune_parser.hpp"
#include "console/tune/tune_report.hpp"
#include "robot/core/error.hpp"

namespace stride::tune {
namespace {

struct Stopped {};  // the search was interrupted: its output stays resumable

// Where a batch's walks run (MPI: the ranks are told the batch first).
using ExecutorFor = std::function<std::unique_ptr<sweep::Executor>(const Batch&)>;

Batch fixed_batch(const std::string& kind, std::vector<std::string> labels,
                  const std::vector<std::vector<double>>& values) {
  return Batch{kind, 0, std::move(labels), values};
}

std::vector<double> thesis_values(const TuneSpec& t) {
  std::vector<double> v;
  for (const TuneParam& p : t.params) v.push_back(p.thesis);
  return v;
}

// One search on rank 0 or on this machine alone.
class Search {
 public:
  Search(const TuneRequest& r, TuneSpec spec, ExecutorFor executor, std::ostream& out,
         std::ostream& err)
      : r_(r), t_(std::move(spec)), executor_(std::move(executor)), out_(out), err_(err) {}

  // Loads every scene once with the thesis' values and binds every key and the objective, so a
  // bad file stops here, before the output is touched.
  void check() {
    const Batch thesis = fixed_batch("generation", {"thesis"}, {thesis_values(t_)});
    const sweep::Sweep train(batch_spec(t_, thesis), true);
    if (!train.unloadable_scenes().empty()) throw Error(train.unloadable_scenes().front());
    if (train.column_is_text("objective"))
      throw error_at(t_.file, t_.objective_line, "objective: expected a number, not a text");
    record_ = train.record_columns();
    const sweep::Sweep held(heldout_spec(thesis_values(t_), thesis_values(t_)), true);
    if (!held.unloadable_scenes().empty()) throw Error(held.unloadable_scenes().front());
    const sweep::Tallies tallies(held);
  }

  TuneResult run() {
    TuneOutput output(r_.out_dir, sweep::read_whole_file(t_.file), r_.resume, r_.overwrite,
                      r_.command);
    output_ = &output;
    TuneResult result;
    sweep::InterruptGuard guard;
    try {
      search(result);
      heldout(result);
      result.complete = true;
    } catch (const Stopped&) {
      err_ << "tune " << t_.name << ": stopped after " << result.generations
           << " whole generation(s); continue with --resume (output: " << r_.out_dir << ")\n";
    }
    return result;
  }

 private:
  sweep::SweepSpec heldout_spec(const std::vector<double>& thesis,
                                const std::vector<double>& tuned) const {
    sweep::SweepSpec s =
        batch_spec(t_, fixed_batch("heldout", {"thesis", "tuned"}, {thesis, tuned}));
    add_heldout_tallies(s, record_);
    return s;
  }

  // Runs one batch's sweep into `dir`; its candidates' scores. Throws Stopped when interrupted.
  std::vector<CandidateScore> run_batch(sweep::SweepSpec spec, const Batch& batch,
                                        const std::string& dir, const std::string& label,
                                        sweep::SweepResult& result) {
    const sweep::Sweep sweep(std::move(spec), false);
    const sweep::Tallies tallies(sweep);
    auto executor =
        executor_(batch);  // after everything that can throw: MPI ranks now wait for runs
    sweep::SweepOptions o;
    o.out_dir = dir;
    o.resume = r_.resume;
    o.print_tallies = batch.kind == "heldout";
    o.plots = false;
    o.command = r_.command;
    sweep::RunProgress progress(err_, label, r_.quiet);
    o.progress = [&](std::size_t d, std::size_t f, std::size_t n) { progress.update(d, f, n); };
    o.tick = [&] { progress.tick(); };
    o.stop = [&] { return sweep::InterruptGuard::interrupted() || (r_.stop && r_.stop()); };
    result = sweep::run_sweep(sweep, tallies, *executor, o, out_);
    progress.finish();
    if (!result.complete) throw Stopped{};
    return candidate_scores(sweep, result.rows, batch, t_.failed_value);
  }

  std::vector<double> generation(const std::vector<std::vector<double>>& candidates,
                                 TuneResult& result) {
    Batch b{"generation", result.generations, {}, candidates};
    for (std::size_t c = 0; c < candidates.size(); ++c) b.labels.push_back(std::to_string(c));
    const auto t0 = std::chrono::steady_clock::now();
    sweep::SweepResult swept;
    const std::string label = "tune " + t_.name + " generation " + std::to_string(b.generation) +
                              "/" + std::to_string(t_.generations);
    const std::vector<CandidateScore> scores =
        run_batch(batch_spec(t_, b), b, output_->generation_dir(b.generation), label, swept);
    std::vector<double> objectives;
    std::size_t best_here = 0;
    for (std::size_t c = 0; c < candidates.size(); ++c) {
      records_.push_back({b.generation, b.labels[c], candidates[c], scores[c]});
      objectives.push_back(scores[c].objective);
      if (scores[c].objective > scores[best_here].objective) best_here = c;
      result.walks += static_cast<std::size_t>(scores[c].walks);
      result.failed += static_cast<std::size_t>(scores[c].failed);
      if (records_.size() == 1 || scores[c].objective > result.best.score.objective)
        result.best = records_.back();
    }
    output_->write_search(t_, records_);
    ++result.generations;
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!r_.quiet)
      err_ << "tune " << t_.name << ": generation " << b.generation << "/" << t_.generations
           << " done in " << wall << " s (" << swept.ran << " walks run now): best of generation "
           << scores[best_here].objective << " (candidate " << best_here << "), best so far "
           << result.best.score.objective << " (generation " << result.best.generation
           << ", candidate " << result.best.label << "); " << result.walks << " walks, "
           << result.failed << " failed\n";
    return objectives;
  }

  void search(TuneResult& result) {
    SearchSettings s;
    for (const TuneParam& p : t_.params) s.lower.push_back(p.min), s.upper.push_back(p.max);
    s.population = t_.population;
    s.generations = t_.generations;
    s.seed = t_.seed;
    run_search(s, [&](const std::vector<std::vector<double>>& c) { return generation(c, result); });
  }

  void heldout(TuneResult& result) {
    const std::vector<double> thesis = thesis_values(t_);
    const Batch b = fixed_batch("heldout", {"thesis", "tuned"}, {thesis, result.best.values});
    sweep::SweepResult swept;
    const auto scores = run_batch(heldout_spec(thesis, result.best.values), b,
                                  output_->heldout_dir(), "tune " + t_.name + " held-out", swept);
    result.heldout_thesis = scores[0];
    result.heldout_tuned = scores[1];
    result.heldout = swept.tallies;
    const std::string text = report_text(t_, result);
    out_ << "\n" << text;
    output_->write_file("results.txt", text);
    write_tune_plots(*output_, records_, result, r_.plots);
  }

  const TuneRequest& r_;
  TuneSpec t_;
  ExecutorFor executor_;
  std::ostream& out_;
  std::ostream& err_;
  std::vector<sweep::RecordColumn> record_;
  std::vector<SearchRecord> records_;
  const TuneOutput* output_ = nullptr;
};

// Every rank but 0: builds each batch's sweep as rank 0 announces it and runs the walks it is
// handed, until rank 0 announces the end (an empty text).
void serve(const TuneRequest& r, sweep::MpiSession& mpi) {
  std::optional<TuneSpec> spec;
  try {
    spec = request_tune_spec(r);
  } catch (const Error&) {  // rank 0 reads the same file and says what is wrong
  }
  for (;;) {
    const std::string text = sweep::mpi_broadcast(mpi, "");
    if (text.empty()) return;
    std::optional<sweep::Sweep> sweep;
    try {
      if (spec) sweep.emplace(batch_spec(*spec, decode_batch(text)), false);
    } catch (const Error&) {
    }
    sweep::mpi_worker(mpi, [&](std::size_t i) {
      if (sweep) return sweep->run(i);
      sweep::RunRow failed;
      failed.run = static_cast<std::int64_t>(i);
      failed.reason = "rank could not build the search's sweep";
      return failed;
    });
  }
}

// Rank 0's end of the search: tells the other ranks, also when the search throws.
struct EndRanks {
  sweep::MpiSession& mpi;
  ~EndRanks() { sweep::mpi_broadcast(mpi, ""); }
};

// A file whose keys, settings or objective do not bind is a bad input, as one that does not parse.
void checked(Search& search) {
  try {
    search.check();
  } catch (const UsageError&) {
    throw;
  } catch (const Error& e) {
    throw InputError(e.what());
  }
}

}  // namespace

TuneSpec request_tune_spec(const TuneRequest& r) {
  TuneSpec spec = parse_tune_file(r.file);
  spec.settings.insert(spec.settings.begin(), r.settings.begin(), r.settings.end());
  return spec;
}

std::optional<TuneResult> run_tune(const TuneRequest& r, std::ostream& out, std::ostream& err) {
  if (r.out_dir.empty()) throw UsageError("tune: expected an output directory");
  if (!(r.force_mpi || sweep::started_by_mpi_launcher())) {
    const int jobs = r.jobs > 0 ? r.jobs : sweep::hardware_jobs();
    Search search(
        r, request_tune_spec(r),
        [jobs](const Batch&) {
          return jobs == 1 ? sweep::in_process_executor() : sweep::worker_process_executor(jobs);
        },
        out, err);
    checked(search);
    return search.run();
  }
  if (!sweep::mpi_built()) throw Error(sweep::mpi_missing_text());
  sweep::MpiSession mpi;
  if (mpi.rank() != 0) {
    serve(r, mpi);
    return std::nullopt;
  }
  EndRanks end{mpi};
  Search search(
      r, request_tune_spec(r),
      [&mpi](const Batch& b) {
        sweep::mpi_broadcast(mpi, encode_batch(b));
        return sweep::mpi_coordinator(mpi);
      },
      out, err);
  checked(search);
  return search.run();
}

}  // namespace stride::tune
