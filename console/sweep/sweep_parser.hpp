#pragma once
// Sweep XML -> SweepSpec, with the conventions of scene files: SI units unless a unit is written,
// every attribute declared, every error one line "file:line: <element>: what was expected".
// The format is described in scenes/experiments/README.md ("Sweep files").
#include <functional>
#include <string>
#include <string_view>

#include "console/sweep/sweep_spec.hpp"
#include "robot/core/xml_element.hpp"

namespace stride::sweep {

SweepSpec parse_sweep_file(const std::string& path);
// `text` as if it were the file `virtual_path` (scenes resolve from its directory).
SweepSpec parse_sweep_text(const std::string& text, const std::string& virtual_path);

// What sweep and tuning files share: `text` parsed as XML whose root is <root_name>, handed to
// `parse` (errors "path:line: ..."); a file's text, or an InputError "path:0: cannot open <what>".
void parse_xml_root(const std::string& text, const std::string& path, std::string_view root_name,
                    const std::function<void(const XmlElement&)>& parse);
std::string read_input_file(const std::string& path, const std::string& what);

// <record>: value, summary, derived and trace children (also a tuning file's <record>).
void parse_record(const XmlElement& e, RecordSpec& r);

// "walk_end+50ms", "2s", "end", "walk_start - 0.5 s"; throws std::invalid_argument.
TimePoint parse_time_point(const std::string& text);

}  // namespace stride::sweep
