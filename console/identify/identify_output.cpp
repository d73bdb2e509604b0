#include "console/identify/identify_output.hpp"

#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>

#include "robot/hal/joint_id.hpp"

namespace stride::identify {
namespace {

constexpr double kDeg = 180 / std::numbers::pi;

std::string fmt(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

// "gain 231.4 +- 3.1 1/s (nominal 200)" or "torque not identifiable from this log (...)"
std::string describe(const IdentifiedParam& p) {
  const char* unit = p.param.kind == ParamKind::gain ? " 1/s" : " N m";
  const std::string kind(kind_name(p.param.kind));
  if (!p.identified && !std::isfinite(p.half_width))
    return kind +
           " not identifiable from this log (a change of it moves the replay no more than "
           "the simulation's numerical noise; kept at the nominal " +
           fmt("%.4g", p.param.nominal) + ")";
  if (!p.identified)
    return kind + " not identifiable from this log (95 % interval +-" + fmt("%.3g", p.half_width) +
           unit + ", wanted +-" + fmt("%.3g", p.param.wanted) + "; kept at the nominal " +
           fmt("%.4g", p.param.nominal) + ")";
  return kind + " " + fmt("%.5g", p.value) + " +- " + fmt("%.2g", p.half_width) + unit +
         " (nominal " + fmt("%.4g", p.param.nominal) + ")";
}

std::string attribute(const IdentifiedParam& p) {
  switch (p.param.kind) {
    case ParamKind::gain:
      return "gain=\"" + fmt("%.6g", p.value) + "\"";
    case ParamKind::torque:
      return "stall_torque=\"" + fmt("%.6g", p.value) + "\"";
  }
  return "";
}

}  // namespace

std::string override_text(const IdentifyResult& r, const std::string& source) {
  std::string s = "<?xml version=\"1.0\"?>\n<!-- stride identify " + source +
                  ": servo parameters and gyro bias fitted to that log (docs/identify.md).\n"
                  "     Include it in a scene's <robot>: <include file=\"this file\"/>. Values "
                  "with 95 % intervals;\n     parameters the log could not resolve are left out "
                  "(the device file's stand). -->\n<robot_override>\n";
  std::map<int, std::vector<const IdentifiedParam*>> by_joint;
  for (const auto& p : r.params) by_joint[p.param.joint].push_back(&p);
  for (const auto& jf : r.joints) {
    std::string attrs, notes;
    for (const IdentifiedParam* p : by_joint[jf.joint]) {
      if (p->identified) attrs += " " + attribute(*p);
      notes += std::string(notes.empty() ? "" : "; ") + describe(*p);
    }
    const std::string name(hal::kJointNames[jf.joint]);
    s += "  <!-- " + name + ": " + notes + "; RMS position error " +
         fmt("%.3g", jf.rms_identified * 1e3) + " mrad (nominal " +
         fmt("%.3g", jf.rms_nominal * 1e3) + ") -->\n";
    if (!attrs.empty()) s += "  <servo joint=\"" + name + "\"" + attrs + "/>\n";
  }
  if (r.gyro) {
    const auto& g = *r.gyro;
    s += "  <!-- gyro bias (deg/s): ";
    for (int a = 0; a < 3; ++a)
      s += std::string(a ? ", " : "") + "xyz"[a] + " " + fmt("%.4g", g.value[a] * kDeg) + " +- " +
           fmt("%.2g", g.half_width[a] * kDeg);
    s += " (nominal " + fmt("%.4g", g.nominal[0] * kDeg) + " " + fmt("%.4g", g.nominal[1] * kDeg) +
         " " + fmt("%.4g", g.nominal[2] * kDeg) + ") -->\n  <imu gyro_bias=\"";
    for (int a = 0; a < 3; ++a)
      s += std::string(a ? " " : "") + fmt("%.9g", g.value[a] * kDeg) + "deg";
    s += "\"/>\n";
  }
  return s + "</robot_override>\n";
}

std::vector<std::string> report_lines(const IdentifyResult& r) {
  std::vector<std::string> lines;
  for (const auto& p : r.params)
    lines.push_back(std::string(hal::kJointNames[p.param.joint]) + " " + describe(p));
  for (const auto& j : r.joints)
    lines.push_back(std::string(hal::kJointNames[j.joint]) + " RMS position error " +
                    fmt("%.3g", j.rms_identified * 1e3) + " mrad, nominal model " +
                    fmt("%.3g", j.rms_nominal * 1e3) + " mrad");
  if (r.gyro)
    for (int a = 0; a < 3; ++a)
      lines.push_back(std::string("gyro bias ") + "xyz"[a] + " " +
                      fmt("%.4g", r.gyro->value[a] * kDeg) + " +- " +
                      fmt("%.2g", r.gyro->half_width[a] * kDeg) + " deg/s (nominal " +
                      fmt("%.4g", r.gyro->nominal[a] * kDeg) + ")");
  lines.push_back("fit: cost " + fmt("%.6g", r.fit.start_cost) + " -> " + fmt("%.6g", r.fit.cost) +
                  " in " + std::to_string(r.fit.iterations) + " iterations, " +
                  std::to_string(r.fit.evaluations) + " replays");
  return lines;
}

std::string traces_csv(const IdentifyLog& log, const IdentifyResult& r) {
  std::string s = "time";
  for (const auto& j : r.joints) {
    const std::string n(hal::kJointNames[j.joint]);
    s += "," + n + "_logged," + n + "_identified," + n + "_nominal";
  }
  s += "\n";
  for (std::size_t f = 0; f < log.frames.size() && f < r.identified.size() && f < r.nominal.size();
       ++f) {
    s += fmt("%.4f", log.frames[f].time);
    for (const auto& j : r.joints)
      s += fmt(",%.6f", log.frames[f].position[j.joint]) +
           fmt(",%.6f", r.identified[f].position[j.joint]) +
           fmt(",%.6f", r.nominal[f].position[j.joint]);
    s += "\n";
  }
  return s;
}

}  // namespace stride::identify
