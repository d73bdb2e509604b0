#pragma once
// The files the view serves over HTTP: the page and the three vendor libraries, by URL path, with
// their MIME types. Only files below the roots are ever resolved (no "..", no symlink escapes).
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace stride::view {

struct WebRoots {
  std::filesystem::path page;   // console/view/web, or an installed share/stride/web
  std::filesystem::path three;  // Debian's libjs-three
  std::filesystem::path uplot;  // uPlot's dist/ from the npm registry
  std::filesystem::path noble;  // @noble/hashes' esm/ from the npm registry (the page's HMAC)
};

// The roots of this build or installation (robot/core/data_dir.hpp finds the data directory).
WebRoots default_web_roots();

// The file a request target names ("/", "/app.js?x=1", "/vendor/three/build/three.min.js"), or
// nothing: unknown prefix, "..", a percent escape, a NUL, a directory, or a path outside its root.
std::optional<std::filesystem::path> resolve_web_path(const WebRoots& roots,
                                                      std::string_view target);

// "text/html; charset=utf-8" and the like by extension; application/octet-stream otherwise.
std::string_view mime_type(const std::filesystem::path& file);

}  // namespace stride::view
