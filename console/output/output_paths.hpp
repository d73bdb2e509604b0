#pragma once
// Output paths named on a command line (--report, --csv, --snapshot, --video, --out, --plots,
// --log) are checked before a run starts, so an hour's study never fails at its last write, and
// no directory is created beyond the one the user named.
#include <string>

namespace stride::console {

// A file to be written: its folder exists and is writable, and the path is not a folder. Creates
// nothing. Throws stride::Error "<flag>: cannot write '<path>': <why>".
void check_output_file(const std::string& flag, const std::string& path);

// A folder to be filled: it exists and is writable, or its parent does and it can be created.
// Creates nothing. Throws stride::Error like check_output_file.
void check_output_dir(const std::string& flag, const std::string& path);

// check_output_dir, then creates that one folder if missing (never its parents).
void make_output_dir(const std::string& flag, const std::string& path);

}  // namespace stride::console
