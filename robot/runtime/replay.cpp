#include "robot/runtime/replay.hpp"
#include "robot/runtime/world_pose.hpp"

namespace stride {

ReplayLink::ReplayLink(const LogReader& log, std::size_t first_frame)
    : log_(log), next_(first_frame) {
  if (log.frame_count() > 0) period_ = log.read<FrameInfo>(0).period;
  log.read<hal::SensorFrame>(0);  // fails early, naming the problem, if sensors were not logged
}

bool ReplayLink::read(hal::SensorFrame& out) {
  if (next_ >= log_.readable_prefix()) return false;  // never past a damaged frame
  out = log_.read<hal::SensorFrame>(next_++);
  return true;
}

ReplayResult replay_and_compare(const LogReader& log, const ModuleRegistry& registry,
                                const RuntimeConfig& config) {
  ReplayLink link(log);
  Runtime runtime(registry, config, link);
  ReplayResult result;
  result.stopped_before_damaged = log.readable_prefix() < log.frame_count();
  std::vector<std::pair<int, const Slot*>> pairs;
  for (std::size_t i = 0; i < log.types().size(); ++i) {
    const auto& name = log.types()[i].name;
    // Times vary, and the simulated pose is the world's: a replay has no world.
    if (name == "ModuleTimes" || name == SimulatedTorsoPose::kTypeName) continue;
    pairs.emplace_back(static_cast<int>(i), &runtime.representation_slot(name));
    result.compared.push_back(name);
  }
  std::string bytes;
  while (runtime.step()) {
    const std::size_t frame = result.frames++;
    for (const auto& [index, slot] : pairs) {
      bytes.clear();
      ByteWriter w(bytes);
      slot->encode(w);
      if (bytes != log.bytes(frame, index))
        result.mismatches.push_back({frame, log.types()[index].name});
    }
  }
  return result;
}

namespace {

std::string csv_quote(const std::string& cell) {
  if (cell.find_first_of(",\"\n") == std::string::npos) return cell;
  std::string out = "\"";
  for (char c : cell) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

struct Column {
  std::string representation;
  std::string path;
};

}  // namespace

void export_csv(const LogReader& log, const std::vector<std::string>& keys, std::ostream& out) {
  std::vector<Column> columns;
  std::vector<std::string> header{"frame"};
  for (const auto& key : keys) {
    const auto cut = std::min(key.find('.'), key.find('['));
    Column c{key.substr(0, cut), cut == std::string::npos ? "" : key.substr(cut)};
    if (!c.path.empty() && c.path[0] == '.') c.path.erase(0, 1);
    const int i = log.index_of(c.representation);
    if (i < 0) throw Error("csv: representation '" + c.representation + "' is not in this log");
    const auto& desc = *log.types()[i].desc;
    const auto shape = default_value(desc);  // navigation needs a value; lists are empty here
    csv_columns(*value_at(desc, shape, c.path, c.representation).first, key, header);
    columns.push_back(std::move(c));
  }
  auto write_row = [&](const std::vector<std::string>& cells) {
    for (std::size_t i = 0; i < cells.size(); ++i) out << (i ? "," : "") << csv_quote(cells[i]);
    out << "\n";
  };
  write_row(header);
  std::vector<std::string> cells;
  for (std::size_t f = 0; f < log.frame_count(); ++f) {
    if (!log.readable(f)) continue;  // a damaged frame has no row; the frame column shows the gap
    cells.assign(1, std::to_string(f));
    for (const auto& c : columns) {
      const auto v = log.value(f, c.representation);
      const auto& desc = *log.types()[log.index_of(c.representation)].desc;
      const auto [sub_desc, sub_value] = value_at(desc, v, c.path, c.representation);
      csv_cells(*sub_desc, *sub_value, cells);
    }
    write_row(cells);
  }
}

}  // namespace stride
