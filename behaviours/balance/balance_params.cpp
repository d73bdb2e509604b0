#include "behaviours/balance/balance_params.hpp"

#include <string>

#include "robot/core/error.hpp"

namespace stride::balance {

namespace {
void require(bool ok, const char* field, const char* expected) {
  if (!ok) throw Error(std::string("balance parameter ") + field + ": expected " + expected);
}
}  // namespace

void validate(const BalanceParams& p) {
  require(std::isfinite(p.g) && p.g > 0, "g", "a positive number");
  require(std::isfinite(p.z_cm) && p.z_cm > 0, "z_cm", "a positive number");
  require(std::isfinite(p.mass) && p.mass > 0, "mass", "a positive number");
  require(std::isfinite(p.zmp_min) && std::isfinite(p.zmp_max) && p.zmp_min < p.zmp_max,
          "zmp_min/zmp_max", "zmp_min < zmp_max");
  require(std::isfinite(p.inertia) && p.inertia > 0, "inertia", "a positive number");
  require(std::isfinite(p.tau_forward) && p.tau_forward > 0, "tau_forward", "a positive torque");
  require(std::isfinite(p.tau_backward) && p.tau_backward < 0, "tau_backward", "a negative torque");
  require(std::isfinite(p.theta_max_forward) && p.theta_max_forward > p.theta0, "theta_max_forward",
          "a limit above theta0");
  require(std::isfinite(p.theta_max_backward) && p.theta_max_backward < p.theta0,
          "theta_max_backward", "a limit below theta0");
  require(std::isfinite(p.theta_dot0), "theta_dot0", "a finite number");
}

}  // namespace stride::balance
