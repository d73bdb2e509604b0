#include "console/view/view_json.hpp"

#include <cmath>

namespace stride::view {

namespace {

// Sub-micrometre digits only cost bytes on the wire; non-finite numbers become null.
Json number(double v) {
  if (!std::isfinite(v)) return nullptr;
  return std::round(v * 1e6) / 1e6;
}

}  // namespace

Json pose_json(const Eigen::Isometry3d& pose) {
  const Eigen::Vector3d p = pose.translation();
  const Eigen::Quaterniond q(pose.rotation());
  return Json::array({number(p.x()), number(p.y()), number(p.z()), number(q.w()), number(q.x()),
                      number(q.y()), number(q.z())});
}

Json point_json(const Eigen::Vector3d& p) {
  return Json::array({number(p.x()), number(p.y()), number(p.z())});
}

Json point2_json(const Eigen::Vector2d& p) {
  return Json::array({number(p.x()), number(p.y())});
}

std::string dump(const Json& message) {
  return message.dump(-1, ' ', false, Json::error_handler_t::replace);
}

}  // namespace stride::view
