#include "console/view/static_files.hpp"

#include <array>
#include <utility>

#include "robot/core/data_dir.hpp"
#include "robot/core/error.hpp"

namespace stride::view {

namespace fs = std::filesystem;

namespace {

// `installed` below the data directory if it exists there, else `fallback`.
fs::path first_existing(const fs::path& installed, const fs::path& fallback) {
  std::error_code ec;
  return fs::is_directory(installed, ec) ? installed : fallback;
}

// A relative path made only of plain names (no "..", ".", empty parts, escapes or controls).
bool plain_relative(std::string_view rel) {
  if (rel.empty()) return false;
  std::size_t start = 0;
  while (start <= rel.size()) {
    const std::size_t end = std::min(rel.find('/', start), rel.size());
    const std::string_view part = rel.substr(start, end - start);
    if (part.empty() || part == "." || part == "..") return false;
    start = end + 1;
  }
  for (char c : rel)
    if (static_cast<unsigned char>(c) < 0x20 || c == '%' || c == '\\' || c == 0x7f) return false;
  return true;
}

// `root/rel` if it is a regular file whose real path stays below the real root.
std::optional<fs::path> inside(const fs::path& root, std::string_view rel) {
  if (!plain_relative(rel)) return std::nullopt;
  std::error_code ec;
  const fs::path real_root = fs::canonical(root, ec);
  if (ec) return std::nullopt;
  const fs::path file = fs::canonical(real_root / fs::path(std::string(rel)), ec);
  if (ec || !fs::is_regular_file(file, ec)) return std::nullopt;
  if (!file.string().starts_with(real_root.string() + "/")) return std::nullopt;
  return file;
}

}  // namespace

WebRoots default_web_roots() {
  const fs::path data = data_dir();
  // Installed: share/stride/web with web/vendor/{three,uplot,noble-hashes}; else the source tree,
  // Debian's and the npm registry's in .deps/web.
  const fs::path npm = data / ".deps" / "web" / "node_modules";
  return {
      first_existing(data / "web", data / "console" / "view" / "web"),
      first_existing(data / "web" / "vendor" / "three", "/usr/share/javascript/three"),
      first_existing(data / "web" / "vendor" / "uplot", npm / "uplot" / "dist"),
      first_existing(data / "web" / "vendor" / "noble-hashes", npm / "@noble" / "hashes" / "esm")};
}

std::optional<fs::path> resolve_web_path(const WebRoots& roots, std::string_view target) {
  if (target.empty() || target[0] != '/') return std::nullopt;
  target = target.substr(0, target.find_first_of("?#"));
  if (target == "/") target = "/index.html";
  const std::array<std::pair<std::string_view, const fs::path*>, 3> vendors{
      {{"/vendor/three/", &roots.three},
       {"/vendor/uplot/", &roots.uplot},
       {"/vendor/noble-hashes/", &roots.noble}}};
  for (const auto& [prefix, root] : vendors)
    if (target.starts_with(prefix)) return inside(*root, target.substr(prefix.size()));
  if (target.starts_with("/vendor/")) return std::nullopt;
  return inside(roots.page, target.substr(1));
}

std::string_view mime_type(const fs::path& file) {
  static constexpr std::array<std::pair<std::string_view, std::string_view>, 12> types{{
      {".html", "text/html; charset=utf-8"},
      {".js", "text/javascript; charset=utf-8"},
      {".mjs", "text/javascript; charset=utf-8"},
      {".css", "text/css; charset=utf-8"},
      {".json", "application/json"},
      {".svg", "image/svg+xml"},
      {".png", "image/png"},
      {".ico", "image/x-icon"},
      {".txt", "text/plain; charset=utf-8"},
      {".map", "application/json"},
      {".woff2", "font/woff2"},
      {".wasm", "application/wasm"},
  }};
  const std::string ext = file.extension().string();
  for (const auto& [e, type] : types)
    if (ext == e) return type;
  return "application/octet-stream";
}

}  // namespace stride::view
