#pragma once
// The <physics> attributes only MuJoCo reads: its contact softness (solref = timeconst,
// dampratio; solimp = dmin, dmax), friction cone and no-slip pass. They exist to measure how a
// walk depends on MuJoCo's contact model (issue 33); the defaults are the engine's (mjcf_writer).
// An ODE scene stating one is an error at its line, as an ODE setting is on MuJoCo.
#include <array>

#include "robot/core/xml_element.hpp"
#include "simulator/scene/scene_description.hpp"

namespace stride::sim {

inline constexpr std::array<const char*, 6> kMujocoOnly{
    "cone",         "noslip_iterations", "contact_timeconst", "contact_dampratio",
    "contact_dmin", "contact_dmax"};

// Reads them into `p` (engine already read); on engine="ode" any of them fails at its line.
void parse_mujoco_options(const XmlElement& e, PhysicsSettings& p);

}  // namespace stride::sim
