#pragma once
// Frame logs: an append-only binary file in which every frame carries its own checksum.
//   "STRDLOG2" | u32 header size | u32 crc32(header) |
//   header: u32 m, m x (key, value) metadata | u32 n, n x (name, TypeDesc) |
//   per frame: u32 'STRF' | u64 frame number | u32 payload size | u32 crc32(number, size, payload)
//              | payload: n x (u32 size, encoded representation)
// Strings are u32 length + bytes; all integers little-endian. Each frame is flushed when written,
// so a killed process loses at most the frame being written. A reader keeps every frame whose
// checksum matches: a damaged frame is reported by its number and the frames around it stay
// readable (the frame marker and numbers let it find the next good frame). Logs of the previous
// format, STRDLOG1 (no metadata, no checksums), still load.
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "robot/framework/slot.hpp"

namespace stride {

class OutputFile;

struct LoggedType {
  std::string name;
  TypeDescPtr desc;
};

// Free-form facts about a recording (e.g. the providers it ran with, the robot's name), stored
// in the header.
using LogMetadata = std::map<std::string, std::string>;

class LogWriter {
 public:
  // Writes the header for `slots` (name, object); every frame records the same list. Throws
  // stride::Error naming the path if the file cannot be written.
  LogWriter(const std::string& path, std::vector<std::pair<std::string, const Slot*>> slots,
            const LogMetadata& metadata = {});
  ~LogWriter();
  LogWriter(const LogWriter&) = delete;
  LogWriter& operator=(const LogWriter&) = delete;

  // Appends and flushes one frame; a failed write throws stride::Error naming the path.
  void write_frame();
  // Closes the file, checking the close; throws like write_frame.
  void close();
  std::size_t frames_written() const { return frames_; }

 private:
  std::unique_ptr<OutputFile> file_;
  std::vector<std::pair<std::string, const Slot*>> slots_;
  std::string buffer_;
  std::size_t frames_ = 0;
};

// What a reader found in a log's frames.
struct LogIntegrity {
  int version = 2;                          // 1: STRDLOG1, whose frames carry no checksum
  std::size_t complete = 0;                 // frames read whole (checksum matched in version 2)
  std::size_t damaged = 0;                  // frames lost to a checksum mismatch or bad bytes
  std::size_t truncated = 0;                // 1 when the file ends inside a frame
  std::vector<std::size_t> damaged_frames;  // their numbers, in order
};

class LogReader {
 public:
  // Reads the file (size and kind checked first); throws on a missing file or a bad header.
  explicit LogReader(const std::string& path);
  // The same from bytes in memory; `name` stands for the file in messages.
  static LogReader from_bytes(std::string data, const std::string& name);

  // Frames 0..frame_count()-1: the complete and the damaged ones (not a truncated last frame).
  std::size_t frame_count() const { return frames_.size(); }
  bool readable(std::size_t frame) const { return frame < frames_.size() && frames_[frame].ok; }
  // Frames before the first damaged one: what a replay may use.
  std::size_t readable_prefix() const;
  bool truncated() const { return integrity_.truncated > 0; }  // bytes after the last frame
  const LogIntegrity& integrity() const { return integrity_; }
  // One line: "120 frames: 118 complete, 2 damaged (17, 18), 1 truncated".
  std::string summary() const;
  const LogMetadata& metadata() const { return metadata_; }
  const std::vector<LoggedType>& types() const { return types_; }
  int index_of(std::string_view name) const;  // -1 if not logged

  // Encoded bytes of representation `name` in frame `frame`; throws naming what is missing or
  // that the frame is damaged.
  std::string_view bytes(std::size_t frame, std::string_view name) const;
  std::string_view bytes(std::size_t frame, int index) const;
  Value value(std::size_t frame, std::string_view name) const;
  std::string text(std::size_t frame, std::string_view name) const;

  // Decodes into a T after checking that the logged type description matches T's.
  template <class T>
  T read(std::size_t frame) const {
    const auto name = Reflect<T>::type_name();
    const int i = index_of(name);
    check_type(i, name, *describe<T>());
    T v{};
    from_binary(v, bytes(frame, i));
    return v;
  }

 private:
  struct Frame {
    bool ok = false;
    std::vector<std::string_view> parts;  // per type: encoded bytes
  };
  LogReader(std::string data, std::string name);
  std::size_t read_header(std::string_view all);
  void read_frames_v1(std::string_view all, std::size_t pos);
  void read_frames_v2(std::string_view all, std::size_t pos);
  bool split_parts(std::string_view payload, std::vector<std::string_view>& parts) const;
  void check_type(int index, std::string_view name, const TypeDesc& expected) const;

  std::string name_;
  std::unique_ptr<const std::string> data_;  // frames_ point into it: its bytes never move
  LogMetadata metadata_;
  std::vector<LoggedType> types_;
  std::vector<Frame> frames_;
  LogIntegrity integrity_;
};

}  // namespace stride
