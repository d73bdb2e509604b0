#pragma once
// LoLA, the NAO v6's low-level access (nao-facts.md "LoLA"): every 12 ms one msgpack map of
// sensor data on a unix stream socket, answered by one msgpack map of actuator commands.
// Strings are fixstr, floats float32, 25-element arrays array16; the sensor packet is 896 bytes,
// the full actuator map 786. The keys, their order and lengths are fixed here, once.
#include <array>
#include <cstddef>
#include <string_view>

#include "robot/hal/joint_id.hpp"

namespace stride::hal::lola {

inline constexpr std::string_view kDefaultSocket = "/tmp/robocup";
inline constexpr double kPeriod = 0.012;  // s
inline constexpr std::size_t kSensorPacketSize = 896;
inline constexpr std::size_t kActuatorPacketSize = 786;  // every actuator key present
// Anything longer is not a LoLA packet; a reader drops it rather than buffer without bound.
inline constexpr std::size_t kMaxPacketSize = 4096;

// LoLA's FSRs report kilograms; SensorFrame carries newtons.
inline constexpr double kFsrNewtonPerKg = 9.80665;

struct KeyLength {
  std::string_view key;
  int length;  // array elements
};

// The sensor map in the order LoLA writes it (nao-facts.md).
inline constexpr std::array<KeyLength, 13> kSensorKeys = {{{"Stiffness", kNumJoints},
                                                           {"Position", kNumJoints},
                                                           {"Temperature", kNumJoints},
                                                           {"Current", kNumJoints},
                                                           {"Battery", 4},
                                                           {"Accelerometer", 3},
                                                           {"Gyroscope", 3},
                                                           {"Angles", 2},
                                                           {"Sonar", 2},
                                                           {"FSR", kNumFsr},
                                                           {"Status", kNumJoints},
                                                           {"Touch", kNumTouch},
                                                           {"RobotConfig", 4}}};

// The actuator map; a client may send any subset. LED keys carry 0..1 intensities.
inline constexpr std::array<KeyLength, 11> kActuatorKeys = {{{"Position", kNumJoints},
                                                             {"Stiffness", kNumJoints},
                                                             {"Chest", 3},
                                                             {"LEar", 10},
                                                             {"REar", 10},
                                                             {"LEye", 24},
                                                             {"REye", 24},
                                                             {"LFoot", 3},
                                                             {"RFoot", 3},
                                                             {"Skull", 12},
                                                             {"Sonar", 2}}};

// What the simulator says it is (RobotConfig): body id, body version, head id, head version, in
// the shape of a NAO v6's (20-character ids): with them the sensor packet is LoLA's 896 bytes.
inline constexpr std::array<std::string_view, 4> kSimulatedRobotConfig = {
    "P0000SIMULATEDBODY01", "6.0.0", "P0000SIMULATEDHEAD01", "6.0.0"};

}  // namespace stride::hal::lola
