#include "robot/model/inertia_check.hpp"

#include <Eigen/Eigenvalues>

#include "robot/core/number_text.hpp"
#include "robot/core/physical_limits.hpp"

namespace stride::model {

std::string inertia_problem(const Eigen::Matrix3d& inertia) {
  if (inertia.isZero(0)) return "";
  if (!inertia.allFinite()) return "not finite";
  const Eigen::Vector3d m =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(inertia, Eigen::EigenvaluesOnly)
          .eigenvalues();  // ascending
  const std::string moments = "principal moments " + short_number(m[0]) + ", " +
                              short_number(m[1]) + ", " + short_number(m[2]) + " kg*m^2";
  const std::string range =
      "[" + short_number(limits::kMinInertia) + ", " + short_number(limits::kMaxInertia) + "]";
  if (m[0] <= 0) return "not positive definite (" + moments + "; expected each in " + range + ")";
  if (m[0] < limits::kMinInertia || m[2] > limits::kMaxInertia)
    return moments + " outside " + range;
  // With a relative tolerance: thin rods and flat plates sit on the boundary.
  if (m[0] + m[1] < m[2] * (1 - 1e-6))
    return "violates the triangle inequality (" + moments +
           ": the two smaller sum to less than the largest)";
  return "";
}

}  // namespace stride::model
