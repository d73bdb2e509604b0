#pragma once
// Frame logs: a compact append-only binary file.
//   "STRDLOG1" | u32 header size | header: u32 n, n x (name, TypeDesc) |
//   per frame: u32 payload size | payload: n x (u32 size, encoded representation)
// Each frame is flushed when written, so a crash loses at most the frame being written; a reader
// stops at the first incomplete frame.
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "robot/framework/slot.hpp"

namespace stride {

struct LoggedType {
  std::string name;
  TypeDescPtr desc;
};

class LogWriter {
 public:
  // Writes the header for `slots` (name, object); every frame records the same list.
  LogWriter(const std::string& path, std::vector<std::pair<std::string, const Slot*>> slots);
  ~LogWriter();
  LogWriter(const LogWriter&) = delete;
  LogWriter& operator=(const LogWriter&) = delete;

  void write_frame();
  std::size_t frames_written() const { return frames_; }

 private:
  std::FILE* file_ = nullptr;
  std::vector<std::pair<std::string, const Slot*>> slots_;
  std::string buffer_;
  std::size_t frames_ = 0;
};

class LogReader {
 public:
  explicit LogReader(const std::string& path);  // throws on a missing file or a bad header

  std::size_t frame_count() const { return frames_.size(); }
  bool truncated() const { return truncated_; }  // bytes after the last complete frame
  const std::vector<LoggedType>& types() const { return types_; }
  int index_of(std::string_view name) const;  // -1 if not logged

  // Encoded bytes of representation `name` in frame `frame`; throws naming what is missing.
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
  void check_type(int index, std::string_view name, const TypeDesc& expected) const;
  std::string data_;
  std::vector<LoggedType> types_;
  std::vector<std::vector<std::string_view>> frames_;  // per frame, per type: encoded bytes
  bool truncated_ = false;
};

}  // namespace stride
