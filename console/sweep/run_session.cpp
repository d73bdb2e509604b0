#include "console/sweep/run_session.hpp"

#include <charconv>
#include <filesystem>

#include "console/sweep/scene_edit.hpp"
#include "console/sweep/sweep.hpp"
#include "robot/core/error.hpp"
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

std::unique_ptr<console::SimSession> build_run_session(const SweepSpec& spec, const RunPlan& run) {
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
  auto session = std::make_unique<console::SimSession>(std::move(d));
  Runtime* rt = session->simulation().robot_count() > 0 ? session->runtime(0) : nullptr;
  // Providers first, then parameters in order: a parameter may belong to a swapped-in module.
  for (int pass = 0; pass < 2; ++pass)
    for (const Setting& s : run.settings) {
      const bool provider = s.target.rfind("provider:", 0) == 0;
      const bool parameter =
          s.target.find('.') != std::string::npos && s.target.find(':') == std::string::npos;
      if (!(pass == 0 ? provider : parameter)) continue;
      if (!rt) throw Error(scene + ": " + s.target + ": robot 0 has no <controller>");
      try {
        if (provider) {
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

}  // namespace stride::sweep
