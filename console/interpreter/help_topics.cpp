#include "console/interpreter/help_topics.hpp"

#include <array>

namespace stride::console {

namespace {

constexpr std::string_view kSpeed =
    "  The walk's speed is PatternWalk's forward waist speed: preset slow|medium|fast\n"
    "  (0.08-0.09, 0.18-0.19, 0.23-0.24 m/s within a step) or V_min and V_max [m/s]\n"
    "  themselves; T_stride [s] is the period of two steps. The pattern is planned when the\n"
    "  walk starts, so set it before `run` (after load or reset; reset goes back to the\n"
    "  scene's values); a change after the walk started is refused. `get\n"
    "  module:PatternWalk ?` lists every field with its unit and range. To change speed,\n"
    "  direction or turn while walking, RequestWalk walks on request: set\n"
    "  representation:WalkRequest mode=walk forward=0.2 (scenes/walking/requests/steer.xml;\n"
    "  docs/console.md 'Steering a walk').\n"
    "  example:  stride run scenes/walking/open_loop_medium.xml --seconds 17 --set \\\n"
    "              PatternWalk.preset=fast\n"
    "            (console) reset; set module:PatternWalk V_min=0.12 V_max=0.13; run\n"
    "            (scene)   <parameter module=\"PatternWalk\" field=\"preset\" value=\"fast\"/>\n";

constexpr std::string_view kPush =
    "  push <link> <fx> <fy> <fz> <seconds>: a force in newtons on a link of the selected\n"
    "  simulated robot, in the world frame (x the walking direction, y left, z up), from\n"
    "  now for that long. The NAO's links: torso Neck Head, L|R + Shoulder Bicep Elbow\n"
    "  ForeArm Hand Pelvis Hip Thigh Tibia Ankle Foot (LThigh, RFoot, ...). In a scene:\n"
    "  <push robot body force start duration>; many pushes: stride push-sweep, stride\n"
    "  experiment push.\n"
    "  example:  push torso 0 20 0 0.1      (then: run 2; get robot.fell)\n"
    "            (scene) <push robot=\"nao\" body=\"torso\" force=\"0 20 0\" start=\"6s\" \\\n"
    "              duration=\"0.1s\"/>\n";

constexpr std::string_view kMujoco =
    "  A scene runs on MuJoCo instead of ODE with <physics engine=\"mujoco\"/> (solver\n"
    "  exact|cg|iterative; the same robots, devices, pushes and floors). stride run, sweep\n"
    "  and experiment take it over any scene with --physics engine=mujoco[,solver=exact].\n"
    "  Built when Debian's libmujoco-dev is installed (CMake STRIDE_MUJOCO). What carries\n"
    "  over and what is an error: docs/scenes.md.\n"
    "  example:  stride run scenes/walking/open_loop_medium.xml --physics engine=mujoco\n"
    "            (scene) <physics engine=\"mujoco\" solver=\"exact\" step=\"0.5ms\"/>\n"
    "            stride experiment posture --seeds 2 --physics engine=mujoco,solver=exact\n";

constexpr std::string_view kRealtime =
    "  realtime on paces runs to the wall clock, so a walk can be watched, plotted and\n"
    "  changed as it happens; realtime off runs as fast as the machine can (a 17 s walk in\n"
    "  a few seconds) and the prompt reads 'stride (fast)>'. The REPL at a terminal starts\n"
    "  with realtime on; scripts, -c, pipes and stride run --seconds run as fast as\n"
    "  possible unless they say realtime on. A simulation served with stride run --debug is\n"
    "  paced to the wall clock, one on LoLA with --realtime (12 ms frames).\n"
    "  example:  realtime on; run; watch robot.torso.pitch every 50\n";

constexpr std::string_view kRemote =
    "  Any robot runtime serves the console over TCP with --debug: stride-robot on a NAO\n"
    "  v6, or a simulated one. Then stride --connect host:port (or connect host:port in the\n"
    "  console) sends get, set, mr, dr, watch, plot, log and run to the robot; restart\n"
    "  starts its scenario again (to watch a walk from its start); disconnect comes back.\n"
    "  Beyond loopback both ends need a token (--token-file f, mode 600).\n"
    "  docs/physical-robot.md.\n"
    "  example:  stride run scenes/nao_stand_controlled.xml --debug 127.0.0.1:7000 &\n"
    "            stride --connect 127.0.0.1:7000\n"
    "            (NAO) ./stride-robot --config hip_walk.xml --debug 0.0.0.0:7000 --token-file t\n";

constexpr std::string_view kView =
    "  stride view serves a page (3D scene, plots, data tree, module graph, console, log\n"
    "  player) on http://127.0.0.1:8080 for a scene, a robot's debug server or a log; view\n"
    "  in the console serves the session it acts on (view stop closes it).\n"
    "  example:  stride view scenes/nao_stand_controlled.xml\n"
    "            stride view --connect 127.0.0.1:7000\n"
    "            stride view --log walk.log\n";

constexpr std::string_view kLog =
    "  log start <file> records every representation each frame (and the providers and\n"
    "  parameters it ran with) until log stop; log load <file> opens one, log info lists\n"
    "  it, log goto <frame> shows a frame (on the blackboard; robot.torso.* and snapshot\n"
    "  show the logged robot), log export <csv> <key>... writes columns, log\n"
    "  replay runs the modules again. Connected to a robot, log save <file> downloads its\n"
    "  log (checked by SHA-256).\n"
    "  example:  log start /tmp/walk.log; run 5; log stop; log load /tmp/walk.log; log replay\n"
    "            stride view --log /tmp/walk.log\n";

constexpr std::array<HelpTopic, 7> kTopics = {{{"speed", kSpeed},
                                               {"push", kPush},
                                               {"mujoco", kMujoco},
                                               {"realtime", kRealtime},
                                               {"remote", kRemote},
                                               {"view", kView},
                                               {"log", kLog}}};

}  // namespace

std::span<const HelpTopic> help_topics() {
  return kTopics;
}

std::string help_topic_text(std::string_view word) {
  for (const HelpTopic& t : kTopics)
    if (t.name == word) return "topic " + std::string(t.name) + ":\n" + std::string(t.answer);
  return {};
}

std::string help_topic_list() {
  std::string line = "topics (help <topic>):";
  for (const HelpTopic& t : kTopics) line += " " + std::string(t.name);
  return line + "\n";
}

}  // namespace stride::console
