#pragma once
// The two swing-leg models of App. C seen as plants for the Ch. 5 controllers: dynamics terms
// from the true parameter vector a, and the regressor Y the adaptive law uses.
#include <Eigen/Core>

#include "robot/model/dynamics/swing_leg_3d.hpp"
#include "robot/model/dynamics/swing_leg_planar.hpp"

namespace stride::swing_leg {

struct PlanarLegPlant {
  static constexpr int kJoints = 3, kParameters = 9;
  using Vec = Eigen::Vector3d;
  using Params = model::Vector9d;
  using Regressor = model::PlanarRegressor;
  Params a = model::planar_parameters(model::thesis_planar_leg());

  using Mat = Eigen::Matrix3d;
  // H(q), and C(q, q') q' + g(q) (the plant of Eq. 5.2, true parameters).
  void dynamics(const Vec& q, const Vec& qd, Mat& h, Vec& bias) const {
    h = model::planar_inertia(q, a);
    bias = model::planar_coriolis(q, qd, a) * qd + model::planar_gravity(q, a);
  }
  static Regressor regressor(const Vec& q, const Vec& qd, const Vec& qd_r, const Vec& qdd_r) {
    return model::planar_regressor(q, qd, qd_r, qdd_r);
  }
};

struct Leg3dPlant {
  static constexpr int kJoints = 5, kParameters = 17;
  using Vec = model::Vector5d;
  using Params = model::Vector17d;
  using Regressor = model::Leg3dRegressor;
  Params a = model::leg3d_parameters(model::thesis_3d_leg());

  using Mat = model::Matrix5d;
  void dynamics(const Vec& q, const Vec& qd, Mat& h, Vec& bias) const {
    const model::Leg3dTerms t = model::leg3d_terms(q, qd, a);
    h = t.inertia;
    bias = t.coriolis * qd + t.gravity;
  }
  static Regressor regressor(const Vec& q, const Vec& qd, const Vec& qd_r, const Vec& qdd_r) {
    return model::leg3d_regressor(q, qd, qd_r, qdd_r);
  }
};

}  // namespace stride::swing_leg
