#include "robot/debug/log_directory.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#include <openssl/evp.h>

#include "robot/core/error.hpp"
#include "robot/core/one_line.hpp"

namespace stride::debug {

namespace {
struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

File open_for_reading(const std::string& path) {
  File f(std::fopen(path.c_str(), "rb"));
  if (!f) throw Error("log '" + path + "': " + std::strerror(errno));
  return f;
}
}  // namespace

std::string LogDirectory::path_of(const std::string& name) const {
  bool ok = !name.empty() && name.size() <= 100 && name[0] != '.';
  for (char c : name)
    ok = ok && ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                c == '.' || c == '_' || c == '-');
  if (!ok)
    throw Error("log file '" + one_line(name) +
                "': expected a plain name of letters, digits, '.', '_', '-' (the robot keeps its "
                "logs in its log directory)");
  return dir_ + "/" + name;
}

LogDirectory::Info LogDirectory::info(const std::string& name) const {
  const std::string path = path_of(name);
  Info i;
  File f = open_for_reading(path);
  std::fseek(f.get(), 0, SEEK_END);
  i.size = static_cast<std::uint64_t>(std::ftell(f.get()));
  i.sha256 = file_sha256(path, i.size);  // a log being recorded grows: its first `size` bytes
  return i;
}

std::string LogDirectory::read(const std::string& name, std::uint64_t offset, std::uint64_t length,
                               std::uint64_t& size) const {
  const std::string path = path_of(name);
  File f = open_for_reading(path);
  std::fseek(f.get(), 0, SEEK_END);
  size = static_cast<std::uint64_t>(std::ftell(f.get()));
  if (offset > size)
    throw Error("log '" + name + "': offset " + std::to_string(offset) + " is past its end (" +
                std::to_string(size) + " bytes)");
  std::string out(std::min(length, size - offset), '\0');
  std::fseek(f.get(), static_cast<long>(offset), SEEK_SET);
  out.resize(std::fread(out.data(), 1, out.size(), f.get()));
  return out;
}

std::string file_sha256(const std::string& path, std::uint64_t limit) {
  File f = open_for_reading(path);
  std::unique_ptr<EVP_MD_CTX, void (*)(EVP_MD_CTX*)> ctx(EVP_MD_CTX_new(), EVP_MD_CTX_free);
  if (!ctx || EVP_DigestInit_ex(ctx.get(), EVP_sha256(), nullptr) != 1)
    throw Error("SHA-256 unavailable (OpenSSL)");
  char buffer[65536];
  for (std::size_t n;
       limit > 0 &&
       (n = std::fread(buffer, 1, std::min<std::uint64_t>(sizeof buffer, limit), f.get())) > 0;
       limit -= n)
    EVP_DigestUpdate(ctx.get(), buffer, n);
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  EVP_DigestFinal_ex(ctx.get(), digest, &length);
  return std::string(reinterpret_cast<const char*>(digest), length);
}

}  // namespace stride::debug
