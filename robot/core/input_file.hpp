#pragma once
// Reading a whole input file (scene, URDF, device file, script, log) with its kind and size
// checked before a byte is read: a directory, a device such as /dev/zero or /dev/urandom, a FIFO
// or a file over the limit is refused with one line naming the path, instead of a read that never
// ends or fills memory.
#include <cstdint>
#include <string>

namespace stride {

// Size limits by kind of input, stated in docs/scenes.md "Limits".
inline constexpr std::uint64_t kMaxTextInputBytes = 64ull << 20;  // scenes, URDFs, device files
inline constexpr std::uint64_t kMaxScriptBytes = 16ull << 20;     // console scripts
inline constexpr std::uint64_t kMaxLogBytes = 8ull << 30;         // frame logs

// The file's bytes; throws stride::Error("<what> '<path>': <reason>"), e.g.
// "scene file '/dev/zero': not a regular file (a character device)".
std::string read_input_file(const std::string& path, std::uint64_t max_bytes,
                            const std::string& what);

// The same checks without reading: "" when `path` may be read, else the reason.
std::string input_file_problem(const std::string& path, std::uint64_t max_bytes);

}  // namespace stride
