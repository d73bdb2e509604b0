#pragma once
// PNG files through libpng's simplified API. Errors throw stride::Error naming the file.
#include <string>

#include "simulator/render/image.hpp"

namespace stride::render {

// Fast trades file size for encoding time (a movie's frames); Small is libpng's default.
enum class PngEncoding { Small, Fast };

void write_png(const std::string& path, const RgbaImage& image,
               PngEncoding encoding = PngEncoding::Small);
RgbaImage read_png(const std::string& path);

}  // namespace stride::render
