#include "behaviours/swing_leg/tracking_simulation.hpp"

#include <cmath>

#include <Eigen/Dense>

#include "behaviours/swing_leg/adaptive_control.hpp"
#include "behaviours/swing_leg/swing_leg_plant.hpp"
#include "robot/core/error.hpp"

namespace stride::swing_leg {
namespace {

// The recorded state at time t: errors, estimate, the Lyapunov function and the torque.
template <typename Plant>
TrackingSample sample_at(const Plant& plant, const TrackingOptions& o, double t,
                         const typename Plant::Vec& q, const typename Plant::Vec& qd,
                         const JointReference<Plant::kJoints>& r, const typename Plant::Mat& h,
                         const typename Plant::Params& a_hat) {
  constexpr int N = Plant::kJoints, P = Plant::kParameters;
  const typename Plant::Params gamma = o.gamma;
  const SlidingTerms<N> st = sliding_terms<N>(q, qd, r, o.lambda);
  TrackingSample s;
  s.t = t;
  s.q = q;
  s.q_desired = r.q;
  s.a_hat = a_hat;
  const typename Plant::Params a_err = a_hat - plant.a;
  s.lyapunov = 0.5 * st.s.dot(h * st.s) +
               0.5 * a_err.dot(gamma.cwiseInverse().cwiseProduct(a_err));  // Eq. 5.7
  s.tau = o.controller == Controller::Adaptive
              ? adaptive_torque<N, P>(Plant::regressor(q, qd, st.qd_r, st.qdd_r), a_hat, st, o.kd)
              : pd_torque<N>(q, qd, r, o.lambda, o.kd);
  return s;
}

// Tracking errors over a run: RMS over all steps and over its last fifth, and the largest.
template <typename Vec>
struct ErrorStats {
  Vec sum_sq = Vec::Zero(), late_sq = Vec::Zero(), worst = Vec::Zero();
  long late_count = 0;
  void add(const Vec& err, bool late) {
    sum_sq += err.cwiseAbs2();
    if (late) {
      late_sq += err.cwiseAbs2();
      ++late_count;
    }
    worst = worst.cwiseMax(err.cwiseAbs());
  }
  void write(TrackingResult& out, long samples) const {
    out.rms_error = (sum_sq / static_cast<double>(samples)).cwiseSqrt();
    out.late_rms_error = (late_sq / static_cast<double>(late_count)).cwiseSqrt();
    out.max_error = worst;
  }
};

template <typename Plant>
TrackingResult run(const TrackingOptions& o, const ReferenceFunction& ref) {
  constexpr int N = Plant::kJoints;
  using Vec = typename Plant::Vec;
  using Par = typename Plant::Params;
  const Plant plant;
  const Par gamma = o.gamma;
  Vec q = o.q0.size() ? Vec(o.q0) : Vec::Zero();
  Vec qd = Vec::Zero();
  Par a_hat = Par::Zero();       // no a-priori knowledge, as in every Sec. 5.4.1 run
  Vec q_prev = q, qd_prev = qd;  // the previous step, for the two-step integrator
  Par a_prev = a_hat;
  Eigen::VectorXd rq(N), rqd(N), rqdd(N);
  TrackingResult out;
  out.true_parameters = plant.a;
  ErrorStats<Vec> errors;
  const auto steps = static_cast<long>(std::llround(o.duration / o.dt));
  const auto record = std::max<long>(1, std::llround(o.record_every / o.dt));
  typename Plant::Mat h;
  Vec bias;
  Eigen::VectorXd nq(N), nqd(N), nqdd(N);
  for (long k = 0; k <= steps; ++k) {
    const double t = k * o.dt;
    ref(t, rq, rqd, rqdd);
    const JointReference<N> r{rq, rqd, rqdd};
    errors.add(q - r.q, 5 * k >= 4 * steps);
    plant.dynamics(q, qd, h, bias);
    if (k % record == 0 || k == steps) {
      TrackingSample s = sample_at(plant, o, t, q, qd, r, h, a_hat);
      out.max_torque = std::max(out.max_torque, s.tau.cwiseAbs().maxCoeff());
      out.samples.push_back(std::move(s));
    }
    if (k == steps) break;
    // The loop (plant, -K_D s, and for the adaptive law Eq. 5.6) is stiff against the light foot.
    // Second-order IMEX BDF: s and a^ implicit at the end of the step against the reference
    // there; H, Y and C q' + g explicit at the state extrapolated to it. Adaptation acts like an
    // extra gain beta Y Gamma Y^T on s. The first step is implicit Euler.
    const bool first = k == 0;
    const double dt = o.dt, beta = first ? dt : 2.0 / 3.0 * dt;
    const Vec q_pred = first ? q : Vec((4 * q - q_prev) / 3);
    const Vec v_pred = first ? qd : Vec((4 * qd - qd_prev) / 3);
    const Par a_pred = first ? a_hat : Par((4 * a_hat - a_prev) / 3);
    const Vec q_ex = first ? q : Vec(2 * q - q_prev);
    const Vec v_ex = first ? qd : Vec(2 * qd - qd_prev);
    ref(t + dt, nq, nqd, nqdd);
    const JointReference<N> next{nq, nqd, nqdd};
    if (!first) plant.dynamics(q_ex, v_ex, h, bias);
    using Mat = typename Plant::Mat;
    Mat k_eff = o.kd * Mat::Identity();
    Vec drive = -bias;
    typename Plant::Regressor y;
    if (o.controller == Controller::Adaptive) {
      const SlidingTerms<N> st = sliding_terms<N>(q_ex, v_ex, next, o.lambda);
      y = Plant::regressor(q_ex, v_ex, st.qd_r, st.qdd_r);
      k_eff += beta * y * gamma.asDiagonal() * y.transpose();
      drive += y * a_pred;
    }
    // s at the end of the step if the velocity kept its predicted value.
    const Vec s_pred =
        (1 + o.lambda * beta) * v_pred + o.lambda * q_pred - next.qd - o.lambda * next.q;
    const Mat lhs = h + beta * (1 + o.lambda * beta) * k_eff;
    const Vec dv = lhs.ldlt().solve(beta * (drive - k_eff * s_pred));
    q_prev = q, qd_prev = qd, a_prev = a_hat;
    qd = v_pred + dv;
    q = q_pred + beta * qd;
    if (o.controller == Controller::Adaptive)  // the law of Eq. 5.6 with s at the end of the step
      a_hat = a_pred -
              beta * (gamma.asDiagonal() * (y.transpose() * (s_pred + (1 + o.lambda * beta) * dv)));
    if (!q.allFinite() || !qd.allFinite() || !a_hat.allFinite())
      throw Error("swing-leg simulation diverged at t = " + std::to_string(t) + " s");
  }
  errors.write(out, steps + 1);
  out.final_estimate = a_hat;
  return out;
}

}  // namespace

int joint_count(LegModel m) {
  return m == LegModel::Planar ? 3 : 5;
}
int parameter_count(LegModel m) {
  return m == LegModel::Planar ? 9 : 17;
}

std::vector<std::string> joint_names(LegModel m) {
  if (m == LegModel::Planar) return {"hip_pitch", "knee", "ankle_pitch"};
  return {"hip_roll", "hip_pitch", "knee", "ankle_pitch", "ankle_roll"};
}

TrackingResult simulate_tracking(const TrackingOptions& o, const ReferenceFunction& ref) {
  const int n = joint_count(o.model), p = parameter_count(o.model);
  if (!(o.dt > 0 && o.dt <= 0.01)) throw Error("swing-leg: dt: expected (0, 0.01] s");
  if (!(o.duration > 0 && o.duration / o.dt <= 2e8))
    throw Error("swing-leg: duration: expected > 0 and at most 2e8 steps");
  if (!(o.lambda > 0) || !(o.kd > 0)) throw Error("swing-leg: lambda and kd: expected > 0");
  if (o.controller == Controller::Adaptive && (o.gamma.size() != p || !(o.gamma.array() > 0).all()))
    throw Error("swing-leg: gamma: expected " + std::to_string(p) + " positive weights");
  if (o.q0.size() != 0 && o.q0.size() != n)
    throw Error("swing-leg: q0: expected " + std::to_string(n) + " joint angles");
  TrackingOptions checked = o;
  if (checked.gamma.size() != p) checked.gamma = Eigen::VectorXd::Ones(p);  // PD: unused
  return o.model == LegModel::Planar ? run<PlanarLegPlant>(checked, ref)
                                     : run<Leg3dPlant>(checked, ref);
}

}  // namespace stride::swing_leg
