#pragma once
// The robot's log directory as debug clients see it: they name files by plain names only (no
// directories, no "..": a client never reaches a file elsewhere on the robot). A log is always a
// new file (created exclusively: nothing there is overwritten, no link is followed), and only the
// logs this server created are served: never the token file, nor anything else that sits there.
#include <sys/types.h>

#include <cstdint>
#include <map>
#include <string>

namespace stride::debug {

class LogDirectory {
 public:
  explicit LogDirectory(std::string dir) : dir_(std::move(dir)) {}
  // dir/name; throws stride::Error unless name is 1-100 of [A-Za-z0-9._-] not starting with '.'
  // and ending in ".log".
  std::string path_of(const std::string& name) const;

  // Creates the empty file `name` for a log (never an existing file or link) and serves it from
  // now on; returns its path. Throws naming the file.
  std::string create(const std::string& name);
  // A created log the loop did not start: removed, no longer served.
  void discard(const std::string& name);

  struct Info {
    std::uint64_t size = 0;
    std::string sha256;  // 32 bytes
  };
  Info info(const std::string& name) const;  // throws naming the file
  // Up to `length` bytes from `offset`; `size` receives the file's size.
  std::string read(const std::string& name, std::uint64_t offset, std::uint64_t length,
                   std::uint64_t& size) const;

 private:
  struct Identity {
    dev_t device = 0;
    ino_t inode = 0;
  };
  int open_served(const std::string& name) const;  // an fd of the very file created, or throws

  std::string dir_;
  std::map<std::string, Identity> created_;
};

// SHA-256 of a file's first `limit` bytes (OpenSSL); throws naming the file.
std::string file_sha256(const std::string& path, std::uint64_t limit = UINT64_MAX);

}  // namespace stride::debug
