#include "console/identify/least_squares.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "robot/core/error.hpp"

namespace stride::identify {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

constexpr double kZ95 = 1.96;

VectorXd as_vector(const std::vector<double>& v) {
  return Eigen::Map<const VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
}

struct Linearised {
  VectorXd r;
  MatrixXd J;  // columns of the active parameters only
  // |r(x + step_i) - r(x)| per active parameter, and that of a change far below any step: the
  // simulation's own numerical noise, which a parameter must move the residual well beyond.
  std::vector<double> moved;
  double noise = 0;
};

// A parameter whose step moves the residual less than this many times the numerical noise is
// not seen by the data (a flat cost): it is not fitted.
constexpr double kSignalOverNoise = 3;

class Solver {
 public:
  Solver(const std::vector<LsqParam>& p, const BatchResidual& e, LsqResult& out)
      : params_(p), evaluate_(e), out_(out) {}

  std::vector<std::vector<double>> run_batch(const std::vector<std::vector<double>>& xs) {
    out_.evaluations += static_cast<int>(xs.size());
    auto rs = evaluate_(xs);
    if (rs.size() != xs.size()) throw Error("identify: the evaluation lost candidates");
    for (const auto& r : rs)
      if (r.size() != rs.front().size()) throw Error("identify: residuals of unequal length");
    return rs;
  }

  // Residual at x and its forward differences (backward at an upper bound) for `active`.
  Linearised linearise(const std::vector<double>& x, const std::vector<int>& active,
                       bool with_noise = false) {
    std::vector<std::vector<double>> xs{x};
    std::vector<double> h;
    for (int i : active) {
      const LsqParam& p = params_[i];
      const double step = x[i] + p.step <= p.upper ? p.step : -p.step;
      h.push_back(step);
      xs.push_back(x);
      xs.back()[i] += step;
    }
    if (with_noise && !active.empty()) {
      xs.push_back(x);
      xs.back()[active[0]] += 1e-9 * params_[active[0]].step;
    }
    const auto rs = run_batch(xs);
    Linearised l{
        as_vector(rs[0]),
        MatrixXd(static_cast<Eigen::Index>(rs[0].size()), static_cast<Eigen::Index>(active.size())),
        {},
        0};
    for (std::size_t c = 0; c < active.size(); ++c) {
      const VectorXd d = as_vector(rs[c + 1]) - l.r;
      l.moved.push_back(d.norm());
      l.J.col(static_cast<Eigen::Index>(c)) = d / h[c];
    }
    if (with_noise && !active.empty()) l.noise = (as_vector(rs.back()) - l.r).norm();
    return l;
  }

  // 95 % half widths of the active parameters from J at residual scale s2.
  static VectorXd half_widths(const MatrixXd& J, double s2) {
    const MatrixXd H = J.transpose() * J;
    const MatrixXd cov = H.completeOrthogonalDecomposition().pseudoInverse();
    VectorXd w(H.rows());
    for (Eigen::Index i = 0; i < H.rows(); ++i)
      w[i] = H(i, i) > 0 ? kZ95 * std::sqrt(std::max(0.0, cov(i, i) * s2))
                         : std::numeric_limits<double>::infinity();
    return w;
  }

  // Drops, one at a time, the active parameter whose interval is widest against its wanted
  // precision until every one left resolves; records the widths of those dropped.
  std::vector<int> screen(const Linearised& l, std::vector<int> active, double s2) {
    std::vector<int> cols;
    for (std::size_t c = 0; c < active.size(); ++c)
      if (l.moved[c] > kSignalOverNoise * l.noise) cols.push_back(static_cast<int>(c));
    for (std::size_t c = 0; c < active.size(); ++c)
      if (std::ranges::count(cols, static_cast<int>(c)) == 0) {
        out_.identified[active[c]] = false;
        out_.half_width[active[c]] = std::numeric_limits<double>::infinity();
      }
    std::vector<int> kept;
    for (int c : cols) kept.push_back(active[c]);
    active = kept;
    while (!active.empty()) {
      MatrixXd J(l.J.rows(), static_cast<Eigen::Index>(cols.size()));
      for (std::size_t c = 0; c < cols.size(); ++c) J.col(c) = l.J.col(cols[c]);
      const VectorXd w = half_widths(J, s2);
      std::size_t worst = 0;
      double worst_ratio = 0;
      for (std::size_t c = 0; c < active.size(); ++c) {
        out_.half_width[active[c]] = w[c];
        const double ratio = w[c] / params_[active[c]].wanted;
        if (ratio > worst_ratio) worst_ratio = ratio, worst = c;
      }
      if (worst_ratio <= 1) break;
      out_.identified[active[worst]] = false;
      active.erase(active.begin() + static_cast<long>(worst));
      cols.erase(cols.begin() + static_cast<long>(worst));
    }
    return active;
  }

