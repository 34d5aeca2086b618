#pragma once
// Reads a video back with the libraries that wrote it (libavformat, libavcodec, libswscale):
// the codec's name, the picture's size, the stream's frame rate, its duration, the number of
// packets (one per frame) and every frame decoded to RGB through the colour matrix and range
// the stream is tagged with, as a player converts it.

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

#include <QImage>
#include <QString>

#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace linkwright::testing {

struct VideoReadback {
  std::string codec;      ///< the decoder's name: "h264", "vp9"
  std::string container;  ///< the demuxer's names: "mov,mp4,m4a,3gp,3g2,mj2", "matroska,webm"
  int width = 0;
  int height = 0;
  double framesPerSecond = 0.0;  ///< the stream's average frame rate
  double durationSeconds = 0.0;  ///< the stream's, else the container's duration
  int packets = 0;               ///< compressed frames in the file
  std::vector<QImage> frames;    ///< Format_RGB888, decoded in presentation order
};

inline std::optional<VideoReadback> readVideo(const QString& path) {
  struct Input {
    AVFormatContext* f = nullptr;
    ~Input() { avformat_close_input(&f); }
  } input;
  if (avformat_open_input(&input.f, path.toLocal8Bit().constData(), nullptr, nullptr) < 0) return std::nullopt;
  if (avformat_find_stream_info(input.f, nullptr) < 0) return std::nullopt;
  const AVCodec* decoder = nullptr;
  const int index = av_find_best_stream(input.f, AVMEDIA_TYPE_VIDEO, -1, -1, &decoder, 0);
  if (index < 0 || decoder == nullptr) return std::nullopt;
  const AVStream* stream = input.f->streams[index];
  const auto freeCodec = [](AVCodecContext* c) { avcodec_free_context(&c); };
  const std::unique_ptr<AVCodecContext, decltype(freeCodec)> codec(avcodec_alloc_context3(decoder), freeCodec);
  if (avcodec_parameters_to_context(codec.get(), stream->codecpar) < 0 ||
      avcodec_open2(codec.get(), decoder, nullptr) < 0)
    return std::nullopt;

  VideoReadback out;
  out.codec = decoder->name;
  out.container = input.f->iformat->name;
  out.width = codec->width;
  out.height = codec->height;
  out.framesPerSecond = av_q2d(stream->avg_frame_rate);
  out.durationSeconds = stream->duration != AV_NOPTS_VALUE ? double(stream->duration) * av_q2d(stream->time_base)
                                                           : double(input.f->duration) / AV_TIME_BASE;
  const auto freeFrame = [](AVFrame* f) { av_frame_free(&f); };
  const auto freePacket = [](AVPacket* p) { av_packet_free(&p); };
  const std::unique_ptr<AVFrame, decltype(freeFrame)> frame(av_frame_alloc(), freeFrame);
  const std::unique_ptr<AVPacket, decltype(freePacket)> packet(av_packet_alloc(), freePacket);
  const auto freeScale = [](SwsContext* s) { sws_freeContext(s); };
  std::unique_ptr<SwsContext, decltype(freeScale)> scale(nullptr, freeScale);

  const auto receive = [&]() {
    while (avcodec_receive_frame(codec.get(), frame.get()) == 0) {
      if (!scale) {
        scale.reset(sws_getContext(frame->width, frame->height, AVPixelFormat(frame->format), frame->width,
                                   frame->height, AV_PIX_FMT_RGB24, SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT,
                                   nullptr, nullptr, nullptr));
        const int matrix = frame->colorspace == AVCOL_SPC_BT709 ? SWS_CS_ITU709 : SWS_CS_DEFAULT;
        sws_setColorspaceDetails(scale.get(), sws_getCoefficients(matrix), frame->color_range == AVCOL_RANGE_JPEG,
                                 sws_getCoefficients(matrix), 1, 0, 1 << 16, 1 << 16);
      }
      QImage image(frame->width, frame->height, QImage::Format_RGB888);
      uint8_t* target[1] = {image.bits()};
      const int stride[1] = {int(image.bytesPerLine())};
      sws_scale(scale.get(), frame->data, frame->linesize, 0, frame->height, target, stride);
      out.frames.push_back(image);
    }
  };
  while (av_read_frame(input.f, packet.get()) >= 0) {
    if (packet->stream_index == index) {
      ++out.packets;
      avcodec_send_packet(codec.get(), packet.get());
      receive();
    }
    av_packet_unref(packet.get());
  }
  avcodec_send_packet(codec.get(), nullptr);
  receive();
  return out;
}

/// The mean absolute difference of two images of one size, per channel (0 to 255), the
/// largest of red's, green's and blue's.
inline double meanAbsoluteDifference(const QImage& a, const QImage& b) {
  const QImage x = a.convertToFormat(QImage::Format_RGB888);
  const QImage y = b.convertToFormat(QImage::Format_RGB888);
  if (x.size() != y.size()) return 255.0;
  double sums[3] = {0.0, 0.0, 0.0};
  for (int row = 0; row < x.height(); ++row) {
    const uchar* p = x.constScanLine(row);
    const uchar* q = y.constScanLine(row);
    for (int i = 0; i < 3 * x.width(); ++i) sums[i % 3] += std::abs(int(p[i]) - int(q[i]));
  }
  const double pixels = double(x.width()) * x.height();
  return std::max({sums[0], sums[1], sums[2]}) / pixels;
}

}  // namespace linkwright::testing
