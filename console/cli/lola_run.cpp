#include "console/cli/lola_run.hpp"

#include <ostream>

#include "robot/core/error.hpp"
#include "simulator/lola/lola_scene.hpp"

namespace stride::cli {
namespace {

int lola_robot(const sim::SceneDescription& scene, const LolaRunOptions& o) {
  if (scene.robots.empty()) throw Error("stride run: --lola: the scene has no robot");
  if (o.robot.empty()) return 0;
  for (std::size_t i = 0; i < scene.robots.size(); ++i)
    if (scene.robots[i].name == o.robot) return static_cast<int>(i);
  throw Error("stride run: --robot: no robot named '" + o.robot + "' in the scene");
}

void serve_over(sim::Simulation& sim, int robot, sim::LolaServer& server) {
  sim.set_controller(robot, &server);
}

}  // namespace

LolaRunOptions read_lola_options(ArgumentReader& a) {
  LolaRunOptions o;
  o.socket = a.text_or("--lola", "");
  o.packets = a.flag("--lola-packets");
  o.realtime = a.flag("--realtime");
  const bool has_robot = a.has("--robot"), has_wait = a.has("--lola-wait");
  o.robot = a.text_or("--robot", "");
  o.wait = a.number_or("--lola-wait", o.wait);
  if (!o.socket.empty() && o.packets)
    throw Error("stride run: --lola and --lola-packets: expected one of them");
  if (!o.any() && (has_robot || o.realtime || has_wait))
    throw Error("stride run: --robot, --realtime and --lola-wait go with --lola <socket>");
  if (o.packets && (o.realtime || has_wait))
    throw Error("stride run: --realtime and --lola-wait go with --lola <socket>");
  if (!(o.wait > 0)) throw Error("stride run: --lola-wait: expected a time > 0 s");
  return o;
}

sim::SceneDescription lola_scene(sim::SceneDescription scene, const LolaRunOptions& o) {
  if (!o.any()) return scene;
  const auto robot = static_cast<std::size_t>(lola_robot(scene, o));
  if (o.packets && !scene.robots[robot].has_controller)
    throw Error("stride run: --lola-packets: robot '" + scene.robots[robot].name +
                "' has no <controller>");
  sim::prepare_lola_robot(scene, robot,
                          o.packets ? sim::LolaController::InProcess : sim::LolaController::Client);
  return scene;
}

std::unique_ptr<sim::LolaServer> attach_lola(console::SimSession& session, const LolaRunOptions& o,
                                             std::ostream& events) {
  if (!o.any()) return nullptr;
  auto& sim = session.simulation();
  const int robot = lola_robot(sim.scene(), o);
  if (o.packets) {
    session.route_through_lola_packets(robot);
    return nullptr;
  }
  auto server = std::make_unique<sim::LolaServer>(
      o.socket, o.realtime ? sim::LolaPacing::Realtime : sim::LolaPacing::Lockstep,
      sim.robot(robot), events);
  events << "lola: robot '" << sim.robot(robot).name() << "' waits for a client on " << o.socket
         << std::endl;
  server->wait_for_client(o.wait);
  serve_over(sim, robot, *server);
  return server;
}

LolaRestarts::LolaRestarts(console::SimSession& session, sim::LolaServer& server,
                           const LolaRunOptions& o)
    : session_(session),
      server_(server),
      robot_(lola_robot(session.simulation().scene(), o)),
      listener_(o.socket) {}

bool LolaRestarts::poll() {
  if (!listener_.take_request()) return false;
  session_.reset();  // gives every robot the session's own controller: LoLA's link again
  auto& sim = session_.simulation();
  serve_over(sim, robot_, server_);
  server_.restarted(sim.robot(robot_));
  listener_.answer_done();
  return true;
}

}  // namespace stride::cli
