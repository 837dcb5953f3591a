#include "plugins/video_av/audio_source.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "plugins/video_av/video_av.h"

extern "C" {
#include <libswresample/swresample.h>
}

namespace sdfreel {
namespace {

struct InputFree {
  void operator()(AVFormatContext* c) const { avformat_close_input(&c); }
};
struct SwrFree {
  void operator()(SwrContext* c) const { swr_free(&c); }
};

}  // namespace

struct AudioSource::Impl {
  std::string path;
  std::unique_ptr<AVFormatContext, InputFree> input;
  AvCodecContextPtr decoder;
  std::unique_ptr<SwrContext, SwrFree> resampler;
  AvPacketPtr packet{av_packet_alloc()};
  AvFramePtr frame{av_frame_alloc()};
  int stream = -1;
  std::vector<float> pending;  // converted samples not yet handed out (interleaved stereo)
  size_t skip = 0;             // frames still to drop to reach the start time
  bool decoder_flushed = false, resampler_flushed = false;

  [[noreturn]] void fail(const std::string& what, int ret = 0) const {
    throw std::runtime_error(path + ": " + what + (ret < 0 ? ": " + av_error_text(ret) : ""));
  }

  Impl(const std::string& p, double start) : path(p) {
    if (!packet || !frame) fail("out of memory");
    AVFormatContext* raw = nullptr;
    if (int ret = avformat_open_input(&raw, path.c_str(), nullptr, nullptr); ret < 0)
      fail("cannot open it", ret);
    input.reset(raw);
    if (int ret = avformat_find_stream_info(input.get(), nullptr); ret < 0)
      fail("cannot read it as audio", ret);
    const AVCodec* codec = nullptr;
    stream = av_find_best_stream(input.get(), AVMEDIA_TYPE_AUDIO, -1, -1, &codec, 0);
    if (stream < 0 || !codec) fail("it holds no audio stream libav decodes");
    decoder.reset(avcodec_alloc_context3(codec));
    if (!decoder) fail("out of memory");
    avcodec_parameters_to_context(decoder.get(), input->streams[stream]->codecpar);
    if (int ret = avcodec_open2(decoder.get(), codec, nullptr); ret < 0)
      fail("cannot open its decoder", ret);
    AVChannelLayout stereo;
    av_channel_layout_default(&stereo, 2);
    SwrContext* swr = nullptr;
    if (int ret = swr_alloc_set_opts2(&swr, &stereo, AV_SAMPLE_FMT_FLT, kSoundtrackRate,
                                      &decoder->ch_layout, decoder->sample_fmt,
                                      decoder->sample_rate, 0, nullptr);
        ret < 0 || swr_init(swr) < 0) {
      swr_free(&swr);
      fail("cannot convert its samples to 48 kHz stereo");
    }
    resampler.reset(swr);
    skip = size_t(std::llround(start * kSoundtrackRate));
  }

  // Converts `in` (nullptr: the resampler's remainder) onto `pending`.
  void convert(const AVFrame* in) {
    const int capacity = swr_get_out_samples(resampler.get(), in ? in->nb_samples : 0);
    if (capacity <= 0) return;
    const size_t at = pending.size();
    pending.resize(at + size_t(capacity) * 2);
    uint8_t* out[1] = {reinterpret_cast<uint8_t*>(pending.data() + at)};
    const int got = swr_convert(resampler.get(), out, capacity,
                                in ? const_cast<const uint8_t**>(in->extended_data) : nullptr,
                                in ? in->nb_samples : 0);
    if (got < 0) fail("resampling failed", got);
    pending.resize(at + size_t(got) * 2);
  }

  // Decodes more of the file onto `pending`; false at the very end.
  bool decode_more() {
    for (;;) {
      const int ret = avcodec_receive_frame(decoder.get(), frame.get());
      if (ret == 0) {
        convert(frame.get());
        av_frame_unref(frame.get());
        return true;
      }
      if (ret == AVERROR_EOF) {
        if (resampler_flushed) return false;
        convert(nullptr);
        resampler_flushed = true;
        return true;
      }
      if (ret != AVERROR(EAGAIN)) fail("cannot decode it", ret);
      if (decoder_flushed) return false;
      const int read = av_read_frame(input.get(), packet.get());
      if (read == AVERROR_EOF) {
        avcodec_send_packet(decoder.get(), nullptr);
        decoder_flushed = true;
        continue;
      }
      if (read < 0) fail("cannot read it", read);
      if (packet->stream_index == stream) {
        const int sent = avcodec_send_packet(decoder.get(), packet.get());
        if (sent < 0 && sent != AVERROR(EAGAIN)) fail("cannot decode it", sent);
      }
      av_packet_unref(packet.get());
    }
  }

  size_t read(std::vector<float>& out, size_t max_frames) {
    for (;;) {
      const size_t have = pending.size() / 2;
      if (skip && have) {
        const size_t dropped = std::min(skip, have);
        pending.erase(pending.begin(), pending.begin() + std::ptrdiff_t(dropped * 2));
        skip -= dropped;
        continue;
      }
      if (!skip && have >= max_frames) break;
      if (!decode_more()) break;
    }
    const size_t frames = skip ? 0 : std::min(max_frames, pending.size() / 2);
    out.insert(out.end(), pending.begin(), pending.begin() + std::ptrdiff_t(frames * 2));
    pending.erase(pending.begin(), pending.begin() + std::ptrdiff_t(frames * 2));
    return frames;
  }
};

AudioSource::AudioSource(const std::string& path, double start_seconds)
    : impl_(std::make_unique<Impl>(path, start_seconds)) {}
AudioSource::~AudioSource() = default;

size_t AudioSource::read(std::vector<float>& out, size_t max_frames) {
  return impl_->read(out, max_frames);
}

}  // namespace sdfreel
