#pragma once
// Something that acts between two frames of a Runtime (e.g. the debug server's exchange): called
// at the end of every Runtime::step(), after the actuators were written and the frame logged, so
// whatever it changes (parameters, providers, logs) takes effect from the next frame on, exactly
// as a console command between frames does.
namespace stride {

class Runtime;

class FrameBoundary {
 public:
  virtual ~FrameBoundary() = default;
  virtual void after_frame(Runtime& runtime) = 0;
  // The runtime was given another boundary (or none, before it is destroyed): whatever this
  // boundary holds of it (pointers into its blackboard) must be let go.
  virtual void detached(Runtime& /*runtime*/) {}
};

}  // namespace stride
