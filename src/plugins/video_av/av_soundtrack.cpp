#include "plugins/video_av/av_soundtrack.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "plugins/video_av/audio_source.h"

namespace sdfreel {
namespace {

// Stereo floats (interleaved) into the encoder's sample format.
void fill_frame(AVFrame* frame, const float* samples, int count) {
  const auto format = AVSampleFormat(frame->format);
  for (int i = 0; i < count; ++i)
    for (int c = 0; c < 2; ++c) {
      const float v = samples[2 * i + c];
      const int16_t s16 = int16_t(std::lrint(std::clamp(v, -1.0f, 1.0f) * 32767.0f));
      switch (format) {
        case AV_SAMPLE_FMT_FLT:
          reinterpret_cast<float*>(frame->data[0])[2 * i + c] = v;
          break;
        case AV_SAMPLE_FMT_FLTP:
          reinterpret_cast<float*>(frame->data[c])[i] = v;
          break;
        case AV_SAMPLE_FMT_S16:
          reinterpret_cast<int16_t*>(frame->data[0])[2 * i + c] = s16;
          break;
        case AV_SAMPLE_FMT_S16P:
          reinterpret_cast<int16_t*>(frame->data[c])[i] = s16;
          break;
        default:
          throw std::runtime_error("audio: unexpected sample format");
      }
    }
}

// The encoder's float format if it takes one (no rounding to 16 bits), else its first.
AVSampleFormat pick_format(const AVCodec* codec) {
  const AVSampleFormat* formats = nullptr;
#if LIBAVCODEC_VERSION_INT >= AV_VERSION_INT(61, 13, 100)  // FFmpeg 7.1 deprecates sample_fmts
  const void* configs = nullptr;
  if (avcodec_get_supported_config(nullptr, codec, AV_CODEC_CONFIG_SAMPLE_FORMAT, 0, &configs,
                                   nullptr) >= 0)
    formats = static_cast<const AVSampleFormat*>(configs);
#else
  formats = codec->sample_fmts;
#endif
  for (AVSampleFormat want : {AV_SAMPLE_FMT_FLT, AV_SAMPLE_FMT_FLTP})
    for (const AVSampleFormat* f = formats; f && *f != AV_SAMPLE_FMT_NONE; ++f)
      if (*f == want) return want;
  return formats ? formats[0] : AV_SAMPLE_FMT_FLT;  // none listed: it takes any
}

}  // namespace

std::shared_ptr<const EncodedAudio> encode_av_soundtrack(const AudioCut& cut,
                                                         const std::string& encoder,
                                                         const std::string& video_path) {
  AudioSource source(cut.path, cut.offset);
  auto result = std::make_shared<EncodedAudio>();
  result->encoder = encoder;
  const AVCodec* codec = avcodec_find_encoder_by_name(result->encoder.c_str());
  if (!codec)
    throw std::runtime_error("audio: this machine's libav has no " + result->encoder + " encoder");
  AvCodecContextPtr ctx(avcodec_alloc_context3(codec));
  if (!ctx) throw std::runtime_error("audio: out of memory");
  ctx->sample_rate = kSoundtrackRate;
  av_channel_layout_default(&ctx->ch_layout, 2);
  ctx->sample_fmt = pick_format(codec);
  ctx->time_base = AVRational{1, kSoundtrackRate};
  ctx->bit_rate = result->encoder == "aac" ? 192000 : result->encoder == "libopus" ? 160000 : 0;
  ctx->flags |= AV_CODEC_FLAG_BITEXACT;
  const AVOutputFormat* container = av_guess_format(nullptr, video_path.c_str(), nullptr);
  if (container && (container->flags & AVFMT_GLOBALHEADER))
    ctx->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  av_check(avcodec_open2(ctx.get(), codec, nullptr),
           "opening the audio encoder " + result->encoder);

  const int frame_size = ctx->frame_size > 0 ? ctx->frame_size : 1024;
  const int64_t total = std::llround(cut.length * kSoundtrackRate);
  const int64_t fade_from = total - std::llround(cut.fade * kSoundtrackRate);
  AvFramePtr frame(av_frame_alloc());
  AvPacketPtr packet(av_packet_alloc());
  if (!frame || !packet) throw std::runtime_error("audio: out of memory");
  auto drain = [&] {
    for (;;) {
      const int ret = avcodec_receive_packet(ctx.get(), packet.get());
      if (ret == AVERROR(EAGAIN) || ret == AVERROR_EOF) return;
      av_check(ret, "encoding the audio");
      AvPacketPtr kept(av_packet_alloc());
      if (!kept) throw std::runtime_error("audio: out of memory");
      av_packet_move_ref(kept.get(), packet.get());
      result->packets.push_back(std::move(kept));
    }
  };
  std::vector<float> samples;
  for (int64_t done = 0; done < total;) {
    const int n = int(std::min<int64_t>(frame_size, total - done));
    samples.clear();
    source.read(samples, size_t(n));
    samples.resize(size_t(n) * 2, 0.0f);  // silence past the file's end
    for (int i = 0; i < n; ++i)
      if (done + i >= fade_from) {
        const float gain = float(total - (done + i)) / float(total - fade_from);
        samples[2 * i] *= gain;
        samples[2 * i + 1] *= gain;
      }
    frame->nb_samples = n;
    frame->format = ctx->sample_fmt;
    frame->sample_rate = kSoundtrackRate;
    av_check(av_channel_layout_copy(&frame->ch_layout, &ctx->ch_layout), "audio layout");
    av_check(av_frame_get_buffer(frame.get(), 0), "allocating audio");
    fill_frame(frame.get(), samples.data(), n);
    frame->pts = done;
    av_check(avcodec_send_frame(ctx.get(), frame.get()), "encoding the audio");
    av_frame_unref(frame.get());
    drain();
    done += n;
  }
  av_check(avcodec_send_frame(ctx.get(), nullptr), "finishing the audio");
  drain();
  result->params = avcodec_parameters_alloc();
  if (!result->params) throw std::runtime_error("audio: out of memory");
  av_check(avcodec_parameters_from_context(result->params, ctx.get()), "audio parameters");
  result->time_base = ctx->time_base;
  return result;
}

}  // namespace sdfreel
