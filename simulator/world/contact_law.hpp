#pragma once
// The scene's contact law (ContactLaw) in the terms both engines share: one contact point's spring
// and damper as ERP/CFM (its body's split over the body's points), and the pyramid's first axis.
#include <algorithm>

#include <Eigen/Core>

#include "simulator/scene/contact_softness.hpp"
#include "simulator/scene/scene_description.hpp"

namespace stride::sim {

// A robot geom's friction: the law's, else the coefficient every scene had before <contact>.
inline double robot_geom_friction(const PhysicsSettings& p) {
  return p.contact_law ? p.contact_law->friction : 0.8;
}

// A body's contact points against the static scene in one step: how many, and their summed depth.
struct LawBodyLoad {
  int points = 0;
  double depth = 0;  // m, the points' depths (negative ones as 0) added up
};

// A point's share of its body's law under per="body": its depth over the body's (with a micrometre
// each, so level points share alike), so a point that appears at the surface takes almost nothing
// from the others and the body's force does not jump with the collider's point count; 1 per point.
inline double law_point_share(const ContactLaw& law, double depth, const LawBodyLoad& body) {
  if (!law.per_body || body.points <= 1) return 1;
  constexpr double kLevel = 1e-6;
  return (std::max(depth, 0.0) + kLevel) / (body.depth + body.points * kLevel);
}

// The spring and damper of a point that carries `share` of the law, at step h.
inline ContactSoftness law_point_softness(const ContactLaw& law, double share, double h) {
  return contact_softness(law.stiffness * share, law.damping * share, h);
}

// The pyramid's first friction axis: world x in the contact plane (world y where the normal lies
// near x), so that both engines' pyramids face the same way.
inline Eigen::Vector3d law_friction_axis(const Eigen::Vector3d& normal) {
  Eigen::Vector3d t = Eigen::Vector3d::UnitX() - normal.x() * normal;
  if (t.norm() < 0.3) t = Eigen::Vector3d::UnitY() - normal.y() * normal;
  return t.normalized();
}

}  // namespace stride::sim
