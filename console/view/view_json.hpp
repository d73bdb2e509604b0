#pragma once
// Small JSON pieces the view's messages share (console/view/PROTOCOL.md): poses, points, and the
// one way every message is written (invalid UTF-8 from a user's text replaced, never thrown).
#include <Eigen/Geometry>
#include <nlohmann/json.hpp>
#include <string>

namespace stride::view {

using Json = nlohmann::json;

// [x,y,z,qw,qx,qy,qz]
Json pose_json(const Eigen::Isometry3d& pose);
Json point_json(const Eigen::Vector3d& p);
Json point2_json(const Eigen::Vector2d& p);
std::string dump(const Json& message);

}  // namespace stride::view
