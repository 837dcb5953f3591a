// UTF-8 validation and "did you mean" suggestions.
#include <gtest/gtest.h>

#include "timeline/suggest.h"
#include "timeline/utf8.h"

namespace sdfreel {
namespace {

TEST(Utf8, AcceptsValidText) {
  EXPECT_FALSE(find_invalid_utf8("plain ascii\nline two"));
  EXPECT_FALSE(find_invalid_utf8("caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x8e\x86"));  // é € 🎆
}

TEST(Utf8, ReportsFirstBadByteWithLineAndColumn) {
  auto bad = find_invalid_utf8("ok\nab\xff");
  ASSERT_TRUE(bad);
  EXPECT_EQ(bad->line, 2);
  EXPECT_EQ(bad->column, 3);
  // Columns count code points, not bytes.
  bad = find_invalid_utf8("\xc3\xa9\xc3\xa9\x80");
  ASSERT_TRUE(bad);
  EXPECT_EQ(bad->column, 3);
}

TEST(Utf8, RefusesOverlongSurrogatesAndTruncation) {
  EXPECT_TRUE(find_invalid_utf8("\xc0\xaf"));          // overlong '/'
  EXPECT_TRUE(find_invalid_utf8("\xe0\x80\xaf"));      // overlong, 3 bytes
  EXPECT_TRUE(find_invalid_utf8("\xed\xa0\x80"));      // UTF-16 surrogate
  EXPECT_TRUE(find_invalid_utf8("\xf4\x90\x80\x80"));  // past U+10FFFF
  EXPECT_TRUE(find_invalid_utf8("ab\xe2\x82"));        // truncated at the end
}

TEST(Suggest, EditDistanceCountsTranspositionAsOne) {
  EXPECT_EQ(edit_distance("fps", "fps"), 0);
  EXPECT_EQ(edit_distance("fsp", "fps"), 1);
  EXPECT_EQ(edit_distance("smoth", "smooth"), 1);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3);
}

TEST(Suggest, OffersOnlyCloseCandidates) {
  const std::vector<std::string> keys = {"scene", "fps", "duration", "resolution"};
  EXPECT_EQ(did_you_mean("resolutoin", keys), "; did you mean 'resolution'?");
  EXPECT_EQ(did_you_mean("Scene", keys), "; did you mean 'scene'?");
  EXPECT_EQ(did_you_mean("colour", keys), "");
}

}  // namespace
}  // namespace sdfreel
