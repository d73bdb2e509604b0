// Ensembles of perturbed starts: members drawn within their spreads and independent of the
// ensemble's size, placed as drawn, the same results in worker processes as in this one, and
// the spread and agreement figures against hand-computed values.
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "console/cli/subcommand.hpp"
#include "console/ensemble/convergence.hpp"
#include "console/ensemble/ensemble_run.hpp"
#include "console/ensemble/ensemble_summary.hpp"
#include "simulator/simulation.hpp"

namespace stride {
namespace cli {
int run_main(Args args, std::ostream& out, std::ostream& err);
int converge_main(Args args, std::ostream& out, std::ostream& err);
}  // namespace cli
namespace {

const std::string kStand = std::string(STRIDE_SOURCE_DIR) + "/scenes/nao_stand.xml";

int run(std::vector<std::string> args, std::ostream& out, std::ostream& err) {
  return cli::run_main(args, out, err);
}

TEST(EnsembleStarts, MembersLieWithinTheirSpreadsAndDependOnTheirSeedOnly) {
  sim::EnsembleSpec small{
      .members = 2, .first_seed = 5, .heading_spread = 0.003, .position_spread = 0.002};
  sim::EnsembleSpec large = small;
  large.members = 50;
  double largest_heading = 0;
  for (int k = 0; k < large.members; ++k) {
    const sim::StartPerturbation p = sim::ensemble_member(large, k);
    EXPECT_EQ(p.seed, 5u + k);
    EXPECT_LE(std::abs(p.heading), 0.003);
    EXPECT_LE(p.offset.cwiseAbs().maxCoeff(), 0.002);
    largest_heading = std::max(largest_heading, std::abs(p.heading));
  }
  EXPECT_GT(largest_heading, 0.002);  // the draws use the range, not a corner of it
  const sim::StartPerturbation a = sim::ensemble_member(small, 1),
                               b = sim::ensemble_member(large, 1);
  EXPECT_EQ(a.heading, b.heading);
  EXPECT_EQ(a.offset, b.offset);
  EXPECT_NE(sim::ensemble_member(small, 0).heading, a.heading);
}

TEST(EnsembleStarts, TheRobotStartsWhereTheMemberSays) {
  sim::SceneDescription scene = sim::parse_scene_file(kStand);
  const sim::Simulation plain(scene);
  sim::StartPerturbation p{.seed = 9, .heading = 0.02, .offset = {0.01, -0.005}};
  sim::apply_start(scene, p);
  const sim::Simulation moved(scene);
  EXPECT_EQ(moved.scene().physics.seed, 9u);
  const sim::TorsoPose t0 = plain.robot(0).torso_pose(), t1 = moved.robot(0).torso_pose();
  EXPECT_NEAR(t1.yaw - t0.yaw, 0.02, 1e-12);
  EXPECT_NEAR(t1.x - t0.x, 0.01, 1e-12);
  EXPECT_NEAR(t1.y - t0.y, -0.005, 1e-12);
  EXPECT_NEAR(t1.z, t0.z, 1e-12);
}

TEST(EnsembleRun, WorkersGiveTheSameMembersInOrder) {
  ensemble::EnsembleRequest r{
      kStand, sim::parse_physics_setting("iterations=10"), {.members = 3, .first_seed = 1}, 0.12};
  ensemble::EnsembleRequest exact = r;
  exact.physics = sim::parse_physics_setting("solver=exact");
  exact.spec.members = 1;
  const auto here = ensemble::run_ensembles({r, exact}, 1);
  const auto forked = ensemble::run_ensembles({r, exact}, 2);
  ASSERT_EQ(here.size(), 2u);
  ASSERT_EQ(here[0].size(), 3u);
  ASSERT_EQ(here[1].size(), 1u);
  for (std::size_t i = 0; i < 2; ++i)
    for (std::size_t k = 0; k < here[i].size(); ++k) {
      EXPECT_EQ(here[i][k].walk.torso_distance, forked[i][k].walk.torso_distance);
      EXPECT_EQ(here[i][k].walk.yaw_max, forked[i][k].walk.yaw_max);
      EXPECT_NEAR(here[i][k].sim_seconds, 0.12, 1e-9);
    }
  // Members differ (their starts do), and so do the solvers on one start.
  EXPECT_NE(here[0][0].walk.torso_distance, here[0][1].walk.torso_distance);
  EXPECT_NE(here[0][0].walk.torso_distance, here[1][0].walk.torso_distance);
}

ensemble::MemberOutcome walk(double distance, int steps, bool fell = false,
                             sim::Tip tip = sim::Tip::None) {
  ensemble::MemberOutcome m;
  m.walk.true_distance = distance;
  m.walk.fk_distance = distance + 0.5;
  m.walk.steps = steps;
  m.walk.fell = fell;
  m.walk.tipped = tip;
  m.sim_seconds = 10;
  m.wall_seconds = 2;
  return m;
}

TEST(EnsembleSummary, SpreadOverKeptWalksAndLostCount) {
  const ensemble::Spread s = ensemble::spread_of({1.0, 2.0, 4.0});
  EXPECT_DOUBLE_EQ(s.mean, 7.0 / 3);
  EXPECT_DOUBLE_EQ(s.sd, std::sqrt(((1 - 7.0 / 3) * (1 - 7.0 / 3) + (2 - 7.0 / 3) * (2 - 7.0 / 3) +
                                    (4 - 7.0 / 3) * (4 - 7.0 / 3)) /
                                   2));
  EXPECT_EQ(s.min, 1.0);
  EXPECT_EQ(s.max, 4.0);
  const auto e = ensemble::summarize_ensemble(
      {walk(2.0, 60), walk(2.2, 62), walk(0.7, 20, true), walk(1.5, 50, false, sim::Tip::Left)});
  EXPECT_EQ(e.members, 4);
  EXPECT_EQ(e.fell, 1);
  EXPECT_EQ(e.lost, 2);
  EXPECT_EQ(e.true_distance.n, 2);
  EXPECT_DOUBLE_EQ(e.true_distance.mean, 2.1);
  EXPECT_DOUBLE_EQ(e.fk_distance.mean, 2.6);
  EXPECT_DOUBLE_EQ(e.steps.mean, 61);
  EXPECT_DOUBLE_EQ(e.real_time_factor, 5.0);
  EXPECT_EQ(ensemble::spread_text(ensemble::spread_of({}), 3), "-");
}

TEST(Convergence, AgreementAndTheCheapestAgreeingSetting) {
  using ensemble::EnsembleSummary;
  auto summary = [](std::vector<ensemble::MemberOutcome> m, double wall) {
    for (auto& x : m) x.wall_seconds = wall;
    return ensemble::summarize_ensemble(m);
  };
  const EnsembleSummary reference = summary({walk(2.0, 60), walk(2.0, 60), walk(1.0, 30, true)}, 8);
  const EnsembleSummary close = summary({walk(2.08, 61), walk(2.0, 60), walk(1, 9, true)}, 2);
  const EnsembleSummary far = summary({walk(2.4, 60), walk(2.4, 60), walk(1, 9, true)}, 1);
  const EnsembleSummary falls = summary({walk(2.0, 60), walk(1, 9, true), walk(1, 9, true)}, 1);
  ensemble::Tolerance tol{.distance = 0.05, .lost = 1};
  std::string why;
  EXPECT_TRUE(ensemble::agrees(close, reference, tol, why)) << why;
  EXPECT_FALSE(ensemble::agrees(far, reference, tol, why));
  EXPECT_EQ(why, "distance 2.400 vs 2.000 m");
  EXPECT_TRUE(ensemble::agrees(falls, reference, tol, why));
  tol.lost = 0;
  EXPECT_FALSE(ensemble::agrees(falls, reference, tol, why));
  EXPECT_EQ(why, "lost 2 vs 1");
  EXPECT_EQ(ensemble::cheapest_agreeing({far, close, falls, reference}, 3, tol), 1);
  tol.distance = 0.25;
  EXPECT_EQ(ensemble::cheapest_agreeing({far, close, falls, reference}, 3, tol), 0);
}

TEST(EnsembleCommand, RunPrintsEveryMemberAndTheSpread) {
  std::ostringstream out, err;
  const int rc =
      run({kStand, "--ensemble", "2", "--seconds", "0.05", "--jobs", "2", "--seed", "3"}, out, err);
  ASSERT_EQ(rc, 0) << err.str();
  const std::string text = out.str();
  EXPECT_NE(text.find("ensemble of 2 perturbed starts"), std::string::npos) << text;
  EXPECT_NE(text.find("lost"), std::string::npos);
  EXPECT_NE(text.find("0/2"), std::string::npos);  // two standing NAOs: none fell
  std::ostringstream bad_out, bad_err;
  EXPECT_EQ(run({kStand, "--ensemble", "2", "--report", "r.json"}, bad_out, bad_err),
            2);  // a wrong command line
  EXPECT_EQ(bad_err.str(), "stride run: --report: not with --ensemble (one run only)\n");
}

TEST(ConvergeCommand, TablesEverySettingAndWritesTheCurves) {
  const std::string dir = testing::TempDir() + "/converge_test";
  std::vector<std::string> args{kStand,     "--settings", "iterations=10 solver=exact",
                                "--starts", "2",          "--seconds",
                                "0.05",     "--jobs",     "1",
                                "--out",    dir,          "--no-plots"};
  std::ostringstream out, err;
  ASSERT_EQ(cli::converge_main(args, out, err), 0) << err.str();
  const std::string text = out.str();
  EXPECT_NE(text.find("2 starts (seeds 1-2"), std::string::npos) << text;
  EXPECT_NE(text.find("reference solver=exact"), std::string::npos);
  EXPECT_NE(text.find("iterations=10 "), std::string::npos);
  EXPECT_NE(text.find("cheapest agreeing setting: "), std::string::npos);
  std::ifstream csv(dir + "/converge_distance.csv");
  ASSERT_TRUE(csv.good());
  int lines = 0;
  for (std::string line; std::getline(csv, line);) ++lines;
  EXPECT_EQ(lines, 3);  // header + two settings
  std::ifstream names(dir + "/converge_settings.txt");
  std::string first;
  std::getline(names, first);
  EXPECT_EQ(first, "1 iterations=10");
}

// A study in which every walk falls has completed with a negative result: it says so, writes its
// tables and the outcome plot, leaves out the distance plot (no point to draw; gnuplot refused
// it, and the command exited 1 before writing the rest), and exits 0.
TEST(ConvergeCommand, NoKeptWalkIsSaidAndTabledAndExitsZero) {
  const std::string dir = testing::TempDir() + "/converge_none";
  const std::string scene = testing::TempDir() + "/converge_limp.xml";
  const std::string robots = std::string(STRIDE_SOURCE_DIR) + "/scenes/robots/nao/";
  std::ofstream(scene) << "<scene><physics step=\"1ms\" seed=\"1\"/><ground/>"
                       << "<robot name=\"nao\" urdf=\"" << robots << "nao.urdf\" devices=\""
                       << robots << "nao.devices.xml\" xyz=\"0 0 auto\" stiffness=\"0\">"
                       << "<joints LKneePitch=\"0.6\"/></robot></scene>";
  std::vector<std::string> args{scene,       "--settings", "iterations=10", "--starts", "1",
                                "--seconds", "1.2",        "--jobs",        "1",        "--out",
                                dir};
  std::ostringstream out, err;
  ASSERT_EQ(cli::converge_main(args, out, err), 0) << err.str();
  EXPECT_EQ(err.str(), "");
  EXPECT_NE(out.str().find("\niterations=10   1/1   1/1"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("no setting kept the walk upright in 1 starts"), std::string::npos);
  EXPECT_EQ(out.str().find("cheapest agreeing setting"), std::string::npos);
  std::ifstream csv(dir + "/converge_distance.csv");
  std::string header, row;
  std::getline(csv, header);
  std::getline(csv, row);
  EXPECT_EQ(row.substr(0, 6), "1,1,1,");  // setting 1: one member, fell, lost
  EXPECT_FALSE(std::ifstream(dir + "/converge_distance.png").good());
  EXPECT_TRUE(std::ifstream(dir + "/converge_outcome.png").good());
  EXPECT_TRUE(std::ifstream(dir + "/converge_settings.txt").good());
}

}  // namespace
}  // namespace stride
