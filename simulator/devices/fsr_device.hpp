#pragma once
// Four force sensors under one sole, from the contact forces the solver applied to the foot:
// the foot's normal load and its centre of pressure are shared among the four sensors as a rigid
// plate on four supports would (least-norm, non-negative), then noise and saturation.
#include <array>
#include <vector>

#include <Eigen/Dense>

#include "simulator/scene/device_description.hpp"
#include "simulator/scene/noise_source.hpp"
#include "simulator/world/physics_world.hpp"
#include "simulator/world/robot_body.hpp"

namespace stride::sim {

// Non-negative least-norm forces at four fixed points whose sum is a load and whose moment centre
// is a given centre of pressure. The fifteen support subsets' decompositions depend on the points
// only, so they are made once.
class LoadSplitter {
 public:
  explicit LoadSplitter(const std::array<Eigen::Vector2d, 4>& points);
  std::array<double, 4> split(double load, const Eigen::Vector2d& cop) const;

 private:
  using Subset = Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, 4>;  // bounded: off the heap
  struct Support {
    int mask;
    Subset a;  // columns (1, x, y) of the subset's points
    Eigen::CompleteOrthogonalDecomposition<Subset> cod;
  };
  std::vector<Support> supports_;  // masks 1..15
};

class FsrDevice {
 public:
  FsrDevice(const RobotBody& body, int robot_index, const FsrSpec& spec, NoiseSource noise);
  // After each physics step: add this step's sole-normal load and its moments.
  void accumulate(const RobotBody& body, const PhysicsWorld& world);
  // End of a control frame: mean over the frame's steps, shared out, noise, clamp; resets.
  std::array<double, 4> sample(bool noise_on);
  // The sole-normal load of each physics step of the frame sample() last closed, before the
  // sharing, noise and saturation: what the floor really pushed with (N).
  const std::vector<double>& frame_loads() const { return closed_loads_; }

 private:
  FsrSpec spec_;
  LoadSplitter splitter_;
  int link_;
  int robot_;
  NoiseSource noise_;
  double load_sum_ = 0;
  Eigen::Vector2d moment_sum_ = Eigen::Vector2d::Zero();  // sum of load * (x, y)
  int steps_ = 0;
  std::vector<double> step_loads_, closed_loads_;  // this frame's, the last closed frame's
};

}  // namespace stride::sim
