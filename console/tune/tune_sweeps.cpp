#include "console/tune/tune_sweeps.hpp"

#include <charconv>
#include <cmath>
#include <sstream>

#include "console/sweep/run_plan.hpp"
#include "robot/core/error.hpp"

namespace stride::tune {
namespace {

sweep::Factor candidate_factor(const TuneSpec& tune, const Batch& batch) {
  sweep::Factor f{"candidate", {}, 0};
  for (std::size_t c = 0; c < batch.values.size(); ++c) {
    sweep::Level l;
    l.label = batch.labels.at(c);
    for (std::size_t p = 0; p < tune.params.size(); ++p) {
      const TuneParam& param = tune.params[p];
      const double v = batch.values[c].at(p);
      for (const std::string& t : param.targets)
        l.settings.push_back({t, sweep::format_value(param.format, v)});
      l.columns.emplace_back(param.name, sweep::number_text(v));
    }
    f.levels.push_back(std::move(l));
  }
  return f;
}

sweep::Factor floor_factor(const TuneSpec& tune, const WalkSet& walks) {
  sweep::Factor f{"floor", {}, walks.line};
  for (const std::string& name : walks.floors)
    for (const TuneFloor& floor : tune.floors)
      if (floor.name == name) f.levels.push_back({floor.name, floor.settings, {}});
  return f;
}

double parse_number(const std::string& text) {
  double v = 0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || r.ec != std::errc() || r.ptr != text.data() + text.size())
    throw Error("tune batch: bad number '" + text + "'");
  return v;
}

}  // namespace

sweep::SweepSpec batch_spec(const TuneSpec& tune, const Batch& batch) {
  if (batch.values.empty() || batch.labels.size() != batch.values.size())
    throw Error("tune batch: expected one label per candidate, at least one candidate");
  const bool heldout = batch.kind == "heldout";
  const WalkSet& walks = heldout ? tune.heldout : tune.train;
  sweep::SweepSpec s;
  s.name = tune.name + (heldout ? "-heldout" : "-gen" + std::to_string(batch.generation));
  s.file = tune.file;
  s.scene_dir = tune.scene_dir;
  s.settings = tune.settings;
  sweep::Block b;
  b.factors = {candidate_factor(tune, batch), floor_factor(tune, walks)};
  s.blocks.push_back(std::move(b));
  s.seeds = walks.seeds;
  s.start_heading_spread = walks.heading_spread;
  s.start_position_spread = walks.position_spread;
  s.until = tune.until;
  s.record = tune.record;
  s.record.derived.push_back({"objective", tune.objective, tune.objective_line});
  return s;
}

void add_heldout_tallies(sweep::SweepSpec& spec, const std::vector<sweep::RecordColumn>& record) {
  using K = sweep::TallyColumn::Kind;
  for (const auto& [name, by] :
       {std::pair<std::string, std::vector<std::string>>{"heldout", {"candidate"}},
        {"heldout_floors", {"candidate", "floor"}}}) {
    sweep::TallySpec t;
    t.name = name;
    t.by = by;
    t.title = "Held-out walks (" + std::string(by.size() > 1 ? "per floor" : "all floors") +
              "): the thesis' parameters against the tuned ones, mean+-sd over the seeds";
    t.columns.push_back({K::Count, "walks"});
    t.columns.push_back({K::Mean, "objective", "objective", "", true, 4});
    t.columns.push_back({K::Min, "min", "objective", "", false, 4});
    t.columns.push_back({K::Max, "max", "objective", "", false, 4});
    for (const sweep::RecordColumn& c : record)
      if (!c.text && c.name != "objective")
        t.columns.push_back({K::Mean, c.name, c.name, "", true, 4});
    spec.tallies.push_back(std::move(t));
  }
}

std::string encode_batch(const Batch& batch) {
  std::string out = batch.kind + " " + std::to_string(batch.generation) + "\n";
  for (std::size_t c = 0; c < batch.values.size(); ++c) {
    out += batch.labels.at(c);
    for (double v : batch.values[c]) out += " " + sweep::number_text(v);
    out += "\n";
  }
  return out;
}

Batch decode_batch(const std::string& text) {
  std::istringstream in(text);
  Batch b;
  std::string line;
  if (!std::getline(in, line)) throw Error("tune batch: empty");
  std::istringstream head(line);
  if (!(head >> b.kind >> b.generation) || (b.kind != "generation" && b.kind != "heldout"))
    throw Error("tune batch: bad first line '" + line + "'");
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string label, word;
    if (!(words >> label)) throw Error("tune batch: empty candidate line");
    std::vector<double> values;
    while (words >> word) values.push_back(parse_number(word));
    b.labels.push_back(label);
    b.values.push_back(std::move(values));
  }
  return b;
}

std::vector<CandidateScore> candidate_scores(const sweep::Sweep& sweep,
                                             const std::vector<std::vector<std::string>>& rows,
                                             const Batch& batch, double failed_value) {
  const std::vector<std::string> header = sweep.csv_header();
  const auto column = [&](const std::string& name) {
    for (std::size_t i = 0; i < header.size(); ++i)
      if (header[i] == name) return i;
    throw Error("tune: the sweep has no column '" + name + "'");
  };
  const std::size_t cand = column("candidate"), status = column("status"),
                    objective = column("objective");
  std::vector<CandidateScore> scores(batch.labels.size());
  std::vector<std::vector<double>> walks(batch.labels.size());
  for (const std::vector<std::string>& row : rows) {
    std::size_t c = 0;
    while (c < batch.labels.size() && batch.labels[c] != row.at(cand)) ++c;
    if (c == batch.labels.size()) throw Error("tune: a row of unknown candidate " + row.at(cand));
    double v = failed_value;
    if (row.at(status) == "ok") {
      v = std::strtod(row.at(objective).c_str(), nullptr);  // "nan", "inf" read as such
      if (!std::isfinite(v)) v = failed_value;
    }
    scores[c].failed += row.at(status) != "ok";
    walks[c].push_back(v);  // in run order: the same sum for the same rows
  }
  for (std::size_t c = 0; c < scores.size(); ++c) {
    CandidateScore& s = scores[c];
    s.walks = static_cast<int>(walks[c].size());
    if (walks[c].empty()) {
      s.objective = failed_value;
      continue;
    }
    double sum = 0, squares = 0;
    for (double v : walks[c]) sum += v;
    s.objective = sum / s.walks;
    for (double v : walks[c]) squares += (v - s.objective) * (v - s.objective);
    s.sd = std::sqrt(squares / s.walks);
    s.values = walks[c];
  }
  return scores;
}

}  // namespace stride::tune
