#include "console/sweep/factor_parser.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "console/sweep/run_plan.hpp"
#include "console/sweep/value_template.hpp"
#include "robot/core/error.hpp"

namespace stride::sweep {
namespace {

constexpr std::size_t kMaxLevels = 100000;

template <class F>
void children(const XmlElement& e, F&& f) {
  for (const auto* c = e.raw()->FirstChildElement(); c; c = c->NextSiblingElement())
    f(XmlElement(c, e.file()));
}

// "a:b:step", inclusive; each value printed with 12 significant digits so that 0.1 steps read
// 0.3, not 0.30000000000000004.
std::vector<std::string> range_values(const XmlElement& e) {
  const std::string text = e.text("range");
  std::vector<double> v;
  std::stringstream ss(text);
  for (std::string part; std::getline(ss, part, ':');) {
    std::size_t used = 0;
    double x = 0;
    try {
      x = std::stod(part, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || part.find_first_not_of(" ", used) != std::string::npos || !std::isfinite(x))
      e.fail_attr("range", "expected first:last:step, got '" + text + "'");
    v.push_back(x);
  }
  if (v.size() != 3 || !(v[2] > 0) || v[1] < v[0])
    e.fail_attr("range",
                "expected first:last:step with first <= last and step > 0, got '" + text + "'");
  if ((v[1] - v[0]) / v[2] > kMaxLevels) e.fail_attr("range", "more than 100000 levels");
  std::vector<std::string> out;
  for (int i = 0; v[0] + i * v[2] <= v[1] + 1e-9 * v[2]; ++i) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.12g", v[0] + i * v[2]);
    out.emplace_back(buf);
  }
  return out;
}

std::string expand(const XmlElement& e, const std::string& text, const std::string& name,
                   const std::string& level) {
  try {
    return expand_template(text, name, level);
  } catch (const Error& x) {
    e.fail(x.what());
  }
}

// A level's own <set> and <column> children and the factor's templates, for level text `value`.
void add_templates(const XmlElement& factor, Level& l, const std::string& value) {
  const std::string name = factor.text("name");
  children(factor, [&](const XmlElement& c) {
    if (c.name() == "set") {
      Setting s = parse_set(c);
      l.settings.push_back({s.target, expand(c, s.value, name, value)});
    } else if (c.name() == "column") {
      c.allow_only({"name", "value"});
      l.columns.emplace_back(c.text("name"), expand(c, c.text("value"), name, value));
    }
  });
}

Level parse_level(const XmlElement& e, const XmlElement& factor,
                  const std::vector<std::string>& targets, const std::string& format) {
  Level l;
  const auto* a = e.raw()->FirstAttribute();
  for (; a; a = a->Next()) {
    const std::string n = a->Name();
    if (n != "label" && n != "value") l.columns.emplace_back(n, a->Value());
  }
  const bool has_value = e.has("value");
  if (!has_value && !e.has("label")) e.fail("expected label or value");
  if (!targets.empty() && !has_value) e.fail("expected value (the factor has a target)");
  const std::string value = e.text_or("value", "");
  l.label = e.text_or("label", value);
  for (const std::string& t : targets) l.settings.push_back({t, expand(e, format, "", value)});
  add_templates(factor, l, value);
  children(e, [&](const XmlElement& c) {
    if (c.name() != "set") c.fail("unknown element (expected set)");
    Setting s = parse_set(c);
    l.settings.push_back({s.target, expand(c, s.value, factor.text("name"), value)});
  });
  return l;
}

}  // namespace

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> out;
  const bool commas = text.find(',') != std::string::npos;
  std::string item;
  const auto flush = [&] {
    const auto a = item.find_first_not_of(" \t\n\r"), b = item.find_last_not_of(" \t\n\r");
    if (a != std::string::npos) out.push_back(item.substr(a, b - a + 1));
    item.clear();
  };
  for (char c : text) {
    if (commas ? c == ',' : std::isspace(static_cast<unsigned char>(c)))
      flush();
    else
      item += c;
  }
  flush();
  return out;
}

Setting parse_set(const XmlElement& e) {
  e.allow_only({"target", "value"});
  return {e.text("target"), e.text("value")};
}

