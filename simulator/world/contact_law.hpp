#pragma once
// The scene's contact law (ContactLaw) in the terms both engines share: one contact point's spring
// and damper as ERP/CFM (its body's split over the body's points), and the pyramid's first axis.
#include <algorithm>

#include <Eigen/Core>

#include "simulator/scene/scene_description.hpp"
#include "simulator/world/contact_softness.hpp"

namespace stride::sim {

// A robot geom's friction: the law's, else the coefficient every scene had before <contact>.
inline double robot_geom_friction(const PhysicsSettings& p) {
  return p.contact_law ? p.contact_law->friction : 0.8;
}

// One of a body's `points` contact points against the static scene at step h (a robot-robot
// point, or any point of a per-point law, takes the whole spring: points = 1).
inline ContactSoftness law_point_softness(const ContactLaw& law, int points, double h) {
  const double n = law.per_body ? std::max(points, 1) : 1;
  return contact_softness(law.stiffness / n, law.damping / n, h);
}

// The pyramid's first friction axis: world x in the contact plane (world y where the normal lies
// near x), so that both engines' pyramids face the same way.
inline Eigen::Vector3d law_friction_axis(const Eigen::Vector3d& normal) {
  Eigen::Vector3d t = Eigen::Vector3d::UnitX() - normal.x() * normal;
  if (t.norm() < 0.3) t = Eigen::Vector3d::UnitY() - normal.y() * normal;
  return t.normalized();
}

}  // namespace stride::sim
