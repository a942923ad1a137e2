// SPDX-License-Identifier: MIT
#include "VideoFile.hpp"

#include "host/AtomicFile.hpp"

#include <QFile>
#include <QFileInfo>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/imgutils.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <cmath>
#include <optional>
#include <stdexcept>

namespace volpost::app {

namespace {

struct Container {
  const char* extension;
  const char* format;   // libavformat's muxer
  const char* encoder;  // libavcodec's encoder
};

// H.264 where players expect it, VP9 for the web's open container, MPEG-4 part 2 for the
// old .avi players. Each encoder is one Debian's libavcodec59 has.
constexpr Container kContainers[] = {
    {"mp4", "mp4", "libx264"},
    {"mkv", "matroska", "libx264"},
    {"webm", "webm", "libvpx-vp9"},
    {"avi", "avi", "mpeg4"},
};

const Container* containerOf(const QString& path) {
  const QString suffix = QFileInfo(path).suffix().toLower();
  for (const Container& c : kContainers)
    if (suffix == c.extension) return &c;
  return nullptr;
}

std::string ffmpegMessage(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, text, sizeof text);
  return text;
}

}  // namespace

struct VideoFile::Encoder {
  std::string path;  // the target, for messages
  std::optional<AtomicFile> file;
  AVFormatContext* format = nullptr;
  AVCodecContext* codec = nullptr;
  AVStream* stream = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  SwsContext* scaler = nullptr;
  bool ioOpen = false;
  int frames = 0;

  ~Encoder() {
    sws_freeContext(scaler);
    av_packet_free(&packet);
    av_frame_free(&frame);
    avcodec_free_context(&codec);
    if (format && ioOpen) avio_closep(&format->pb);
    avformat_free_context(format);
    // `file`, not committed, removes the temporary file.
  }

  [[noreturn]] void fail(const std::string& what, int code) const {
    throw WriteError(path, what + (code < 0 ? " (" + ffmpegMessage(code) + ")" : std::string()));
  }

  // Every packet the encoder has ready goes into the container.
  void drain() {
    for (;;) {
      const int got = avcodec_receive_packet(codec, packet);
      if (got == AVERROR(EAGAIN) || got == AVERROR_EOF) return;
      if (got < 0) fail("the video encoder failed", got);
      av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      const int wrote = av_interleaved_write_frame(format, packet);
      if (wrote < 0) fail("could not write the video (is the disk full?)", wrote);
    }
  }
};

bool VideoFile::isVideoPath(const QString& path) { return containerOf(path) != nullptr; }

QStringList VideoFile::extensions() {
  QStringList list;
  for (const Container& c : kContainers) list << c.extension;
  return list;
}

