#pragma once
// The robot-side programs, for a `main` that links only robot/ and behaviours/ (`stride-robot`,
// which `stride robot` and `stride lola` start):
//   stride robot --config <robot.xml> [--lola <socket>] [--log <file>]
//                [--debug <addr:port> [--token-file f] [--log-dir d] [--no-wait]]
//                [--rt-priority 1..99] [--cpu N]
//   stride lola dump [<socket>] [--frames N]
#include <iosfwd>
#include <span>
#include <string>

#include "robot/framework/module_registry.hpp"

namespace stride {

int robot_main(std::span<const std::string> args, const ModuleRegistry& registry, std::ostream& out,
               std::ostream& err);

// Prints decoded sensor frames from any LoLA server (robot or simulator), answering each packet
// with an empty map so nothing moves and a lockstep simulator keeps going.
int lola_main(std::span<const std::string> args, std::ostream& out, std::ostream& err);

inline constexpr std::string_view kRobotUsage =
    "robot --config <robot.xml> [--lola <socket>] [--log <file>] [--debug <addr:port> "
    "[--token-file f] [--log-dir d] [--no-wait]] [--rt-priority 1..99] [--cpu N]: the robot "
    "runtime on LoLA (a NAO v6, or `stride run <scene> --lola <socket>`), with a debug server for "
    "`connect` (--debug; the robot stands, controller paused, until the first console connects "
    "unless --no-wait), its control loop under SCHED_FIFO (--rt-priority) on one CPU (--cpu); runs "
    "until "
    "SIGINT/SIGTERM";
inline constexpr std::string_view kLolaUsage =
    "lola dump [<socket>] [--frames N]: print decoded LoLA sensor frames (default /tmp/robocup)";

}  // namespace stride
