#pragma once
// One CSV line (RFC 4180 quoting) each way: how sweep rows are written and read back on --resume.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stride::sweep {

// The text as a field: quoted when it holds a comma, a quote or a line break.
std::string csv_field(std::string_view text);
// The fields, joined, with a final '\n'.
std::string csv_line(const std::vector<std::string>& fields);
// The fields of one line (without its '\n'); nullopt when a quoted field is not closed.
std::optional<std::vector<std::string>> parse_csv_line(std::string_view line);

}  // namespace stride::sweep
