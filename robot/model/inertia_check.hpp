#pragma once
// Whether an inertia tensor belongs to a physical body: symmetric positive definite, principal
// moments within limits and satisfying the triangle inequality (each at most the sum of the
// other two). A physics engine divides by these moments; a bad tensor asserts or explodes.
#include <string>

#include <Eigen/Core>

namespace stride::model {

// "" when `inertia` (kg m^2, about the centre of mass) is physical, else why not, e.g.
// "not positive definite (principal moments -0.01, 0.01, 0.03 kg*m^2; expected each in
// [1e-12, 1e+05])". The all-zero tensor (a point mass or no mass) is accepted.
std::string inertia_problem(const Eigen::Matrix3d& inertia);

}  // namespace stride::model
