#pragma once
// Seven-link single-support model of thesis App. D (Fig. D.2): stance leg (foot, tibia, thigh),
// torso, swing leg (thigh, tibia, foot); 12 generalised coordinates ordered as the thesis' script:
//   q = [ankle_roll1, ankle_pitch1, knee1, hip_pitch1, hip_roll1, hip_roll2, hip_pitch2, knee2,
//        ankle_pitch2, ankle_roll2, torso_pitch, torso_roll]   (1 = stance, 2 = swing)
// measured from the stance sole. H q'' + C q' + G = B tau + J^T f_e (Eq. D.13): H from the link
// CoM Jacobians and the pitch/roll inertias, C by Eq. C.14, G the gradient of the potential,
// B from the joint map Phi_0, J the Jacobian of the swing sole point. All derivatives are exact
// (dual numbers), nothing is typed symbol by symbol.
#include <Eigen/Core>

namespace stride::model {

inline constexpr int kFullBodyDof = 12;
using FullBodyVector = Eigen::Matrix<double, kFullBodyDof, 1>;
using FullBodyMatrix = Eigen::Matrix<double, kFullBodyDof, kFullBodyDof>;

struct FullBodyLink {
  double mass = 0;
  double com_offset = 0;  // along the link from its proximal point (c_* / b_* of the script)
  double ixx = 0, iyy = 0;
};

struct FullBodyParams {
  double l_thigh = 0, l_tibia = 0, l_foot = 0;
  FullBodyLink foot1, tibia1, thigh1, torso, thigh2, tibia2, foot2;
  double gravity = 9.81;
};

// NAO values: leg links as in Sec. 5.4.1.2 (stance and swing alike), the rest of the 5.183 kg
// robot (App. A) lumped into the torso with its CoM 0.1 m above the hip.
FullBodyParams nao_full_body_params();

struct FullBodyTerms {
  FullBodyMatrix inertia;                                 // H
  FullBodyMatrix coriolis;                                // C
  FullBodyVector gravity;                                 // G
  Eigen::Matrix<double, kFullBodyDof, 10> input;          // B: ten leg joint torques
  Eigen::Matrix<double, 3, kFullBodyDof> swing_jacobian;  // J of the swing sole point
};

FullBodyTerms full_body_terms(const FullBodyParams& p, const FullBodyVector& q,
                              const FullBodyVector& qd);

// Swing sole point (p_foot2 of the script) and the total energy K + P, for tests and plots.
Eigen::Vector3d full_body_swing_foot(const FullBodyParams& p, const FullBodyVector& q);
double full_body_energy(const FullBodyParams& p, const FullBodyVector& q, const FullBodyVector& qd);

}  // namespace stride::model
