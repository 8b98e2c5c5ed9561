// The records of a streamed preview (server/preview_stream.h): a tile's
// head and its RGBA bytes as a whole preview has them, and the end record
// with its error.
#include "server/preview_stream.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>

namespace shadetree {
namespace {

std::uint32_t u32_at(const std::string& bytes, std::size_t at) {
  std::uint32_t value = 0;
  for (int i = 3; i >= 0; --i) value = value << 8 | static_cast<unsigned char>(bytes[at + i]);
  return value;
}

// 3 x 2 RGB pixels whose red is x/4 and green y/2; blue NaN at (0, 1).
Image ramp() {
  Image image{3, 2, 3, {}};
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x) image.pixels.insert(image.pixels.end(), {x / 4.0f, y / 2.0f, 2.0f});
  image.pixels[(1 * 3 + 0) * 3 + 2] = std::numeric_limits<float>::quiet_NaN();
  return image;
}

TEST(PreviewStream, ATileRecordIsItsPlaceThenItsPixelsRowByRow) {
  const std::string record = tile_record(ramp(), {1, 0, 2, 2});
  ASSERT_EQ(record.size(), 16u + 2 * 2 * 4);
  EXPECT_EQ(u32_at(record, 0), 1u);
  EXPECT_EQ(u32_at(record, 4), 0u);
  EXPECT_EQ(u32_at(record, 8), 2u);
  EXPECT_EQ(u32_at(record, 12), 2u);
  // (1, 0): red 0.25 -> 64, green 0, blue 2 clamped to 255, alpha 255.
  EXPECT_EQ(record.substr(16, 4), std::string("\x40\x00\xff\xff", 4));
  // (2, 1): red 0.5 -> 128, green 0.5 -> 128.
  EXPECT_EQ(record.substr(16 + 12, 4), std::string("\x80\x80\xff\xff", 4));
}

TEST(PreviewStream, TheWholeImagesBytesAreTheFullTilesAndNanIsBlack) {
  const std::string whole = rgba_bytes(ramp());
  EXPECT_EQ(whole, tile_record(ramp(), {0, 0, 3, 2}).substr(16));
  EXPECT_EQ(static_cast<unsigned char>(whole[(1 * 3 + 0) * 4 + 2]), 0) << "NaN is 0, as PNG output writes it";
}

TEST(PreviewStream, TheEndRecordCarriesTheError) {
  EXPECT_EQ(end_record(""), std::string(16, '\0'));
  const std::string failed = end_record("superseded");
  EXPECT_EQ(u32_at(failed, 8), 0u);
  EXPECT_EQ(u32_at(failed, 12), 10u);
  EXPECT_EQ(failed.substr(16), "superseded");
}

}  // namespace
}  // namespace shadetree
