#pragma once
// Bounded nonlinear least squares (Levenberg-Marquardt with a finite-difference Jacobian) whose
// every batch of residual evaluations goes to one call, so a caller runs them on workers; and
// each parameter's 95 % interval from the Jacobian at the optimum. A parameter the residual
// cannot resolve to its wanted precision is not fitted: it stays at its start value and is
// reported as such, rather than moved by noise.
#include <functional>
#include <vector>

namespace stride::identify {

struct LsqParam {
  double start, lower, upper;
  double step;    // finite-difference step
  double wanted;  // a 95 % interval wider than +-wanted: not identifiable from these data
};

// Residual vectors (all of one length) for a batch of parameter vectors, in order.
using BatchResidual =
    std::function<std::vector<std::vector<double>>(const std::vector<std::vector<double>>&)>;

struct LsqResult {
  std::vector<double> value;
  std::vector<double> half_width;   // 95 % interval: value +- half_width
  std::vector<bool> identified;     // false: kept at its start, half_width what it would have had
  double start_cost = 0, cost = 0;  // sum of squared residuals
  int iterations = 0;
  int evaluations = 0;
};

// Screens the parameters with the Jacobian at the start (one batch of n + 1), then fits the
// identifiable ones for at most `iterations` Jacobians.
LsqResult least_squares(const std::vector<LsqParam>& params, const BatchResidual& evaluate,
                        int iterations = 8);

}  // namespace stride::identify
