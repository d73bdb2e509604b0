// `stride dyn params --model planar|3d [--json]`: the swing-leg parameter vectors of App. C with
// the thesis' data (Sec. 5.4.1), next to the values the thesis prints.
#include <iomanip>
#include <ostream>
#include <string>
#include <vector>

#include "console/cli/arguments.hpp"
#include "console/cli/exit_codes.hpp"
#include "console/cli/subcommand.hpp"
#include "robot/core/error.hpp"
#include "robot/core/json_writer.hpp"
#include "robot/core/number_text.hpp"
#include "robot/core/quote.hpp"
#include "robot/model/dynamics/swing_leg_3d.hpp"
#include "robot/model/dynamics/swing_leg_planar.hpp"

namespace stride::cli {
namespace {

struct Entry {
  const char* name;
  double value;
  const char* printed;  // as the thesis prints it
};

std::vector<Entry> planar_entries() {
  const model::Vector9d a = model::planar_parameters(model::thesis_planar_leg());
  const char* names[9] = {"J1", "J2", "J3", "J4", "J5", "J6", "G1", "G2", "G3"};
  const char* printed[9] = {"0.00725",  "0.0031", "0.00355", "0.000539", "0.000814",
                            "0.000524", "0.650",  "0.3044",  "0.0514"};
  std::vector<Entry> e;
  for (int i = 0; i < 9; ++i) e.push_back({names[i], a[i], printed[i]});
  return e;
}

std::vector<Entry> spatial_entries() {
  const model::Vector17d a = model::leg3d_parameters(model::thesis_3d_leg());
  const char* names[17] = {"J1",  "J2",  "J3",  "J4",  "J5",  "J6",  "J7",  "J8", "J9",
                           "J10", "J11", "J12", "J13", "J14", "J15", "J16", "J17"};
  const char* printed[17] = {"0.0011",   "0.000717", "0.0029", "0.000276", "0.0016",    "0.0017",
                             "0.000668", "0.000688", "0.0031", "0.0028",   "0.0002694", "0.0016",
                             "0.0011",   "0.000644", "0.65",   "0.305",    "0.0656"};
  std::vector<Entry> e;
  for (int i = 0; i < 17; ++i) e.push_back({names[i], a[i], printed[i]});
  return e;
}

void print_json(std::ostream& out, const std::string& model, const std::vector<Entry>& e) {
  JsonWriter j(JsonWriter::Style::Spaced);
  j.begin_object().field("model", model).key("a").begin_array();
  for (const Entry& x : e) j.value(x.value);
  j.end_array().key("thesis").begin_array();
  for (const Entry& x : e) j.value(parse_number(x.printed, "thesis value"));
  out << j.end_array().end_object().str() << "\n";
}

void print(std::ostream& out, const std::string& model, bool json) {
  const std::vector<Entry> e = model == "planar" ? planar_entries() : spatial_entries();
  out << std::setprecision(6);
  if (json) return print_json(out, model, e);
  out << "swing-leg parameters, " << model << " model (thesis App. C, data of Sec. 5.4.1)\n";
  for (size_t i = 0; i < e.size(); ++i)
    out << "a" << std::left << std::setw(3) << i + 1 << std::setw(4) << e[i].name << std::setw(14)
        << e[i].value << "thesis " << e[i].printed << "\n";
}

}  // namespace

int dyn_main(Args args, std::ostream& out, std::ostream& err) {
  try {
    if (args.empty() || args[0] != "params")
      throw UsageError("stride dyn: " +
                       (args.empty() ? "expected params" : quote(args[0]) + ": expected params"));
    ArgumentReader a(args.subspan(1), "dyn");
    const std::string model = a.text_or("--model", "");
    const bool json = a.flag("--json");
    a.finish();
    if (model != "planar" && model != "3d")
      throw UsageError("stride dyn: --model: expected planar or 3d");
    print(out, model, json);
    return 0;
  } catch (const Error& e) {
    return report_error(e, err);
  }
}

}  // namespace stride::cli
