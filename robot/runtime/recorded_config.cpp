#include "robot/runtime/recorded_config.hpp"

#include <set>
#include <sstream>

#include "robot/representations/frame_info.hpp"

namespace stride {

namespace {

constexpr std::string_view kProvider = "provider:";
constexpr std::string_view kParameter = "parameter:";

std::string time_range(const LogReader& log) {
  if (log.frame_count() == 0 || log.index_of("FrameInfo") < 0) return "";
  try {
    std::ostringstream out;
    out << ", t = " << log.read<FrameInfo>(0).time << " .. "
        << log.read<FrameInfo>(log.frame_count() - 1).time << " s";
    return out.str();
  } catch (const Error&) {
    return "";  // FrameInfo of another revision: the frame count says enough
  }
}

}  // namespace

LogMetadata config_metadata(const RuntimeConfig& config) {
  LogMetadata m;
  for (const auto& [representation, module] : config.providers)
    m[std::string(kProvider) + representation] = module;
  for (const auto& [key, value] : config.parameters) m[std::string(kParameter) + key] = value;
  return m;
}

bool has_recorded_config(const LogMetadata& metadata) {
  for (const auto& [key, value] : metadata)
    if (key.starts_with(kProvider)) return true;
  return false;
}

RuntimeConfig recorded_config(const LogMetadata& metadata, RuntimeConfig fallback) {
  if (!has_recorded_config(metadata)) return fallback;
  RuntimeConfig c = std::move(fallback);  // its model and error policy
  c.providers.clear();
  c.parameters.clear();
  for (const auto& [key, value] : metadata) {
    if (key.starts_with(kProvider)) c.providers[key.substr(kProvider.size())] = value;
    if (key.starts_with(kParameter)) c.parameters[key.substr(kParameter.size())] = value;
  }
  return c;
}

std::vector<std::string> log_info_lines(const LogReader& log) {
  std::vector<std::string> lines;
  lines.push_back("frames: " + std::to_string(log.frame_count()) + time_range(log) +
                  (log.truncated() ? " (an incomplete last frame was dropped)" : ""));
  lines.push_back("representations: " + std::to_string(log.types().size()));
  for (const auto& t : log.types()) {
    std::string line = "  " + t.name;
    if (t.desc->name != t.name) line += " (" + type_label(*t.desc) + ")";
    if (log.frame_count() > 0)
      line += ", " + std::to_string(log.bytes(0, t.name).size()) + " bytes a frame";
    lines.push_back(line);
  }
  if (!has_recorded_config(log.metadata())) {
    lines.push_back("providers: not recorded (a log written before logs carried them)");
    return lines;
  }
  const RuntimeConfig c = recorded_config(log.metadata(), {});
  lines.push_back("providers (as recorded; log replay uses them):");
  for (const auto& [representation, module] : c.providers)
    lines.push_back("  " + representation + " <- " + module);
  std::set<std::string> modules;
  for (const auto& [key, value] : c.parameters) modules.insert(key.substr(0, key.find('.')));
  lines.push_back("parameters: " + std::to_string(c.parameters.size()) + " values of " +
                  std::to_string(modules.size()) + " modules (as recorded; log replay uses them)");
  return lines;
}

}  // namespace stride
