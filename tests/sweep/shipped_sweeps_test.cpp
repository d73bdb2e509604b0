// Every sweep file shipped under scenes/ (the thesis studies and the new ones) parses, names
// known keys, columns and setting targets, and its scenes load with each first run's settings:
// what `stride sweep` checks before any run, so a broken study shows here.
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "console/sweep/sweep_parser.hpp"
#include "console/sweep/sweep_spec.hpp"
#include "console/sweep/tally.hpp"
#include "robot/core/error.hpp"

namespace stride::sweep {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> shipped_sweeps() {
  std::vector<fs::path> out;
  for (const auto& e : fs::recursive_directory_iterator(fs::path(STRIDE_SOURCE_DIR) / "scenes"))
    if (e.path().filename().string().ends_with(".sweep.xml")) out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

TEST(ShippedSweeps, EveryOneParsesAndItsScenesLoad) {
  const auto files = shipped_sweeps();
  // posture, knee-energy, gains, fastest, arm-swing, push, push-walk
  EXPECT_GE(files.size(), 7u);
  for (const fs::path& p : files) {
    SCOPED_TRACE(p.string());
    try {
      const Sweep s(parse_sweep_file(p.string()));
      const Tallies t(s);
      EXPECT_GT(s.plan().runs.size(), 0u);
      // Only the overnight sweep mixes in a scene meant not to load (its runs: failed rows).
      const bool hostile = p.filename() == "overnight.sweep.xml";
      EXPECT_EQ(s.unloadable_scenes().size(), hostile ? 1u : 0u);
    } catch (const Error& e) {
      ADD_FAILURE() << e.what();
    }
  }
}

// Issue 33's rule for the studies: a walk figure over several walks comes with its spread and
// with how many walks fell. Every visible mean of a walk study's tally carries its standard
// deviation (sd="true": the printed "+-", a *_sd CSV column), and the file counts falls or lost
// walks in some tally. A file of single runs only (no mean) has nothing to spread. push.sweep.xml
// is left out: the robot stands, each row is one push.
TEST(ShippedSweeps, WalkFiguresComeWithSpreadAndFallCount) {
  int walk_studies = 0;
  for (const fs::path& p : shipped_sweeps()) {
    if (p.filename() == "push.sweep.xml") continue;
    SCOPED_TRACE(p.string());
    const SweepSpec spec = parse_sweep_file(p.string());
    bool counts_falls = false;
    int means = 0;
    for (const TallySpec& t : spec.tallies)
      for (const TallyColumn& c : t.columns) {
        if (c.kind == TallyColumn::Kind::Count && (c.where.find("fell") != std::string::npos ||
                                                   c.where.find("lost") != std::string::npos))
          counts_falls = true;
        if (c.kind != TallyColumn::Kind::Mean || c.hidden) continue;
        ++means;
        EXPECT_TRUE(c.with_sd) << t.name << ": mean '" << c.name << "' (line " << c.line
                               << ") without sd=\"true\"";
      }
    if (means == 0) continue;  // rows of single runs (landing.sweep.xml: one draw per row)
    EXPECT_TRUE(counts_falls) << "no tally counts fell or lost walks";
    ++walk_studies;
  }
  // posture, knee-energy, gains, fastest, arm-swing, push-walk
  EXPECT_GE(walk_studies, 6);
}

// The posture table's kept distance: mean with its sd, min and max, and the walks lost.
TEST(ShippedSweeps, PostureCasesTallyHasDistanceSpread) {
  const SweepSpec spec =
      parse_sweep_file(std::string(STRIDE_SOURCE_DIR) + "/scenes/experiments/posture.sweep.xml");
  const auto cases = std::find_if(spec.tallies.begin(), spec.tallies.end(),
                                  [](const TallySpec& t) { return t.name == "cases"; });
  ASSERT_NE(cases, spec.tallies.end());
  std::vector<std::string> names;
  for (const TallyColumn& c : cases->columns) {
    names.push_back(c.name);
    if (c.name == "dist[m]" || c.name == "fk[m]") {
      EXPECT_TRUE(c.with_sd) << c.name;
    }
  }
  for (const char* want : {"lost", "fell", "dist[m]", "dist min", "dist max", "fk[m]"})
    EXPECT_NE(std::find(names.begin(), names.end(), want), names.end()) << want;
}

}  // namespace
}  // namespace stride::sweep