  std::vector<double> clamp(std::vector<double> x) const {
    for (std::size_t i = 0; i < x.size(); ++i)
      x[i] = std::clamp(x[i], params_[i].lower, params_[i].upper);
    return x;
  }

 private:
  const std::vector<LsqParam>& params_;
  const BatchResidual& evaluate_;
  LsqResult& out_;
};

MatrixXd columns(const MatrixXd& J, const std::vector<int>& all, const std::vector<int>& keep) {
  MatrixXd out(J.rows(), static_cast<Eigen::Index>(keep.size()));
  for (std::size_t c = 0; c < keep.size(); ++c)
    out.col(c) = J.col(std::ranges::find(all, keep[c]) - all.begin());
  return out;
}

}  // namespace

LsqResult least_squares(const std::vector<LsqParam>& params, const BatchResidual& evaluate,
                        int iterations) {
  const std::size_t n = params.size();
  LsqResult out;
  out.identified.assign(n, true);
  out.half_width.assign(n, 0);
  Solver solver(params, evaluate, out);
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = params[i].start;
  std::vector<int> all(n);
  for (std::size_t i = 0; i < n; ++i) all[i] = static_cast<int>(i);
  Linearised l = solver.linearise(x, all, true);
  out.start_cost = l.r.squaredNorm();
  // Screened at the sensors' own spread (residual rows are in noise units).
  std::vector<int> active = solver.screen(l, all, 1.0);
  l.J = columns(l.J, all, active);
  double cost = out.start_cost, lambda = 1e-2;
  bool fresh = true;  // l is linearised at x
  for (int it = 0; it < iterations && !active.empty(); ++it) {
    if (!fresh) {
      l = solver.linearise(x, active);
      fresh = true;
    }
    ++out.iterations;
    const MatrixXd H = l.J.transpose() * l.J;
    const VectorXd g = l.J.transpose() * l.r;
    // Several damping levels in one batch: the workers try them at once.
    std::vector<double> lambdas{lambda * 0.1, lambda, lambda * 10, lambda * 100};
    std::vector<std::vector<double>> xs;
    for (double lam : lambdas) {
      MatrixXd A = H;
      A.diagonal() += lam * H.diagonal().cwiseMax(1e-12);
      const VectorXd d = A.ldlt().solve(-g);
      std::vector<double> c = x;
      for (std::size_t a = 0; a < active.size(); ++a) c[active[a]] += d[a];
      xs.push_back(solver.clamp(c));
    }
    const auto rs = solver.run_batch(xs);
    std::size_t best = 0;
    double best_cost = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < rs.size(); ++k)
      if (const double c = as_vector(rs[k]).squaredNorm(); c < best_cost) best_cost = c, best = k;
    if (!(best_cost < cost)) {
      lambda *= 1e3;
      if (lambda > 1e6) break;
      continue;
    }
    const double gain = (cost - best_cost) / cost;
    x = xs[best];
    cost = best_cost;
    lambda = lambdas[best];
    fresh = false;
    if (gain < 1e-4) break;
  }
  if (!fresh && !active.empty()) l = solver.linearise(x, active);
  out.cost = cost;
  // The final intervals at the fit's own residual scale, never below the sensors' spread.
  const double dof = static_cast<double>(l.r.size()) - static_cast<double>(active.size());
  const double s2 = std::max(1.0, cost / std::max(1.0, dof));
  const VectorXd w = active.empty() ? VectorXd() : Solver::half_widths(l.J, s2);
  for (std::size_t a = 0; a < active.size(); ++a) {
    out.half_width[active[a]] = w[a];
    if (w[a] > params[active[a]].wanted) out.identified[active[a]] = false;
  }
  out.value = x;
  for (std::size_t i = 0; i < n; ++i)
    if (!out.identified[i]) out.value[i] = params[i].start;
  return out;
}

}  // namespace stride::identify
