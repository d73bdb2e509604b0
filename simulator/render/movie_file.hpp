#pragma once
// A movie written frame by frame, its kind chosen by the file's extension:
//  - .mp4 through FFmpeg's libraries (Debian libavcodec, libavformat, libswscale), H.264 (libx264)
//    where the library has it, else MPEG-4 Part 2; only in a build that found those libraries;
//  - .apng, an animated PNG (libpng's format with zlib, no further dependency): every browser
//    plays it, and any PNG viewer shows its first frame.
// The movie goes to "<path>.part" and is renamed to <path> when closed, so a movie file that
// exists is complete.
#include <memory>
#include <string>

#include "simulator/render/image.hpp"

namespace stride::render {

// True for a path that names a movie file (.mp4 or .apng) rather than a folder of PNGs.
bool is_movie_path(const std::string& path);
// Whether this build writes MP4 (FFmpeg's libraries were found when it was configured).
bool mp4_supported();

class MovieFile {
 public:
  // What writes one kind of movie into the .part file.
  class Encoder {
   public:
    virtual ~Encoder() = default;
    virtual void add(const RgbaImage& frame) = 0;
    virtual void finish() = 0;  // flushes and closes the file
    virtual std::string codec() const = 0;
  };

  // Opens the movie for frames of width x height (both even) at `fps`; throws stride::Error
  // naming the path when it cannot.
  MovieFile(const std::string& path, int width, int height, double fps);
  ~MovieFile();  // an unclosed movie is abandoned: its .part file is removed
  MovieFile(const MovieFile&) = delete;
  MovieFile& operator=(const MovieFile&) = delete;

  // Frames must have the size given at opening.
  void add(const RgbaImage& frame);
  // Finishes the file and renames it into place.
  void close();

  long long frames() const { return frames_; }
  const std::string& codec() const { return codec_; }  // "h264", "mpeg4" or "apng"

 private:
  [[noreturn]] void fail(const std::string& why) const;

  std::string path_, part_, codec_;
  int width_ = 0, height_ = 0;
  long long frames_ = 0;
  bool closed_ = false;
  std::unique_ptr<Encoder> encoder_;
};

}  // namespace stride::render
