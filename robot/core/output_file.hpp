#pragma once
// Every output Stride writes goes through here, so that a full disk, /dev/full or a vanished
// directory is an error naming the path, never a "wrote ..." for a file that is not there.
//
// Replace (reports, CSV, plots, pictures): bytes go to a temporary file beside the target and
// are renamed onto it by commit(), after every write and the close succeeded; without commit()
// (an error, an exception) the temporary is removed and an older file of that name is left as it
// was. A target that is not a regular file (/dev/null, /dev/full, a FIFO) is written directly.
//
// Stream (logs): bytes go straight to the target and flush() pushes them to the kernel, so a
// process killed later keeps everything flushed before; a failed write is an error and the
// reader of such a file sees its last record incomplete.
#include <cstdio>
#include <string>
#include <string_view>

namespace stride {

class OutputFile {
 public:
  enum class Mode { Replace, Stream };
  // Opens (creates) the output; throws stride::Error("cannot write '<path>': <reason>").
  explicit OutputFile(std::string path, Mode mode = Mode::Replace);
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  void write(std::string_view bytes);
  void flush();   // to the kernel; checked
  void commit();  // flush, close and (Replace) rename onto the target; checked
  const std::string& path() const { return path_; }
  bool committed() const { return file_ == nullptr && !failed_; }

 private:
  [[noreturn]] void fail(const std::string& what, int err);
  void discard() noexcept;

  std::string path_;
  std::string temp_;  // empty when writing the target directly
  std::FILE* file_ = nullptr;
  bool failed_ = false;
};

// The whole of `contents` as the file `path`, or an error naming it (nothing at `path` changes).
void write_file(const std::string& path, std::string_view contents);

// A copy of the file `from` as `to`, read in pieces (logs can be large); errors name the path.
void copy_file_checked(const std::string& from, const std::string& to);

}  // namespace stride
