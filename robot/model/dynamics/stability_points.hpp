#pragma once
// Ground points that summarise balance (thesis Sec. 2.1): ZMP from the multi-body motion and from
// a point mass, CoP from force sensors, FRI and CMP as diagnostics. Ground: z = ground_z plane,
// gravity along -z. All allocation-free.
#include <array>
#include <optional>
#include <span>

#include <Eigen/Geometry>

namespace stride::model {

inline constexpr double kGravity = 9.81;

// One rigid segment's state for the moment balances: CoM position and acceleration and the rate
// of change of its angular momentum about its own CoM, d(I w)/dt.
struct SegmentMotion {
  double mass = 0;
  Eigen::Vector3d com = Eigen::Vector3d::Zero();
  Eigen::Vector3d com_acceleration = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular_momentum_rate = Eigen::Vector3d::Zero();
};

// ZMP of an articulated body on the plane z = ground_z (Eq. 2.3).
Eigen::Vector2d zmp_multibody(std::span<const SegmentMotion> segments, double ground_z = 0,
                              double gravity = kGravity);

// ZMP of a point mass with the total angular momentum rate about the CoG (Eq. 2.5).
Eigen::Vector2d zmp_point_mass(
    const Eigen::Vector3d& com, const Eigen::Vector3d& com_acceleration, double mass,
    const Eigen::Vector3d& angular_momentum_rate = Eigen::Vector3d::Zero(), double ground_z = 0,
    double gravity = kGravity);

// Centre of pressure: normal-force-weighted mean of the sensor positions (Sec. 2.1.1). Empty when
// the total force is not above min_total_force (foot in the air).
std::optional<Eigen::Vector3d> centre_of_pressure(std::span<const double> forces,
                                                  std::span<const Eigen::Vector3d> positions,
                                                  double min_total_force = 1e-3);

// CoP of the NAO's eight FSRs (LoLA order) given both soles' frames in a common frame.
std::optional<Eigen::Vector3d> nao_fsr_centre_of_pressure(std::span<const double, 8> forces,
                                                          const Eigen::Isometry3d& left_sole,
                                                          const Eigen::Isometry3d& right_sole,
                                                          double min_total_force = 1e-3);

// Sec. 2.1.2: foot-rotation indicator. The stance foot contributes only its weight; the rest of
// the body its inertial forces and angular momentum rates.
Eigen::Vector2d foot_rotation_indicator(const SegmentMotion& stance_foot,
                                        std::span<const SegmentMotion> rest_of_body,
                                        double ground_z = 0, double gravity = kGravity);

// Sec. 2.1.3: centroidal moment pivot, where the line through the CoM parallel to the ground
// reaction force meets the ground.
Eigen::Vector2d cmp_from_ground_reaction(const Eigen::Vector3d& com,
                                         const Eigen::Vector3d& ground_reaction_force,
                                         double ground_z = 0);

// The same with the reaction force from the CoM motion, R = M (a_G - g).
Eigen::Vector2d cmp_from_com_motion(const Eigen::Vector3d& com,
                                    const Eigen::Vector3d& com_acceleration, double ground_z = 0,
                                    double gravity = kGravity);

}  // namespace stride::model
