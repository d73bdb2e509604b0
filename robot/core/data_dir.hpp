#pragma once
// Where the shipped data (scenes/, scenes/robots/) lives, so that no default path depends on the
// working directory: $STRIDE_DATA if set, else <executable dir>/../share/stride (an installed
// stride), else the source tree the binary was built from.
#include <filesystem>
#include <string>

namespace stride {

// The data directory (it holds scenes/); throws stride::Error naming the places looked in, or a
// STRIDE_DATA that has no scenes/.
std::filesystem::path data_dir();

// A shipped file by its path inside the data directory, e.g. "scenes/robots/nao/nao.urdf".
std::string data_file(const std::string& relative);

// A path a user gave: as given if it exists (relative to the working directory); else, for a
// relative path, the data directory's file of that name if there is one; else as given, so the
// caller's "cannot open" names what the user wrote.
std::string find_input(const std::string& path);

// One line for `stride help`: the data directory in use and how to override it.
std::string data_dir_line();

}  // namespace stride
