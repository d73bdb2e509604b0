// `stride tune` on a search of 20 ms standing runs whose objective has a known optimum (the Stand
// parameters read back: shoulder_pitch 1.2, elbow_yaw 0.3): bad files are one file:line line and
// run nothing; an unwritable or occupied output is refused before any walk; the same file gives
// the same rows byte for byte at --jobs 1 and 2; a search killed with -9 and resumed gives the
// uninterrupted search's rows; `mpirun -n 2` gives the --jobs 1 rows and best candidate; the
// held-out sweep walks only the held-out seeds; the optimiser finds the optimum; the tuning-file
// fuzz target's corpus and mutations (tests/fuzz_tune).
#include <signal.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>

#include "console/tune/tune_parser.hpp"
#include "console/tune/tune_run.hpp"
#include "tests/child_process.hpp"
#include "tests/error_text.hpp"
#include "tests/fuzz_support/corpus.hpp"
#include "tests/fuzz_support/fuzz_loop.hpp"
#include "tests/fuzz_support/mutation.hpp"
#include "tests/fuzz_tune/tune_fuzz_target.hpp"

namespace stride {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

const std::string kStride = std::string(STRIDE_BINARY_DIR) + "/stride";

constexpr auto read = &test_support::read_text;

fs::path fresh(const std::string& name) {
  const fs::path d = test_support::fresh_path("tune", name);
  fs::create_directories(d);
  return d;
}

// The search as a file in `dir`: `train` seeds, runs of `seconds`, population x generations.
fs::path tune_file(const fs::path& dir, const std::string& train, double seconds, int population,
                   int generations) {
  std::ostringstream t;
  t << "<tune name=\"stand\" scenes=\"" << STRIDE_SOURCE_DIR << "/scenes\">\n"
    << "  <scene file=\"nao_stand_controlled.xml\"/>\n"
    << "  <param name=\"sp\" target=\"Stand.shoulder_pitch\" min=\"0.5\" max=\"2\" "
       "thesis=\"1.5\"/>\n"
    << "  <param name=\"ey\" target=\"Stand.elbow_yaw\" min=\"-1\" max=\"1\" thesis=\"0\"/>\n"
    << "  <train><seeds values=\"" << train << "\"/></train>\n"
    << "  <heldout><seeds values=\"7 8 9\"/></heldout>\n"
    << "  <run seconds=\"" << seconds << "\"/>\n"
    << "  <record>\n"
    << "    <value name=\"sp_read\" key=\"module:Stand.shoulder_pitch\"/>\n"
    << "    <value name=\"ey_read\" key=\"module:Stand.elbow_yaw\"/>\n"
    << "    <value name=\"hash\" key=\"sim.hash\"/>\n"
    << "  </record>\n"
    << "  <objective value=\"-(sp_read - 1.2) * (sp_read - 1.2) - (ey_read - 0.3) * (ey_read - "
       "0.3)\" failed=\"-10\"/>\n"
    << "  <search population=\"" << population << "\" generations=\"" << generations
    << "\" seed=\"3\"/>\n"
    << "</tune>\n";
  const fs::path f = dir / "stand.tune.xml";
  std::ofstream(f) << t.str();
  return f;
}

tune::TuneResult search(const fs::path& file, const fs::path& out, int jobs) {
  tune::TuneRequest r;
  r.file = file.string();
  r.out_dir = out.string();
  r.jobs = jobs;
  r.quiet = true;
  r.plots = false;
  std::ostringstream sink;
  return *tune::run_tune(r, sink, sink);
}

// Every file a search's rows are in, as one text: search.csv, each generation's runs.csv, the
// held-out runs.csv.
std::string rows(const fs::path& out) {
  std::string all = read(out / "search.csv");
  for (int g = 0; fs::exists(out / "generations" / ("gen-000" + std::to_string(g))); ++g)
    all += read(out / "generations" / ("gen-000" + std::to_string(g)) / "runs.csv");
  return all + read(out / "heldout" / "runs.csv");
}

// The values of column `name` in a runs.csv.
std::set<std::string> column(const fs::path& csv, const std::string& name) {
  std::istringstream in(read(csv));
  std::string line, cell;
  std::getline(in, line);
  std::istringstream head(line);
  int at = 0;
  while (std::getline(head, cell, ',') && cell != name) ++at;
  std::set<std::string> values;
  while (std::getline(in, line)) {
    std::istringstream cells(line);
    for (int i = 0; i <= at; ++i) std::getline(cells, cell, ',');
    values.insert(cell);
  }
  return values;
}

std::string parse_error(const std::string& text) {
  return test_support::error_of([&] { tune::parse_tune_text(text, "t.xml"); });
}

// The binary's exit code (its output in `log`); with `started`, returns at once with its pid.
int run_binary(const std::vector<std::string>& args, const fs::path& log,
               pid_t* started = nullptr) {
  const pid_t pid = test_support::start_process(args, log, log.string() + ".err");
  if (started) return *started = pid, 0;
  const int code = test_support::finish_process(pid);
  std::ofstream(log, std::ios::app) << read(log.string() + ".err");
  return code;
}

TEST(TuneFile, ErrorsAreOneLineNamingFileAndLine) {
  const std::string head = "<tune>\n<scene file=\"s.xml\"/>\n";
  const std::string tail =
      "<train><seeds values=\"1\"/></train>\n<heldout><seeds values=\"2\"/></heldout>\n"
      "<run seconds=\"1\"/>\n<objective value=\"1\" failed=\"0\"/>\n"
      "<search population=\"4\" generations=\"1\"/>\n</tune>\n";
  const std::string param = "<param name=\"k\" target=\"M.k\" min=\"0\" max=\"1\" thesis=\"0\"/>\n";
  EXPECT_EQ(parse_error(head + param + tail), "");
  EXPECT_EQ(
      parse_error(head + "<param name=\"k\" target=\"M.k\" min=\"1\" max=\"0\" thesis=\"0\"/>\n" +
                  tail),
      "t.xml:3: <param>: attribute 'max': expected finite bounds with max > min");
  EXPECT_EQ(parse_error(head + param + "<heldout><seeds values=\"3\"/></heldout>\n" + tail),
            "t.xml:6: <heldout>: a second <heldout>");
  EXPECT_EQ(parse_error(head + tail), "t.xml:1: <tune>: expected at least one <param>");
  const std::string overlap = head + param +
                              "<train><seeds values=\"1 2\"/></train>\n"
                              "<heldout><seeds values=\"2 3\"/></heldout>\n"
                              "<run seconds=\"1\"/>\n<objective value=\"1\" failed=\"0\"/>\n"
                              "<search population=\"4\" generations=\"1\"/>\n</tune>\n";
  EXPECT_EQ(parse_error(overlap),
            "t.xml:5: held-out walk (floor scene, seed 2) is also a training walk");
}

TEST(TuneFile, ShippedTuningFilesParseAndBindOnTheirScenes) {
  int files = 0;
  for (const auto& e : fs::recursive_directory_iterator(fs::path(STRIDE_SOURCE_DIR) / "scenes")) {
    if (!e.path().filename().string().ends_with(".tune.xml")) continue;
    SCOPED_TRACE(e.path().string());
    const tune::TuneSpec spec = tune::parse_tune_file(e.path().string());
    std::vector<double> thesis;
    for (const tune::TuneParam& p : spec.params) thesis.push_back(p.thesis);
    const sweep::Sweep sweep(tune::batch_spec(spec, {"generation", 0, {"0"}, {thesis}}), true);
    EXPECT_TRUE(sweep.unloadable_scenes().empty());
    ++files;
  }
  EXPECT_GE(files, 1);
}

TEST(TuneProcess, BadFileIsOneLineAndRunsNothing) {
  const fs::path dir = fresh("bad");
  std::string text = read(tune_file(dir, "1", 0.02, 4, 1));
  text.replace(text.find("sp_read - 1.2"), 7, "nope");  // an unknown column in the objective
  std::ofstream(dir / "bad.xml") << text;
  EXPECT_EQ(
      run_binary({kStride, "tune", (dir / "bad.xml").string(), "--out", (dir / "out").string()},
                 dir / "log"),
      3);
  const std::string log = read(dir / "log");
  EXPECT_EQ(log.rfind((dir / "bad.xml").string() + ":13: expression '-(nope - 1.2)", 0), 0u) << log;
  EXPECT_NE(log.find("unknown column 'nope'"), std::string::npos) << log;
  EXPECT_EQ(std::count(log.begin(), log.end(), '\n'), 1) << log;
  EXPECT_FALSE(fs::exists(dir / "out"));
  fs::remove_all(dir);
}

TEST(TuneProcess, UnwritableOrOccupiedOutputIsRefusedBeforeAnyWalk) {
  const fs::path dir = fresh("refused");
  const fs::path file = tune_file(dir, "1", 0.02, 4, 1);
  std::ofstream(dir / "plain") << "a file, not a directory\n";
  tune::TuneRequest r;
  r.file = file.string();
  r.out_dir = (dir / "plain" / "out").string();
  r.jobs = 1;
  std::ostringstream out, err;
  EXPECT_THROW(tune::run_tune(r, out, err), Error);
  EXPECT_EQ(err.str(), "");  // no progress: nothing ran
  search(file, dir / "done", 1);
  const std::string before = rows(dir / "done");
  r.out_dir = (dir / "done").string();
  try {
    tune::run_tune(r, out, err);
    ADD_FAILURE() << "an output holding a search was reused";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("already holds a search"), std::string::npos) << e.what();
  }
  EXPECT_EQ(rows(dir / "done"), before);
  fs::remove_all(dir);
}

