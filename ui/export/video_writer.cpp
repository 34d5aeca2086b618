#include "ui/export/video_writer.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/error.h>
#include <libavutil/log.h>
#include <libavutil/opt.h>
#include <libavutil/rational.h>
#include <libswscale/swscale.h>
}

#include <cmath>

namespace linkwright::ui {

namespace {

// FFmpeg's objects are freed by functions that take the pointer's address; each owner here
// frees one kind whatever path the export takes (a failure, a cancel, an exception).
struct CodecFree {
  void operator()(AVCodecContext* c) const { avcodec_free_context(&c); }
};
struct FrameFree {
  void operator()(AVFrame* f) const { av_frame_free(&f); }
};
struct PacketFree {
  void operator()(AVPacket* p) const { av_packet_free(&p); }
};
struct ScaleFree {
  void operator()(SwsContext* s) const { sws_freeContext(s); }
};
// The output context and the file it opened: closing the file first, as avformat_free_context
// does not.
struct OutputFree {
  void operator()(AVFormatContext* f) const {
    if (f->pb != nullptr && (f->oformat->flags & AVFMT_NOFILE) == 0) avio_closep(&f->pb);
    avformat_free_context(f);
  }
};
// A dictionary of options, which FFmpeg's calls take by address and may replace.
struct Dictionary {
  AVDictionary* entries = nullptr;
  Dictionary() = default;
  ~Dictionary() { av_dict_free(&entries); }
  Dictionary(const Dictionary&) = delete;
  Dictionary& operator=(const Dictionary&) = delete;
};

std::string averrorText(int averror) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  if (av_strerror(averror, text, sizeof text) < 0) return "FFmpeg error " + std::to_string(averror);
  return text;
}

const char* muxerName(VideoCodec codec) { return codec == VideoCodec::H264Mp4 ? "mp4" : "webm"; }

const char* formatName(VideoCodec codec) { return codec == VideoCodec::H264Mp4 ? "MP4 (H.264)" : "WebM (VP9)"; }

}  // namespace

const char* encoderName(VideoCodec codec) { return codec == VideoCodec::H264Mp4 ? "libx264" : "libvpx-vp9"; }

bool needsEvenSides(VideoCodec codec) { return codec == VideoCodec::H264Mp4; }

std::optional<std::string> encoderMissing(VideoCodec codec) {
  if (avcodec_find_encoder_by_name(encoderName(codec)) != nullptr) return std::nullopt;
  return std::string(formatName(codec)) + " needs FFmpeg's " + encoderName(codec) +
         " encoder, which this system's libavcodec was built without (Debian's has it)";
}

struct VideoWriter::Handles {
  std::unique_ptr<AVFormatContext, OutputFree> output;
  std::unique_ptr<AVCodecContext, CodecFree> codec;
  std::unique_ptr<AVFrame, FrameFree> frame;
  std::unique_ptr<AVPacket, PacketFree> packet;
  std::unique_ptr<SwsContext, ScaleFree> scale;
  AVStream* stream = nullptr;  // owned by `output`
};

VideoWriter::VideoWriter(const std::string& path, const VideoOptions& options)
    : m_options(options), m_av(std::make_unique<Handles>()) {
  const bool even = !needsEvenSides(options.codec) || (options.width % 2 == 0 && options.height % 2 == 0);
  if (options.width <= 0 || options.height <= 0 || options.width > 16384 || options.height > 16384 || !even) {
    m_error = std::string("the image size must be ") + (needsEvenSides(options.codec) ? "even, " : "") +
              "1 to 16384 pixels each way (got " + std::to_string(options.width) + " × " +
              std::to_string(options.height) + ")";
    return;
  }
  if (!std::isfinite(options.framesPerSecond) || options.framesPerSecond <= 0.0 || options.framesPerSecond > 1000.0) {
    m_error = "the frame rate must be above 0 and at most 1000 frames per second";
    return;
  }
  // FFmpeg's log is process-wide; errors only, so that libx264's statistics and the muxer's
  // notes do not reach the terminal of `linkwright --animation` (what fails is said in error()).
  av_log_set_level(AV_LOG_ERROR);
  if (auto missing = encoderMissing(options.codec)) {
    m_error = *missing;
    return;
  }
  open(path);
}

VideoWriter::~VideoWriter() = default;

// `what` may be empty where FFmpeg's reason says it all: a write that failed ("File too large",
// "No space left on device"), which the one writer prefixes with "Cannot write FILE".
bool VideoWriter::fail(const std::string& what, int averror) {
  if (!m_error.empty()) return false;
  const std::string why = averror < 0 ? averrorText(averror) : std::string();
  m_error = what.empty() ? why : why.empty() ? what : what + ": " + why;
  return false;
}

