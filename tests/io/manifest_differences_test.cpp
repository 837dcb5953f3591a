// verify names what differs between its render and a manifest's, not just "other settings".
#include "io/manifest_differences.h"

#include <gtest/gtest.h>

namespace sdfreel {
namespace {

ManifestHeader header() {
  ManifestHeader h;
  h.timeline_sha256 = "abc";
  h.timeline_parsed_sha256 = "def";
  h.scene = "sdf_morph";
  h.backend = "egl";
  h.versions = {{"egl.mesa", "25.0.7"}, {"openexr", "3.1.5"}};
  h.width = 64;
  h.height = 36;
  return h;
}

TEST(ManifestDifferences, NoneForTheSameRender) {
  EXPECT_TRUE(header_differences(header(), header()).empty());
}

TEST(ManifestDifferences, NamesTheVersionKeyAndBothValues) {
  ManifestHeader there = header();
  there.versions["egl.mesa"] = "22.3.6";
  const auto d = header_differences(header(), there);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0], "versions.egl.mesa: 25.0.7 here, 22.3.6 in the manifest");
}

TEST(ManifestDifferences, AKeyOnlyOneSideHasIsShownAsNone) {
  ManifestHeader there = header();
  there.versions["osmesa.platform"] = "osmesa";
  const auto d = header_differences(header(), there);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0], "versions.osmesa.platform: (none) here, osmesa in the manifest");
}

TEST(ManifestDifferences, ListsEveryFieldThatDiffers) {
  ManifestHeader there = header();
  there.backend = "cpu";
  there.width = 1280;
  there.samples = 4;
  const auto d = header_differences(header(), there);
  ASSERT_EQ(d.size(), 3u);
  EXPECT_EQ(d[0], "backend: egl here, cpu in the manifest");
  EXPECT_EQ(d[1], "resolution: 64x36 here, 1280x36 in the manifest");
  EXPECT_EQ(d[2], "samples: 1 here, 4 in the manifest");
}

TEST(ManifestDifferences, AgreesWithSameRenderAs) {
  ManifestHeader there = header();
  there.timeline_path = "elsewhere.toml";  // not part of the render's identity
  EXPECT_TRUE(header().same_render_as(there));
  EXPECT_TRUE(header_differences(header(), there).empty());
  there.quality = "final";
  EXPECT_FALSE(header().same_render_as(there));
  EXPECT_FALSE(header_differences(header(), there).empty());
}

}  // namespace
}  // namespace sdfreel
