#pragma once
// An RGBA8 image, rows top to bottom.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace stride::render {

struct RgbaImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4

  const std::uint8_t* pixel(int x, int y) const {
    return rgba.data() + (static_cast<std::size_t>(y) * width + x) * 4;
  }
};

}  // namespace stride::render
