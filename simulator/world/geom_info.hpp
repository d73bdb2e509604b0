#pragma once
// What the contact callback needs to know about a collision geometry (stored as ODE geom data).
namespace stride::sim {

struct GeomInfo {
  int robot = -1;         // -1: static environment
  int link = -1;          // link index within the robot's model
  double friction = 0.8;  // Coulomb coefficient; a pair uses the smaller of the two
};

}  // namespace stride::sim
