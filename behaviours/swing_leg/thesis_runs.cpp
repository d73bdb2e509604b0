#include "behaviours/swing_leg/thesis_runs.hpp"

#include <cmath>
#include <memory>
#include <numbers>

#include "behaviours/walking/pattern/pattern_joints.hpp"
#include "behaviours/walking/pattern/pattern_parameters.hpp"
#include "behaviours/walking/pattern/walking_pattern.hpp"
#include "robot/core/error.hpp"
#include "robot/core/quote.hpp"

namespace stride::swing_leg {
namespace {

constexpr double kDeg = std::numbers::pi / 180;

Eigen::VectorXd vec(std::initializer_list<double> v) {
  Eigen::VectorXd out(static_cast<Eigen::Index>(v.size()));
  Eigen::Index i = 0;
  for (double x : v) out[i++] = x;
  return out;
}

// A sum of sines a_k sin(2 pi f_k t) with its first two derivatives.
struct Sines {
  std::vector<std::pair<double, double>> terms;  // amplitude, frequency (Hz)
  void eval(double t, double& q, double& qd, double& qdd) const {
    q = qd = qdd = 0;
    for (const auto& [a, f] : terms) {
      const double w = 2 * std::numbers::pi * f;
      q += a * std::sin(w * t);
      qd += a * w * std::cos(w * t);
      qdd -= a * w * w * std::sin(w * t);
    }
  }
};

}  // namespace

ReferenceFunction step_reference(const Eigen::VectorXd& target) {
  return [target](double, Eigen::VectorXd& q, Eigen::VectorXd& qd, Eigen::VectorXd& qdd) {
    q = target;
    qd.setZero(target.size());
    qdd.setZero(target.size());
  };
}

ReferenceFunction planar_sine_reference() {
  // Each joint adds its own slow and fast sine to the previous joint's signal (Sec. 5.4.1.1).
  const Sines hip{{{0.8, 0.05}, {0.25, 1.0}}};
  const Sines knee{{{0.8, 0.05}, {0.25, 1.0}, {0.4, 0.03}, {0.15, 1.5}}};
  const Sines ankle{{{0.8, 0.05}, {0.25, 1.0}, {0.4, 0.03}, {0.15, 1.5}, {0.6, 0.04}, {0.1, 2.0}}};
  return [=](double t, Eigen::VectorXd& q, Eigen::VectorXd& qd, Eigen::VectorXd& qdd) {
    q.resize(3), qd.resize(3), qdd.resize(3);
    hip.eval(t, q[0], qd[0], qdd[0]);
    knee.eval(t, q[1], qd[1], qdd[1]);
    ankle.eval(t, q[2], qd[2], qdd[2]);
  };
}

ReferenceFunction walking_pattern_reference(const std::string& preset) {
  auto pattern = std::make_shared<walking::StretchedKneePattern>(walking::preset(preset));
  // Fixed size: a control frame that calls this with q, qd, qdd of size 5 does not allocate.
  const auto angles = [pattern](double t) {
    const double clamped = std::clamp(t, 0.0, pattern->duration());
    const auto& l = walking::leg_joints(pattern->sample(clamped)).left;
    return Eigen::Matrix<double, 5, 1>(l[1], l[2], l[3], l[4], l[5]);
  };
  return [angles](double t, Eigen::VectorXd& q, Eigen::VectorXd& qd, Eigen::VectorXd& qdd) {
    constexpr double h = 1e-3;  // s: smooth enough for the pattern, far above rounding
    const Eigen::Matrix<double, 5, 1> before = angles(t - h), after = angles(t + h);
    q = angles(t);
    qd = (after - before) / (2 * h);
    qdd = (after - 2 * q + before) / (h * h);
  };
}

std::vector<std::string> thesis_run_names() {
  return {"planar-step", "planar-track", "3d-step", "3d-track"};
}

ThesisRun thesis_run(const std::string& name) {
  ThesisRun r;
  r.name = name;
  TrackingOptions& o = r.options;
  if (name == "planar-step") {
    r.figures = "Figs. 5.2-5.4";
    o.model = LegModel::Planar;
    o.duration = 2.5;
    o.lambda = 200, o.kd = 100;
    o.gamma = vec({0.5, 0.1, 0.1, 0.3, 0.08, 0.04, 9, 15, 6});
    r.reference = step_reference(vec({-60 * kDeg, 45 * kDeg, -30 * kDeg}));
  } else if (name == "planar-track") {
    r.figures = "Figs. 5.5-5.6";
    o.model = LegModel::Planar;
    o.duration = 20;
    o.lambda = 500, o.kd = 100;
    o.gamma = vec({0.001, 0.002, 0.002, 0.001, 0.001, 0.001, 2, 0.8, 0.06});
    r.reference = planar_sine_reference();
  } else if (name == "3d-step") {
    r.figures = "Figs. 5.8-5.9";
    o.model = LegModel::ThreeD;
    o.duration = 1.0;
    o.lambda = 700, o.kd = 100;
    o.gamma = vec({0.05, 0.01, 0.01, 0.03, 0.08, 0.04, 0.05, 0.01, 0.01, 0.03, 0.08, 0.04, 0.01,
                   0.03, 9, 15, 6});
    r.reference = step_reference(vec({-18 * kDeg, -30 * kDeg, 30 * kDeg, -45 * kDeg, -20 * kDeg}));
  } else if (name == "3d-track") {
    r.figures = "Figs. 5.10-5.11";
    o.model = LegModel::ThreeD;
    o.duration = 15;
    o.lambda = 500, o.kd = 100;
    o.gamma = vec({0.02, 0.08, 0.05, 0.01, 0.02, 0.06, 0.01, 0.05, 0.07, 0.03, 0.01, 0.04, 0.05,
                   0.05, 9, 15, 6});
    r.reference = walking_pattern_reference("medium");
    Eigen::VectorXd q, qd, qdd;
    r.reference(0, q, qd, qdd);
    o.q0 = q;  // start on the pattern's standing posture
  } else {
    std::string known;
    for (const auto& n : thesis_run_names()) known += (known.empty() ? "" : ", ") + n;
    throw Error("unknown swing-leg study " + quote(name) + " (expected " + known + ")");
  }
  return r;
}

}  // namespace stride::swing_leg