VideoFile::VideoFile(const QString& path, int width, int height, double framesPerSecond)
    : encoder_(std::make_unique<Encoder>()) {
  Encoder& e = *encoder_;
  e.path = QFile::encodeName(path).toStdString();
  const Container* container = containerOf(path);
  if (!container)
    throw WriteError(e.path, "videos are written as ." + extensions().join(", .").toStdString() + ", by the file's extension");
  if (width < 1 || height < 1 || width > 16384 || height > 16384)
    throw std::invalid_argument("a video frame of " + std::to_string(width) + "x" + std::to_string(height) +
                                " pixels is outside 1..16384");
  if (!std::isfinite(framesPerSecond) || framesPerSecond < 0.1 || framesPerSecond > 120)
    throw std::invalid_argument("a video rate of " + std::to_string(framesPerSecond) +
                                " frames per second is outside 0.1..120");
  av_log_set_level(AV_LOG_ERROR);  // the encoders' chatter is not the user's business

  const AVCodec* codec = avcodec_find_encoder_by_name(container->encoder);
  if (!codec) e.fail(std::string("this FFmpeg has no ") + container->encoder + " encoder for ." + container->extension, 0);
  e.file.emplace(e.path);  // throws WriteError for a missing folder or no permission
  int code = avformat_alloc_output_context2(&e.format, nullptr, container->format, e.file->temporaryPath().c_str());
  if (code < 0 || !e.format) e.fail("could not start the video container", code);
  e.stream = avformat_new_stream(e.format, nullptr);
  e.codec = avcodec_alloc_context3(codec);
  e.frame = av_frame_alloc();
  e.packet = av_packet_alloc();
  if (!e.stream || !e.codec || !e.frame || !e.packet) e.fail("out of memory for the video encoder", 0);

  // Frame times in steps of 1/rate: a rational close to the rate (25 -> 1/25, 2.5 -> 2/5).
  const AVRational rate = av_d2q(framesPerSecond, 1000);
  e.codec->time_base = av_inv_q(rate);
  e.codec->framerate = rate;
  e.codec->width = width + (width & 1);
  e.codec->height = height + (height & 1);
  e.codec->pix_fmt = AV_PIX_FMT_YUV420P;
  e.codec->gop_size = 12;
  if (e.format->oformat->flags & AVFMT_GLOBALHEADER) e.codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  // Quality over size: these are pictures of results that people will read numbers off.
  if (std::string(container->encoder) == "libx264") {
    av_opt_set(e.codec->priv_data, "crf", "18", 0);
    av_opt_set(e.codec->priv_data, "preset", "medium", 0);
  } else if (std::string(container->encoder) == "libvpx-vp9") {
    av_opt_set(e.codec->priv_data, "crf", "24", 0);
    e.codec->bit_rate = 0;
  } else {
    e.codec->flags |= AV_CODEC_FLAG_QSCALE;
    e.codec->global_quality = FF_QP2LAMBDA * 3;
  }
  code = avcodec_open2(e.codec, codec, nullptr);
  if (code < 0) e.fail(std::string("could not open the ") + container->encoder + " encoder", code);
  code = avcodec_parameters_from_context(e.stream->codecpar, e.codec);
  if (code < 0) e.fail("could not describe the video stream", code);
  e.stream->time_base = e.codec->time_base;
  e.stream->avg_frame_rate = rate;

  e.frame->format = e.codec->pix_fmt;
  e.frame->width = e.codec->width;
  e.frame->height = e.codec->height;
  code = av_frame_get_buffer(e.frame, 0);
  if (code < 0) e.fail("out of memory for a video frame", code);

  code = avio_open(&e.format->pb, e.file->temporaryPath().c_str(), AVIO_FLAG_WRITE);
  if (code < 0) e.fail("could not open the file for writing", code);
  e.ioOpen = true;
  AVDictionary* options = nullptr;
  // The index at the front: a browser or player can start before the whole file is there.
  if (std::string(container->format) == "mp4") av_dict_set(&options, "movflags", "+faststart", 0);
  code = avformat_write_header(e.format, &options);
  av_dict_free(&options);
  if (code < 0) e.fail("could not write the video header", code);
}

VideoFile::~VideoFile() = default;

int VideoFile::width() const { return encoder_->codec->width; }
int VideoFile::height() const { return encoder_->codec->height; }
int VideoFile::frameCount() const { return encoder_->frames; }

void VideoFile::add(const QImage& picture) {
  Encoder& e = *encoder_;
  if (picture.isNull()) e.fail("an empty picture cannot be a video frame", 0);
  const QImage rgb = picture.convertToFormat(QImage::Format_RGB888);
  e.scaler = sws_getCachedContext(e.scaler, rgb.width(), rgb.height(), AV_PIX_FMT_RGB24, e.codec->width,
                                  e.codec->height, e.codec->pix_fmt, SWS_BICUBIC, nullptr, nullptr, nullptr);
  if (!e.scaler) e.fail("could not convert a picture to the video's colors", 0);
  int code = av_frame_make_writable(e.frame);
  if (code < 0) e.fail("out of memory for a video frame", code);
  const uint8_t* source[1] = {rgb.constBits()};
  const int stride[1] = {int(rgb.bytesPerLine())};
  sws_scale(e.scaler, source, stride, 0, rgb.height(), e.frame->data, e.frame->linesize);
  e.frame->pts = e.frames;
  code = avcodec_send_frame(e.codec, e.frame);
  if (code < 0) e.fail("the video encoder refused a frame", code);
  ++e.frames;
  e.drain();
}

void VideoFile::finish() {
  Encoder& e = *encoder_;
  if (e.frames == 0) e.fail("a video needs at least one frame", 0);
  int code = avcodec_send_frame(e.codec, nullptr);  // end of stream: the encoder gives back what it holds
  if (code < 0) e.fail("the video encoder failed at the end", code);
  e.drain();
  code = av_write_trailer(e.format);
  if (code < 0) e.fail("could not write the end of the video (is the disk full?)", code);
  code = avio_closep(&e.format->pb);
  e.ioOpen = false;
  if (code < 0) e.fail("could not close the video file (is the disk full?)", code);
  e.file->commit();
}

}  // namespace volpost::app
