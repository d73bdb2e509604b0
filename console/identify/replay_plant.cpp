#include "console/identify/replay_plant.hpp"

#include <filesystem>

#include "robot/core/data_dir.hpp"
#include "robot/core/error.hpp"
#include "simulator/simulation.hpp"

namespace stride::identify {
namespace {

namespace fs = std::filesystem;

// Where a held robot's torso is: high enough that no foot reaches the floor.
constexpr double kHeldHeight = 0.6;

sim::SceneDescription replay_scene(const IdentifyLog& log, const RobotFiles& robot,
                                   const std::vector<sim::ServoOverride>& servos) {
  sim::SceneDescription scene;
  scene.name = "identify_replay";
  scene.file = log.file;
  scene.physics.step = 0.001;
  scene.physics.seed = 1;
  sim::RobotPlacement r;
  r.name = "nao";
  r.urdf = robot.urdf;
  r.devices = robot.devices;
  r.file = log.file;
  r.period = log.period;
  r.servos = servos;
  r.sensors.noise = false;
  r.sensors.quantise = false;
  const LoggedFrame& first = log.frames.front();
  if (log.held) {
    r.fixed_base = true;
    r.auto_height = false;
    r.xyz = {0, 0, kHeldHeight};
    r.rpy = {first.angles[0], first.angles[1], 0};
  }
  // The encoders read the true angle less the offset: the joints start where the log says.
  std::map<std::string, double> offset;
  for (const auto& s : servos)
    if (s.offset) offset[s.joint] = *s.offset;
  for (int l = 0; l < hal::kNumJoints - 2; ++l) {  // the hands are no URDF joints
    const std::string name(hal::kJointNames[l]);
    r.joints[name] = first.position[l] + (offset.contains(name) ? offset[name] : 0.0);
  }
  r.joints["RHipYawPitch"] = r.joints["LHipYawPitch"];  // one motor, the mimic's master
  scene.robots.push_back(r);
  return scene;
}

}  // namespace

RobotFiles robot_files(const std::string& robot) {
  RobotFiles f;
  if (robot.empty()) {
    const fs::path nao = fs::path(data_dir()) / "scenes" / "robots" / "nao";
    f.urdf = (nao / "nao.urdf").string();
    f.devices = (nao / "nao.devices.xml").string();
  } else {
    f.urdf = robot;
    fs::path d(robot);
    d.replace_extension(".devices.xml");
    f.devices = d.string();
  }
  for (const std::string& p : {f.urdf, f.devices})
    if (!fs::is_regular_file(p))
      throw Error("stride identify: --robot: " + p + " does not exist (expected a URDF with its " +
                  "devices beside it as <name>.devices.xml)");
  return f;
}

namespace {

// The simulated robot's controller in a replay: the log's commands, one a frame, and what the
// robot sensed at each of those frames kept.
class LogPlayer final : public hal::FrameController {
 public:
  LogPlayer(const IdentifyLog& log, std::vector<LoggedFrame>& out) : log_(log), out_(out) {}

  bool control_frame(const hal::SensorFrame& s, hal::ActuatorFrame& commands) override {
    if (played_ >= out_.size()) return false;
    LoggedFrame& f = out_[played_];
    f.time = s.time;
    f.position = s.position;
    f.current = s.current;
    f.gyro = s.gyroscope;
    f.angles = s.angles;
    f.fsr = s.fsr;
    f.command = log_.frames[played_].command;
    commands = f.command;
    ++played_;
    return true;
  }
  std::size_t played() const { return played_; }

 private:
  const IdentifyLog& log_;
  std::vector<LoggedFrame>& out_;
  std::size_t played_ = 0;
};

}  // namespace

std::vector<LoggedFrame> replay(const IdentifyLog& log, const RobotFiles& robot,
                                const std::vector<sim::ServoOverride>& servos) {
  sim::Simulation sim(replay_scene(log, robot, servos));
  std::vector<LoggedFrame> out(log.frames.size());
  LogPlayer player(log, out);
  sim.set_controller(0, &player);
  sim.run_for(static_cast<double>(log.frames.size()) * log.period);
  if (player.played() < out.size()) out.resize(player.played());
  return out;
}

}  // namespace stride::identify
