#include "console/tune/tune_parser.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <stdexcept>

#include "console/sweep/factor_parser.hpp"
#include "console/sweep/sweep_parser.hpp"
#include "robot/core/error.hpp"

namespace stride::tune {
namespace {

namespace fs = std::filesystem;

// Column names the generated sweeps use themselves.
const std::set<std::string> kReserved = {"run",  "status", "reason",    "scene",
                                         "seed", "floor",  "candidate", "objective"};

template <class F>
void children(const XmlElement& e, F&& f) {
  for (const auto* c = e.raw()->FirstChildElement(); c; c = c->NextSiblingElement())
    f(XmlElement(c, e.file()));
}

TuneParam parse_param(const XmlElement& e) {
  e.allow_only({"name", "target", "min", "max", "thesis", "format"});
  TuneParam p{
      e.text("name"),     sweep::split_list(e.text("target")), e.number("min"), e.number("max"),
      e.number("thesis"), e.text_or("format", "{}"),           e.line()};
  if (p.name.empty() || kReserved.count(p.name))
    e.fail_attr("name", "'" + p.name +
                            "' is taken (run, status, reason, scene, seed, floor, "
                            "candidate, objective)");
  if (p.targets.empty()) e.fail_attr("target", "expected at least one target");
  if (!(std::isfinite(p.min) && std::isfinite(p.max) && p.max > p.min))
    e.fail_attr("max", "expected finite bounds with max > min");
  if (!std::isfinite(p.thesis)) e.fail_attr("thesis", "expected a finite number");
  if (p.format.find("{}") == std::string::npos)
    e.fail_attr("format", "expected {} where the number goes");
  return p;
}

TuneFloor parse_floor(const XmlElement& e) {
  e.allow_only({"name"});
  TuneFloor f{e.text("name"), {}, e.line()};
  children(e, [&](const XmlElement& c) {
    if (c.name() != "set") c.fail("unknown element (expected set)");
    f.settings.push_back(sweep::parse_set(c));
  });
  return f;
}

WalkSet parse_walks(const XmlElement& e) {
  e.allow_only({"floors"});
  WalkSet w;
  w.floors = sweep::split_list(e.text_or("floors", ""));
  w.line = e.line();
  bool seeds = false;
  children(e, [&](const XmlElement& c) {
    if (c.name() != "seeds" || seeds) c.fail("expected one <seeds> child");
    sweep::SeedsElement s = sweep::parse_seeds_element(c);
    w.seeds = std::move(s.seeds);
    w.heading_spread = s.heading_spread, w.position_spread = s.position_spread;
    seeds = true;
  });
  if (!seeds) e.fail("expected a <seeds> child");
  return w;
}

void parse_search(const XmlElement& e, TuneSpec& s) {
  e.allow_only({"method", "population", "generations", "seed"});
  e.choice_or("method", {"pso_gen"}, 0);  // the one pagmo method with a batch evaluator we use
  if (!e.has("population")) e.fail_attr("population", "expected the candidates per generation");
  if (!e.has("generations")) e.fail_attr("generations", "expected the number of generations");
  s.population = e.integer_or("population", 0, 4, 10000);
  s.generations = e.integer_or("generations", 0, 1, 100000);
  s.seed = e.seed_or("seed", 1);
  if (s.seed > 0xffffffffULL) e.fail_attr("seed", "expected at most 4294967295");
  s.search_line = e.line();
}

// One child of <tune>; `once` tracks elements that may appear only once.
void parse_child(const XmlElement& c, TuneSpec& s, std::set<std::string>& once) {
  const std::string n(c.name());
  static const std::set<std::string> single = {"train",  "heldout",   "run",
                                               "record", "objective", "search"};
  if (single.count(n) && !once.insert(n).second) c.fail("a second <" + n + ">");
  if (n == "set") {
    s.settings.push_back(sweep::parse_set(c));
  } else if (n == "scene") {
    c.allow_only({"file"});
    s.settings.push_back({"scene", c.text("file")});
  } else if (n == "param") {
    s.params.push_back(parse_param(c));
  } else if (n == "floor") {
    s.floors.push_back(parse_floor(c));
  } else if (n == "train" || n == "heldout") {
    (n == "train" ? s.train : s.heldout) = parse_walks(c);
  } else if (n == "run") {
    c.allow_only({"seconds", "until"});
    if (c.has("seconds") == c.has("until")) c.fail("expected seconds or until");
    try {
      s.until = c.has("seconds") ? sweep::TimePoint{"start", c.number("seconds", Dimension::Time)}
                                 : sweep::parse_time_point(c.text("until"));
    } catch (const std::invalid_argument& x) {
      c.fail_attr("until", x.what());
    }
    if (s.until.mark == "end") c.fail("the run cannot end relative to its end");
    if (s.until.mark == "start" && !(s.until.offset > 0 && s.until.offset <= 36000))
      c.fail("expected a run length in (0, 10 h]");
  } else if (n == "record") {
    sweep::parse_record(c, s.record);
  } else if (n == "objective") {
    c.allow_only({"value", "failed"});
    s.objective = c.text("value");
    s.failed_value = c.number("failed");
    if (!std::isfinite(s.failed_value)) c.fail_attr("failed", "expected a finite number");
    s.objective_line = c.line();
  } else if (n == "search") {
    parse_search(c, s);
  } else {
    c.fail(
        "unknown element (expected set, scene, param, floor, train, heldout, run, record, "
        "objective or search)");
  }
}

// Floors named by the walk sets exist; without <floor>s there is one, the scene's own.
void check_floors(const XmlElement& root, TuneSpec& s) {
  std::set<std::string> names;
  for (const TuneFloor& f : s.floors)
    if (f.name.empty() || !names.insert(f.name).second)
      throw error_at(s.file, f.line, "floor: name '" + f.name + "' empty or used twice");
  if (s.floors.empty()) s.floors.push_back({"scene", {}, root.line()});
  for (WalkSet* w : {&s.train, &s.heldout}) {
    if (w->floors.empty()) {
      if (s.floors.size() > 1) throw error_at(s.file, w->line, "expected floors=\"...\"");
      w->floors = {s.floors.front().name};
    }
    for (const std::string& f : w->floors)
      if (std::none_of(s.floors.begin(), s.floors.end(),
                       [&](const TuneFloor& x) { return x.name == f; }))
        throw error_at(s.file, w->line, "unknown floor '" + f + "'");
  }
  for (const std::string& f : s.heldout.floors)
    for (std::uint64_t seed : s.heldout.seeds)
      if (std::count(s.train.floors.begin(), s.train.floors.end(), f) &&
          std::count(s.train.seeds.begin(), s.train.seeds.end(), seed))
        throw error_at(s.file, s.heldout.line,
                       "held-out walk (floor " + f + ", seed " + std::to_string(seed) +
                           ") is also a training walk");
}

void parse_root(const XmlElement& root, TuneSpec& s) {
  root.allow_only({"name", "scenes"});
  s.name = root.text_or("name", fs::path(s.file).stem().string());
  const fs::path dir = fs::path(s.file).parent_path();
  s.scene_dir = (dir / root.text_or("scenes", ".")).lexically_normal().string();
  if (s.scene_dir.size() > 1 && s.scene_dir.back() == '/') s.scene_dir.pop_back();
  std::set<std::string> once;
  children(root, [&](const XmlElement& c) { parse_child(c, s, once); });
  for (const char* needed : {"train", "heldout", "run", "objective", "search"})
    if (!once.count(needed)) root.fail(std::string("expected a <") + needed + "> element");
  if (s.params.empty()) root.fail("expected at least one <param>");
  std::set<std::string> names;
  for (const TuneParam& p : s.params)
    if (!names.insert(p.name).second)
      throw error_at(s.file, p.line, "param '" + p.name + "' twice");
  check_floors(root, s);
}

}  // namespace

TuneSpec parse_tune_text(const std::string& text, const std::string& virtual_path) {
  TuneSpec s;
  s.file = virtual_path;
  sweep::parse_xml_root(text, s.file, "tune", [&](const XmlElement& root) { parse_root(root, s); });
  return s;
}

TuneSpec parse_tune_file(const std::string& path) {
  const std::string text = sweep::read_input_file(path, "tuning file");
  try {
    return parse_tune_text(text, path);
  } catch (const InputError&) {
    throw;
  } catch (const Error& e) {
    throw InputError(e.what());  // a file given to stride that does not parse (exit code 3)
  }
}

}  // namespace stride::tune
