// Movies read back (frame count, size, pixels): animated PNG chunk by chunk with its first frame
// through libpng, MP4 through FFmpeg's decoder where the build has it; the sides of the robot in
// their colours, and the text overlay's pixels.
#include <gtest/gtest.h>
#include <png.h>
#include <zlib.h>

#if STRIDE_HAVE_FFMPEG
extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}
#endif

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <sstream>

#include "console/interpreter/interpreter.hpp"
#include "console/target/local_target.hpp"
#include "robot/model/urdf_loader.hpp"
#include "simulator/render/body_side.hpp"
#include "simulator/render/movie_file.hpp"
#include "simulator/render/snapshot.hpp"
#include "simulator/render/text_overlay.hpp"
#include "simulator/render/views.hpp"
#include "simulator/scene/scene_parser.hpp"
#include "simulator/simulation.hpp"
#include "tests/error_text.hpp"
#include "tests/simulator/sim_test_util.hpp"

namespace stride::render {
namespace {

namespace fs = std::filesystem;
using test_support::error_of;

fs::path temp_dir() {
  const fs::path d = fs::temp_directory_path() / ("stride_movie_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

// What a decoder sees in a movie file: its size, frame count, length, and its first frame (MP4:
// every frame) as RGBA.
struct Decoded {
  int width = 0, height = 0, frames = 0;
  double seconds = 0;
  std::string codec;
  RgbaImage first;
  std::vector<RgbaImage> images;
};

// An APNG: every chunk's CRC checked, the frame count from acTL against the fcTL chunks, the first
// frame (the PNG's own image) read by libpng.
Decoded decode_apng(const std::string& path) {
  Decoded d;
  std::ifstream in(path, std::ios::binary);
  const std::string b((std::istreambuf_iterator<char>(in)), {});
  const auto u32 = [&](std::size_t at) {
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v = v << 8 | static_cast<std::uint8_t>(b[at + i]);
    return v;
  };
  if (b.size() < 8 || b.compare(1, 3, "PNG") != 0) return d;
  std::uint32_t declared = 0;
  for (std::size_t at = 8; at + 12 <= b.size();) {
    const std::uint32_t n = u32(at);
    const std::string type = b.substr(at + 4, 4);
    if (at + 12 + n > b.size()) return {};
    const auto* bytes = reinterpret_cast<const Bytef*>(b.data() + at + 4);
    if (crc32(crc32(0L, Z_NULL, 0), bytes, n + 4) != u32(at + 8 + n)) return {};
    if (type == "IHDR")
      d.width = static_cast<int>(u32(at + 8)), d.height = static_cast<int>(u32(at + 12));
    if (type == "acTL") declared = u32(at + 8);
    if (type == "fcTL") {
      ++d.frames;
      const auto u16 = [&](std::size_t a) { return (u32(a) >> 16) & 0xffff; };
      d.seconds += static_cast<double>(u16(at + 28)) / u16(at + 30);  // delay_num / delay_den
    }
    at += 12 + n;
  }
  if (static_cast<int>(declared) != d.frames) return {};
  d.codec = "apng";
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&png, path.c_str())) return d;
  png.format = PNG_FORMAT_RGBA;
  d.first = {static_cast<int>(png.width), static_cast<int>(png.height),
             std::vector<std::uint8_t>(PNG_IMAGE_SIZE(png))};
  if (!png_image_finish_read(&png, nullptr, d.first.rgba.data(), 0, nullptr)) d.first = {};
  return d;
}

#if STRIDE_HAVE_FFMPEG
Decoded decode_mp4(const std::string& path) {
  Decoded d;
  AVFormatContext* format = nullptr;
  if (avformat_open_input(&format, path.c_str(), nullptr, nullptr) < 0) return d;
  std::unique_ptr<AVFormatContext*, void (*)(AVFormatContext**)> close_format(&format,
                                                                              avformat_close_input);
  if (avformat_find_stream_info(format, nullptr) < 0) return d;
  const int s = av_find_best_stream(format, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
  if (s < 0) return d;
  const AVCodecParameters* par = format->streams[s]->codecpar;
  const AVCodec* codec = avcodec_find_decoder(par->codec_id);
  AVCodecContext* ctx = avcodec_alloc_context3(codec);
  avcodec_parameters_to_context(ctx, par);
  avcodec_open2(ctx, codec, nullptr);
  d.width = par->width;
  d.height = par->height;
  d.codec = avcodec_get_name(par->codec_id);
  d.seconds = static_cast<double>(format->duration) / AV_TIME_BASE;
  AVPacket* packet = av_packet_alloc();
  AVFrame* frame = av_frame_alloc();
  const auto take = [&] {
    while (avcodec_receive_frame(ctx, frame) == 0) {
      ++d.frames;
      RgbaImage& img = d.images.emplace_back();
      img = {frame->width, frame->height,
             std::vector<std::uint8_t>(static_cast<std::size_t>(frame->width) * frame->height * 4)};
      SwsContext* sws = sws_getContext(
          frame->width, frame->height, static_cast<AVPixelFormat>(frame->format), frame->width,
          frame->height, AV_PIX_FMT_RGBA, SWS_BILINEAR, nullptr, nullptr, nullptr);
      std::uint8_t* out[1] = {img.rgba.data()};
      const int stride[1] = {frame->width * 4};
      sws_scale(sws, frame->data, frame->linesize, 0, frame->height, out, stride);
      sws_freeContext(sws);
    }
  };
  while (av_read_frame(format, packet) >= 0) {
    if (packet->stream_index == s) avcodec_send_packet(ctx, packet);
    av_packet_unref(packet);
    take();
  }
  avcodec_send_packet(ctx, nullptr);  // flush
  take();
  if (!d.images.empty()) d.first = d.images.front();
  av_frame_free(&frame);
  av_packet_free(&packet);
  avcodec_free_context(&ctx);
  return d;
}
#endif

Decoded decode(const std::string& path) {
#if STRIDE_HAVE_FFMPEG
  if (fs::path(path).extension() == ".mp4") return decode_mp4(path);
#endif
  return decode_apng(path);
}

// The movie kinds this build writes.
std::vector<std::string> movie_kinds() {
  if (mp4_supported()) return {".apng", ".mp4"};
  return {".apng"};
}

// A picture of two halves: red on the left, blue on the right.
RgbaImage halves(int w, int h) {
  RgbaImage img{w, h, std::vector<std::uint8_t>(static_cast<std::size_t>(w) * h * 4)};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = img.rgba.data() + (static_cast<std::size_t>(y) * w + x) * 4;
      p[0] = x < w / 2 ? 220 : 20;
      p[2] = x < w / 2 ? 20 : 220;
      p[1] = 30;
      p[3] = 255;
    }
  return img;
}

TEST(MovieFile, FramesReadBackWithTheirSizeCountAndColours) {
  for (const std::string& kind : movie_kinds()) {
    SCOPED_TRACE(kind);
    const std::string path = (temp_dir() / ("halves" + kind)).string();
    fs::remove(path);
    {
      MovieFile movie(path, 96, 64, 25);
      for (int i = 0; i < 12; ++i) movie.add(halves(96, 64));
      EXPECT_FALSE(fs::exists(path)) << "an unfinished movie is visible";
      movie.close();
      EXPECT_EQ(movie.frames(), 12);
    }
    EXPECT_FALSE(fs::exists(path + ".part"));
    const Decoded d = decode(path);
    EXPECT_EQ(d.width, 96);
    EXPECT_EQ(d.height, 64);
    EXPECT_EQ(d.frames, 12);
    EXPECT_NEAR(d.seconds, 12 / 25.0, 1e-9);
    ASSERT_EQ(d.first.width, 96);
    // MP4 is lossy and 4:2:0: colours come back within a few levels away from the edge between
    // the halves (APNG exactly).
    const std::uint8_t* left = d.first.pixel(20, 32);
    const std::uint8_t* right = d.first.pixel(76, 32);
    const double tolerance = kind == ".apng" ? 0 : 12;
    EXPECT_NEAR(left[0], 220, tolerance);
    EXPECT_NEAR(left[2], 20, tolerance);
    EXPECT_NEAR(right[0], 20, tolerance);
    EXPECT_NEAR(right[2], 220, tolerance);
  }
}

#if STRIDE_HAVE_FFMPEG
// Mean absolute difference over the red, green and blue of every pixel, in levels of 255.
double mean_difference(const RgbaImage& a, const RgbaImage& b) {
  double sum = 0;
  for (std::size_t i = 0; i < a.rgba.size(); ++i)
    if (i % 4 != 3) sum += std::abs(a.rgba[i] - b.rgba[i]);
  return sum / (static_cast<double>(a.width) * a.height * 3);
}

// The share of red, green and blue values that differ by at most `levels`.
double share_within(const RgbaImage& a, const RgbaImage& b, int levels) {
  std::size_t close = 0;
  for (std::size_t i = 0; i < a.rgba.size(); ++i)
    if (i % 4 != 3) close += std::abs(a.rgba[i] - b.rgba[i]) <= levels;
  return static_cast<double>(close) / (static_cast<double>(a.width) * a.height * 3);
}

std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// Three rendered pictures of the standing NAO (front, side, top: each unlike the others) encoded
// and decoded: every frame comes back in its place, close to what was rendered, and the same
// frames give the same bytes.
TEST(MovieFile, Mp4FramesMatchTheRenderedPicturesAndRepeatByteForByte) {
  auto scene = sim::parse_scene_file(test::source_path("scenes/nao_stand.xml"));
  sim::Simulation sim(scene);
  WorldRenderer renderer;
  std::vector<RgbaImage> rendered;
  for (const char* view : {"front", "side", "top"})
    rendered.push_back(render_view(renderer, sim, view));
  const fs::path dir = temp_dir();
  for (const char* name : {"a.mp4", "b.mp4"}) {
    MovieFile movie((dir / name).string(), rendered[0].width, rendered[0].height, 25);
    for (const RgbaImage& img : rendered) movie.add(img);
    movie.close();
  }
  const Decoded d = decode((dir / "a.mp4").string());
  EXPECT_EQ(d.codec, "h264");
  EXPECT_EQ(d.width, 640);
  EXPECT_EQ(d.height, 480);
  EXPECT_EQ(d.frames, 3);
  EXPECT_NEAR(d.seconds, 3 / 25.0, 1e-9);
  ASSERT_EQ(d.images.size(), 3u);
  // Measured (libx264, crf 23): 2.0-2.6 levels from its own picture, 32-34 from the others; 98.7 to
  // 99.5 % of channel values within 16 levels of their own picture's.
  for (std::size_t i = 0; i < 3; ++i) {
    SCOPED_TRACE("frame " + std::to_string(i));
    EXPECT_LT(mean_difference(d.images[i], rendered[i]), 4);
    EXPECT_GT(share_within(d.images[i], rendered[i], 16), 0.97);
    for (std::size_t j = 0; j < 3; ++j) {
      if (j == i) continue;
      EXPECT_GT(mean_difference(d.images[i], rendered[j]), 20);
    }
  }
  EXPECT_EQ(file_bytes((dir / "a.mp4").string()), file_bytes((dir / "b.mp4").string()));
}
#endif

TEST(MovieFile, BadSizesAndPathsAreErrorsAndLeaveNoFile) {
  const fs::path dir = temp_dir();
  for (const std::string& kind : movie_kinds()) {
    SCOPED_TRACE(kind);
    const std::string odd = (dir / ("odd" + kind)).string();
    EXPECT_EQ(error_of([&] { MovieFile(odd, 95, 64, 25); }),
              "movie '" + odd + "': expected an even width and height, got 95x64");
    EXPECT_NE(error_of([&] {
                MovieFile("/nonexistent/x" + kind, 96, 64, 25);
              }).find("movie '/nonexistent/x" + kind + "': cannot open for writing"),
              std::string::npos);
    const fs::path abandoned_path = dir / ("abandoned" + kind);
    {
      MovieFile abandoned(abandoned_path.string(), 96, 64, 25);
      abandoned.add(halves(96, 64));
      EXPECT_NE(
          error_of([&] { abandoned.add(halves(64, 64)); }).find("differs from the movie's 96x64"),
          std::string::npos);
    }
    EXPECT_FALSE(fs::exists(abandoned_path));
    EXPECT_FALSE(fs::exists(abandoned_path.string() + ".part"));
  }
  EXPECT_EQ(error_of([&] { MovieFile((dir / "x.avi").string(), 96, 64, 25); }),
            "movie '" + (dir / "x.avi").string() + "': expected a .mp4 or .apng file");
  if (!mp4_supported()) {
    EXPECT_NE(error_of([&] {
                MovieFile((dir / "x.mp4").string(), 96, 64, 25);
              }).find("MP4 needs FFmpeg's libraries, and this stride was built without them"),
              std::string::npos);
  }
}

TEST(ConsoleVideo, AMovieAndFramesOfTheSameRun) {
  console::LocalTarget target;
  std::ostringstream out;
  console::Interpreter con(target, out);
  con.execute("load " + test::source_path("scenes/nao_stand.xml"));
  const fs::path movie = temp_dir() / ("stand" + movie_kinds().back());
  fs::remove(movie);
  con.execute("video start " + movie.string() + " side fps 50");
  con.execute("run 0.1");  // 100 steps at 50 fps: 5 frames
  out.str("");
  con.execute("video stop");
  EXPECT_EQ(out.str(), "video: 5 frames\n");
  const Decoded d = decode(movie.string());
  EXPECT_EQ(d.frames, 5);
  EXPECT_EQ(d.width, 640);
  EXPECT_EQ(d.height, 480);
}

TEST(BodySide, NamesAsRobotMakersWriteThem) {
  EXPECT_EQ(side_of_link("LThigh"), BodySide::Left);
  EXPECT_EQ(side_of_link("RAnkle"), BodySide::Right);
  EXPECT_EQ(side_of_link("l_sole"), BodySide::Left);
  EXPECT_EQ(side_of_link("right_foot"), BodySide::Right);
  EXPECT_EQ(side_of_link("torso"), BodySide::Centre);
  EXPECT_EQ(side_of_link("Rotor"), BodySide::Centre);  // 'R' followed by a small letter
  EXPECT_EQ(side_of_link("Leg"), BodySide::Centre);
  // Every NAO link but the torso, neck and head is on one side, and its mirror on the other.
  const auto model = model::load_urdf(test::source_path("scenes/robots/nao/nao.urdf"));
  int left = 0, right = 0;
  for (const auto& link : model.links) {
    const BodySide s = side_of_link(link.name);
    left += s == BodySide::Left;
    right += s == BodySide::Right;
    if (s == BodySide::Left) {
      EXPECT_EQ(side_of_link("R" + link.name.substr(1)), BodySide::Right) << link.name;
    }
  }
  EXPECT_EQ(left, 11);
  EXPECT_EQ(right, 11);
}

// Seen from the front the robot's left (+y) is the picture's right: blue there, orange opposite.
// Only the robot's pixels count (those that differ from the same view without it: the sky is
// blue too).
TEST(WorldRenderer, LeftSideBlueRightSideOrange) {
  auto scene = sim::parse_scene_file(test::source_path("scenes/nao_stand.xml"));
  sim::Simulation with_robot(scene);
  scene.robots.clear();
  sim::Simulation empty(scene);
  const CameraView view = resolve_view(with_robot, "front");
  WorldRenderer renderer;
  const RgbaImage img = renderer.render(with_robot.world(), view, {});
  const RgbaImage bare = renderer.render(empty.world(), view, {});
  int blue[2] = {0, 0}, orange[2] = {0, 0};
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const std::uint8_t* p = img.pixel(x, y);
      if (std::memcmp(p, bare.pixel(x, y), 3) == 0) continue;
      const int half = x < img.width / 2 ? 0 : 1;
      blue[half] += p[2] > p[0] + 60;
      orange[half] += p[0] > p[2] + 60 && p[1] > p[2];
    }
  EXPECT_GT(blue[1], 500);
  EXPECT_GT(orange[0], 500);
  EXPECT_LT(blue[0], blue[1] / 20);
  EXPECT_LT(orange[1], orange[0] / 20);
}

TEST(TextOverlay, GlyphPixelsInsideTheTextBoxOnly) {
  RgbaImage img{200, 60, std::vector<std::uint8_t>(200 * 60 * 4, 0)};
  const TextStyle style{.scale = 2, .colour = {255, 255, 255}, .backing = {0, 0, 0, 0}};
  draw_text(img, 10, 20, "T 1.5", style);
  EXPECT_EQ(text_width("T 1.5", style), (5 * 6 - 1) * 2);
  int lit = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      if (img.pixel(x, y)[0] == 255) {
        ++lit;
        EXPECT_GE(x, 10);
        EXPECT_LT(x, 10 + text_width("T 1.5", style));
        EXPECT_GE(y, 20);
        EXPECT_LT(y, 20 + 7 * 2);
      }
  // Lit cells of the 5x7 font: T 11, space 0, 1 10, . 4, 5 17; each 2x2 pixels at scale 2.
  EXPECT_EQ(lit, (11 + 10 + 4 + 17) * 4);
}

// A line too wide for the picture at scale 2 (24 characters x 12 pixels > 200) is drawn at
// scale 1: every lit pixel is in the picture and the text ends before its right edge.
TEST(TextOverlay, ALineTooWideIsDrawnSmallerNotCutOff) {
  RgbaImage img{200, 60, std::vector<std::uint8_t>(200 * 60 * 4, 0)};
  const std::string line = "NAO: STEPS 123  FELL 1.0";
  draw_overlay(img, {line}, {.scale = 2, .colour = {255, 255, 255}, .backing = {0, 0, 0, 0}});
  int lit = 0, rightmost = 0, lowest = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      if (img.pixel(x, y)[0] == 255) ++lit, rightmost = std::max(rightmost, x), lowest = y;
  EXPECT_GT(lit, 0);
  EXPECT_LT(rightmost, 200 - 1);
  EXPECT_LT(rightmost, text_width(line, {.scale = 1}) + 10);
  EXPECT_LT(lowest, 20);  // 7 rows of glyph at scale 1 below the margin
}

TEST(TextOverlay, SnapshotsCarryTheTimeAndCanDoWithout) {
  auto scene = sim::parse_scene_file(test::source_path("scenes/nao_stand.xml"));
  sim::Simulation sim(scene);
  EXPECT_EQ(status_lines(sim, 0).at(0), "t 0.00 s");
  WorldRenderer renderer;
  const RgbaImage plain = render_view(renderer, sim, "front", 0, false);
  const RgbaImage marked = render_view(renderer, sim, "front", 0, true);
  int changed_top = 0, changed_elsewhere = 0;
  for (int y = 0; y < plain.height; ++y)
    for (int x = 0; x < plain.width; ++x) {
      const bool differs = std::memcmp(plain.pixel(x, y), marked.pixel(x, y), 3) != 0;
      (y < 60 ? changed_top : changed_elsewhere) += differs;
    }
  EXPECT_GT(changed_top, 1000);
  EXPECT_EQ(changed_elsewhere, 0);
}

}  // namespace
}  // namespace stride::render
