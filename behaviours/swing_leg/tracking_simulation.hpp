#pragma once
// Closed-loop runs of a swing-leg model under the Ch. 5 controllers (the thesis' Sec. 5.4.1
// studies): step responses and trajectory tracking, with the parameter estimates over time.
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "robot/framework/reflect.hpp"

namespace stride::swing_leg {

enum class LegModel { Planar, ThreeD };
enum class Controller { Adaptive, Pd };

// Desired joint position, velocity and acceleration at time t (vectors of the model's size).
using ReferenceFunction =
    std::function<void(double t, Eigen::VectorXd& q, Eigen::VectorXd& qd, Eigen::VectorXd& qdd)>;

struct TrackingOptions {
  LegModel model = LegModel::Planar;
  Controller controller = Controller::Adaptive;
  double duration = 2.5;  // s
  double dt = 1e-4;       // s; the feedback terms are integrated implicitly, so any dt is stable
  double record_every = 0.001;  // s between recorded samples
  double lambda = 200, kd = 100;
  Eigen::VectorXd gamma;  // adaptation weights (model's parameter count)
  Eigen::VectorXd q0;     // initial joint angles (zero if empty); the leg starts at rest
};

struct TrackingSample {
  double t = 0;
  Eigen::VectorXd q, q_desired, tau, a_hat;
  double lyapunov = 0;  // V of Eq. 5.7 (adaptive runs)
};

struct TrackingResult {
  std::vector<TrackingSample> samples;
  Eigen::VectorXd rms_error, max_error;  // per joint, rad, over the whole run
  Eigen::VectorXd late_rms_error;        // per joint, rad, over the last fifth (after adapting)
  Eigen::VectorXd true_parameters, final_estimate;
  double max_torque = 0;  // N m, largest |tau| of any joint
};

// Throws stride::Error on inconsistent options (sizes, non-positive gains or steps).
TrackingResult simulate_tracking(const TrackingOptions& options, const ReferenceFunction& ref);

int joint_count(LegModel m);
int parameter_count(LegModel m);
std::vector<std::string> joint_names(LegModel m);

}  // namespace stride::swing_leg

namespace stride {
template <>
struct EnumNames<swing_leg::Controller> {
  static constexpr std::string_view type_name = "SwingLegController";
  static constexpr std::array<std::string_view, 2> names{"adaptive", "pd"};
};
}  // namespace stride
