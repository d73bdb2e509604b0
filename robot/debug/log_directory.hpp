#pragma once
// The robot's log directory as debug clients see it: they name files by plain names only (no
// directories, no "..": a client never reaches a file elsewhere on the robot), start logs there
// and download them in chunks.
#include <cstdint>
#include <string>

namespace stride::debug {

class LogDirectory {
 public:
  explicit LogDirectory(std::string dir) : dir_(std::move(dir)) {}
  // dir/name; throws stride::Error unless name is 1-100 of [A-Za-z0-9._-] not starting with '.'.
  std::string path_of(const std::string& name) const;

  struct Info {
    std::uint64_t size = 0;
    std::string sha256;  // 32 bytes
  };
  Info info(const std::string& name) const;  // throws naming the file
  // Up to `length` bytes from `offset`; `size` receives the file's size.
  std::string read(const std::string& name, std::uint64_t offset, std::uint64_t length,
                   std::uint64_t& size) const;

 private:
  std::string dir_;
};

// SHA-256 of a file's first `limit` bytes (OpenSSL); throws naming the file.
std::string file_sha256(const std::string& path, std::uint64_t limit = UINT64_MAX);

}  // namespace stride::debug