class TuneSearch : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fresh("search");
    file_ = tune_file(dir_, "1 2", 0.02, 4, 2);
    one_ = search(file_, dir_ / "jobs1", 1);
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }
  static fs::path dir_, file_;
  static tune::TuneResult one_;
};
fs::path TuneSearch::dir_, TuneSearch::file_;
tune::TuneResult TuneSearch::one_;

TEST_F(TuneSearch, SameRowsByteForByteAtOneAndTwoWorkers) {
  ASSERT_TRUE(one_.complete);
  EXPECT_EQ(one_.generations, 3);
  EXPECT_EQ(one_.walks, 24u);  // 3 generations x 4 candidates x 2 seeds
  search(file_, dir_ / "jobs2", 2);
  EXPECT_EQ(rows(dir_ / "jobs2"), rows(dir_ / "jobs1"));
  EXPECT_EQ(read(dir_ / "jobs1" / "search.csv").size(), read(dir_ / "jobs2" / "search.csv").size());
}

TEST_F(TuneSearch, HeldOutWalksAreTheHeldOutSeedsOnly) {
  const fs::path held = dir_ / "jobs1" / "heldout" / "runs.csv";
  EXPECT_EQ(column(held, "seed"), (std::set<std::string>{"7", "8", "9"}));
  EXPECT_EQ(column(held, "candidate"), (std::set<std::string>{"thesis", "tuned"}));
  for (const char* g : {"gen-0000", "gen-0001", "gen-0002"})
    EXPECT_EQ(column(dir_ / "jobs1" / "generations" / g / "runs.csv", "seed"),
              (std::set<std::string>{"1", "2"}));
  // The thesis' values read back (1.5, 0): -(0.3^2) - (0.3^2).
  EXPECT_NEAR(one_.heldout_thesis.objective, -0.18, 1e-12);
  EXPECT_EQ(one_.heldout_thesis.walks, 3);
  // The same walk on every seed here: the tuned values' objective (a mean of 3, not 2, walks).
  EXPECT_NEAR(one_.heldout_tuned.objective, one_.best.score.objective, 1e-15);
}

