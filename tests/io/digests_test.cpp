// sdfreel's own MD5 (io/md5.h) against RFC 1321's vectors, and it and SHA-256 (timeline/sha256.h,
// whose FIPS vectors are tests/timeline/sha256_test.cpp) against libavutil's, which sdfreel used
// before, for lengths around every block boundary and for data fed in pieces of every size.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "io/md5.h"
#include "render/hex_digest.h"
#include "timeline/sha256.h"

extern "C" {
#include <libavutil/md5.h>
#include <libavutil/mem.h>
#include <libavutil/sha.h>
}

namespace sdfreel {
namespace {

std::string md5_hex(const std::string& s) {
  Md5 md5;
  md5.update(s.data(), s.size());
  const auto d = md5.finish();
  return hex_digest(d.data(), d.size());
}

std::string av_md5_hex(const std::string& s) {
  uint8_t d[16];
  av_md5_sum(d, reinterpret_cast<const uint8_t*>(s.data()), s.size());
  return hex_digest(d, 16);
}

std::string av_sha256_hex(const std::string& s) {
  AVSHA* sha = av_sha_alloc();
  av_sha_init(sha, 256);
  av_sha_update(sha, reinterpret_cast<const uint8_t*>(s.data()), s.size());
  uint8_t d[32];
  av_sha_final(sha, d);
  av_free(sha);
  return hex_digest(d, 32);
}

TEST(Digests, Md5OfRfc1321sVectors) {
  EXPECT_EQ(md5_hex(""), "d41d8cd98f00b204e9800998ecf8427e");
  EXPECT_EQ(md5_hex("a"), "0cc175b9c0f1b6a831c399e269772661");
  EXPECT_EQ(md5_hex("abc"), "900150983cd24fb0d6963f7d28e17f72");
  EXPECT_EQ(md5_hex("message digest"), "f96b697d7cb7938d525a2f31aaf161d0");
  EXPECT_EQ(md5_hex("abcdefghijklmnopqrstuvwxyz"), "c3fcd3d76192e4007dfb496cca67e13b");
  EXPECT_EQ(
      md5_hex(std::string(
          "12345678901234567890123456789012345678901234567890123456789012345678901234567890")),
      "57edf4a22be3c955ac49da2e2107b67a");
}

TEST(Digests, BothAsLibavutilAtEveryLengthAndInPieces) {
  std::mt19937 rng(8);
  std::string data(300, '\0');
  for (char& c : data) c = char(rng());
  for (size_t n = 0; n <= data.size(); ++n) {
    const std::string s = data.substr(0, n);
    ASSERT_EQ(md5_hex(s), av_md5_hex(s)) << n << " bytes";
    ASSERT_EQ(sha256_hex(s), av_sha256_hex(s)) << n << " bytes";
  }
  // Fed in pieces of every size from 1 to 130 bytes: the buffering across calls.
  for (size_t piece = 1; piece <= 130; ++piece) {
    Md5 md5;
    for (size_t at = 0; at < data.size(); at += piece)
      md5.update(data.data() + at, std::min(piece, data.size() - at));
    const auto d = md5.finish();
    ASSERT_EQ(hex_digest(d.data(), d.size()), av_md5_hex(data)) << "pieces of " << piece;
  }
}

}  // namespace
}  // namespace sdfreel
