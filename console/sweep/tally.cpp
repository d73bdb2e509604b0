#include "console/sweep/tally.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <limits>
#include <map>
#include <ostream>

#include "console/sweep/csv_line.hpp"
#include "console/sweep/run_plan.hpp"
#include "console/sweep/sweep_compiled.hpp"
#include "robot/core/error.hpp"

namespace stride::sweep {

using K = TallyColumn::Kind;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Tallies::Compiled {
  const TallySpec* spec = nullptr;
  std::vector<int> by;  // CSV columns
  std::optional<Expression> where;
  struct Column {
    std::optional<Expression> of, where;  // aggregates: over the CSV row; Expr: over the tally row
  };
  std::vector<Column> columns;
};

namespace {

Error at(const Sweep& s, int line, const std::string& what) {
  if (s.spec().file.empty()) return Error("sweep '" + s.spec().name + "': " + what);
  return error_at(s.spec().file, line, what);
}

std::string printed(const Cell& c, int decimals) {
  if (const std::string* s = std::get_if<std::string>(&c)) return *s;
  const double v = std::get<double>(c);
  if (!std::isfinite(v)) return "-";
  if (decimals < 0) return number_text(v);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

// "{lost}/{walks}": each placeholder replaced by that column's printed text.
std::string fill(const std::string& format, const std::vector<std::string>& names,
                 const std::vector<std::string>& texts) {
  std::string out;
  for (std::size_t i = 0; i < format.size();) {
    const std::size_t open = format.find('{', i), close = format.find('}', open);
    if (open == std::string::npos || close == std::string::npos) {
      out += format.substr(i);
      break;
    }
    out += format.substr(i, open - i);
    const std::string name = format.substr(open + 1, close - open - 1);
    const auto it = std::find(names.begin(), names.end(), name);
    const auto k = static_cast<std::size_t>(it - names.begin());
    out += k < texts.size() ? texts[k] : "{" + name + "}";  // only columns left of this one
    i = close + 1;
  }
  return out;
}

struct Aggregate {
  Cell value = kNaN;
  double sd = kNaN;
};

Aggregate aggregate(const TallyColumn& spec, const Tallies::Compiled::Column& c,
                    const std::vector<const std::vector<Cell>*>& rows) {
  std::vector<Cell> picked;
  for (const auto* r : rows)
    if (!c.where || c.where->truth(*r)) picked.push_back(c.of ? c.of->evaluate(*r) : Cell(1.0));
  Aggregate a;
  if (spec.kind == K::Count) return {static_cast<double>(picked.size()), kNaN};
  if (picked.empty()) return a;
  if (spec.kind == K::First) return {picked.front(), kNaN};
  if (spec.kind == K::Last) return {picked.back(), kNaN};
  std::vector<double> v;
  for (const Cell& x : picked) {
    const double* d = std::get_if<double>(&x);
    if (!d) throw Error("tally column '" + spec.name + "': '" + spec.of + "' gave a text");
    v.push_back(*d);
  }
  double sum = 0;
  for (double x : v) sum += x;
  if (spec.kind == K::Sum) return {sum, kNaN};
  if (spec.kind == K::Min || spec.kind == K::Max) {
    double m = v[0];
    for (double x : v) m = spec.kind == K::Min ? std::min(m, x) : std::max(m, x);
    return {m, kNaN};
  }
  const double mean = sum / static_cast<double>(v.size());
  double sq = 0;
  for (double x : v) sq += (x - mean) * (x - mean);
  return {mean, std::sqrt(sq / static_cast<double>(v.size()))};
}

}  // namespace

Tallies::Tallies(const Sweep& sweep) : sweep_(sweep) {
  const std::vector<std::string> header = sweep.csv_header();
  const auto column = [&](std::string_view n) -> int {
    const auto it = std::find(header.begin(), header.end(), n);
    if (it == header.end()) {
      std::string known;
      for (const auto& h : header) known += (known.empty() ? "" : ", ") + h;
      throw Error("unknown column '" + std::string(n) + "' (columns: " + known + ")");
    }
    return static_cast<int>(it - header.begin());
  };
  for (const TallySpec& t : sweep.spec().tallies) {
    auto c = std::make_unique<Compiled>();
    c->spec = &t;
    try {
      for (const std::string& b : t.by) c->by.push_back(column(b));
      if (!t.where.empty()) c->where.emplace(t.where, column);
    } catch (const Error& e) {
      throw at(sweep, t.line, e.what());
    }
    std::vector<std::string> names = t.by;  // what expressions over the tally row may name
    for (const TallyColumn& col : t.columns) {
      Compiled::Column out;
      try {
        if (col.kind == K::Expr) {
          out.of.emplace(col.of, [&](std::string_view n) -> int {
            const auto it = std::find(names.begin(), names.end(), n);
            if (it == names.end()) throw Error("unknown tally column '" + std::string(n) + "'");
            return static_cast<int>(it - names.begin());
          });
        } else if (col.kind != K::Text) {
          if (!col.of.empty()) out.of.emplace(col.of, column);
          if (!col.where.empty()) out.where.emplace(col.where, column);
        }
      } catch (const Error& e) {
        throw at(sweep, col.line, e.what());
      }
      if (std::find(names.begin(), names.end(), col.name) != names.end())
        throw at(sweep, col.line, "tally column '" + col.name + "' is named twice");
      names.push_back(col.name);
      c->columns.push_back(std::move(out));
    }
    tallies_.push_back(std::move(c));
  }
  for (const PlotSpec& p : sweep.spec().plots) {
    const auto t = std::find_if(sweep.spec().tallies.begin(), sweep.spec().tallies.end(),
                                [&](const TallySpec& x) { return x.name == p.tally; });
    if (t == sweep.spec().tallies.end())
      throw at(sweep, p.line, "<plot>: no tally named '" + p.tally + "'");
    std::vector<std::string> names = t->by;
    for (const TallyColumn& col : t->columns) names.push_back(col.name);
    std::vector<std::string> wanted = p.y;
    wanted.push_back(p.x);
    if (!p.series.empty()) wanted.push_back(p.series);
    for (const std::string& w : wanted)
      if (std::find(names.begin(), names.end(), w) == names.end())
        throw at(sweep, p.line, "<plot>: tally '" + p.tally + "' has no column '" + w + "'");
    if (p.where.empty()) continue;
    try {
      const Expression where(p.where, [&](std::string_view n) -> int {
        const auto it = std::find(names.begin(), names.end(), n);
        if (it == names.end()) throw Error("unknown tally column '" + std::string(n) + "'");
        return static_cast<int>(it - names.begin());
      });
    } catch (const Error& e) {
      throw at(sweep, p.line, std::string("<plot> where: ") + e.what());
    }
  }
}

Tallies::~Tallies() = default;

namespace {

// The CSV rows as values: plan columns as the plan reads them, the others by their column's kind.
std::vector<std::vector<Cell>> rows_as_cells(const Sweep& sweep,
                                             const std::vector<std::vector<std::string>>& rows) {
  const std::vector<std::string> header = sweep.csv_header();
  const auto& plan_columns = sweep.plan().columns;
  std::vector<std::vector<Cell>> cells;
  for (const auto& r : rows) {
    std::vector<Cell> v;
    for (std::size_t i = 0; i < r.size() && i < header.size(); ++i) {
      const bool plan = i >= 1 && i <= plan_columns.size();
      v.push_back(plan ? plan_cells(RunPlan{0, {}, {r[i]}})[0]
                       : cell_value(r[i], sweep.column_is_text(header[i])));
    }
    cells.push_back(std::move(v));
  }
  return cells;
}

}  // namespace

std::vector<TallyTable> Tallies::compute(const std::vector<std::vector<std::string>>& rows) const {
  const auto& plan_columns = sweep_.plan().columns;
  const std::vector<std::vector<Cell>> cells = rows_as_cells(sweep_, rows);
  const std::size_t status = plan_columns.size() + 1;
  std::vector<TallyTable> out;
  for (const auto& c : tallies_) {
    const TallySpec& spec = *c->spec;
    TallyTable t{spec.name,
                 spec.title,
                 spec.by.size(),
                 spec.by,
                 std::vector<bool>(spec.by.size(), false),
                 {},
                 {},
                 {}};
    std::vector<std::vector<std::string>> keys;  // groups in order of first appearance
    std::map<std::vector<std::string>, std::pair<std::vector<const std::vector<Cell>*>, int>>
        groups;
    for (std::size_t i = 0; i < cells.size(); ++i) {
      std::vector<std::string> key;
      for (int b : c->by) key.push_back(rows[i][static_cast<std::size_t>(b)]);
      auto [it, fresh] = groups.try_emplace(key);
      if (fresh) keys.push_back(key);
      if (rows[i][status] != "ok")
        ++it->second.second;
      else if (!c->where || c->where->truth(cells[i]))
        it->second.first.push_back(&cells[i]);
    }
    bool any_failed = false;
    for (const auto& key : keys) any_failed = any_failed || groups[key].second > 0;
    for (const TallyColumn& col : spec.columns) {
      t.columns.push_back(col.name);
      t.hidden.push_back(col.hidden);
    }
    if (any_failed) t.columns.push_back("failed"), t.hidden.push_back(false);
    for (const auto& key : keys) {
      const auto& [members, failed] = groups[key];
      std::vector<Cell> row;
      for (const std::string& k : key) row.push_back(plan_cells(RunPlan{0, {}, {k}})[0]);
      std::vector<double> sd(key.size(), kNaN);
      std::vector<std::string> text(key.begin(), key.end());
      for (std::size_t k = 0; k < spec.columns.size(); ++k) {
        const TallyColumn& col = spec.columns[k];
        Aggregate a;
        if (col.kind == K::Expr)
          a.value = c->columns[k].of->evaluate(row);
        else if (col.kind == K::Text)
          a.value = fill(col.of, t.columns, text);
        else
          a = aggregate(col, c->columns[k], members);
        row.push_back(a.value);
        sd.push_back(col.with_sd ? a.sd : kNaN);
        // A mean over no walk (all fell) prints "-", not "-+--".
        const double* v = std::get_if<double>(&a.value);
        const bool spread = col.with_sd && v && !std::isnan(*v);
        text.push_back(printed(a.value, col.decimals) +
                       (spread ? "+-" + printed(a.sd, col.decimals) : ""));
      }
      if (any_failed) {
        row.push_back(static_cast<double>(failed));
        sd.push_back(kNaN);
        text.push_back(std::to_string(failed));
      }
      t.rows.push_back(std::move(row));
      t.sds.push_back(std::move(sd));
      t.texts.push_back(std::move(text));
    }
    out.push_back(std::move(t));
  }
  return out;
}

void print_tally(std::ostream& out, const TallyTable& t) {
  if (!t.title.empty()) out << t.title << "\n";
  std::vector<std::size_t> shown;
  for (std::size_t c = 0; c < t.columns.size(); ++c)
    if (!t.hidden[c]) shown.push_back(c);
  std::vector<std::size_t> width;
  for (std::size_t c : shown) {
    width.push_back(t.columns[c].size());
    for (const auto& r : t.texts) width.back() = std::max(width.back(), r[c].size());
  }
  const auto line = [&](const std::vector<std::string>& cells) {
    for (std::size_t k = 0; k < shown.size(); ++k)
      out << (k == 0 ? std::left : std::right) << std::setw(static_cast<int>(width[k]))
          << cells[shown[k]] << (k + 1 < shown.size() ? "  " : "");
    out << std::right << "\n";
  };
  line(t.columns);
  for (const auto& r : t.texts) line(r);
}

std::string tally_csv(const TallyTable& t) {
  std::string csv;
  const auto has_sd = [&](std::size_t c) {
    return std::any_of(t.sds.begin(), t.sds.end(),
                       [&](const std::vector<double>& s) { return !std::isnan(s[c]); });
  };
  const auto cell = [](const Cell& v) {
    const double* d = std::get_if<double>(&v);
    return csv_field(d ? number_text(*d) : std::get<std::string>(v));
  };
  for (std::size_t c = 0; c < t.columns.size(); ++c)
    csv += (c ? "," : "") + csv_field(t.columns[c]) +
           (has_sd(c) ? "," + csv_field(t.columns[c] + "_sd") : "");
  csv += "\n";
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    for (std::size_t c = 0; c < t.columns.size(); ++c) {
      csv += (c ? "," : "") + cell(t.rows[r][c]);
      if (has_sd(c)) csv += "," + number_text(t.sds[r][c]);
    }
    csv += "\n";
  }
  return csv;
}

}  // namespace stride::sweep
