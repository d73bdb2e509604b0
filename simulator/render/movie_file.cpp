#include "simulator/render/movie_file.hpp"

#include <filesystem>

#include "robot/core/error.hpp"
#include "robot/core/quote.hpp"
#include "simulator/render/movie_encoders.hpp"

namespace stride::render {

bool is_movie_path(const std::string& path) {
  const auto ext = std::filesystem::path(path).extension();
  return ext == ".mp4" || ext == ".apng";
}

bool mp4_supported() {
#if STRIDE_HAVE_FFMPEG
  return true;
#else
  return false;
#endif
}

namespace {

std::unique_ptr<MovieFile::Encoder> open_encoder(bool apng, const std::string& part, int width,
                                                 int height, double fps) {
  if (apng) return open_apng(part, width, height, fps);
#if STRIDE_HAVE_FFMPEG
  return open_mp4(part, width, height, fps);
#else
  throw Error(
      "MP4 needs FFmpeg's libraries, and this stride was built without them (Debian "
      "libavcodec-dev, libavformat-dev, libswscale-dev, libavutil-dev; -DSTRIDE_MP4=ON); name a "
      ".apng movie instead");
#endif
}

}  // namespace

MovieFile::MovieFile(const std::string& path, int width, int height, double fps)
    : path_(path), part_(path + ".part"), width_(width), height_(height) {
  if (width <= 0 || height <= 0 || width % 2 || height % 2)
    fail("expected an even width and height, got " + std::to_string(width) + "x" +
         std::to_string(height));
  if (!(fps >= 1 && fps <= 1000)) fail("expected 1 to 1000 frames/s");
  const auto ext = std::filesystem::path(path).extension();
  if (ext != ".mp4" && ext != ".apng") fail("expected a .mp4 or .apng file");
  try {
    encoder_ = open_encoder(ext == ".apng", part_, width, height, fps);
  } catch (const Error& e) {
    std::error_code ec;
    std::filesystem::remove(part_, ec);
    fail(e.what());
  }
  codec_ = encoder_->codec();
}

MovieFile::~MovieFile() {
  if (closed_) return;
  encoder_.reset();  // closes the file before it is removed
  std::error_code ec;
  std::filesystem::remove(part_, ec);
}

void MovieFile::fail(const std::string& why) const {
  throw Error("movie " + quote(path_) + ": " + why);
}

void MovieFile::add(const RgbaImage& image) {
  if (closed_) fail("already closed");
  if (image.width != width_ || image.height != height_)
    fail("frame " + std::to_string(image.width) + "x" + std::to_string(image.height) +
         " differs from the movie's " + std::to_string(width_) + "x" + std::to_string(height_));
  try {
    encoder_->add(image);
  } catch (const Error& e) {
    fail(e.what());
  }
  ++frames_;
}

void MovieFile::close() {
  if (closed_) return;
  try {
    encoder_->finish();
  } catch (const Error& e) {
    fail(e.what());
  }
  closed_ = true;
  std::error_code ec;
  std::filesystem::rename(part_, path_, ec);
  if (ec) fail("cannot move " + quote(part_) + " into place: " + ec.message());
}

}  // namespace stride::render
