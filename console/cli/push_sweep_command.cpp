// `stride push-sweep --scene S --strategy ankle|hip|combined|lqr --impulses a:b:step
//  --directions d1,d2 [--duration s] [--settle s] [--observe s] [--estimate-delay s] [--seed N]
//  [--set "Module.field=value ..."] [--csv f] [--json]`:
// pushes the standing robot's torso once per (impulse, direction) in a freshly loaded scene,
// predicts the outcome from the post-push CoM state with balance::classify (thesis Ch. 7) and
// compares it with what the simulation does in the next seconds.
// The Ch. 7 models are sagittal: the CoM state along x is classified, so directions other than
// 0 (forward) and 180 (backward) add lateral motion the prediction does not see.
#include <iomanip>
#include <ostream>
#include <sstream>

#include "console/cli/arguments.hpp"
#include "console/cli/exit_codes.hpp"
#include "console/cli/subcommand.hpp"
#include "console/experiments/push_sweep_study.hpp"
#include "console/output/output_paths.hpp"
#include "robot/core/error.hpp"
#include "robot/core/json_writer.hpp"
#include "robot/core/number_text.hpp"
#include "robot/core/output_file.hpp"
#include "robot/core/quote.hpp"

namespace stride::cli {

namespace {

using experiments::kMaxPushes;
using experiments::PushOutcome;
using experiments::PushSweepOptions;

std::vector<ParameterOverride> parse_settings(const std::string& text) {
  std::vector<ParameterOverride> out;
  std::istringstream ss(text);
  for (std::string item; ss >> item;) {
    try {
      out.push_back(parse_parameter_override(item, "stride push-sweep: --set"));
    } catch (const Error& e) {
      throw UsageError(e.what());
    }
  }
  return out;
}

double parse_value(const std::string& flag, const std::string& s) {
  try {
    return parse_number(s, "stride push-sweep: " + flag);
  } catch (const Error& e) {
    throw UsageError(e.what());
  }
}

// "a:b:step" (inclusive) or "v1,v2,...".
std::vector<double> parse_list(const std::string& flag, const std::string& text) {
  std::vector<std::string> parts;
  const char sep = text.find(':') != std::string::npos ? ':' : ',';
  std::stringstream ss(text);
  for (std::string p; std::getline(ss, p, sep);) parts.push_back(p);
  std::vector<double> v;
  if (sep == ',') {
    for (const auto& p : parts) v.push_back(parse_value(flag, p));
  } else {
    if (parts.size() != 3)
      throw UsageError("stride push-sweep: " + flag + ": expected first:last:step, got " +
                       quote(text));
    const double a = parse_value(flag, parts[0]), b = parse_value(flag, parts[1]),
                 s = parse_value(flag, parts[2]);
    if (!(s > 0) || b < a)
      throw UsageError("stride push-sweep: " + flag + ": expected first <= last and step > 0");
    if ((b - a) / s >= kMaxPushes)
      throw UsageError("stride push-sweep: " + flag + ": " + quote(text) + " has more than " +
                       std::to_string(kMaxPushes) + " values; expected a coarser step");
    for (int i = 0; a + i * s <= b + 1e-9 * s; ++i) v.push_back(a + i * s);
  }
  if (v.empty()) throw UsageError("stride push-sweep: " + flag + ": expected at least one value");
  return v;
}

std::string observed(const PushOutcome& r) {
  return r.recovered() ? "recovered" : r.fell ? "fell" : "stepped";
}

void print_table(std::ostream& out, const PushSweepOptions& o, const std::vector<PushOutcome>& rs) {
  out << "push sweep: strategy " << o.strategy << ", push " << o.duration << " s on the torso\n";
  out << std::setw(8) << "impulse" << std::setw(5) << "dir" << std::setw(9) << "x_est"
      << std::setw(9) << "v_est" << std::setw(9) << "x_true" << std::setw(9) << "v_true"
      << std::setw(10) << "predicted" << std::setw(10) << "pred_true" << std::setw(10) << "expected"
      << std::setw(11) << "observed" << std::setw(7) << "agree"
      << "\n";
  int agree = 0, agree_truth = 0;
  for (const auto& r : rs) {
    agree += r.agree();
    agree_truth += r.truth_expects_recovery == r.recovered();
    out << std::fixed << std::setprecision(2) << std::setw(8) << r.impulse << std::setw(5)
        << std::setprecision(0) << r.direction << std::setprecision(4) << std::setw(9) << r.x_est
        << std::setw(9) << r.v_est << std::setw(9) << r.x_true << std::setw(9) << r.v_true
        << std::setw(10) << balance::to_string(r.predicted) << std::setw(10)
        << balance::to_string(r.predicted_true) << std::setw(10)
        << (r.expected_recovery ? "recover" : "fall") << std::setw(11) << observed(r)
        << std::setw(7) << (r.agree() ? "yes" : "no") << "\n";
  }
  out << std::defaultfloat << "agreement: " << agree << "/" << rs.size() << " = "
      << std::setprecision(3) << 100.0 * agree / rs.size() << " %\n";
  out << "agreement from the simulator's CoM state: " << agree_truth << "/" << rs.size() << " = "
      << 100.0 * agree_truth / rs.size() << " %\n";
}

void write_csv(std::ostream& f, const std::vector<PushOutcome>& rs) {
  f << "impulse,direction,x_est,v_est,x_true,v_true,predicted,predicted_true,expected,observed,"
       "foot_motion,agree\n";
  for (const auto& r : rs)
    f << r.impulse << ',' << r.direction << ',' << r.x_est << ',' << r.v_est << ',' << r.x_true
      << ',' << r.v_true << ',' << balance::to_string(r.predicted) << ','
      << balance::to_string(r.predicted_true) << ',' << (r.expected_recovery ? "recover" : "fall")
      << ',' << observed(r) << ',' << r.foot_motion << ',' << r.agree() << '\n';
}

void write_json(std::ostream& out, const PushSweepOptions& o, const std::vector<PushOutcome>& rs) {
  int agree = 0;
  JsonWriter j(JsonWriter::Style::Spaced);
  j.begin_object().field("strategy", o.strategy).key("pushes").begin_array();
  for (const PushOutcome& r : rs) {
    agree += r.agree();
    j.begin_object().field("impulse", r.impulse).field("direction", r.direction);
    j.field("x_est", r.x_est).field("v_est", r.v_est);
    j.field("x_true", r.x_true).field("v_true", r.v_true);
    j.field("predicted", balance::to_string(r.predicted));
    j.field("expected", r.expected_recovery ? "recover" : "fall").field("observed", observed(r));
    j.field("foot_motion", r.foot_motion).field("agree", r.agree()).end_object();
  }
  j.end_array().field("agreement", static_cast<double>(agree) / rs.size()).end_object();
  out << j.str() << "\n";
}

PushSweepOptions parse(ArgumentReader& a) {
  PushSweepOptions o;
  o.scene = a.text("--scene");
  o.strategy = a.text_or("--strategy", "ankle");
  o.impulses = parse_list("--impulses", a.text("--impulses"));
  o.directions = parse_list("--directions", a.text_or("--directions", "0,180"));
  o.duration = a.number_or("--duration", o.duration);
  o.settle = a.number_or("--settle", o.settle);
  o.observe = a.number_or("--observe", o.observe);
  o.estimate_delay = a.number_or("--estimate-delay", o.estimate_delay);
  o.parameters = parse_settings(a.text_or("--set", ""));
  if (a.has("--seed")) o.seed = a.unsigned_integer("--seed");
  return o;
}

}  // namespace

int push_sweep_main(Args args, std::ostream& out, std::ostream& err) {
  try {
    ArgumentReader a(args, "push-sweep");
    if (asks_for_settings(args)) {
      print_module_parameters(out);
      return kExitOk;
    }
    const PushSweepOptions o = parse(a);
    const std::string csv = a.text_or("--csv", "");
    const bool json = a.flag("--json");
    const int jobs = a.has("--jobs") ? static_cast<int>(a.unsigned_integer("--jobs")) : 1;
    a.finish();
    experiments::check_push_sweep(o);
    if (jobs < 1) throw UsageError("stride push-sweep: --jobs: expected at least 1");
    if (!csv.empty()) console::check_output_file("stride push-sweep: --csv", csv);

    const std::vector<PushOutcome> results = experiments::run_push_sweep(o, jobs);
    if (json)
      write_json(out, o, results);
    else
      print_table(out, o, results);
    if (!csv.empty()) {
      std::ostringstream f;
      write_csv(f, results);
      write_file(csv, f.str());
    }
    return 0;
  } catch (const Error& e) {
    return report_error(e, err);
  } catch (const std::exception& e) {
    err << e.what() << "\n";
    return kExitRunFailure;
  }
}

}  // namespace stride::cli
