#pragma once
// `stride identify`'s study: replays a robot's log on the simulated robot and fits the chosen
// servo parameters of the chosen leg joints (least_squares.hpp, each batch on the sweep engine's
// workers), then the gyro bias from what the fitted replay leaves unexplained.
#include <array>
#include <optional>
#include <vector>

#include "console/identify/identify_log.hpp"
#include "console/identify/identify_params.hpp"
#include "console/identify/least_squares.hpp"
#include "console/identify/replay_plant.hpp"

namespace stride::identify {

struct IdentifiedParam {
  Param param;
  double value = 0;       // the nominal when not identified
  double half_width = 0;  // 95 % interval
  bool identified = false;
};

struct JointFit {
  int joint;
  double rms_nominal = 0, rms_identified = 0;  // rad, simulated vs logged position
};

struct GyroBias {
  std::array<double, 3> value{}, half_width{}, nominal{};  // rad/s
};

struct IdentifyResult {
  std::vector<IdentifiedParam> params;
  std::vector<JointFit> joints;
  std::optional<GyroBias> gyro;
  LsqResult fit;
  std::vector<LoggedFrame> nominal, identified;  // the replays, for plots
};

struct IdentifyRequest {
  ParamChoice choice;
  std::vector<int> joints;
  int jobs = 1;
  int iterations = 8;
};

IdentifyResult identify(const IdentifyLog& log, const RobotFiles& robot, const IdentifyRequest& r);

}  // namespace stride::identify
