#include "robot/runtime/log.hpp"

#include <fstream>
#include <sstream>

namespace stride {

namespace {
constexpr std::string_view kMagic = "STRDLOG1";
}

LogWriter::LogWriter(const std::string& path,
                     std::vector<std::pair<std::string, const Slot*>> slots)
    : slots_(std::move(slots)) {
  file_ = std::fopen(path.c_str(), "wb");
  if (!file_) throw Error("log: cannot open '" + path + "' for writing");
  std::string header;
  ByteWriter w(header);
  w.put(static_cast<std::uint32_t>(slots_.size()));
  for (const auto& [name, slot] : slots_) {
    w.put_string(name);
    write_type_desc(w, slot->desc());
  }
  std::string out(kMagic);
  ByteWriter o(out);
  o.put(static_cast<std::uint32_t>(header.size()));
  out += header;
  std::fwrite(out.data(), 1, out.size(), file_);
  std::fflush(file_);
}

LogWriter::~LogWriter() {
  if (file_) std::fclose(file_);
}

void LogWriter::write_frame() {
  buffer_.assign(4, '\0');  // payload size, patched below
  ByteWriter w(buffer_);
  for (const auto& [name, slot] : slots_) {
    const auto at = buffer_.size();
    w.put(std::uint32_t{0});
    slot->encode(w);
    const auto size = static_cast<std::uint32_t>(buffer_.size() - at - 4);
    std::memcpy(buffer_.data() + at, &size, 4);
  }
  const auto payload = static_cast<std::uint32_t>(buffer_.size() - 4);
  std::memcpy(buffer_.data(), &payload, 4);
  std::fwrite(buffer_.data(), 1, buffer_.size(), file_);
  std::fflush(file_);
  ++frames_;
}

LogReader::LogReader(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("log: cannot open '" + path + "'");
  std::ostringstream s;
  s << in.rdbuf();
  data_ = s.str();
  std::string_view all(data_);
  if (all.substr(0, kMagic.size()) != kMagic)
    throw Error("log '" + path + "': not a stride log (bad magic)");
  ByteReader r(all.substr(kMagic.size()));
  std::uint32_t header_size = 0;
  try {
    header_size = r.get<std::uint32_t>();
    if (header_size > r.remaining()) throw Error("header ends early");
    ByteReader h(all.substr(kMagic.size() + 4, header_size));
    const auto n = h.get<std::uint32_t>();
    for (std::uint32_t i = 0; i < n; ++i) {
      LoggedType t;
      t.name = h.get_string();
      t.desc = read_type_desc(h);
      types_.push_back(std::move(t));
    }
  } catch (const Error& e) {
    throw Error("log '" + path + "': bad header: " + e.what());
  }
  std::size_t pos = kMagic.size() + 4 + header_size;
  while (pos < all.size()) {
    if (all.size() - pos < 4) break;
    std::uint32_t payload = 0;
    std::memcpy(&payload, all.data() + pos, 4);
    if (all.size() - pos - 4 < payload) break;
    std::vector<std::string_view> parts;
    std::size_t p = pos + 4;
    const std::size_t end = p + payload;
    bool ok = true;
    for (std::size_t i = 0; i < types_.size() && ok; ++i) {
      std::uint32_t size = 0;
      if (end - p < 4)
        ok = false;
      else {
        std::memcpy(&size, all.data() + p, 4);
        ok = end - p - 4 >= size;
        if (ok) parts.push_back(all.substr(p + 4, size));
        p += 4 + size;
      }
    }
    if (!ok || p != end) break;  // corrupt frame: treat like a truncation
    frames_.push_back(std::move(parts));
    pos = end;
  }
  truncated_ = pos != all.size();
}

int LogReader::index_of(std::string_view name) const {
  for (std::size_t i = 0; i < types_.size(); ++i)
    if (types_[i].name == name) return static_cast<int>(i);
  return -1;
}

std::string_view LogReader::bytes(std::size_t frame, int index) const {
  if (frame >= frames_.size())
    throw Error("log: no frame " + std::to_string(frame) + " (the log has " +
                std::to_string(frames_.size()) + " complete frames)");
  if (index < 0 || index >= static_cast<int>(types_.size()))
    throw Error("log: no representation index " + std::to_string(index));
  return frames_[frame][index];
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
