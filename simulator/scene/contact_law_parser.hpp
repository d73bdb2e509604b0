#pragma once
// <contact stiffness damping per friction cone>: the scene's one contact law (ContactLaw), and the
// checks that need the whole scene: what it replaces in <physics>, what an engine cannot realise.
#include <string>
#include <vector>

#include "robot/core/xml_element.hpp"
#include "simulator/scene/scene_description.hpp"

namespace stride::sim {

// The default law: 1e5 N/m and 1000 N s/m per body, friction 0.8 on an elliptic cone
// (docs/scenes.md, "Contact law").
inline constexpr double kDefaultLawStiffness = 1e5;
inline constexpr double kDefaultLawDamping = 1000;

void parse_contact_law(const XmlElement& e, PhysicsSettings& p);

// The <physics> attributes a law replaces; "file:line: attribute" of the first stated, if any.
inline constexpr const char* kReplacedByLaw[] = {
    "contact_erp",        "contact_cfm",  "contact_stiffness", "contact_damping",
    "contact_spring_per", "cone",         "contact_timeconst", "contact_dampratio",
    "contact_dmin",       "contact_dmax", "noslip_iterations"};

// The first of them <physics> stated (attr empty: none).
struct ReplacedAttribute {
  std::string file, attr;
  int line = 0;
};

// After the whole scene is read: a law beside a replaced <physics> attribute is an error at
// file:line; the surfaces that stated no friction take the law's.
struct UnstatedFriction {
  bool ground = false;
  std::vector<std::size_t> boxes, uneven;
};
void finish_contact_law(SceneDescription& s, const ReplacedAttribute& replaced,
                        const UnstatedFriction& unstated);

}  // namespace stride::sim
