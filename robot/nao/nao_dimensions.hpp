#pragma once
// NAO H25 dimensions in metres, one place for every module (nao-facts.md, thesis Appendix A).
#include <array>

#include <Eigen/Core>

namespace stride::nao {

inline constexpr double kNeckOffsetZ = 0.1265;
inline constexpr double kShoulderOffsetY = 0.098;
inline constexpr double kShoulderOffsetZ = 0.100;
inline constexpr double kUpperArmLength = 0.105;
inline constexpr double kElbowOffsetY = 0.015;
inline constexpr double kLowerArmLength = 0.05595;
inline constexpr double kHandOffsetX = 0.05775;
inline constexpr double kHandOffsetZ = 0.01231;
inline constexpr double kHipOffsetY = 0.050;
inline constexpr double kHipOffsetZ = 0.085;
inline constexpr double kThighLength = 0.100;
inline constexpr double kTibiaLength = 0.1029;
inline constexpr double kFootHeight = 0.04519;  // thesis/Docs; the V5 URDF says 0.04511

// Sole rectangle (thesis: 160 x 91 mm), placed like B-Human's sole: more of it ahead of the
// ankle than behind, and more outside than inside. Left foot, ankle frame.
inline constexpr double kSoleLength = 0.160;
inline constexpr double kSoleWidth = 0.091;
inline constexpr double kSoleCentreX = 0.020;       // sole spans x in [-0.060, 0.100]
inline constexpr double kSoleCentreYLeft = 0.0056;  // outer edge +0.051, inner -0.040

// FSR positions, ankle frame, LoLA order (L FL, FR, RL, RR, R FL, FR, RL, RR); z = -kFootHeight.
inline const std::array<Eigen::Vector2d, 8> kFsrPositions = {
    Eigen::Vector2d(0.07025, 0.0299),  Eigen::Vector2d(0.07025, -0.0231),
    Eigen::Vector2d(-0.03025, 0.0299), Eigen::Vector2d(-0.02965, -0.0191),
    Eigen::Vector2d(0.07025, 0.0231),  Eigen::Vector2d(0.07025, -0.0299),
    Eigen::Vector2d(-0.03025, 0.0191), Eigen::Vector2d(-0.02965, -0.0299)};

inline constexpr double kFsrMaxForce = 25.0;  // N per sensor (thesis Sec. 6.3)

// The largest torque any NAO leg joint's motor gives (stall at the joint: hip yaw-pitch, hip roll,
// ankle roll; nao-facts.md), N m. Figures far beyond it come from a typed mistake, not a robot.
inline constexpr double kLargestStallTorque = 13.1;

// Thesis' standing posture: knees slightly bent so the servos are not at the stretched limit.
inline constexpr double kStandHipPitch = -0.30;
inline constexpr double kStandKneePitch = 0.60;
inline constexpr double kStandAnklePitch = -0.30;

}  // namespace stride::nao
