#pragma once
// Position and its first two time derivatives along one axis.

namespace stride::walking {

struct Motion1d {
  double p = 0.0;  // position
  double v = 0.0;  // velocity
  double a = 0.0;  // acceleration
};

}  // namespace stride::walking
