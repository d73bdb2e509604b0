// Ch. 5 swing-leg control: the adaptive and PD laws against their definitions, the Lyapunov
// function of Eq. 5.7 along closed-loop runs, parameter convergence, and integration accuracy.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include <unistd.h>

#include "behaviours/swing_leg/adaptive_control.hpp"
#include "behaviours/swing_leg/swing_leg_plant.hpp"
#include "behaviours/swing_leg/thesis_runs.hpp"
#include "console/cli/subcommand.hpp"
#include "robot/core/error.hpp"

namespace stride::swing_leg {
namespace {

TEST(SlidingTerms, VelocityErrorIsQTildeDotPlusLambdaQTilde) {  // Eq. 5.3
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-2, 2);
  for (int k = 0; k < 100; ++k) {
    const Eigen::Vector3d q(u(rng), u(rng), u(rng)), qd(u(rng), u(rng), u(rng));
    const JointReference<3> r{
        {u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}};
    const double lambda = 1 + 100 * std::abs(u(rng));
    const SlidingTerms<3> t = sliding_terms<3>(q, qd, r, lambda);
    EXPECT_LT((t.s - ((qd - r.qd) + lambda * (q - r.q))).norm(), 1e-9);
    // The PD law with K_P = Lambda K_D is exactly -K_D s (Eq. 5.15).
    EXPECT_LT((pd_torque<3>(q, qd, r, lambda, 100) + 100 * t.s).norm(), 1e-6);
  }
}

TEST(AdaptiveLaw, WithTheTrueParametersItIsComputedTorquePlusFeedback) {  // Eqs. 5.1-5.5
  const PlanarLegPlant plant;
  const Eigen::Vector3d q(0.3, -0.5, 0.2), qd(1.0, -2.0, 0.5);
  const JointReference<3> r{{0.1, -0.4, 0.1}, {0.8, -1.5, 0.2}, {3.0, 1.0, -2.0}};
  const SlidingTerms<3> t = sliding_terms<3>(q, qd, r, 200);
  const auto y = PlanarLegPlant::regressor(q, qd, t.qd_r, t.qdd_r);
  const Eigen::Vector3d tau = adaptive_torque<3, 9>(y, plant.a, t, 100);
  const Eigen::Vector3d expected = model::planar_inertia(q, plant.a) * t.qdd_r +
                                   model::planar_coriolis(q, qd, plant.a) * t.qd_r +
                                   model::planar_gravity(q, plant.a) - 100 * t.s;
  EXPECT_LT((tau - expected).norm(), 1e-9 * expected.norm());
  // Eq. 5.6: the estimate moves against Y^T s, weighted per parameter.
  const model::Vector9d gamma = model::Vector9d::Constant(0.5);
  EXPECT_LT((adaptation_rate<3, 9>(y, t, gamma) + 0.5 * y.transpose() * t.s).norm(), 1e-12);
}

// V' = -s^T K_D s <= 0 (Eq. 5.13): along a smooth tracking run V falls at every step.
double worst_lyapunov_rise(double dt, double* v0, double* v_end) {
  ThesisRun run = thesis_run("planar-track");  // smooth: no step for the integrator to smear
  run.options.duration = 2.0;
  run.options.dt = dt;
  run.options.record_every = dt;
  const TrackingResult r = simulate_tracking(run.options, run.reference);
  double worst = 0;
  for (size_t i = 1; i < r.samples.size(); ++i)
    worst = std::max(worst, r.samples[i].lyapunov - r.samples[i - 1].lyapunov);
  *v0 = r.samples.front().lyapunov;
  *v_end = r.samples.back().lyapunov;
  return worst;
}

TEST(ClosedLoop, LyapunovFunctionFallsUnderAdaptiveControl) {  // Eqs. 5.7-5.13
  for (double dt : {1e-4, 2.5e-5}) {
    double v0 = 0, v_end = 0;
    EXPECT_LE(worst_lyapunov_rise(dt, &v0, &v_end), 1e-12 * v0) << dt;
    EXPECT_GT(v0, 0.1);  // mostly the parameter error: a^ starts at zero
    EXPECT_LT(v_end, 0.6 * v0);
  }
}

TEST(ClosedLoop, StepResponsesSettleOnTheCommandedAngles) {
  for (const char* name : {"planar-step", "3d-step"}) {
    ThesisRun run = thesis_run(name);
    for (Controller c : {Controller::Adaptive, Controller::Pd}) {
      run.options.controller = c;
      const TrackingResult r = simulate_tracking(run.options, run.reference);
      EXPECT_LT((r.samples.back().q - r.samples.back().q_desired).cwiseAbs().maxCoeff(), 1e-4)
          << name;
    }
  }
}

TEST(ClosedLoop, GravitationalEstimatesConvergeToTheModelsValues) {
  // Sec. 5.4.1.1 shows them settling within 500 s; a 1 ms step keeps this test short.
  ThesisRun run = thesis_run("planar-step");
  run.options.duration = 500;
  run.options.dt = 1e-3;
  run.options.record_every = 1.0;
  const TrackingResult r = simulate_tracking(run.options, run.reference);
  for (int i = 6; i < 9; ++i)
    EXPECT_NEAR(r.final_estimate[i], r.true_parameters[i], 0.05 * r.true_parameters[6]) << i;
}

TEST(ClosedLoop, HalvingTheStepChangesTrackingErrorsByLittle) {
  ThesisRun run = thesis_run("planar-track");
  run.options.duration = 4;
  run.options.controller = Controller::Pd;
  const TrackingResult coarse = simulate_tracking(run.options, run.reference);
  run.options.dt /= 2;
  const TrackingResult fine = simulate_tracking(run.options, run.reference);
  for (int j = 0; j < 3; ++j)
    EXPECT_NEAR(coarse.late_rms_error[j], fine.late_rms_error[j], 0.05 * fine.late_rms_error[j]);
}

TEST(ClosedLoop, BadOptionsAreOneLineErrors) {
  ThesisRun run = thesis_run("planar-step");
  run.options.gamma.resize(4);
  EXPECT_THROW(simulate_tracking(run.options, run.reference), Error);
  run = thesis_run("planar-step");
  run.options.dt = 0;
  EXPECT_THROW(simulate_tracking(run.options, run.reference), Error);
  try {
    thesis_run("nope");
    FAIL();
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(),
                 "unknown swing-leg study 'nope' (expected planar-step, planar-track, 3d-step, "
                 "3d-track)");
  }
}

}  // namespace
}  // namespace stride::swing_leg

