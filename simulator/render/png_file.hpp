#pragma once
// PNG files through libpng's simplified API. Errors throw stride::Error naming the file.
#include <string>

#include "simulator/render/image.hpp"

namespace stride::render {

void write_png(const std::string& path, const RgbaImage& image);
RgbaImage read_png(const std::string& path);

}  // namespace stride::render
