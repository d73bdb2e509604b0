#pragma once
// Runs tests/lola/decode_with_python.py (Debian's python3-msgpack) on a packet: an independent
// decoder for checking Stride's packets key by key.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace stride::test {

struct PythonElement {
  std::string key;
  int index = 0;
  std::string type;   // Python's type name: float, int, str, bool
  std::string value;  // floats as repr(): strtod gives the exact double back
};

struct PythonDecoded {
  std::size_t size = 0;
  std::string keys;  // comma separated, in map order
  std::vector<PythonElement> elements;
};

inline PythonDecoded decode_with_python(const std::string& packet) {
  const auto file = std::filesystem::temp_directory_path() /
                    ("stride_lola_packet_" + std::to_string(::getpid()) + ".bin");
  std::ofstream(file, std::ios::binary) << packet;
  const std::string cmd =
      "/usr/bin/python3 " STRIDE_SOURCE_DIR "/tests/lola/decode_with_python.py " + file.string();
  std::string text;
  if (FILE* pipe = ::popen(cmd.c_str(), "r")) {
    char buf[4096];
    while (std::size_t n = std::fread(buf, 1, sizeof buf, pipe)) text.append(buf, n);
    EXPECT_EQ(::pclose(pipe), 0) << text;
  } else {
    ADD_FAILURE() << "cannot run " << cmd;
  }
  std::filesystem::remove(file);
  PythonDecoded d;
  std::istringstream in(text);
  std::string word;
  in >> word >> d.size >> word >> d.keys;
  PythonElement e;
  while (in >> e.key >> e.index >> e.type >> e.value) d.elements.push_back(e);
  return d;
}

}  // namespace stride::test
