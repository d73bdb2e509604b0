// MP4 through FFmpeg's libraries: built only where CMake found them (STRIDE_HAVE_FFMPEG).
#include "simulator/render/movie_encoders.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/imgutils.h>
#include <libavutil/log.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <cmath>
#include <cstdio>

#include "robot/core/error.hpp"

namespace stride::render {

namespace {

struct Mp4Encoder final : MovieFile::Encoder {
  std::string part;
  int width = 0, height = 0;
  std::string codec_name;
  AVFormatContext* format = nullptr;
  AVCodecContext* context = nullptr;
  AVStream* stream = nullptr;
  SwsContext* scale = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  long long frames = 0;
  bool header_written = false, closed = false;

  [[noreturn]] void fail(const std::string& what, int code = 0) const {
    std::string why = what;
    if (code < 0) {
      char text[AV_ERROR_MAX_STRING_SIZE] = {};
      av_strerror(code, text, sizeof text);
      why += std::string(": ") + text;
    }
    throw Error(why);
  }

  ~Mp4Encoder() override {
    if (format && header_written && !closed) av_write_trailer(format);
    if (format && format->pb) avio_closep(&format->pb);
    avformat_free_context(format);
    avcodec_free_context(&context);
    sws_freeContext(scale);
    av_frame_free(&frame);
    av_packet_free(&packet);
  }

  // Sends one frame (or nullptr: flush) and writes every packet the encoder has ready.
  void encode(AVFrame* f) {
    int rc = avcodec_send_frame(context, f);
    if (rc < 0) fail("encoding a frame", rc);
    while ((rc = avcodec_receive_packet(context, packet)) >= 0) {
      // Every frame lasts one frame period; without it the MP4's edit list drops the last one.
      if (packet->duration == 0) packet->duration = 1;
      av_packet_rescale_ts(packet, context->time_base, stream->time_base);
      packet->stream_index = stream->index;
      rc = av_interleaved_write_frame(format, packet);
      if (rc < 0) fail("writing", rc);
    }
    if (rc != AVERROR(EAGAIN) && rc != AVERROR_EOF) fail("encoding", rc);
  }

  void add(const RgbaImage& image) override;
  void finish() override;
  std::string codec() const override { return codec_name; }
};

// H.264 plays everywhere; Debian's libavcodec has it through libx264. MPEG-4 Part 2 is built in.
const AVCodec* pick_encoder() {
  av_log_set_level(AV_LOG_ERROR);  // libx264's statistics are not the user's business
  if (const AVCodec* c = avcodec_find_encoder_by_name("libx264")) return c;
  return avcodec_find_encoder(AV_CODEC_ID_MPEG4);
}

}  // namespace

std::unique_ptr<MovieFile::Encoder> open_mp4(const std::string& part, int width, int height,
                                             double fps) {
  auto encoder = std::make_unique<Mp4Encoder>();
  Mp4Encoder& e = *encoder;
  e.width = width;
  e.height = height;
  const AVCodec* codec = pick_encoder();
  if (!codec) e.fail("this FFmpeg has neither an H.264 nor an MPEG-4 encoder");
  e.codec_name = codec->id == AV_CODEC_ID_H264 ? "h264" : "mpeg4";
  e.part = part;
  int rc = avformat_alloc_output_context2(&e.format, nullptr, "mp4", e.part.c_str());
  if (rc < 0 || !e.format) e.fail("no MP4 muxer", rc);
  e.context = avcodec_alloc_context3(codec);
  e.stream = avformat_new_stream(e.format, nullptr);
  e.frame = av_frame_alloc();
  e.packet = av_packet_alloc();
  if (!e.context || !e.stream || !e.frame || !e.packet) e.fail("out of memory");
  // Whole frames per second as a rational: 25 -> 1/25; 29.97 -> 100/2997.
  const AVRational rate = av_d2q(fps, 100000);
  e.context->width = width;
  e.context->height = height;
  e.context->time_base = av_inv_q(rate);
  e.context->framerate = rate;
  e.context->pix_fmt = AV_PIX_FMT_YUV420P;
  e.context->gop_size = 50;
  e.context->thread_count = 1;  // one thread: the same bytes on every machine
  if (e.format->oformat->flags & AVFMT_GLOBALHEADER)
    e.context->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  // A key frame every 50 frames (2 s at 25 frames/s) and nowhere else: no scene-cut detection, so
  // seeking and file sizes do not depend on what the picture shows.
  e.context->keyint_min = e.context->gop_size;
  if (e.codec_name == "h264") {
    av_opt_set(e.context->priv_data, "preset", "veryfast", 0);
    av_opt_set(e.context->priv_data, "crf", "23", 0);
    av_opt_set(e.context->priv_data, "x264-params", "scenecut=0", 0);
  } else {
    e.context->bit_rate = 4'000'000;
    av_opt_set_int(e.context->priv_data, "sc_threshold", 1'000'000'000, 0);
  }
  rc = avcodec_open2(e.context, codec, nullptr);
  if (rc < 0) e.fail("cannot open the " + e.codec_name + " encoder", rc);
  rc = avcodec_parameters_from_context(e.stream->codecpar, e.context);
  if (rc < 0) e.fail("stream parameters", rc);
  e.stream->time_base = e.context->time_base;
  rc = avio_open(&e.format->pb, e.part.c_str(), AVIO_FLAG_WRITE);
  if (rc < 0) e.fail("cannot open for writing", rc);
  rc = avformat_write_header(e.format, nullptr);
  if (rc < 0) e.fail("cannot write the MP4 header", rc);
  e.header_written = true;
  e.frame->format = AV_PIX_FMT_YUV420P;
  e.frame->width = width;
  e.frame->height = height;
  rc = av_frame_get_buffer(e.frame, 0);
  if (rc < 0) e.fail("frame buffer", rc);
  e.scale = sws_getContext(width, height, AV_PIX_FMT_RGBA, width, height, AV_PIX_FMT_YUV420P,
                           SWS_BILINEAR, nullptr, nullptr, nullptr);
  if (!e.scale) e.fail("no RGBA to YUV conversion");
  return encoder;
}

void Mp4Encoder::add(const RgbaImage& image) {
  Mp4Encoder& e = *this;
  const int rc = av_frame_make_writable(e.frame);
  if (rc < 0) e.fail("frame buffer", rc);
  const std::uint8_t* source[1] = {image.rgba.data()};
  const int stride[1] = {image.width * 4};
  sws_scale(e.scale, source, stride, 0, image.height, e.frame->data, e.frame->linesize);
  e.frame->pts = e.frames++;
  e.encode(e.frame);
}

void Mp4Encoder::finish() {
  Mp4Encoder& e = *this;
  e.encode(nullptr);
  int rc = av_write_trailer(e.format);
  if (rc < 0) e.fail("cannot write the MP4 index", rc);
  rc = avio_closep(&e.format->pb);
  if (rc < 0) e.fail("closing", rc);
  e.closed = true;
}

}  // namespace stride::render