bool VideoWriter::open(const std::string& path) {
  const AVCodec* encoder = avcodec_find_encoder_by_name(encoderName(m_options.codec));
  AVFormatContext* output = nullptr;
  int status = avformat_alloc_output_context2(&output, nullptr, muxerName(m_options.codec), path.c_str());
  if (output == nullptr) return fail("cannot start the file", status);
  m_av->output.reset(output);
  m_av->codec.reset(avcodec_alloc_context3(encoder));
  m_av->frame.reset(av_frame_alloc());
  m_av->packet.reset(av_packet_alloc());
  if (!m_av->codec || !m_av->frame || !m_av->packet) return fail("out of memory", 0);

  // 29.97 becomes 2997/100, 25 becomes 25/1: one tick of the time base per frame.
  const AVRational rate = av_d2q(m_options.framesPerSecond, 100000);
  AVCodecContext* c = m_av->codec.get();
  c->width = m_options.width;
  c->height = m_options.height;
  c->pix_fmt = AV_PIX_FMT_YUV420P;
  c->time_base = av_inv_q(rate);
  c->framerate = rate;
  c->color_range = AVCOL_RANGE_MPEG;
  c->colorspace = AVCOL_SPC_BT709;
  c->color_primaries = AVCOL_PRI_BT709;
  c->color_trc = AVCOL_TRC_BT709;
  if (m_options.codec == VideoCodec::H264Mp4) {
    av_opt_set(c->priv_data, "preset", "medium", 0);
    av_opt_set(c->priv_data, "crf", "18", 0);  // visually lossless on flat colours and thin lines
  } else {
    c->bit_rate = 0;  // with a CRF: constant quality, no bit-rate target
    av_opt_set(c->priv_data, "crf", "30", 0);
    av_opt_set(c->priv_data, "deadline", "good", 0);
    av_opt_set(c->priv_data, "cpu-used", "4", 0);
    av_opt_set(c->priv_data, "row-mt", "1", 0);
  }
  if ((m_av->output->oformat->flags & AVFMT_GLOBALHEADER) != 0) c->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  if ((status = avcodec_open2(c, encoder, nullptr)) < 0)
    return fail(std::string("cannot start the ") + encoderName(m_options.codec) + " encoder", status);

  m_av->stream = avformat_new_stream(m_av->output.get(), nullptr);
  if (m_av->stream == nullptr) return fail("out of memory", 0);
  m_av->stream->time_base = c->time_base;
  m_av->stream->avg_frame_rate = rate;
  if ((status = avcodec_parameters_from_context(m_av->stream->codecpar, c)) < 0)
    return fail("cannot describe the stream", status);

  AVFrame* f = m_av->frame.get();
  f->format = c->pix_fmt;
  f->width = c->width;
  f->height = c->height;
  if ((status = av_frame_get_buffer(f, 0)) < 0) return fail("cannot make a frame", status);
  m_av->scale.reset(sws_getContext(c->width, c->height, AV_PIX_FMT_RGB24, c->width, c->height, AV_PIX_FMT_YUV420P,
                                   SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT, nullptr, nullptr, nullptr));
  if (!m_av->scale) return fail("cannot convert RGB to YUV at this size", 0);
  // Full-range RGB in, limited-range BT.709 YUV out, as the stream is tagged.
  const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
  sws_setColorspaceDetails(m_av->scale.get(), bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);

  if ((status = avio_open(&m_av->output->pb, path.c_str(), AVIO_FLAG_WRITE)) < 0)
    return fail("cannot open the file", status);
  Dictionary muxerOptions;
  // The index first, so a browser or a slide program can start playing before it has it all
  // (the muxer moves it there at the end, reading the file back by its path).
  if (m_options.codec == VideoCodec::H264Mp4) av_dict_set(&muxerOptions.entries, "movflags", "+faststart", 0);
  if ((status = avformat_write_header(m_av->output.get(), &muxerOptions.entries)) < 0)
    return fail("cannot write the file's header", status);
  return true;
}

// Sends one frame (or, with `flush`, the end of the stream) and writes every packet it yields.
bool VideoWriter::send(bool flush) {
  AVCodecContext* c = m_av->codec.get();
  int status = avcodec_send_frame(c, flush ? nullptr : m_av->frame.get());
  if (status < 0) return fail("cannot encode frame " + std::to_string(m_frames + 1), status);
  AVPacket* packet = m_av->packet.get();
  while ((status = avcodec_receive_packet(c, packet)) == 0) {
    if (packet->duration == 0) packet->duration = 1;  // one frame, in the encoder's time base
    av_packet_rescale_ts(packet, c->time_base, m_av->stream->time_base);
    packet->stream_index = m_av->stream->index;
    // Takes the packet's data and leaves it blank for the next.
    if ((status = av_interleaved_write_frame(m_av->output.get(), packet)) < 0) return fail({}, status);
  }
  if (status != AVERROR(EAGAIN) && status != AVERROR_EOF) return fail("cannot encode", status);
  return true;
}

bool VideoWriter::addFrame(const std::vector<std::uint8_t>& rgb) {
  if (!m_error.empty() || !m_av->scale) return false;
  const auto bytes = 3 * static_cast<std::size_t>(m_options.width) * static_cast<std::size_t>(m_options.height);
  if (rgb.size() != bytes) {
    m_error = "frame " + std::to_string(m_frames + 1) + " has " + std::to_string(rgb.size()) + " bytes, not " +
              std::to_string(bytes);
    return false;
  }
  AVFrame* f = m_av->frame.get();
  // The encoder may still hold the previous frame's buffers.
  if (const int status = av_frame_make_writable(f); status < 0) return fail("cannot make a frame", status);
  const std::uint8_t* source[1] = {rgb.data()};
  const int stride[1] = {3 * m_options.width};
  sws_scale(m_av->scale.get(), source, stride, 0, m_options.height, f->data, f->linesize);
  f->pts = m_frames;
  if (!send(false)) return false;
  ++m_frames;
  return true;
}

bool VideoWriter::finish() {
  if (!m_error.empty() || !m_av->scale) return false;
  if (m_frames == 0) {
    m_error = "the animation has no frames";
    return false;
  }
  if (!send(true)) return false;
  AVFormatContext* output = m_av->output.get();
  if (const int status = av_write_trailer(output); status < 0) return fail({}, status);
  // A write that failed part-way (a full disk) may only show in the I/O context's error.
  if (output->pb->error < 0) return fail({}, output->pb->error);
  if (const int status = avio_closep(&output->pb); status < 0) return fail({}, status);
  return true;
}

}  // namespace linkwright::ui
