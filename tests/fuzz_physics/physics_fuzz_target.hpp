#pragma once
// One physics fuzz input: a scene, optionally followed by a URDF and a device file, each after a
// separator line; the scene may name them (fuzz.urdf, fuzz.devices.xml) or the shipped NAO
// (nao.urdf, nao.devices.xml). The world and its controllers are built and stepped for a few
// frames. A stride::Error is a clean refusal; anything else escaping (another exception, an ODE
// assertion, a sanitizer report) is a bug.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "console/session/sim_session.hpp"
#include "robot/core/error.hpp"

namespace stride::test {

inline constexpr std::string_view kUrdfSeparator = "\n--- urdf\n";
inline constexpr std::string_view kDevicesSeparator = "\n--- devices\n";

// The directory the fuzz files are written to, with the NAO's files beside them (one per
// process, so parallel fuzz jobs do not share it).
inline const std::filesystem::path& physics_fuzz_dir() {
  static const std::filesystem::path dir = [] {
    namespace fs = std::filesystem;
    const fs::path d =
        fs::temp_directory_path() / ("stride_physics_fuzz_" + std::to_string(getpid()));
    fs::create_directories(d);
    const fs::path nao = fs::path(STRIDE_SOURCE_DIR) / "scenes/robots/nao";
    for (const char* f : {"nao.urdf", "nao.devices.xml"})
      fs::copy_file(nao / f, d / f, fs::copy_options::overwrite_existing);
    return d;
  }();
  return dir;
}

inline void write_text(const std::filesystem::path& p, std::string_view text) {
  std::ofstream(p, std::ios::binary).write(text.data(), static_cast<std::streamsize>(text.size()));
}

// Returns the error message, or "" when the world was built and stepped.
inline std::string run_physics_fuzz_input(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return "";
  const int steps = 1 + data[0] % 64;
  std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
  std::string_view urdf, devices;
  if (const auto d = text.find(kDevicesSeparator); d != std::string_view::npos) {
    devices = text.substr(d + kDevicesSeparator.size());
    text = text.substr(0, d);
  }
  if (const auto u = text.find(kUrdfSeparator); u != std::string_view::npos) {
    urdf = text.substr(u + kUrdfSeparator.size());
    text = text.substr(0, u);
  }
  const auto& dir = physics_fuzz_dir();
  write_text(dir / "fuzz.urdf", urdf);
  write_text(dir / "fuzz.devices.xml", devices);
  write_text(dir / "fuzz.xml", text);
  try {
    console::SimSession session((dir / "fuzz.xml").string());
    for (int k = 0; k < steps; ++k) session.simulation().step();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace stride::test
