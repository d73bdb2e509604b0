#pragma once
// The byte layout of frame logs shared by the writer and the reader (described in log.hpp).
#include <cstdint>
#include <string_view>

#include <zlib.h>

namespace stride::log_format {

inline constexpr std::string_view kMagicV1 = "STRDLOG1";
inline constexpr std::string_view kMagicV2 = "STRDLOG2";
inline constexpr std::uint32_t kFrameMarker = 0x46525453;  // "STRF" in the file
// Marker, frame number, payload size, checksum.
inline constexpr std::size_t kFrameHeaderBytes = 4 + 8 + 4 + 4;

// zlib's CRC-32 of `bytes`, continuing `crc` (0 to start).
inline std::uint32_t crc32_of(std::string_view bytes, std::uint32_t crc = 0) {
  uLong c = crc;
  while (!bytes.empty()) {  // zlib takes lengths as uInt
    const auto n = static_cast<uInt>(std::min<std::size_t>(bytes.size(), 1u << 30));
    c = ::crc32(c, reinterpret_cast<const Bytef*>(bytes.data()), n);
    bytes.remove_prefix(n);
  }
  return static_cast<std::uint32_t>(c);
}

}  // namespace stride::log_format
