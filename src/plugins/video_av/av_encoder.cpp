#include "plugins/video_av/av_encoder.h"

#include <climits>
#include <cstring>
#include <stdexcept>

#include "io/palette.h"
#include "io/video_codecs.h"
#include "io/video_encoder.h"
#include "plugins/video_av/av_codecs.h"
#include "plugins/video_av/encoded_audio.h"
#include "plugins/video_av/video_av.h"
#include "plugins/video_av/video_sink.h"

namespace sdfreel {
namespace {

AVRational checked_fps(const Rational& fps) {
  if (fps.num <= 0 || fps.den <= 0 || fps.num > INT_MAX || fps.den > INT_MAX)
    throw std::runtime_error("video: frame rate " + std::to_string(fps.num) + "/" +
                             std::to_string(fps.den) + " is not a positive fraction of ints");
  AVRational r{int(fps.num), int(fps.den)};
  av_reduce(&r.num, &r.den, r.num, r.den, INT_MAX);
  return r;
}

const VideoCodecSpec& checked_codec(const VideoSettings& s) {
  const VideoCodecSpec* spec = find_video_codec(s.codec);
  if (!spec)
    throw std::runtime_error("video: unknown codec '" + s.codec +
                             "' (known: " + known_video_codecs() + ")");
  if (s.width <= 0 || s.height <= 0)
    throw std::runtime_error("video: invalid size " + std::to_string(s.width) + "x" +
                             std::to_string(s.height));
  if (spec->even_size && (s.width % 2 || s.height % 2))
    throw std::runtime_error("video: " + s.codec + " needs an even width and height, got " +
                             std::to_string(s.width) + "x" + std::to_string(s.height));
  return *spec;
}

// The mov muxer (mp4, mov) moves its index to the front so players can start before the end.
bool is_mov_family(const AVOutputFormat* f) {
  return std::strcmp(f->name, "mp4") == 0 || std::strcmp(f->name, "mov") == 0;
}

}  // namespace

class AvEncoder final : public EncoderSession {
 public:
  VideoSettings settings;
  const VideoCodecSpec& spec;
  // Declared before the libav objects, so the file outlives the muxer that writes into it.
  std::unique_ptr<VideoFileSink> sink;
  AvOutputContextPtr format;
  AvCodecContextPtr encoder;
  AVStream* stream = nullptr;  // owned by format
  AVStream* audio_stream = nullptr;
  size_t audio_written = 0;  // settings.audio's packets already muxed
  SwsContextPtr converter;
  AvFramePtr frame;
  AvPacketPtr packet;
  int64_t next_pts = 0;
  bool finished = false;

  explicit AvEncoder(const VideoSettings& s) : settings(s), spec(checked_codec(s)) {
    const AVRational fps = checked_fps(s.fps);
    // Chosen from the final name: the temporary one (".NAME.tmp-HOST-PID-N") has no extension.
    const AVOutputFormat* container = av_guess_format(nullptr, s.path.c_str(), nullptr);
    if (!container)
      throw std::runtime_error("video: cannot tell the container from the file name " + s.path +
                               " (use .mp4, .mkv, .mov, .webm, .webp or .gif)");
    const AVCodec* codec = avcodec_find_encoder_by_name(spec.encoder);
    if (!codec)
      throw std::runtime_error(std::string("video: this libav has no encoder ") + spec.encoder);
    if (avformat_query_codec(container, codec->id, FF_COMPLIANCE_NORMAL) == 0)
      throw std::runtime_error("video: the " + std::string(container->name) + " container of " +
                               s.path + " cannot hold " + s.codec);

    open_encoder(codec, container, fps);
    open_converter();
    open_output(container);
  }

