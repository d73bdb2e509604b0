#include "console/sweep/run_session.hpp"

#include <charconv>
#include <filesystem>

#include "console/sweep/scene_edit.hpp"
#include "console/sweep/sweep.hpp"
#include "robot/core/error.hpp"
#include "simulator/lola/lola_scene.hpp"
#include "simulator/scene/start_perturbation.hpp"

namespace stride::sweep {

std::string scene_path_of(const SweepSpec& spec, const RunPlan& run) {
  std::string scene;
  for (const Setting& s : run.settings)
    if (s.target == "scene") scene = s.value;
  if (scene.empty())
    throw Error("run " + std::to_string(run.id) + ": no scene (a \"scene\" setting)");
  std::filesystem::path p(scene);
  if (p.is_relative() && !spec.scene_dir.empty()) p = std::filesystem::path(spec.scene_dir) / p;
  return p.lexically_normal().string();
}

bool is_provider_setting(const Setting& s) {
  return s.target.rfind("provider:", 0) == 0;
}

bool is_parameter_setting(const Setting& s) {
  return s.target.find('.') != std::string::npos && s.target.find(':') == std::string::npos;
}

void check_setting_target(const std::string& t) {
  if (t == "scene" || t == "seed") return;
  if (t.rfind("scene:", 0) == 0) return check_scene_target(t);
  if (t.rfind("provider:", 0) == 0 && t.size() > 9) return;
  const std::size_t dot = t.find('.');
  if (dot != std::string::npos && dot > 0 && dot + 1 < t.size() &&
      t.find_first_of(":@/ ") == std::string::npos)
    return;
  throw Error("target '" + t +
              "': expected scene, seed, provider:<Representation>, Module.field or "
              "scene:<element>@<attribute>");
}

sim::SceneDescription run_scene(const SweepSpec& spec, const RunPlan& run, RobotLink link) {
  const std::string scene = scene_path_of(spec, run);
  std::vector<Setting> edits;
  std::optional<std::uint64_t> seed;
  for (const Setting& s : run.settings) {
    if (s.target.rfind("scene:", 0) == 0) edits.push_back(s);
    if (s.target != "seed") continue;
    std::uint64_t v = 0;
    const auto r = std::from_chars(s.value.data(), s.value.data() + s.value.size(), v);
    if (r.ec != std::errc() || r.ptr != s.value.data() + s.value.size())
      throw Error("seed '" + s.value + "': expected a whole number >= 0");
    seed = v;
  }
  sim::SceneDescription d = load_edited_scene(scene, edits);
  if (seed) d.physics.seed = *seed;
  if (spec.start_heading_spread > 0 || spec.start_position_spread > 0) {
    const sim::EnsembleSpec start{1, d.physics.seed, spec.start_heading_spread,
                                  spec.start_position_spread};
    sim::apply_start(d, sim::ensemble_member(start, 0));
  }
  if (link == RobotLink::InProcess) return d;
  if (d.robots.empty()) throw Error(scene + ": the scene has no robot");
  if (link == RobotLink::Packets && !d.robots[0].has_controller)
    throw Error(scene + ": --lola-packets: robot 0 has no <controller>");
  sim::prepare_lola_robot(
      d, 0,
      link == RobotLink::Packets ? sim::LolaController::InProcess : sim::LolaController::Client);
  return d;
}

std::unique_ptr<console::SimSession> build_run_session(const SweepSpec& spec, const RunPlan& run,
                                                       RobotLink link) {
  if (link == RobotLink::Lola)
    throw Error("build_run_session: a run through LoLA has no controller in this process");
  const std::string scene = scene_path_of(spec, run);
  auto session = std::make_unique<console::SimSession>(run_scene(spec, run, link));
  if (link == RobotLink::Packets) session->route_through_lola_packets(0);
  Runtime* rt = session->simulation().robot_count() > 0 ? session->runtime(0) : nullptr;
  // Providers first, then parameters in order: a parameter may belong to a swapped-in module.
  for (int pass = 0; pass < 2; ++pass)
    for (const Setting& s : run.settings) {
      if (!(pass == 0 ? is_provider_setting(s) : is_parameter_setting(s))) continue;
      if (!rt) throw Error(scene + ": " + s.target + ": robot 0 has no <controller>");
      try {
        if (pass == 0) {
          rt->swap_provider(s.target.substr(9), s.value);
        } else {
          const std::size_t dot = s.target.find('.');
          rt->set_parameters(s.target.substr(0, dot), s.target.substr(dot + 1) + "=" + s.value);
        }
      } catch (const Error& e) {
        throw Error(scene + ": " + s.target + "=" + s.value + ": " + e.what());
      }
    }
  return session;
}

ControllerConfig run_controller(ControllerConfig scene_controller, const RunPlan& run) {
  for (const Setting& s : run.settings) {
    if (is_provider_setting(s)) scene_controller.providers[s.target.substr(9)] = s.value;
    if (is_parameter_setting(s)) scene_controller.parameters[s.target] = s.value;
  }
  return scene_controller;
}

}  // namespace stride::sweep
