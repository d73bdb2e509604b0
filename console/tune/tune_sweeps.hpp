#pragma once
// The sweeps a search runs: one per generation (its candidates x the training floors x the
// training seeds) and one for the held-out comparison (the thesis' values and the tuned ones x
// the held-out floors x seeds), built in code from the tuning file so that the engine's
// executors run them unchanged. Their rows carry the candidate's parameters as plan columns and
// the objective as the last record column.
#include <cstdint>
#include <string>
#include <vector>

#include "console/sweep/sweep.hpp"
#include "console/tune/tune_spec.hpp"

namespace stride::tune {

// What one sweep of a search evaluates. kind "generation" (the training walks) or "heldout".
struct Batch {
  std::string kind = "generation";
  int generation = 0;
  std::vector<std::string> labels;          // the candidate column's texts
  std::vector<std::vector<double>> values;  // per candidate, one value per param
};

// The batch as a sweep spec (named "<tune>-gen<N>" or "<tune>-heldout").
sweep::SweepSpec batch_spec(const TuneSpec& tune, const Batch& batch);

// The held-out sweep's tables, per candidate and per candidate and floor: walks, the objective
// (mean+-sd over the seeds, min, max) and every numeric record column's mean+-sd.
void add_heldout_tallies(sweep::SweepSpec& spec, const std::vector<sweep::RecordColumn>& record);

// The batch as one text line per candidate and back (MPI ranks rebuild the same sweep from it);
// numbers in the shortest text that reads back to the same bits. decode throws stride::Error.
std::string encode_batch(const Batch& batch);
Batch decode_batch(const std::string& text);

// Each candidate's objective: the mean over its walks of the objective column, a failed walk or
// a non-finite objective counting as `failed_value`. Read from the rows' texts, so a resumed
// generation gives the very bits a fresh one gives.
struct CandidateScore {
  double objective = 0;
  double sd = 0;  // population standard deviation over the walks
  int walks = 0, failed = 0;
  std::vector<double> values;  // each walk's objective, in run order
};
std::vector<CandidateScore> candidate_scores(const sweep::Sweep& sweep,
                                             const std::vector<std::vector<std::string>>& rows,
                                             const Batch& batch, double failed_value);

}  // namespace stride::tune