  void open_encoder(const AVCodec* codec, const AVOutputFormat* container, AVRational fps) {
    encoder.reset(avcodec_alloc_context3(codec));
    if (!encoder) throw std::runtime_error("video: out of memory");
    configure_video_codec(spec, encoder.get(), settings.width, settings.height, fps, settings.crf);
    if (container->flags & AVFMT_GLOBALHEADER) encoder->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    av_check(avcodec_open2(encoder.get(), codec, nullptr),
             std::string("opening encoder ") + spec.encoder);

    frame.reset(av_frame_alloc());
    packet.reset(av_packet_alloc());
    if (!frame || !packet) throw std::runtime_error("video: out of memory");
    frame->format = encoder->pix_fmt;
    frame->width = encoder->width;
    frame->height = encoder->height;
    frame->color_primaries = encoder->color_primaries;
    frame->color_trc = encoder->color_trc;
    frame->colorspace = encoder->colorspace;
    frame->color_range = encoder->color_range;
    av_check(av_frame_get_buffer(frame.get(), 0), "allocating a frame");
  }

  // Packed 16-bit RGB (full range; native byte order, as the uint16 vector holds it) to the
  // encoder's format. Same size: the scaler flag only picks
  // the chroma filter. BITEXACT keeps SIMD and C paths identical across machines.
  void open_converter() {
    if (spec.pix_fmt == AV_PIX_FMT_PAL8) return;  // median_cut_palette instead
    const int w = settings.width, h = settings.height;
    converter.reset(sws_getContext(w, h, AV_PIX_FMT_RGB48, w, h, spec.pix_fmt,
                                   SWS_BICUBIC | SWS_ACCURATE_RND | SWS_BITEXACT, nullptr, nullptr,
                                   nullptr));
    if (!converter)
      throw std::runtime_error("video: swscale cannot convert rgb48 for " + settings.codec);
    if (spec.yuv) {
      // swscale's default matrix is BT.601 (red would come back as (255,23,0)); the tags alone
      // do not change the pixels.
      const int* matrix = sws_getCoefficients(spec.bt601 ? SWS_CS_ITU601 : SWS_CS_ITU709);
      av_check(sws_setColorspaceDetails(converter.get(), matrix, /*srcRange=*/1, matrix,
                                        /*dstRange=*/0, 0, 1 << 16, 1 << 16),
               "setting the Y'CbCr matrix");
    }
  }

  void open_output(const AVOutputFormat* container) {
    sink = std::make_unique<VideoFileSink>(settings.path);
    const std::string& temp_name = sink->temp_path();
    AVFormatContext* raw = nullptr;
    av_check(avformat_alloc_output_context2(&raw, container, nullptr, temp_name.c_str()),
             "creating the " + std::string(container->name) + " container");
    format.reset(raw);
    format->flags |= AVFMT_FLAG_BITEXACT;  // no muxer version string, no random UIDs

    stream = avformat_new_stream(format.get(), nullptr);
    if (!stream) throw std::runtime_error("video: out of memory");
    av_check(avcodec_parameters_from_context(stream->codecpar, encoder.get()),
             "copying encoder parameters");
    // HEVC in MP4 and MOV as hvc1 (parameter sets in the header): what Apple's players take.
    if (encoder->codec_id == AV_CODEC_ID_HEVC && is_mov_family(container))
      stream->codecpar->codec_tag = MKTAG('h', 'v', 'c', '1');
    stream->time_base = encoder->time_base;  // a hint; the muxer may pick its own
    stream->avg_frame_rate = encoder->framerate;

    if (settings.audio) {
      audio_stream = avformat_new_stream(format.get(), nullptr);
      if (!audio_stream) throw std::runtime_error("video: out of memory");
      av_check(avcodec_parameters_copy(audio_stream->codecpar, settings.audio->params),
               "copying audio parameters");
      audio_stream->time_base = settings.audio->time_base;
    }

    format->pb = sink->avio();
    format->flags |= AVFMT_FLAG_CUSTOM_IO;
    AVDictionary* options = nullptr;
    if (is_mov_family(container)) av_dict_set(&options, "movflags", "+faststart", 0);
    if (std::strcmp(container->name, "webp") == 0)
      av_dict_set(&options, "loop", "0", 0);  // forever
    const int ret = avformat_write_header(format.get(), &options);
    av_dict_free(&options);
    av_check(ret, "writing the header of " + settings.path);
  }

