// The engine on the standing NAO (short runs): every executor gives the same rows byte for byte;
// a diverging run and a worker killed twice are failed rows with their reason while the sweep
// goes on; a worker killed once costs one retry and no difference; a stopped sweep resumes to the
// same runs.csv as an uninterrupted one; an unwritable output is refused before any run.
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "console/sweep/sweep_engine.hpp"
#include "console/sweep/sweep_parser.hpp"
#include "tests/error_text.hpp"

namespace stride::sweep {
namespace {

namespace fs = std::filesystem;
using test_support::error_of;

// Four runs of 0.3 s: the standing robot on earth and pushed apart (a 1e7 N push on its hand
// makes the state explode) x two seeds.
Sweep standing_sweep() {
  return Sweep(parse_sweep_text(R"(<sweep name="stand" scenes="../../scenes">
  <scene file="nao_stand_controlled.xml"/>
  <factor name="g">
    <level label="earth"><set target="scene:physics@gravity" value="0 0 -9.81"/></level>
    <level label="blown"><set target="scene" value="../tests/sweep/data/nao_pushed_apart.xml"/></level>
  </factor>
  <seeds from="1" to="2"/>
  <run seconds="0.3"/>
  <record>
    <value name="hash" key="sim.hash"/>
    <value name="z" key="frame.torso_z"/>
    <summary name="pitch_sd" key="frame.true_pitch" stat="sd" from="0.1s"/>
    <summary name="frames" key="representation:FrameInfo.time" stat="count"/>
    <derived name="z_mm" value="z * 1000"/>
  </record>
  <tally name="by_g" by="g"><count name="n"/><mean name="z" of="z" sd="true" decimals="4"/></tally>
</sweep>)",
                                std::string(STRIDE_SOURCE_DIR) + "/tests/sweep/stand.sweep.xml"));
}

fs::path fresh_dir(const std::string& name) {
  const fs::path d =
      fs::temp_directory_path() / ("stride_sweep_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  return d;
}

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

SweepResult run(const Sweep& s, Executor& e, const fs::path& out, const RunFunction& fn = {},
                std::function<bool()> stop = {}, bool resume = false) {
  SweepOptions o;
  o.out_dir = out.string();
  o.resume = resume;
  o.print_tallies = false;
  o.plots = false;
  o.stop = std::move(stop);
  std::ostringstream text;
  if (!fn) return run_sweep(s, Tallies(s), e, o, text);
  // Run through `fn` instead of the sweep's own run function.
  struct Wrapped final : Executor {
    Executor& inner;
    const RunFunction& fn;
    Wrapped(Executor& i, const RunFunction& f) : inner(i), fn(f) {}
    std::string describe() const override { return inner.describe(); }
    int workers() const override { return inner.workers(); }
    void execute(const std::vector<std::size_t>& todo, const RunFunction&,
                 const ExecutorEvents& ev) override {
      inner.execute(todo, fn, ev);
    }
  } wrapped(e, fn);
  return run_sweep(s, Tallies(s), wrapped, o, text);
}

TEST(SweepEngine, EveryExecutorGivesTheSameRowsAndDivergenceIsAFailedRow) {
  const Sweep s = standing_sweep();
  const fs::path a = fresh_dir("one"), b = fresh_dir("two");
  const SweepResult one = run(s, *in_process_executor(), a);
  const SweepResult two = run(s, *worker_process_executor(2), b);
  ASSERT_TRUE(one.complete && two.complete);
  EXPECT_EQ(read(a / "runs.csv"), read(b / "runs.csv"));  // sorted by run id at the end
  EXPECT_EQ(one.failed, 2u);
  const auto& ok = one.rows[0];
  EXPECT_EQ(ok[4], "ok");
  EXPECT_EQ(ok[8], "30");                     // control frames of 10 ms in 0.3 s
  EXPECT_GT(std::stod(ok[6]), 0.3);           // torso height, m
  EXPECT_NE(one.rows[0][5], one.rows[1][5]);  // seeds give other worlds
  const auto& blown = one.rows[2];
  EXPECT_EQ(blown[4], "failed");
  EXPECT_NE(blown.back().find("physics diverged"), std::string::npos) << blown.back();
  ASSERT_EQ(one.tallies.size(), 1u);
  EXPECT_EQ(one.tallies[0].texts[0][1], "2");  // n: the two ok runs on earth
  EXPECT_EQ(one.tallies[0].columns.back(), "failed");
  EXPECT_EQ(one.tallies[0].texts[1].back(), "2");
  EXPECT_EQ(read(a / "by_g.csv").substr(0, 15), "g,n,z,z_sd,fail");
  fs::remove_all(a), fs::remove_all(b);
}

TEST(SweepEngine, ASummaryThroughTheEndHasTheLastStepsFrameWhenTheMarkFallsJustShort) {
  // 0.30999999999999994 s rounds to step 310, whose frame is at 0.31 s: the 31st of 10 ms.
  const Sweep s(parse_sweep_text(R"(<sweep name="end" scenes="../../scenes">
  <scene file="nao_stand_controlled.xml"/>
  <run seconds="0.30999999999999994"/>
  <record>
    <value name="t" key="representation:FrameInfo.time"/>
    <summary name="frames" key="representation:FrameInfo.time" stat="count"/>
    <summary name="t_final" key="representation:FrameInfo.time" stat="final"/>
  </record>
</sweep>)",
                                 std::string(STRIDE_SOURCE_DIR) + "/tests/sweep/end.sweep.xml"));
  const fs::path d = fresh_dir("end");
  const SweepResult r = run(s, *in_process_executor(), d);
  ASSERT_TRUE(r.complete);
  const auto& row = r.rows[0];  // run, scene, seed, status, t, frames, t_final
  EXPECT_EQ(row[3], "ok");
  EXPECT_EQ(row[5], "31");
  EXPECT_EQ(row[6], row[4]);
  EXPECT_NEAR(std::stod(row[6]), 0.31, 1e-12);
  fs::remove_all(d);
}

TEST(SweepEngine, AWorkerKilledOnceIsRetriedAndOneKilledTwiceIsAFailedRow) {
  const Sweep s = standing_sweep();
  const fs::path ref = fresh_dir("ref"), out = fresh_dir("kill");
  run(s, *in_process_executor(), ref);
  const fs::path marker = out.string() + ".killed";
  fs::remove(marker);
  // Run 0 kills its worker the first time; run 1 every time.
  const RunFunction killing = [&](std::size_t i) {
    const bool first = !fs::exists(marker);
    if (i == 0 && first) std::ofstream(marker) << "x";
    if ((i == 0 && first) || i == 1) ::kill(::getpid(), SIGKILL);
    return s.run(i);
  };
  const SweepResult r = run(s, *worker_process_executor(2), out, killing);
  ASSERT_TRUE(r.complete);
  const std::string timing = read(out / "timing.csv");
  EXPECT_NE(timing.find("\n0,"), std::string::npos);
  EXPECT_EQ(r.rows[1][4], "failed");
  EXPECT_NE(r.rows[1].back().find("its worker died twice (last: worker process"),
            std::string::npos);
  EXPECT_NE(r.rows[1].back().find("killed by signal 9"), std::string::npos) << r.rows[1].back();
  // Run 0's row is the uninterrupted one.
  std::istringstream lines(read(ref / "runs.csv"));
  std::string header, row0;
  std::getline(lines, header), std::getline(lines, row0);
  EXPECT_NE(read(out / "runs.csv").find(row0 + "\n"), std::string::npos);
  fs::remove_all(ref), fs::remove_all(out), fs::remove(marker);
}

TEST(SweepEngine, AStoppedSweepResumesToTheUninterruptedRows) {
  const Sweep s = standing_sweep();
  const fs::path ref = fresh_dir("full"), out = fresh_dir("resume");
  run(s, *in_process_executor(), ref);
  std::atomic<int> runs{0};
  const RunFunction counted = [&](std::size_t i) {
    ++runs;
    return s.run(i);
  };
  const SweepResult part =
      run(s, *in_process_executor(), out, counted, [&] { return runs.load() >= 2; });
  EXPECT_FALSE(part.complete);
  EXPECT_EQ(part.ran, 2u);
  EXPECT_THROW(run(s, *in_process_executor(), out), Error);  // no silent overwrite
  runs = 0;
  const SweepResult rest = run(s, *in_process_executor(), out, counted, {}, true);
  EXPECT_TRUE(rest.complete);
  EXPECT_EQ(rest.resumed, 2u);
  EXPECT_EQ(runs.load(), 2);  // only what was missing
  EXPECT_EQ(read(out / "runs.csv"), read(ref / "runs.csv"));
  fs::remove_all(ref), fs::remove_all(out);
}

TEST(SweepEngine, AnUnwritableOutputIsRefusedBeforeAnyRun) {
  const Sweep s = standing_sweep();
  int runs = 0;
  const RunFunction counted = [&](std::size_t i) {
    ++runs;
    return s.run(i);
  };
  const std::string e =
      error_of([&] { run(s, *in_process_executor(), "/proc/stride-sweep/out", counted); });
  EXPECT_EQ(e.rfind("--out: cannot create directory '/proc/stride-sweep/out'", 0), 0u) << e;
  EXPECT_EQ(runs, 0);
}

TEST(SweepEngine, ARunWhoseTraceCannotBeWrittenIsAFailedRowAndTheSweepGoesOn) {
  const Sweep s = standing_sweep();
  const fs::path out = fresh_dir("trace");
  fs::create_directories(out / "traces" / "run-1.csv");  // a directory where run 1's trace goes
  // Each run ends ok with five record cells and a two-line trace (no physics needed here).
  const RunFunction traced = [](std::size_t i) {
    RunRow row;
    row.run = static_cast<std::int64_t>(i);
    row.ok = true;
    row.cells = {"h", "0.3", "0", "30", "300"};
    row.trace_csv = "t\n" + std::to_string(i) + "\n";
    return row;
  };
  const SweepResult r = run(s, *in_process_executor(), out, traced);
  ASSERT_TRUE(r.complete);
  EXPECT_EQ(r.failed, 1u);
  EXPECT_EQ(r.rows[0][4], "ok");
  EXPECT_EQ(r.rows[1][4], "failed");
  EXPECT_EQ(r.rows[1][5], "");  // a failed row carries no record values
  EXPECT_EQ(r.rows[1].back().rfind("trace not written: cannot write '", 0), 0u) << r.rows[1].back();
  EXPECT_EQ(r.rows[2][4], "ok");
  EXPECT_EQ(r.rows[3][4], "ok");
  EXPECT_EQ(read(out / "traces" / "run-3.csv"), "t\n3\n");
  EXPECT_FALSE(fs::exists(out / "traces" / "run-1.csv.tmp"));  // nothing half-written left
  EXPECT_NE(read(out / "runs.csv").find("\n1,"), std::string::npos);
  fs::remove_all(out);
}

// A sweep over scenes where one robot cannot be simulated (a URDF inertia ODE would abort on):
// the sweep is not refused, its runs are failed rows with the loader's file:line, the others run.
// A sweep whose every scene fails to load is refused before any run.
TEST(SweepEngine, ASceneThatDoesNotLoadGivesFailedRowsWhileAnotherLoads) {
  const auto sweep_of = [](const std::string& levels) {
    return Sweep(parse_sweep_text(R"(<sweep name="mixed" scenes="../../scenes">
  <scene file="nao_stand_controlled.xml"/>
  <factor name="robot">)" + levels + R"(</factor>
  <seeds from="1" to="2"/>
  <run seconds="0.05"/>
  <record><value name="z" key="frame.torso_z"/></record>
</sweep>)",
                                  std::string(STRIDE_SOURCE_DIR) + "/tests/sweep/mixed.sweep.xml"));
  };
  const std::string broken =
      R"(<level label="broken"><set target="scene" value="hostile/broken_urdf.xml"/></level>)";
  const Sweep s = sweep_of(
      R"(<level label="nao"><set target="scene" value="nao_stand_controlled.xml"/></level>)" +
      broken);
  ASSERT_EQ(s.unloadable_scenes().size(), 1u);
  const std::string note = s.unloadable_scenes()[0];
  EXPECT_EQ(note.rfind("run 2: ", 0), 0u) << note;
  EXPECT_NE(note.find("scenes/hostile/broken_urdf.xml:7: <robot name=\"arm\">"), std::string::npos)
      << note;
  const fs::path out = fresh_dir("mixed");
  const SweepResult r = run(s, *in_process_executor(), out);
  ASSERT_TRUE(r.complete);
  EXPECT_EQ(r.failed, 2u);
  EXPECT_EQ(r.rows[0][4], "ok");
  EXPECT_EQ(r.rows[1][4], "ok");
  EXPECT_EQ(r.rows[2][4], "failed");
  EXPECT_NE(r.rows[3].back().find("inertia violates the triangle inequality"), std::string::npos)
      << r.rows[3].back();
  fs::remove_all(out);
  const std::string e = error_of([&] { sweep_of(broken); });
  EXPECT_EQ(e.rfind("sweep 'mixed': run 0: ", 0), 0u) << e;
  EXPECT_NE(e.find("inertia violates the triangle inequality"), std::string::npos) << e;
}

TEST(SweepEngine, UnknownKeysAndColumnsAreFoundBeforeAnyRun) {
  const auto load = [](const std::string& record) {
    return error_of([&] {
      const Sweep s(
          parse_sweep_text("<sweep scenes=\"../../scenes\"><scene "
                           "file=\"nao_stand_controlled.xml\"/><run seconds=\"1\"/>\n" +
                               record + "\n</sweep>",
                           std::string(STRIDE_SOURCE_DIR) + "/tests/sweep/k.xml"));
      Tallies t(s);
    });
  };
  EXPECT_NE(load("<record><value name=\"a\" key=\"walk.stepz\"/></record>")
                .find("k.xml:2: unknown key 'walk.stepz'"),
            std::string::npos);
  EXPECT_NE(load("<record><summary name=\"a\" key=\"representation:TorsoStat.pitch\" "
                 "stat=\"max\"/></record>")
                .find("no representation 'TorsoStat'"),
            std::string::npos);
  EXPECT_NE(load("<tally name=\"t\" by=\"nope\"><count name=\"n\"/></tally>")
                .find("k.xml:2: unknown column 'nope'"),
            std::string::npos);
}

}  // namespace
}  // namespace stride::sweep
