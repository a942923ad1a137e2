// SPDX-License-Identifier: MIT
// Reads a video back, frame by frame, with FFmpeg's decoders (independent of the encoder
// code under test), as RGB pictures the tests compare with what went in.
#pragma once

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

#include <QImage>

#include <stdexcept>
#include <string>
#include <vector>

namespace volpost::test {

struct DecodedVideo {
  std::string codec;       // "h264", "vp9", "mpeg4"
  double framesPerSecond = 0;
  std::vector<QImage> frames;
};

inline DecodedVideo decodeVideo(const std::string& path) {
  DecodedVideo video;
  AVFormatContext* format = nullptr;
  if (avformat_open_input(&format, path.c_str(), nullptr, nullptr) < 0) throw std::runtime_error("cannot open " + path);
  avformat_find_stream_info(format, nullptr);
  const AVCodec* codec = nullptr;
  const int index = av_find_best_stream(format, AVMEDIA_TYPE_VIDEO, -1, -1, &codec, 0);
  if (index < 0 || !codec) {
    avformat_close_input(&format);
    throw std::runtime_error("no video stream in " + path);
  }
  AVStream* stream = format->streams[index];
  video.codec = avcodec_get_name(stream->codecpar->codec_id);
  video.framesPerSecond = av_q2d(stream->avg_frame_rate);
  AVCodecContext* decoder = avcodec_alloc_context3(codec);
  avcodec_parameters_to_context(decoder, stream->codecpar);
  avcodec_open2(decoder, codec, nullptr);
  AVPacket* packet = av_packet_alloc();
  AVFrame* frame = av_frame_alloc();
  SwsContext* scaler = nullptr;
  const auto receive = [&] {
    while (avcodec_receive_frame(decoder, frame) == 0) {
      QImage picture(frame->width, frame->height, QImage::Format_RGB888);
      scaler = sws_getCachedContext(scaler, frame->width, frame->height, AVPixelFormat(frame->format), frame->width,
                                    frame->height, AV_PIX_FMT_RGB24, SWS_BICUBIC, nullptr, nullptr, nullptr);
      uint8_t* target[1] = {picture.bits()};
      const int stride[1] = {int(picture.bytesPerLine())};
      sws_scale(scaler, frame->data, frame->linesize, 0, frame->height, target, stride);
      video.frames.push_back(picture);
    }
  };
  while (av_read_frame(format, packet) >= 0) {
    if (packet->stream_index == index && avcodec_send_packet(decoder, packet) == 0) receive();
    av_packet_unref(packet);
  }
  avcodec_send_packet(decoder, nullptr);
  receive();
  sws_freeContext(scaler);
  av_frame_free(&frame);
  av_packet_free(&packet);
  avcodec_free_context(&decoder);
  avformat_close_input(&format);
  return video;
}

/// Mean absolute difference per color channel, 0..255, of two pictures of one size.
inline double meanColorDifference(const QImage& a, const QImage& b) {
  const QImage x = a.convertToFormat(QImage::Format_RGB888), y = b.convertToFormat(QImage::Format_RGB888);
  if (x.size() != y.size()) return 255;
  double sum = 0;
  for (int row = 0; row < x.height(); ++row)
    for (int i = 0; i < x.width() * 3; ++i) sum += std::abs(int(x.constScanLine(row)[i]) - int(y.constScanLine(row)[i]));
  return sum / (double(x.width()) * x.height() * 3);
}

}  // namespace volpost::test
