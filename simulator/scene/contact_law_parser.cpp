#include "simulator/scene/contact_law_parser.hpp"

#include "robot/core/error.hpp"

namespace stride::sim {

void parse_contact_law(const XmlElement& e, PhysicsSettings& p) {
  e.allow_only({"stiffness", "damping", "per", "friction", "cone"});
  ContactLaw law;
  law.file = e.file();
  law.line = e.line();
  law.stiffness = e.number_or("stiffness", kDefaultLawStiffness);
  if (!(law.stiffness > 0)) e.fail_attr("stiffness", "expected a stiffness > 0 (N/m)");
  law.damping = e.number_or("damping", kDefaultLawDamping);
  if (!(law.damping >= 0)) e.fail_attr("damping", "expected a damping >= 0 (N s/m)");
  law.per_body = e.choice_or("per", {"body", "point"}, 0) == 0;
  law.friction = e.number_or("friction", law.friction);
  if (!(law.friction >= 0 && law.friction <= 10))
    e.fail_attr("friction", "expected a Coulomb coefficient in [0, 10]");
  using Cone = ContactLaw::Cone;
  law.cone = e.choice_or("cone", {"elliptic", "pyramid"}, 0) == 0 ? Cone::Elliptic : Cone::Pyramid;
  p.contact_law = law;
}

void finish_contact_law(SceneDescription& s, const ReplacedAttribute& replaced,
                        const UnstatedFriction& unstated) {
  if (!s.physics.contact_law) return;
  const ContactLaw& law = *s.physics.contact_law;
  const std::string at = law.file + ":" + std::to_string(law.line);
  if (!replaced.attr.empty())
    throw error_at(replaced.file, replaced.line,
                   "<physics>: attribute '" + replaced.attr +
                       "': replaced by the <contact> law at " + at +
                       " (expected the contact stated once, there)");
  if (unstated.ground) s.ground.friction = law.friction;
  for (std::size_t i : unstated.boxes) s.boxes[i].friction = law.friction;
  for (std::size_t i : unstated.uneven) s.uneven[i].friction = law.friction;
}

}  // namespace stride::sim
