#include "console/identify/identify.hpp"

#include <cmath>
#include <cstring>

#include "console/identify/residual.hpp"
#include "console/sweep/ordered_jobs.hpp"
#include "robot/core/error.hpp"

namespace stride::identify {
namespace {

std::string encode(const std::vector<double>& v) {
  std::string bytes(v.size() * sizeof(double), '\0');
  if (!v.empty()) std::memcpy(bytes.data(), v.data(), bytes.size());
  return bytes;
}

std::vector<double> decode(const std::string& bytes) {
  std::vector<double> v(bytes.size() / sizeof(double));
  if (!v.empty()) std::memcpy(v.data(), bytes.data(), v.size() * sizeof(double));
  return v;
}

// Each candidate's replay is one job on the sweep engine's executors (forked workers for
// jobs > 1); results come back in candidate order.
BatchResidual batch_on_workers(const IdentifyLog& log, const RobotFiles& robot,
                               const std::vector<Param>& params, const std::vector<int>& joints,
                               int jobs) {
  return [&log, &robot, &params, &joints, jobs](const std::vector<std::vector<double>>& xs) {
    std::vector<std::vector<double>> out(xs.size());
    sweep::run_jobs(
        xs.size(), jobs,
        [&](std::size_t i) {
          return encode(residual(log, replay(log, robot, servo_overrides(params, xs[i])), joints));
        },
        [&](std::size_t i, std::string&& bytes) {
          out[i] = decode(bytes);
          return true;
        },
        [](std::size_t i) { return "identify candidate " + std::to_string(i); });
    return out;
  };
}

GyroBias gyro_bias(const IdentifyLog& log, const std::vector<LoggedFrame>& simulated,
                   const sim::DeviceDescription& devices) {
  GyroBias g;
  const double n = static_cast<double>(log.frames.size());
  for (int a = 0; a < 3; ++a) {
    double sum = 0, sq = 0;
    for (std::size_t f = 0; f < log.frames.size(); ++f) {
      const double d = log.frames[f].gyro[a] - simulated[f].gyro[a];
      sum += d;
      sq += d * d;
    }
    const double mean = sum / n;
    const double sd = std::sqrt(std::max(0.0, sq / n - mean * mean));
    g.nominal[a] = devices.imu.gyro_bias[a];
    // The replay's gyro carries the device file's bias: what the log adds to it is the change.
    g.value[a] = g.nominal[a] + mean;
    g.half_width[a] = 1.96 * sd / std::sqrt(n);
  }
  return g;
}

}  // namespace

IdentifyResult identify(const IdentifyLog& log, const RobotFiles& robot, const IdentifyRequest& r) {
  const sim::DeviceDescription devices = sim::load_device_file(robot.devices);
  const std::vector<Param> params = make_params(r.choice, r.joints, devices);
  IdentifyResult out;
  std::vector<double> nominal;
  for (const Param& p : params) nominal.push_back(p.nominal);
  if (!params.empty()) {
    std::vector<LsqParam> lsq;
    for (const Param& p : params) lsq.push_back({p.nominal, p.lower, p.upper, p.step, p.wanted});
    out.fit =
        least_squares(lsq, batch_on_workers(log, robot, params, r.joints, r.jobs), r.iterations);
    for (std::size_t i = 0; i < params.size(); ++i)
      out.params.push_back(
          {params[i], out.fit.value[i], out.fit.half_width[i], out.fit.identified[i]});
  }
  out.nominal = replay(log, robot, servo_overrides(params, nominal));
  out.identified =
      params.empty() ? out.nominal : replay(log, robot, servo_overrides(params, out.fit.value));
  for (int j : r.joints)
    out.joints.push_back(
        {j, rms_position_error(log, out.nominal, j), rms_position_error(log, out.identified, j)});
  if (r.choice.gyro_bias) out.gyro = gyro_bias(log, out.identified, devices);
  return out;
}

}  // namespace stride::identify
