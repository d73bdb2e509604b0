#include <cstring>
#include <new>

#include "robot/core/input_file.hpp"
#include "robot/runtime/log.hpp"
#include "robot/runtime/log_format.hpp"

namespace stride {

using namespace log_format;

namespace {

template <class T>
T load(std::string_view all, std::size_t at) {
  T v;
  std::memcpy(&v, all.data() + at, sizeof v);
  return v;
}

// A version 2 frame starting at `at`, if one is there whole with a matching checksum.
struct FrameAt {
  bool found = false;
  bool incomplete = false;  // marker there but the file ends before the frame does
  std::uint64_t number = 0;
  std::string_view payload;
  std::size_t end = 0;
};

FrameAt frame_at(std::string_view all, std::size_t at) {
  FrameAt f;
  if (all.size() - at < kFrameHeaderBytes) {
    f.incomplete = true;
    return f;
  }
  if (load<std::uint32_t>(all, at) != kFrameMarker) return f;
  const auto size = load<std::uint32_t>(all, at + 12);
  if (all.size() - at - kFrameHeaderBytes < size) {
    f.incomplete = true;
    return f;
  }
  f.payload = all.substr(at + kFrameHeaderBytes, size);
  const std::uint32_t crc = crc32_of(f.payload, crc32_of(all.substr(at + 4, 12)));
  if (crc != load<std::uint32_t>(all, at + 16)) return f;
  f.found = true;
  f.number = load<std::uint64_t>(all, at + 4);
  f.end = at + kFrameHeaderBytes + size;
  return f;
}

}  // namespace

LogReader::LogReader(const std::string& path)
    : LogReader(read_input_file(path, kMaxLogBytes, "log"), path) {}

LogReader LogReader::from_bytes(std::string data, const std::string& name) {
  return LogReader(std::move(data), name);
}

LogReader::LogReader(std::string data, std::string name)
    : name_(std::move(name)), data_(std::make_unique<const std::string>(std::move(data))) {
  const std::string_view all(*data_);
  const std::size_t pos = read_header(all);
  try {
    if (integrity_.version == 1)
      read_frames_v1(all, pos);
    else
      read_frames_v2(all, pos);
  } catch (const std::bad_alloc&) {
    throw Error("log '" + name_ + "': out of memory reading its frames");
  }
}

std::size_t LogReader::read_header(std::string_view all) {
  const std::string_view magic = all.substr(0, kMagicV2.size());
  if (magic == kMagicV1)
    integrity_.version = 1;
  else if (magic != kMagicV2)
    throw InputError("log '" + name_ + "': not a stride log (bad magic)");
  const std::size_t fixed = kMagicV2.size() + (integrity_.version == 1 ? 4 : 8);
  try {
    if (all.size() < fixed) throw Error("header ends early");
    const auto size = load<std::uint32_t>(all, kMagicV2.size());
    if (size > all.size() - fixed) throw Error("header ends early");
    const std::string_view header = all.substr(fixed, size);
    if (integrity_.version == 2 && crc32_of(header) != load<std::uint32_t>(all, 12))
      throw Error("checksum mismatch");
    ByteReader h(header);
    if (integrity_.version == 2)
      for (auto m = h.get<std::uint32_t>(); m > 0; --m) {
        std::string key = h.get_string();
        metadata_[key] = h.get_string();
      }
    for (auto n = h.get<std::uint32_t>(); n > 0; --n) {
      LoggedType t;
      t.name = h.get_string();
      t.desc = read_type_desc(h);
      types_.push_back(std::move(t));
    }
    if (h.remaining() != 0) throw Error("unexpected bytes after the type list");
    return fixed + size;
  } catch (const Error& e) {
    throw InputError("log '" + name_ + "': bad header: " + e.what());
  }
}

bool LogReader::split_parts(std::string_view payload, std::vector<std::string_view>& parts) const {
  parts.clear();
  std::size_t p = 0;
  for (std::size_t i = 0; i < types_.size(); ++i) {
    if (payload.size() - p < 4) return false;
    const auto size = load<std::uint32_t>(payload, p);
    if (payload.size() - p - 4 < size) return false;
    parts.push_back(payload.substr(p + 4, size));
    p += 4 + size;
  }
  return p == payload.size();
}

// STRDLOG1: size-prefixed frames without checksums; the first that does not fit ends the log.
void LogReader::read_frames_v1(std::string_view all, std::size_t pos) {
  Frame f;
  while (all.size() - pos >= 4) {
    const auto payload = load<std::uint32_t>(all, pos);
    if (all.size() - pos - 4 < payload || !split_parts(all.substr(pos + 4, payload), f.parts))
      break;
    f.ok = true;
    frames_.push_back(f);
    pos += 4 + payload;
  }
  integrity_.complete = frames_.size();
  integrity_.truncated = pos != all.size() ? 1 : 0;
}

// The next good frame after a bad one at `pos`: marker, a plausible number and a matching
// checksum. Each lost frame took at least a frame header, which bounds how many a gap can hold.
static FrameAt next_good_frame(std::string_view all, std::size_t pos, std::uint64_t expected) {
  for (std::size_t next = pos + 1; next + kFrameHeaderBytes <= all.size(); ++next) {
    if (load<std::uint32_t>(all, next) != kFrameMarker) continue;
    const auto number = load<std::uint64_t>(all, next + 4);
    if (number <= expected || number > expected + (next - pos) / kFrameHeaderBytes) continue;
    FrameAt later = frame_at(all, next);
    if (later.found) return later;
  }
  return {};
}

void LogReader::read_frames_v2(std::string_view all, std::size_t pos) {
  Frame good;
  while (pos < all.size()) {
    const std::uint64_t expected = frames_.size();
    const FrameAt f = frame_at(all, pos);
    if (f.found && f.number == expected && split_parts(f.payload, good.parts)) {
      good.ok = true;
      frames_.push_back(good);
      pos = f.end;
      continue;
    }
    const FrameAt later = next_good_frame(all, pos, expected);
    if (!later.found && f.incomplete) {  // the file ends inside this frame: a write cut short
      integrity_.truncated = 1;
      break;
    }
    const std::uint64_t lost = later.found ? later.number - expected : 1;
    for (std::uint64_t k = 0; k < lost; ++k) {
      integrity_.damaged_frames.push_back(frames_.size());
      frames_.push_back(Frame{});
    }
    if (!later.found) break;
    pos = static_cast<std::size_t>(later.payload.data() - all.data()) - kFrameHeaderBytes;
  }
  integrity_.damaged = integrity_.damaged_frames.size();
  integrity_.complete = frames_.size() - integrity_.damaged;
}

std::size_t LogReader::readable_prefix() const {
  return integrity_.damaged_frames.empty() ? frames_.size() : integrity_.damaged_frames.front();
}

std::string LogReader::summary() const {
  std::string s = std::to_string(frames_.size()) +
                  " frames: " + std::to_string(integrity_.complete) + " complete, " +
                  std::to_string(integrity_.damaged) + " damaged";
  if (!integrity_.damaged_frames.empty()) {
    s += " (";
    const std::size_t shown = std::min<std::size_t>(integrity_.damaged_frames.size(), 10);
    for (std::size_t i = 0; i < shown; ++i)
      s += (i ? ", " : "") + std::to_string(integrity_.damaged_frames[i]);
    if (shown < integrity_.damaged_frames.size()) s += ", ...";
    s += ")";
  }
  s += ", " + std::to_string(integrity_.truncated) + " truncated";
  if (integrity_.version == 1) s += " (old format STRDLOG1: frames carry no checksums)";
  return s;
}

int LogReader::index_of(std::string_view name) const {
  for (std::size_t i = 0; i < types_.size(); ++i)
    if (types_[i].name == name) return static_cast<int>(i);
  return -1;
}

std::string_view LogReader::bytes(std::size_t frame, int index) const {
  if (frame >= frames_.size())
    throw Error("log: no frame " + std::to_string(frame) + " (the log has " +
                std::to_string(frames_.size()) + " frames)");
  if (!frames_[frame].ok)
    throw Error("log: frame " + std::to_string(frame) + " is damaged (checksum mismatch)");
  if (index < 0 || index >= static_cast<int>(types_.size()))
    throw Error("log: no representation index " + std::to_string(index));
  return frames_[frame].parts[index];
}

std::string_view LogReader::bytes(std::size_t frame, std::string_view name) const {
  const int i = index_of(name);
  if (i < 0) throw Error("log: representation '" + std::string(name) + "' is not in this log");
  return bytes(frame, i);
}

Value LogReader::value(std::size_t frame, std::string_view name) const {
  ByteReader r(bytes(frame, name));
  return read_value(*types_[index_of(name)].desc, r);
}

std::string LogReader::text(std::size_t frame, std::string_view name) const {
  return print_value(*types_[index_of(name)].desc, value(frame, name));
}

void LogReader::check_type(int index, std::string_view name, const TypeDesc& expected) const {
  if (index < 0) throw Error("log: representation '" + std::string(name) + "' is not in this log");
  if (!same_type(*types_[index].desc, expected))
    throw Error("log: representation '" + std::string(name) +
                "' was logged with a different type description (another revision?)");
}

}  // namespace stride