namespace stride::cli {
namespace {

int run_swing_leg(std::vector<std::string> args, std::string& out, std::string& err) {
  for (const auto& s : subcommands())
    if (s.name == "swing-leg") {
      std::ostringstream o, e;
      const int rc = s.run(args, o, e);
      out = o.str();
      err = e.str();
      return rc;
    }
  return -1;
}

TEST(SwingLegCommand, PrintsBothControllersAndWritesTheirCsv) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("stride_swing_leg_" + std::to_string(::getpid()));
  std::string out, err;
  ASSERT_EQ(run_swing_leg({"planar-step", "--seconds", "0.2", "--csv", dir.string()}, out, err), 0)
      << err;
  EXPECT_NE(out.find("adaptive  rms error"), std::string::npos) << out;
  EXPECT_NE(out.find("pd        rms error"), std::string::npos) << out;
  std::ifstream csv(dir / "planar-step_adaptive.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header.rfind("t,hip_pitch_desired,knee_desired,ankle_pitch_desired,hip_pitch,", 0), 0u)
      << header;
  EXPECT_TRUE(std::filesystem::exists(dir / "planar-step_pd.csv"));
  EXPECT_EQ(run_swing_leg({"nope"}, out, err), 2);
  EXPECT_EQ(err,
            "unknown swing-leg study 'nope' (expected planar-step, planar-track, 3d-step, "
            "3d-track)\n");
  EXPECT_EQ(run_swing_leg({"3d-step", "--controller", "fuzzy"}, out, err), 2);
  EXPECT_NE(err.find("--controller: expected adaptive, pd or both"), std::string::npos);
}

}  // namespace
}  // namespace stride::cli
