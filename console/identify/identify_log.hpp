#pragma once
// What `stride identify` takes from a robot's log (`stride robot --log`, `stride run --log`): per
// control frame the command sent and the sensors read, checked whole before any fitting starts.
#include <array>
#include <string>
#include <vector>

#include "robot/hal/actuator_frame.hpp"
#include "robot/hal/sensor_frame.hpp"

namespace stride {
class LogReader;
}

namespace stride::identify {

// One control frame: the sensors sampled at its start and the command computed from them.
struct LoggedFrame {
  double time = 0;
  std::array<double, hal::kNumJoints> position{}, current{};
  std::array<double, 3> gyro{};
  std::array<double, 2> angles{};
  std::array<double, hal::kNumFsr> fsr{};
  hal::ActuatorFrame command;
};

struct IdentifyLog {
  std::string file;
  double period = 0;  // s, control period
  std::vector<LoggedFrame> frames;
  bool held = false;  // the feet carried no weight in any frame: the robot was held in the air
};

// The representations a log must hold.
inline constexpr std::array<const char*, 5> kNeededRepresentations = {
    "FrameInfo", "JointSensorData", "JointRequest", "InertialSensorData", "FsrSensorData"};

// A frame with |torso roll| or |pitch| beyond this (rad) is a robot lying on the floor.
inline constexpr double kLyingTilt = 0.8;
// Both feet together under this (N) in every frame: the robot was held, not standing.
inline constexpr double kHeldLoad = 5.0;
// At least this many frames (12 ms each: 2.4 s).
inline constexpr std::size_t kMinFrames = 200;

// Throws stride::Error, one line starting with the file name, for a log that cannot be
// identified from: unreadable, truncated or damaged, missing a needed representation, too short,
// a period other than the first frame's, a non-finite value, or a robot lying on the floor.
IdentifyLog read_identify_log(const LogReader& log, const std::string& name);
IdentifyLog read_identify_log(const std::string& path);

}  // namespace stride::identify
