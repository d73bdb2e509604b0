#pragma once
// Thesis Sec. 5.4.2 in our simulator: the NAO hung by its torso tracks the Ch. 3 pattern with its
// left leg driven in torque mode by the adaptive or the PD law (the SwingLegTracking module, its
// joint velocities from JointVelocityEstimator), within the motors' torque limits.
#include <string>

#include <Eigen/Core>

#include "behaviours/swing_leg/tracking_simulation.hpp"

namespace stride::experiments {

struct OdeSwingLegOptions {
  std::string scene;  // a scene with one robot on a fixed base and a 1 ms control period
  swing_leg::Controller controller = swing_leg::Controller::Adaptive;
  double lambda = 20, kd = 0.1;
  Eigen::VectorXd gamma;  // 17 weights; the thesis' Sec. 5.4.2 values if empty
  double duration = 10;   // s
  std::string preset = "medium";
};

struct OdeSwingLegResult {
  Eigen::VectorXd rms_error, max_error;  // rad per joint (hip roll .. ankle roll), after 1 s
  double max_torque = 0;                 // N m, largest |tau| requested
  double saturated = 0;                  // fraction of frames with a request beyond stall torque
};

// The adaptation weights the thesis used in its ODE simulator (Sec. 5.4.2):
// swing_leg::thesis_ode_gamma(), SwingLegTracking's default.
Eigen::Matrix<double, 17, 1> thesis_ode_gamma();

// Throws stride::Error if the scene does not fit (no robot, no left leg, period not 1 ms...).
OdeSwingLegResult run_ode_swing_leg(const OdeSwingLegOptions& options);

}  // namespace stride::experiments