// The workers (timing.csv's last column) that walked any of a search's batches.
std::set<std::string> workers(const fs::path& out) {
  std::set<std::string> all;
  for (const auto& e : fs::recursive_directory_iterator(out))
    if (e.path().filename() == "timing.csv")
      for (const std::string& w : column(e.path(), "worker")) all.insert(w);
  return all;
}

TEST_F(TuneSearch, MpirunTwoRanksGivesTheSameRowsAndTheSameBest) {
  if (::system("command -v mpirun > /dev/null") != 0) GTEST_SKIP() << "no mpirun";
  const fs::path out = dir_ / "mpi";
  const int code = run_binary(
      test_support::under_mpirun(
          2, {kStride, "tune", file_.string(), "--quiet", "--no-plots", "--out", out.string()}),
      dir_ / "mpi.log");
  const std::string log = read(dir_ / "mpi.log");
  if (log.find("built without MPI") != std::string::npos) GTEST_SKIP() << log;
  ASSERT_EQ(code, 0) << log;
  EXPECT_EQ(rows(out), rows(dir_ / "jobs1"));
  EXPECT_EQ(read(out / "results.txt"), read(dir_ / "jobs1" / "results.txt"));
  // The best candidate as results.txt names it, the one the in-process search chose.
  std::ostringstream best;
  best << "(generation " << one_.best.generation << ", candidate " << one_.best.label << ")";
  EXPECT_NE(read(out / "results.txt").find(best.str()), std::string::npos) << best.str();
  EXPECT_EQ(workers(out), (std::set<std::string>{"0", "1"})) << "both ranks walked";
}

