#pragma once
// Continuous-time algebraic Riccati equation (CARE) and LQR gain, for Eq. 7.39.
#include <Eigen/Dense>

namespace stride::balance {

// Solves A^T S + S A - S B R^-1 B^T S + Q = 0 for the stabilising S (Hamiltonian eigenvectors,
// polished by Newton-Kleinman steps). Throws stride::Error on bad sizes or when (A, B) admits no
// stabilising solution.
Eigen::MatrixXd solve_care(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B,
                           const Eigen::MatrixXd& Q, const Eigen::MatrixXd& R);

// Left-hand side of the CARE for a candidate S (zero for the exact solution).
Eigen::MatrixXd care_residual(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B,
                              const Eigen::MatrixXd& Q, const Eigen::MatrixXd& R,
                              const Eigen::MatrixXd& S);

// Solves Ac^T X + X Ac + M = 0 (Kronecker form; meant for the small systems of Ch. 7).
Eigen::MatrixXd solve_lyapunov(const Eigen::MatrixXd& Ac, const Eigen::MatrixXd& M);

struct LqrSolution {
  Eigen::MatrixXd K;                   // u = -K x, K = R^-1 B^T S
  Eigen::MatrixXd S;                   // CARE solution
  Eigen::VectorXcd closed_loop_poles;  // eig(A - B K)
};
// Matlab's [K, S, e] = lqr(A, B, Q, R).
LqrSolution lqr(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q,
                const Eigen::MatrixXd& R);

}  // namespace stride::balance
