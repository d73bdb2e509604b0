#pragma once
// The encoders behind MovieFile (movie_file.hpp). Each writes `part`; errors are stride::Error
// whose text MovieFile prefixes with the movie's name.
#include <memory>
#include <string>

#include "simulator/render/movie_file.hpp"

namespace stride::render {

std::unique_ptr<MovieFile::Encoder> open_apng(const std::string& part, int width, int height,
                                              double fps);
// Only in a build with FFmpeg's libraries (STRIDE_HAVE_FFMPEG).
std::unique_ptr<MovieFile::Encoder> open_mp4(const std::string& part, int width, int height,
                                             double fps);

}  // namespace stride::render
