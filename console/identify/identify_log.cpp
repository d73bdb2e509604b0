#include "console/identify/identify_log.hpp"

#include <cmath>
#include <sstream>

#include "robot/core/error.hpp"
#include "robot/representations/frame_info.hpp"
#include "robot/representations/fsr_sensor_data.hpp"
#include "robot/representations/inertial_sensor_data.hpp"
#include "robot/representations/joint_request.hpp"
#include "robot/representations/joint_sensor_data.hpp"
#include "robot/runtime/log.hpp"

namespace stride::identify {
namespace {

std::string number(double v) {
  std::ostringstream s;
  s.precision(3);
  s << v;
  return s.str();
}

void check_whole(const LogReader& log, const std::string& name) {
  const LogIntegrity& in = log.integrity();
  if (in.truncated > 0)
    throw Error(name + ": truncated after frame " + std::to_string(log.frame_count()) +
                " (the recording was cut); identify needs a whole log: " + log.summary());
  if (!in.damaged_frames.empty())
    throw Error(name + ": frame " + std::to_string(in.damaged_frames.front()) +
                " is damaged; identify needs a whole log: " + log.summary());
  for (const char* r : kNeededRepresentations)
    if (log.index_of(r) < 0)
      throw Error(
          name + ": the log has no " + r + " (identify needs FrameInfo, JointSensorData, " +
          "JointRequest, InertialSensorData and FsrSensorData: record with stride robot --log)");
  if (log.frame_count() < kMinFrames)
    throw Error(name + ": " + std::to_string(log.frame_count()) + " frames, expected at least " +
                std::to_string(kMinFrames) + " (record a whole excitation motion)");
}

bool finite(const LoggedFrame& f) {
  auto all = [](const auto& a) {
    for (double v : a)
      if (!std::isfinite(v)) return false;
    return true;
  };
  return all(f.position) && all(f.current) && all(f.gyro) && all(f.angles) && all(f.fsr) &&
         all(f.command.position) && all(f.command.stiffness) && all(f.command.torque);
}

LoggedFrame frame_of(const LogReader& log, std::size_t i) {
  LoggedFrame f;
  const auto info = log.read<FrameInfo>(i);
  const auto joints = log.read<JointSensorData>(i);
  const auto imu = log.read<InertialSensorData>(i);
  const auto fsr = log.read<FsrSensorData>(i);
  const auto request = log.read<JointRequest>(i);
  f.time = info.time;
  f.position = joints.position;
  f.current = joints.current;
  for (int a = 0; a < 3; ++a) f.gyro[a] = imu.gyro[a];
  f.angles = {imu.angles.x(), imu.angles.y()};
  f.fsr = fsr.force;
  f.command.mode = request.mode;
  f.command.position = request.position;
  f.command.stiffness = request.stiffness;
  f.command.torque = request.torque;
  return f;
}

}  // namespace

IdentifyLog read_identify_log(const LogReader& log, const std::string& name) {
  check_whole(log, name);
  IdentifyLog out;
  out.file = name;
  out.held = true;
  for (std::size_t i = 0; i < log.frame_count(); ++i) {
    LoggedFrame f;
    double period = 0;
    try {
      f = frame_of(log, i);
      period = log.read<FrameInfo>(i).period;
    } catch (const Error& e) {
      throw Error(name + ": frame " + std::to_string(i) + ": " + e.what());
    }
    if (!finite(f) || !std::isfinite(period))
      throw Error(name + ": frame " + std::to_string(i) + " holds a non-finite value");
    if (i == 0) out.period = period;
    if (!(period > 0) || std::abs(period - out.period) > 1e-9)
      throw Error(name + ": frame " + std::to_string(i) + ": period " + number(period) +
                  " s, expected the first frame's " + number(out.period) + " s throughout");
    const double tilt = std::max(std::abs(f.angles[0]), std::abs(f.angles[1]));
    if (tilt > kLyingTilt)
      throw Error(name + ": frame " + std::to_string(i) + " (" + number(f.time) +
                  " s): the torso is tilted " + number(tilt) +
                  " rad: a robot lying on the floor cannot be identified from");
    double load = 0;
    for (double v : f.fsr) load += v;
    if (load >= kHeldLoad) out.held = false;
    out.frames.push_back(f);
  }
  return out;
}

IdentifyLog read_identify_log(const std::string& path) {
  try {
    return read_identify_log(LogReader(path), path);
  } catch (const Error& e) {
    const std::string what = e.what();
    throw Error(what.starts_with(path) ? what : path + ": " + what);
  }
}

}  // namespace stride::identify
