// Animated PNG (the APNG extension of PNG): the PNG signature and header, an acTL chunk with the
// frame count, then per frame an fcTL chunk (size, delay) and its pixels, zlib-compressed RGB rows
// with the "Up" filter, in IDAT for the first frame (what a plain PNG viewer shows) and fdAT for
// the rest. The frame count is known only at the end: acTL is rewritten then.
#include <zlib.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <vector>

#include "robot/core/error.hpp"
#include "simulator/render/movie_encoders.hpp"

namespace stride::render {
namespace {

using Bytes = std::vector<std::uint8_t>;

void put32(Bytes& b, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) b.push_back(static_cast<std::uint8_t>(v >> shift));
}
void put16(Bytes& b, std::uint16_t v) {
  b.push_back(static_cast<std::uint8_t>(v >> 8));
  b.push_back(static_cast<std::uint8_t>(v));
}

// length, type, data, CRC-32 of type and data.
Bytes chunk(const char (&type)[5], const Bytes& data) {
  Bytes c;
  put32(c, static_cast<std::uint32_t>(data.size()));
  c.insert(c.end(), type, type + 4);
  c.insert(c.end(), data.begin(), data.end());
  const uLong crc = crc32(crc32(0L, Z_NULL, 0), c.data() + 4, static_cast<uInt>(data.size() + 4));
  put32(c, static_cast<std::uint32_t>(crc));
  return c;
}

class ApngEncoder final : public MovieFile::Encoder {
 public:
  ApngEncoder(const std::string& part, int width, int height, double fps)
      : width_(width), height_(height) {
    // Frame delay as a fraction of a second: 1000/fps milliseconds, rounded.
    delay_ms_ = static_cast<std::uint16_t>(std::clamp(std::lround(1000.0 / fps), 1L, 65535L));
    file_ = std::fopen(part.c_str(), "wb");
    if (!file_) fail_errno("cannot open for writing");
    static constexpr std::array<std::uint8_t, 8> kSignature{137, 80, 78, 71, 13, 10, 26, 10};
    write(Bytes(kSignature.begin(), kSignature.end()));
    Bytes header;
    put32(header, static_cast<std::uint32_t>(width));
    put32(header, static_cast<std::uint32_t>(height));
    header.insert(header.end(), {8, 2, 0, 0, 0});  // 8 bits, RGB, deflate, adaptive, no interlace
    write(chunk("IHDR", header));
    actl_at_ = std::ftell(file_);
    write(actl(0));
  }
  ~ApngEncoder() override {
    if (file_) std::fclose(file_);
  }

  void add(const RgbaImage& image) override {
    Bytes control;
    put32(control, sequence_++);
    put32(control, static_cast<std::uint32_t>(width_));
    put32(control, static_cast<std::uint32_t>(height_));
    put32(control, 0);  // x offset
    put32(control, 0);  // y offset
    put16(control, delay_ms_);
    put16(control, 1000);
    control.insert(control.end(), {0, 0});  // dispose: none; blend: source
    write(chunk("fcTL", control));
    const Bytes pixels = compressed_rows(image);
    if (frames_ == 0) {
      write(chunk("IDAT", pixels));
    } else {
      Bytes data;
      put32(data, sequence_++);
      data.insert(data.end(), pixels.begin(), pixels.end());
      write(chunk("fdAT", data));
    }
    ++frames_;
  }

  void finish() override {
    if (frames_ == 0) throw Error("no frames: an APNG needs at least one");
    write(chunk("IEND", {}));
    if (std::fseek(file_, actl_at_, SEEK_SET) != 0) fail_errno("cannot write");
    write(actl(frames_));
    const int rc = std::fclose(file_);
    file_ = nullptr;
    if (rc != 0) fail_errno("cannot write");
  }

  std::string codec() const override { return "apng"; }

 private:
  Bytes actl(std::uint32_t frames) const {
    Bytes a;
    put32(a, frames);
    put32(a, 0);  // plays: forever
    return chunk("acTL", a);
  }

  // Rows of RGB, each after a filter byte 2 ("Up": the difference to the row above), deflated.
  Bytes compressed_rows(const RgbaImage& image) const {
    const std::size_t row = static_cast<std::size_t>(width_) * 3;
    Bytes raw((row + 1) * height_);
    Bytes previous(row, 0), current(row);
    for (int y = 0; y < height_; ++y) {
      for (int x = 0; x < width_; ++x) std::memcpy(&current[x * 3], image.pixel(x, y), 3);
      std::uint8_t* out = &raw[(row + 1) * y];
      out[0] = 2;
      for (std::size_t i = 0; i < row; ++i)
        out[i + 1] = static_cast<std::uint8_t>(current[i] - previous[i]);
      previous.swap(current);
    }
    uLongf size = compressBound(static_cast<uLong>(raw.size()));
    Bytes packed(size);
    if (compress2(packed.data(), &size, raw.data(), static_cast<uLong>(raw.size()), 6) != Z_OK)
      throw Error("zlib could not compress a frame");
    packed.resize(size);
    return packed;
  }

  void write(const Bytes& b) {
    if (std::fwrite(b.data(), 1, b.size(), file_) != b.size()) fail_errno("cannot write");
  }
  [[noreturn]] void fail_errno(const std::string& what) const {
    throw Error(what + ": " + std::strerror(errno));
  }

  std::FILE* file_ = nullptr;
  int width_, height_;
  std::uint16_t delay_ms_ = 40;
  long actl_at_ = 0;
  std::uint32_t sequence_ = 0, frames_ = 0;
};

}  // namespace

std::unique_ptr<MovieFile::Encoder> open_apng(const std::string& part, int width, int height,
                                              double fps) {
  return std::make_unique<ApngEncoder>(part, width, height, fps);
}

}  // namespace stride::render
