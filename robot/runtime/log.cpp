#include "robot/runtime/log.hpp"

#include <cstring>

#include "robot/core/output_file.hpp"
#include "robot/runtime/log_format.hpp"

namespace stride {

using namespace log_format;

LogWriter::LogWriter(const std::string& path,
                     std::vector<std::pair<std::string, const Slot*>> slots,
                     const LogMetadata& metadata)
    : slots_(std::move(slots)) {
  std::string header;
  ByteWriter w(header);
  w.put(static_cast<std::uint32_t>(metadata.size()));
  for (const auto& [key, value] : metadata) {
    w.put_string(key);
    w.put_string(value);
  }
  w.put(static_cast<std::uint32_t>(slots_.size()));
  for (const auto& [name, slot] : slots_) {
    w.put_string(name);
    write_type_desc(w, slot->desc());
  }
  std::string out(kMagicV2);
  ByteWriter o(out);
  o.put(static_cast<std::uint32_t>(header.size()));
  o.put(crc32_of(header));
  out += header;
  file_ = std::make_unique<OutputFile>(path, OutputFile::Mode::Stream);
  file_->write(out);
  file_->flush();
}

LogWriter::~LogWriter() = default;

void LogWriter::write_frame() {
  if (!file_) throw Error("log: the file is closed");
  buffer_.assign(kFrameHeaderBytes, '\0');  // marker, number, size and checksum, patched below
  ByteWriter w(buffer_);
  for (const auto& [name, slot] : slots_) {
    const auto at = buffer_.size();
    w.put(std::uint32_t{0});
    slot->encode(w);
    const auto size = static_cast<std::uint32_t>(buffer_.size() - at - 4);
    std::memcpy(buffer_.data() + at, &size, 4);
  }
  const std::uint64_t number = frames_;
  const auto payload = static_cast<std::uint32_t>(buffer_.size() - kFrameHeaderBytes);
  std::memcpy(buffer_.data(), &kFrameMarker, 4);
  std::memcpy(buffer_.data() + 4, &number, 8);
  std::memcpy(buffer_.data() + 12, &payload, 4);
  const std::string_view view(buffer_);
  const std::uint32_t crc = crc32_of(view.substr(kFrameHeaderBytes), crc32_of(view.substr(4, 12)));
  std::memcpy(buffer_.data() + 16, &crc, 4);
  try {
    file_->write(buffer_);
    file_->flush();
  } catch (...) {
    file_.reset();  // one error, not one per frame
    throw;
  }
  ++frames_;
}

void LogWriter::close() {
  if (!file_) return;
  auto f = std::move(file_);
  f->commit();
}

}  // namespace stride
