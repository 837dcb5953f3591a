#include "io/video_decode.h"

#include <sys/wait.h>

#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace sdfreel::test {
namespace {

struct InputFree {
  void operator()(AVFormatContext* c) const { avformat_close_input(&c); }
};

std::string quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

void receive_all(AVCodecContext* dec, DecodedVideo& out) {
  for (;;) {
    AvFramePtr f(av_frame_alloc());
    const int ret = avcodec_receive_frame(dec, f.get());
    if (ret == AVERROR(EAGAIN) || ret == AVERROR_EOF) return;
    av_check(ret, "decoding");
    out.frames.push_back(std::move(f));
  }
}

}  // namespace

DecodedVideo decode_video(const std::string& path) {
  AVFormatContext* raw = nullptr;
  av_check(avformat_open_input(&raw, path.c_str(), nullptr, nullptr), "opening " + path);
  std::unique_ptr<AVFormatContext, InputFree> input(raw);
  av_check(avformat_find_stream_info(input.get(), nullptr), "reading stream info");
  const AVCodec* codec = nullptr;
  const int index = av_check(
      av_find_best_stream(input.get(), AVMEDIA_TYPE_VIDEO, -1, -1, &codec, 0), "finding video");
  AvCodecContextPtr dec(avcodec_alloc_context3(codec));
  av_check(avcodec_parameters_to_context(dec.get(), input->streams[index]->codecpar), "params");
  av_check(avcodec_open2(dec.get(), codec, nullptr), "opening decoder");

  DecodedVideo out;
  out.codec = codec->name;
  AvPacketPtr packet(av_packet_alloc());
  while (av_read_frame(input.get(), packet.get()) >= 0) {
    if (packet->stream_index == index)
      av_check(avcodec_send_packet(dec.get(), packet.get()), "send");
    av_packet_unref(packet.get());
    receive_all(dec.get(), out);
  }
  av_check(avcodec_send_packet(dec.get(), nullptr), "flush");
  receive_all(dec.get(), out);
  return out;
}

std::vector<uint16_t> gbrp16_to_rgb48(const AVFrame& f) {
  if (f.format != AV_PIX_FMT_GBRP16LE) throw std::runtime_error("not a gbrp16le frame");
  std::vector<uint16_t> out(size_t(f.width) * f.height * 3);
  const int plane_of_channel[3] = {2, 0, 1};  // gbrp planes are G, B, R
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const int p = plane_of_channel[c];
        const uint8_t* b = f.data[p] + size_t(y) * f.linesize[p] + size_t(x) * 2;
        out[(size_t(y) * f.width + x) * 3 + c] = uint16_t(b[0] | (b[1] << 8));
      }
  return out;
}

std::array<double, 3> bt709_pixel_to_rgb(const AVFrame& f, int x, int y) {
  double luma, cb, cr;
  if (f.format == AV_PIX_FMT_YUV420P) {
    luma = (f.data[0][y * f.linesize[0] + x] - 16.0) / 219.0;
    cb = (f.data[1][(y / 2) * f.linesize[1] + x / 2] - 128.0) / 224.0;
    cr = (f.data[2][(y / 2) * f.linesize[2] + x / 2] - 128.0) / 224.0;
  } else if (f.format == AV_PIX_FMT_YUV444P10LE || f.format == AV_PIX_FMT_YUV444P12LE ||
             f.format == AV_PIX_FMT_YUV420P10LE) {
    const double scale = f.format == AV_PIX_FMT_YUV444P12LE ? 16.0 : 4.0;  // from 8-bit levels
    const int sub = f.format == AV_PIX_FMT_YUV420P10LE ? 2 : 1;  // chroma halved both ways
    auto at = [&](int p) {
      const int px = p ? x / sub : x, py = p ? y / sub : y;
      const uint8_t* b = f.data[p] + size_t(py) * f.linesize[p] + size_t(px) * 2;
      return double(b[0] | (b[1] << 8)) / scale;
    };
    luma = (at(0) - 16.0) / 219.0;
    cb = (at(1) - 128.0) / 224.0;
    cr = (at(2) - 128.0) / 224.0;
  } else {
    throw std::runtime_error("bt709_pixel_to_rgb: unexpected pixel format");
  }
  const double kr = 0.2126, kb = 0.0722, kg = 1.0 - kr - kb;
  const double r = luma + 2.0 * (1.0 - kr) * cr;
  const double b = luma + 2.0 * (1.0 - kb) * cb;
  const double g = (luma - kr * r - kb * b) / kg;
  return {r, g, b};
}

std::string run_command(const std::string& command, int* status) {
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) throw std::runtime_error("cannot run " + command);
  std::string out;
  char buf[4096];
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, pipe)) > 0) out.append(buf, n);
  const int rc = pclose(pipe);
  *status = WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
  return out;
}

bool have_program(const std::string& name) {
  int status = 0;
  run_command("command -v " + name + " >/dev/null 2>&1", &status);
  return status == 0;
}

std::map<std::string, std::string> probe_video_stream(const std::string& path) {
  int status = 0;
  const std::string out = run_command(
      "ffprobe -v error -select_streams v:0 -count_frames -show_streams " + quoted(path), &status);
  if (status != 0) throw std::runtime_error("ffprobe failed on " + path);
  std::map<std::string, std::string> fields;
  std::istringstream lines(out);
  for (std::string line; std::getline(lines, line);) {
    const size_t eq = line.find('=');
    if (eq != std::string::npos) fields[line.substr(0, eq)] = line.substr(eq + 1);
  }
  return fields;
}

std::vector<std::string> framemd5_rgb48le(const std::string& path) {
  int status = 0;
  const std::string out = run_command(
      "ffmpeg -v error -i " + quoted(path) + " -pix_fmt rgb48le -fflags +bitexact -f framemd5 -",
      &status);
  if (status != 0) throw std::runtime_error("ffmpeg framemd5 failed on " + path);
  std::vector<std::string> hashes;
  std::istringstream lines(out);
  for (std::string line; std::getline(lines, line);) {
    if (line.empty() || line[0] == '#') continue;
    const size_t comma = line.rfind(',');
    size_t start = comma + 1;
    while (start < line.size() && line[start] == ' ') ++start;
    hashes.push_back(line.substr(start));
  }
  return hashes;
}

}  // namespace sdfreel::test
