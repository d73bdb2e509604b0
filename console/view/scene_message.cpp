#include "console/view/scene_message.hpp"

#include "robot/framework/enum_names.hpp"
#include "simulator/render/body_side.hpp"
#include "simulator/world/physics_world.hpp"

namespace stride::view {

namespace {

Json shape_json(const model::CollisionShape& c) {
  using Kind = model::CollisionShape::Kind;
  Json s = {{"pose", pose_json(c.origin)}};
  switch (c.kind) {
    case Kind::Box:
      s["shape"] = "box";
      s["size"] = point_json(c.box_size);
      break;
    case Kind::Cylinder:
      s["shape"] = "cylinder";
      s["radius"] = c.radius;
      s["length"] = c.length;
      break;
    case Kind::Sphere:
      s["shape"] = "sphere";
      s["radius"] = c.radius;
      break;
  }
  return s;
}

Json box_json(const sim::StaticBox& b, bool named) {
  Json j = {{"size", point_json(b.size)}, {"pose", pose_json(b.pose)}};
  if (named) {
    j["name"] = b.name;
    j["shape"] = "box";
  }
  return j;
}

}  // namespace

Json robot_links_json(const model::RobotModel& model) {
  Json links = Json::array();
  for (const model::Link& link : model.links) {
    Json shapes = Json::array();
    for (const auto& c : link.collisions) shapes.push_back(shape_json(c));
    links.push_back({{"name", link.name},
                     {"side", std::string(enum_name(render::side_of_link(link.name)))},
                     {"shapes", std::move(shapes)}});
  }
  return links;
}

Json scene_message(const std::string& name, const sim::SceneDescription* scene,
                   const std::vector<SceneRobot>& robots) {
  Json statics = Json::array(), tiles = Json::array(), robot_list = Json::array(),
       bodies = Json::array();
  if (scene) {
    for (const auto& b : scene->boxes) statics.push_back(box_json(b, true));
    for (std::size_t i = 0; i < scene->uneven.size(); ++i)
      for (const auto& t : sim::uneven_tiles(scene->uneven[i], sim::uneven_patch_seed(*scene, i)))
        tiles.push_back(box_json(t, false));
  }
  for (const SceneRobot& r : robots) {
    robot_list.push_back({{"name", r.name}, {"links", robot_links_json(*r.model)}});
    for (const auto& link : r.model->links) bodies.push_back(r.name + "/" + link.name);
  }
  return {{"type", "scene"},
          {"name", name},
          {"statics", std::move(statics)},
          {"tiles", std::move(tiles)},
          {"robots", std::move(robot_list)},
          {"bodies", std::move(bodies)},
          {"views", Json::array({"follow", "front", "side", "top"})}};
}

}  // namespace stride::view