  // Muxes the soundtrack's packets that start before `dts` (in `tb`; all of them for INT64_MAX),
  // so the file interleaves audio and video in time order as they arrive.
  void write_audio_until(int64_t dts, AVRational tb) {
    if (!settings.audio) return;
    const auto& packets = settings.audio->packets;
    for (; audio_written < packets.size(); ++audio_written) {
      const AVPacket& p = *packets[audio_written];
      if (dts != INT64_MAX && av_compare_ts(p.pts, settings.audio->time_base, dts, tb) > 0) return;
      AvPacketPtr copy(av_packet_clone(&p));
      if (!copy) throw std::runtime_error("video: out of memory");
      av_packet_rescale_ts(copy.get(), settings.audio->time_base, audio_stream->time_base);
      copy->stream_index = audio_stream->index;
      av_check(av_interleaved_write_frame(format.get(), copy.get()), "writing the audio");
    }
  }

  // Sends one frame (nullptr: flush) and writes every packet the encoder has ready.
  void encode(const AVFrame* f) {
    av_check(avcodec_send_frame(encoder.get(), f), "encoding a frame");
    for (;;) {
      const int ret = avcodec_receive_packet(encoder.get(), packet.get());
      if (ret == AVERROR(EAGAIN) || ret == AVERROR_EOF) return;
      av_check(ret, "encoding a frame");
      av_packet_rescale_ts(packet.get(), encoder->time_base, stream->time_base);
      packet->stream_index = stream->index;
      write_audio_until(packet->dts, stream->time_base);
      // Takes the packet's data and leaves it blank, so nothing accumulates per frame.
      av_check(av_interleaved_write_frame(format.get(), packet.get()), "writing a packet");
    }
  }

  void add_frame(const ImageRGB16& display) override {
    if (finished) throw std::runtime_error("video: add_frame after finish");
    if (display.width != settings.width || display.height != settings.height ||
        display.pixels.size() != size_t(display.width) * display.height * 3)
      throw std::runtime_error("video: frame is " + std::to_string(display.width) + "x" +
                               std::to_string(display.height) + ", the video is " +
                               std::to_string(settings.width) + "x" +
                               std::to_string(settings.height));
    // The encoder may still hold the previous buffer; this gives a fresh one only if so.
    av_check(av_frame_make_writable(frame.get()), "allocating a frame");
    if (spec.pix_fmt == AV_PIX_FMT_PAL8) {
      const PalettedImage paletted = median_cut_palette(display);
      for (int y = 0; y < display.height; ++y)
        std::memcpy(frame->data[0] + size_t(y) * size_t(frame->linesize[0]),
                    paletted.indices.data() + size_t(y) * size_t(display.width),
                    size_t(display.width));
      std::memcpy(frame->data[1], paletted.palette.data(), 256 * 4);
    } else {
      const uint8_t* src[1] = {reinterpret_cast<const uint8_t*>(display.pixels.data())};
      const int src_stride[1] = {display.width * 6};
      sws_scale(converter.get(), src, src_stride, 0, display.height, frame->data, frame->linesize);
    }
    frame->pts = next_pts++;
    encode(frame.get());
  }

  void finish() override {
    if (finished) return;
    encode(nullptr);
    write_audio_until(INT64_MAX, AVRational{1, 1});
    av_check(av_write_trailer(format.get()), "finishing " + settings.path);
    sink->commit();
    finished = true;
  }
};

std::unique_ptr<EncoderSession> open_av_encoder(const VideoSettings& s) {
  // libav prints encoder banners and statistics at its default level (info); stderr belongs to
  // the progress display, so keep only warnings and errors unless someone chose a level.
  if (av_log_get_level() == AV_LOG_INFO) av_log_set_level(AV_LOG_WARNING);
  return std::make_unique<AvEncoder>(s);
}

}  // namespace sdfreel
