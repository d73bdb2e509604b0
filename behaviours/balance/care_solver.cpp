#include "behaviours/balance/care_solver.hpp"

#include <string>
#include <vector>

#include "robot/core/error.hpp"

namespace stride::balance {

namespace {
using Eigen::MatrixXd;

void check_sizes(const MatrixXd& A, const MatrixXd& B, const MatrixXd& Q, const MatrixXd& R) {
  const auto n = A.rows();
  auto fail = [](const std::string& what) { throw Error("CARE: " + what); };
  if (n == 0 || A.cols() != n) fail("A must be square and non-empty");
  if (B.rows() != n || B.cols() == 0) fail("B must have as many rows as A");
  if (Q.rows() != n || Q.cols() != n) fail("Q must be n x n with n = rows of A");
  if (R.rows() != B.cols() || R.cols() != B.cols()) fail("R must be m x m with m = columns of B");
  if (!A.allFinite() || !B.allFinite() || !Q.allFinite() || !R.allFinite())
    fail("matrices must be finite");
  Eigen::LLT<MatrixXd> llt(0.5 * (R + R.transpose()));
  if (llt.info() != Eigen::Success) fail("R must be symmetric positive definite");
}

double relative_residual(const MatrixXd& A, const MatrixXd& B, const MatrixXd& Q, const MatrixXd& R,
                         const MatrixXd& S) {
  return care_residual(A, B, Q, R, S).norm() / std::max(1.0, Q.norm() + S.norm());
}
}  // namespace

MatrixXd care_residual(const MatrixXd& A, const MatrixXd& B, const MatrixXd& Q, const MatrixXd& R,
                       const MatrixXd& S) {
  return A.transpose() * S + S * A - S * B * R.ldlt().solve(B.transpose()) * S + Q;
}

MatrixXd solve_lyapunov(const MatrixXd& Ac, const MatrixXd& M) {
  const auto n = Ac.rows();
  const MatrixXd I = MatrixXd::Identity(n, n);
  // vec(Ac^T X + X Ac) = (I (x) Ac^T + Ac^T (x) I) vec(X), column-major vec.
  MatrixXd L(n * n, n * n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j)
      L.block(i * n, j * n, n, n) = I(i, j) * Ac.transpose() + Ac(j, i) * I;
  const Eigen::VectorXd rhs = -Eigen::Map<const Eigen::VectorXd>(M.data(), n * n);
  const Eigen::VectorXd x = L.fullPivLu().solve(rhs);
  MatrixXd X = Eigen::Map<const MatrixXd>(x.data(), n, n);
  return 0.5 * (X + X.transpose());
}

MatrixXd solve_care(const MatrixXd& A, const MatrixXd& B, const MatrixXd& Q, const MatrixXd& R) {
  check_sizes(A, B, Q, R);
  const auto n = A.rows();
  const MatrixXd G = B * R.ldlt().solve(B.transpose());
  MatrixXd H(2 * n, 2 * n);  // Hamiltonian: its stable invariant subspace spans [I; S]
  H << A, -G, -Q, -A.transpose();
  Eigen::ComplexEigenSolver<MatrixXd> eig(H);
  if (eig.info() != Eigen::Success)
    throw Error("CARE: eigen-decomposition of the Hamiltonian failed");
  std::vector<Eigen::Index> stable;
  for (Eigen::Index i = 0; i < 2 * n; ++i)
    if (eig.eigenvalues()(i).real() < 0) stable.push_back(i);
  if (static_cast<Eigen::Index>(stable.size()) != n)
    throw Error(
        "CARE: Hamiltonian has eigenvalues on the imaginary axis (no stabilising solution)");
  Eigen::MatrixXcd U(2 * n, n);
  for (Eigen::Index k = 0; k < n; ++k) U.col(k) = eig.eigenvectors().col(stable[k]);
  const Eigen::MatrixXcd U1 = U.topRows(n), U2 = U.bottomRows(n);
  Eigen::FullPivLU<Eigen::MatrixXcd> lu(U1);
  if (!lu.isInvertible()) throw Error("CARE: (A, B) is not stabilisable");
  // S U1 = U2, so S = U2 U1^-1, computed as (U1^T \ U2^T)^T.
  MatrixXd S = U1.transpose().fullPivLu().solve(U2.transpose()).transpose().real();
  S = 0.5 * (S + S.transpose());
  // Newton-Kleinman polishing: each step solves one Lyapunov equation; keep only improvements.
  for (int step = 0; step < 4; ++step) {
    const MatrixXd K = R.ldlt().solve(B.transpose() * S);
    const MatrixXd Ac = A - B * K;
    const MatrixXd next = solve_lyapunov(Ac, Q + K.transpose() * R * K);
    if (!next.allFinite() ||
        relative_residual(A, B, Q, R, next) >= relative_residual(A, B, Q, R, S))
      break;
    S = next;
  }
  return S;
}

LqrSolution lqr(const MatrixXd& A, const MatrixXd& B, const MatrixXd& Q, const MatrixXd& R) {
  LqrSolution sol;
  sol.S = solve_care(A, B, Q, R);
  sol.K = R.ldlt().solve(B.transpose() * sol.S);
  sol.closed_loop_poles = (A - B * sol.K).eigenvalues();
  return sol;
}

}  // namespace stride::balance