TEST(TuneProcess, KillNineThenResumeGivesTheUninterruptedRows) {
  const fs::path dir = fresh("killed");
  const fs::path file = tune_file(dir, "1", 0.15, 4, 2);
  ASSERT_EQ(run_binary({kStride, "tune", file.string(), "--jobs", "1", "--quiet", "--no-plots",
                        "--out", (dir / "whole").string()},
                       dir / "whole.log"),
            0)
      << read(dir / "whole.log");
  pid_t pid = -1;
  run_binary({kStride, "tune", file.string(), "--jobs", "1", "--quiet", "--no-plots", "--out",
              (dir / "cut").string()},
             dir / "cut.log", &pid);
  const fs::path second = dir / "cut" / "generations" / "gen-0001" / "runs.csv";
  const auto lines = [&] {
    const std::string t = read(second);
    return std::count(t.begin(), t.end(), '\n');
  };
  for (int i = 0; i < 600 && lines() < 2; ++i) std::this_thread::sleep_for(20ms);
  ::kill(-pid, SIGKILL);
  ::waitpid(pid, nullptr, 0);
  ASSERT_FALSE(fs::exists(dir / "cut" / "heldout")) << "killed before the end";
  EXPECT_EQ(run_binary({kStride, "tune", file.string(), "--jobs", "1", "--quiet", "--no-plots",
                        "--resume", "--out", (dir / "cut").string()},
                       dir / "resumed.log"),
            0)
      << read(dir / "resumed.log");
  EXPECT_EQ(rows(dir / "cut"), rows(dir / "whole"));
  EXPECT_EQ(read(dir / "cut" / "results.txt"), read(dir / "whole" / "results.txt"));
  fs::remove_all(dir);
}

TEST(TuneSearchOptimum, FindsTheKnownOptimumOfATinyProblem) {
  const fs::path dir = fresh("optimum");
  const tune::TuneResult r = search(tune_file(dir, "1", 0.01, 6, 10), dir / "out", 1);
  ASSERT_TRUE(r.complete);
  EXPECT_EQ(r.walks, 66u);
  EXPECT_NEAR(r.best.values.at(0), 1.2, 0.06);
  EXPECT_NEAR(r.best.values.at(1), 0.3, 0.08);
  EXPECT_GT(r.best.score.objective, -0.005);
  // Better than its first, random generation's best (objective: search.csv's fifth column).
  std::istringstream in(read(dir / "out" / "search.csv"));
  std::string line, cell;
  double first = -1e9;
  std::getline(in, line);
  while (std::getline(in, line) && line.rfind("0,", 0) == 0) {
    std::istringstream cells(line);
    for (int c = 0; c < 5; ++c) std::getline(cells, cell, ',');
    first = std::max(first, std::stod(cell));
  }
  EXPECT_GT(r.best.score.objective, first + 0.001);
  fs::remove_all(dir);
}

TEST(TuneFuzz, CorpusAndMutationsAreAcceptedOrFailWithOneLine) {
  const auto seeds = test::read_corpus("tests/fuzz_tune/corpus");
  ASSERT_GE(seeds.size(), 2u);
  static const char* const kTokens[] = {"<",      ">",         "/>",    "\"",     "=",
                                        "nan",    "-1",        "1e308", "<param", "<floor",
                                        "<seeds", "floors=\"", "\0"};
  const test::FuzzOutcomes n = test::fuzz_seeds_and_mutations(
      seeds, 2000, 32,
      [](const std::string& in) {
        return test::tune_fuzz_input(reinterpret_cast<const std::uint8_t*>(in.data()), in.size());
      },
      [&](const std::string& seed, std::mt19937_64& rng) {
        return test::mutate(seed, rng, kTokens, 0);
      });
  EXPECT_GT(n.errors, 100);
  EXPECT_GE(n.accepted, 2);
}

}  // namespace
}  // namespace stride
