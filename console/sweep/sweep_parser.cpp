#include "console/sweep/sweep_parser.hpp"

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>

#include <tinyxml2.h>

#include "console/plot/gnuplot_plot.hpp"
#include "console/sweep/factor_parser.hpp"
#include "robot/core/error.hpp"
#include "robot/core/units.hpp"
#include "robot/core/xml_error.hpp"

namespace stride::sweep {
namespace {

namespace fs = std::filesystem;

template <class F>
void children(const XmlElement& e, F&& f) {
  for (const auto* c = e.raw()->FirstChildElement(); c; c = c->NextSiblingElement())
    f(XmlElement(c, e.file()));
}

TimePoint time_attr(const XmlElement& e, const char* attr, const TimePoint& fallback) {
  if (!e.has(attr)) return fallback;
  try {
    return parse_time_point(e.text(attr));
  } catch (const std::invalid_argument& x) {
    e.fail_attr(attr, x.what());
  }
}

SummarySpec::Stat stat_attr(const XmlElement& e) {
  using S = SummarySpec::Stat;
  static constexpr std::pair<std::string_view, S> kStats[] = {
      {"min", S::Min},           {"max", S::Max},       {"mean", S::Mean},
      {"rms", S::Rms},           {"sd", S::Sd},         {"first", S::First},
      {"final", S::Final},       {"change", S::Change}, {"sum", S::Sum},
      {"integral", S::Integral}, {"count", S::Count},   {"first_past", S::FirstPast}};
  const std::string s = e.text("stat");
  for (const auto& [name, stat] : kStats)
    if (s == name) return stat;
  e.fail_attr("stat",
              "expected min, max, mean, rms, sd, first, final, change, sum, integral, count or "
              "first_past, got '" +
                  s + "'");
}

}  // namespace

void parse_record(const XmlElement& e, RecordSpec& r) {
  e.allow_only({});
  children(e, [&](const XmlElement& c) {
    const std::string_view n = c.name();
    if (n == "value") {
      c.allow_only({"name", "key", "at"});
      r.values.push_back({c.text("name"), c.text("key"), time_attr(c, "at", {"end", 0}), c.line()});
    } else if (n == "summary") {
      c.allow_only({"name", "key", "stat", "from", "to", "through", "until", "threshold"});
      if (c.has("to") && c.has("through")) c.fail("expected to or through, not both");
      SummarySpec m;
      m.name = c.text("name");
      m.key = c.text("key");
      m.stat = stat_attr(c);
      m.from = time_attr(c, "from", {"start", 0});
      m.to_inclusive = !c.has("to");
      m.to = time_attr(c, c.has("to") ? "to" : "through", {"end", 0});
      m.until = c.text_or("until", "");
      m.threshold = c.number_or("threshold", 0);
      if (m.stat == SummarySpec::Stat::FirstPast && !c.has("threshold"))
        c.fail_attr("threshold", "first_past needs a threshold");
      m.line = c.line();
      r.summaries.push_back(std::move(m));
    } else if (n == "derived") {
      c.allow_only({"name", "value"});
      r.derived.push_back({c.text("name"), c.text("value"), c.line()});
    } else if (n == "trace") {
      c.allow_only({"where", "from"});
      TraceSpec t{c.text_or("where", ""), {}, time_attr(c, "from", {"start", 0}), c.line()};
      children(c, [&](const XmlElement& k) {
        if (k.name() != "column") k.fail("unknown element (expected column)");
        k.allow_only({"name", "key"});
        t.columns.emplace_back(k.text("name"), k.text("key"));
      });
      if (t.columns.empty()) c.fail("expected <column name key> children");
      r.traces.push_back(std::move(t));
    } else {
      c.fail("unknown element (expected value, summary, derived or trace)");
    }
  });
}

namespace {

TallyColumn parse_tally_column(const XmlElement& c) {
  using K = TallyColumn::Kind;
  static constexpr std::pair<std::string_view, K> kKinds[] = {
      {"count", K::Count}, {"sum", K::Sum},   {"mean", K::Mean}, {"min", K::Min},  {"max", K::Max},
      {"first", K::First}, {"last", K::Last}, {"expr", K::Expr}, {"text", K::Text}};
  TallyColumn t;
  bool known = false;
  for (const auto& [name, kind] : kKinds)
    if (c.name() == name) t.kind = kind, known = true;
  if (!known)
    c.fail("unknown element (expected count, sum, mean, min, max, first, last, expr or text)");
  t.name = c.text("name");
  t.line = c.line();
  if (t.kind == K::Expr || t.kind == K::Text) {
    c.allow_only({"name", "value", "decimals", "hidden"});
    t.of = c.text("value");
  } else {
    if (t.kind == K::Mean)
      c.allow_only({"name", "of", "where", "sd", "decimals", "hidden"});
    else
      c.allow_only({"name", "of", "where", "decimals", "hidden"});
    if (t.kind != K::Count) t.of = c.text("of");
    t.where = c.text_or("where", "");
    t.with_sd = c.boolean_or("sd", false);
  }
  t.decimals = c.integer_or("decimals", -1, 0, 17);
  t.hidden = c.boolean_or("hidden", false);
  return t;
}

TallySpec parse_tally(const XmlElement& e) {
  e.allow_only({"name", "title", "by", "where"});
  TallySpec t{e.text("name"),
              e.text_or("title", ""),
              split_list(e.text_or("by", "")),
              e.text_or("where", ""),
              {},
              e.line()};
  children(e, [&](const XmlElement& c) { t.columns.push_back(parse_tally_column(c)); });
  if (t.columns.empty()) e.fail("expected columns (count, sum, mean, ...)");
  return t;
}

PlotSpec parse_plot(const XmlElement& e) {
  e.allow_only({"tally", "x", "y", "series", "title", "x_label", "y_label", "where"});
  PlotSpec p{e.text("tally"),          e.text("x"),
             e.text_or("series", ""),  e.text_or("title", ""),
             e.text_or("x_label", ""), e.text_or("y_label", ""),
             split_list(e.text("y")),  e.line(),
             e.text_or("where", "")};
  if (p.y.empty()) e.fail_attr("y", "expected at least one column");
  // Every axis names its unit (plots never mix units on one axis: one <plot> per unit).
  if (!plot::labels_unit(p.x_label.empty() ? p.x : p.x_label))
    e.fail_attr("x_label", "expected the x axis' unit in [], e.g. 'K_p [-]'");
  if (!plot::labels_unit(p.y_label))
    e.fail_attr("y_label", "expected the y axis' unit in [], e.g. 'sway [rad]'");
  return p;
}

void parse_root(const XmlElement& root, SweepSpec& s) {
  root.allow_only({"name", "scenes"});
  s.name = root.text_or("name", fs::path(s.file).stem().string());
  const fs::path dir = fs::path(s.file).parent_path();
  s.scene_dir = (dir / root.text_or("scenes", ".")).lexically_normal().string();
  if (s.scene_dir.size() > 1 && s.scene_dir.back() == '/') s.scene_dir.pop_back();  // "dir/."
  Block top;  // factors written directly under <sweep>
  bool seeds = false, run = false;
  children(root, [&](const XmlElement& c) {
    const std::string_view n = c.name();
    if (n == "set") {
      s.settings.push_back(parse_set(c));
    } else if (n == "scene") {
      c.allow_only({"file"});
      s.settings.push_back({"scene", c.text("file")});
    } else if (n == "factor") {
      top.factors.push_back(parse_factor(c));
    } else if (n == "grid" || n == "sample") {
      s.blocks.push_back(parse_block(c));
    } else if (n == "seeds") {
      if (seeds) c.fail("a second <seeds>");
      SeedsElement e = parse_seeds_element(c);
      s.seeds = std::move(e.seeds), seeds = true;
      s.start_heading_spread = e.heading_spread;
      s.start_position_spread = e.position_spread;
      s.seed_draws = std::move(e.draws);
    } else if (n == "run") {
      c.allow_only({"seconds", "until"});
      if (run || c.has("seconds") == c.has("until"))
        c.fail("expected one <run seconds> or <run until>");
      s.until = c.has("seconds") ? TimePoint{"start", c.number("seconds", Dimension::Time)}
                                 : time_attr(c, "until", {});
      if (s.until.mark == "end") c.fail_attr("until", "the run cannot end relative to its end");
      if (s.until.mark == "start" && !(s.until.offset > 0 && s.until.offset <= 36000))
        c.fail("expected a run length in (0, 10 h]");
      run = true;
    } else if (n == "record") {
      parse_record(c, s.record);
    } else if (n == "tally") {
      s.tallies.push_back(parse_tally(c));
    } else if (n == "plot") {
      s.plots.push_back(parse_plot(c));
    } else {
      c.fail(
          "unknown element (expected set, scene, factor, grid, sample, seeds, run, record, "
          "tally or plot)");
    }
  });
  if (!run) root.fail("expected <run seconds=\"...\"/> or <run until=\"...\"/>");
  if (!top.factors.empty()) s.blocks.insert(s.blocks.begin(), std::move(top));
}

}  // namespace

TimePoint parse_time_point(const std::string& text) {
  std::string t;
  for (char c : text)
    if (!std::isspace(static_cast<unsigned char>(c))) t += c;
  static const char* kMarks[] = {"walk_start", "walk_end", "start", "end"};
  for (const char* m : kMarks) {
    const std::string mark = m;
    if (t.rfind(mark, 0) != 0) continue;
    const std::string rest = t.substr(mark.size());
    if (rest.empty()) return {mark, 0};
    if (rest[0] != '+' && rest[0] != '-')
      throw std::invalid_argument("expected <mark>[+|-<time>], got '" + text + "'");
    const double v = parse_quantity(rest.substr(1), Dimension::Time);
    return {mark, rest[0] == '-' ? -v : v};
  }
  if (!t.empty() && std::isalpha(static_cast<unsigned char>(t[0])))
    throw std::invalid_argument("unknown time mark in '" + text +
                                "' (start, end, walk_start, walk_end, or a time)");
  return {"start", parse_quantity(t, Dimension::Time)};
}

void parse_xml_root(const std::string& text, const std::string& path, std::string_view root_name,
                    const std::function<void(const XmlElement&)>& parse) {
  tinyxml2::XMLDocument doc;
  if (doc.Parse(text.c_str(), text.size()) != tinyxml2::XML_SUCCESS)
    throw error_at(path, doc.ErrorLineNum(), xml_error_text(doc));
  const tinyxml2::XMLElement* root = doc.RootElement();
  if (!root || std::string_view(root->Name()) != root_name)
    throw error_at(path, root ? root->GetLineNum() : 1,
                   "expected <" + std::string(root_name) + "> as the root element");
  parse(XmlElement(root, path));
}

std::string read_input_file(const std::string& path, const std::string& what) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ":0: cannot open " + what);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

SweepSpec parse_sweep_text(const std::string& text, const std::string& virtual_path) {
  SweepSpec s;
  s.file = virtual_path;
  parse_xml_root(text, s.file, "sweep", [&](const XmlElement& root) { parse_root(root, s); });
  return s;
}

SweepSpec parse_sweep_file(const std::string& path) {
  const std::string text = read_input_file(path, "sweep file");
  try {
    return parse_sweep_text(text, path);
  } catch (const InputError&) {
    throw;
  } catch (const Error& e) {
    throw InputError(e.what());  // a file given to stride that does not parse (exit code 3)
  }
}

}  // namespace stride::sweep
