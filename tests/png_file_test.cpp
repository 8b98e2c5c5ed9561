// PNG output through libpng (io/png_file.h), read back through
// OpenImageIO: levels rounded to nearest as OpenImageIO wrote them before,
// every channel count, both depths.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>

#include "io/image_output.h"
#include "io/png_file.h"
#include "support/temp_folder.h"

namespace shadetree {
namespace {

constexpr float nan = std::numeric_limits<float>::quiet_NaN();
constexpr float inf = std::numeric_limits<float>::infinity();

class PngFile : public ::testing::Test {
 protected:
  std::string path(const char* name) const { return (temp_.path() / name).string(); }
  testing::TempFolder temp_{"shadetree-png"};
};

// One row of `values` as grey pixels, written at `bits` and read back.
std::vector<float> round_trip(const std::string& file, const std::vector<float>& values, int bits) {
  Image image{static_cast<int>(values.size()), 1, 1, values};
  EXPECT_EQ(write_png(image, file, bits), "");
  Result<Image> read = read_image(file);
  EXPECT_TRUE(read.ok());
  return read.ok() ? read->pixels : std::vector<float>();
}

TEST_F(PngFile, ValuesAreClampedAndRoundedToTheNearestLevel) {
  const std::vector<float> values = {-1.0f, nan, 0.0f, 0.49f / 255, 0.51f / 255, 0.5f, 127.49f / 255, 1.0f, 2.0f, inf};
  const std::vector<float> levels = {0, 0, 0, 0, 1, 128, 127, 255, 255, 255};
  const std::vector<float> read = round_trip(path("grey8.png"), values, 8);
  ASSERT_EQ(read.size(), levels.size());
  for (std::size_t i = 0; i < levels.size(); ++i) EXPECT_FLOAT_EQ(read[i], levels[i] / 255.0f) << "value " << values[i];
}

TEST_F(PngFile, SixteenBitsKeepSixteenBitLevels) {
  const std::vector<float> values = {0.0f, 1.0f / 65535, 0.5f, 1000.4f / 65535, 1000.6f / 65535, 1.0f};
  const std::vector<float> levels = {0, 1, 32768, 1000, 1001, 65535};
  const std::vector<float> read = round_trip(path("grey16.png"), values, 16);
  ASSERT_EQ(read.size(), levels.size());
  for (std::size_t i = 0; i < levels.size(); ++i) EXPECT_FLOAT_EQ(read[i], levels[i] / 65535.0f) << "value " << values[i];
}

// Grey, grey and alpha, RGB, RGBA: each channel in its place, the top row
// first, at both depths. Alpha is 1, since OpenImageIO multiplies the
// colour it reads by it (see below).
TEST_F(PngFile, EveryChannelCountRoundTrips) {
  for (int bits : {8, 16}) {
    for (int channels = 1; channels <= 4; ++channels) {
      Image image{3, 2, channels, {}};
      for (int i = 0; i < 3 * 2 * channels; ++i)
        image.pixels.push_back(channels % 2 == 0 && i % channels == channels - 1 ? 1.0f : static_cast<float>(i) / 255.0f);
      const std::string file = path("c.png");
      ASSERT_EQ(write_png(image, file, bits), "");
      Result<Image> read = read_image(file);
      ASSERT_TRUE(read.ok()) << read.error().to_string();
      EXPECT_EQ(read->width, 3);
      EXPECT_EQ(read->height, 2);
      ASSERT_EQ(read->channels, channels);
      for (std::size_t i = 0; i < image.pixels.size(); ++i)
        EXPECT_NEAR(read->pixels[i], image.pixels[i], 0.5 / 65535) << bits << " bits, " << channels << " channels";
    }
  }
}

// PNG's alpha is straight, as a texture graph's colour and alpha are: the
// colour is stored as given, and a reader that wants it premultiplied (as
// OpenImageIO does by default, in 8-bit steps) multiplies it.
TEST_F(PngFile, ColourIsStoredStraightBesideAlpha) {
  const std::string file = path("rgba.png");
  ASSERT_EQ(write_png(Image{1, 1, 4, {0.8f, 0.4f, 0.2f, 0.5f}}, file, 8), "");
  Result<Image> read = read_image(file);
  ASSERT_TRUE(read.ok());
  const float alpha = 128.0f / 255;
  EXPECT_FLOAT_EQ(read->pixels[3], alpha);
  EXPECT_NEAR(read->pixels[0], 204.0f / 255 * alpha, 1.0 / 255);
  EXPECT_NEAR(read->pixels[1], 102.0f / 255 * alpha, 1.0 / 255);
  EXPECT_NEAR(read->pixels[2], 51.0f / 255 * alpha, 1.0 / 255);
}

TEST_F(PngFile, TheFileNamesItsSoftware) {
  const std::string file = path("named.png");
  ASSERT_EQ(write_png(Image{1, 1, 3, {0.f, 0.f, 0.f}}, file, 8), "");
  std::ifstream in(file, std::ios::binary);
  const std::string bytes(std::istreambuf_iterator<char>(in), {});
  EXPECT_EQ(bytes.substr(1, 3), "PNG");
  EXPECT_NE(bytes.find(std::string("tEXtSoftware\0shadetree", 22)), std::string::npos);
}

TEST_F(PngFile, FailuresAreOneLineReasons) {
  const Image image{1, 1, 3, {0.f, 0.f, 0.f}};
  EXPECT_EQ(write_png(image, path("missing/x.png"), 8), "cannot create the file");
  EXPECT_EQ(write_png(image, path("x.png"), 12), "PNG samples are 8 or 16 bits, not 12");
  EXPECT_EQ(write_png(Image{1, 1, 5, std::vector<float>(5)}, path("x.png"), 8), "PNG holds 1 to 4 channels, not 5");
  // A full device fails in libpng's write, which reports it back here.
  if (std::ifstream("/dev/full").good())
    EXPECT_EQ(write_png(Image{256, 256, 4, std::vector<float>(256 * 256 * 4, 0.3f)}, "/dev/full", 8).rfind("write failed: ", 0), 0u);
}

}  // namespace
}  // namespace shadetree
