#include "simulator/render/png_file.hpp"

#include <cstring>
#include <memory>
#include <string_view>

#include <png.h>

#include "robot/core/error.hpp"
#include "robot/core/output_file.hpp"

namespace stride::render {

void write_png(const std::string& path, const RgbaImage& image, PngEncoding encoding) {
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  png.width = static_cast<png_uint_32>(image.width);
  png.height = static_cast<png_uint_32>(image.height);
  png.format = PNG_FORMAT_RGBA;
  if (encoding == PngEncoding::Fast) png.flags |= PNG_IMAGE_FLAG_FAST;
  // Encoded in memory, so the file's writes go through the checked writer; into a buffer of the
  // largest size libpng can produce, so the image is encoded once (sizing first encodes twice).
  png_alloc_size_t size = PNG_IMAGE_PNG_SIZE_MAX(png);
  const auto bytes = std::make_unique_for_overwrite<char[]>(size);  // not zeroed: libpng fills it
  if (!png_image_write_to_memory(&png, bytes.get(), &size, 0, image.rgba.data(), 0, nullptr))
    throw Error("cannot write PNG '" + path + "': " + png.message);
  write_file(path, std::string_view(bytes.get(), size));
}

RgbaImage read_png(const std::string& path) {
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&png, path.c_str()))
    throw Error("cannot read PNG '" + path + "': " + png.message);
  png.format = PNG_FORMAT_RGBA;
  RgbaImage out;
  out.width = static_cast<int>(png.width);
  out.height = static_cast<int>(png.height);
  out.rgba.resize(PNG_IMAGE_SIZE(png));
  if (!png_image_finish_read(&png, nullptr, out.rgba.data(), 0, nullptr))
    throw Error("cannot read PNG '" + path + "': " + png.message);
  return out;
}

}  // namespace stride::render