Factor parse_factor(const XmlElement& e) {
  e.allow_only({"name", "target", "values", "range", "format"});
  Factor f;
  f.name = e.text("name");
  f.line = e.line();
  const std::vector<std::string> targets = split_list(e.text_or("target", ""));
  const std::string format = e.text_or("format", "{}");
  if (e.has("values") && e.has("range")) e.fail("expected values or range, not both");
  if (e.has("values") || e.has("range")) {
    const auto texts = e.has("values") ? split_list(e.text("values")) : range_values(e);
    if (texts.empty()) e.fail_attr("values", "expected at least one value");
    if (texts.size() > kMaxLevels) e.fail_attr("values", "more than 100000 levels");
    for (const std::string& v : texts) {
      Level l;
      l.label = v;
      for (const std::string& t : targets) l.settings.push_back({t, expand(e, format, f.name, v)});
      add_templates(e, l, v);
      f.levels.push_back(std::move(l));
    }
  }
  children(e, [&](const XmlElement& c) {
    if (c.name() == "level") {
      if (e.has("values") || e.has("range")) c.fail("a factor with values or range has no <level>");
      f.levels.push_back(parse_level(c, e, targets, format));
    } else if (c.name() != "set" && c.name() != "column") {
      c.fail("unknown element (expected level, set or column)");
    }
  });
  if (f.levels.empty()) e.fail("expected values, range or <level> children");
  if (targets.empty() && std::all_of(f.levels.begin(), f.levels.end(),
                                     [](const Level& l) { return l.settings.empty(); }))
    e.fail("the factor sets nothing (expected target or <set> children)");
  return f;
}

Block::Range parse_range(const XmlElement& c) {
  c.allow_only({"name", "target", "min", "max", "format"});
  Block::Range r{c.text("name"),  split_list(c.text("target")), c.number("min"),
                 c.number("max"), c.text_or("format", "{}"),    c.line()};
  if (!(r.max > r.min)) c.fail_attr("max", "expected max > min");
  if (r.targets.empty()) c.fail_attr("target", "expected at least one target");
  return r;
}

Block parse_block(const XmlElement& e) {
  Block b;
  const bool grid = e.name() == "grid";
  if (grid) {
    e.allow_only({});
  } else {
    e.allow_only({"method", "count", "seed"});
    b.kind = e.choice_or("method", {"random", "lhs"}, 1) == 0 ? Block::Kind::Random
                                                              : Block::Kind::LatinHypercube;
    b.count = e.integer_or("count", 0, 1, 1000000);
    if (!e.has("count")) e.fail_attr("count", "expected the number of points");
    b.seed = e.seed_or("seed", 1);
  }
  children(e, [&](const XmlElement& c) {
    if (c.name() == "set") {
      b.settings.push_back(parse_set(c));
    } else if (c.name() == "column") {
      c.allow_only({"name", "value"});
      b.columns.emplace_back(c.text("name"), c.text("value"));
    } else if (grid && c.name() == "factor") {
      b.factors.push_back(parse_factor(c));
    } else if (!grid && c.name() == "range") {
      b.ranges.push_back(parse_range(c));
    } else {
      c.fail(grid ? "unknown element (expected set, column or factor)"
                  : "unknown element (expected set, column or range)");
    }
  });
  if (grid && b.factors.empty()) e.fail("expected at least one <factor>");
  if (!grid && b.ranges.empty()) e.fail("expected at least one <range>");
  return b;
}

std::vector<std::uint64_t> parse_seeds(const XmlElement& e) {
  e.allow_only({"from", "to", "values", "count", "heading_spread", "position_spread"});
  std::vector<std::uint64_t> seeds;
  if (e.has("values")) {
    for (const std::string& v : split_list(e.text("values"))) {
      std::size_t used = 0;
      unsigned long long s = 0;
      try {
        s = std::stoull(v, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != v.size() || v[0] == '-') e.fail_attr("values", "expected whole numbers >= 0");
      seeds.push_back(s);
    }
  } else if (e.has("count")) {
    const int n = e.integer_or("count", 1, 1, 1000000);
    for (int s = 1; s <= n; ++s) seeds.push_back(static_cast<std::uint64_t>(s));
  } else {
    const std::uint64_t from = e.seed_or("from", 1), to = e.seed_or("to", from);
    if (to < from || to - from >= 1000000)
      e.fail_attr("to", "expected from <= to, at most 1000000 seeds");
    for (std::uint64_t s = from; s <= to; ++s) seeds.push_back(s);
  }
  if (seeds.empty()) e.fail("expected at least one seed");
  return seeds;
}

SeedsElement parse_seeds_element(const XmlElement& e) {
  SeedsElement s{parse_seeds(e), e.number_or("heading_spread", 0, Dimension::Angle),
                 e.number_or("position_spread", 0, Dimension::Length)};
  if (!(s.heading_spread >= 0 && s.heading_spread <= 0.5))
    e.fail_attr("heading_spread", "expected 0 to 0.5 rad");
  if (!(s.position_spread >= 0 && s.position_spread <= 0.5))
    e.fail_attr("position_spread", "expected 0 to 0.5 m");
  children(e, [&](const XmlElement& c) {
    if (c.name() != "range") c.fail("unknown element (expected range)");
    s.draws.push_back(parse_range(c));
  });
  return s;
}

}  // namespace stride::sweep
