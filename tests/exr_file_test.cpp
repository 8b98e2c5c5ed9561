// EXR output through OpenEXR (io/exr_file.h), read back through
// OpenImageIO: 32-bit floats to the bit, unclamped, any channel count.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>

#include <stdlib.h>

#include "io/exr_file.h"
#include "io/image_output.h"
#include "support/temp_folder.h"

namespace shadetree {
namespace {

class ExrFile : public ::testing::Test {
 protected:
  std::string path(const char* name) const { return (temp_.path() / name).string(); }
  std::string bytes(const std::string& file) const {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }
  testing::TempFolder temp_{"shadetree-exr"};
};

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST_F(ExrFile, FloatsComeBackToTheBitUnclamped) {
  const float inf = std::numeric_limits<float>::infinity();
  Image image{3, 2, 4, {-1.5f, 0.0f, 1e-30f, 1.0f, 2.0f, 1e30f, inf, -inf, 0.1f, 0.2f, 0.3f, 0.4f,
                        3.25f, -0.0f, 7.0f, 0.5f, 1e-45f, 65504.0f, 1e6f, 0.75f, 0.01f, 0.02f, 0.03f, 0.04f}};
  const std::string file = path("floats.exr");
  ASSERT_EQ(write_exr(image, file), "");
  Result<Image> read = read_image(file);
  ASSERT_TRUE(read.ok()) << read.error().to_string();
  EXPECT_EQ(read->width, 3);
  EXPECT_EQ(read->height, 2);
  ASSERT_EQ(read->channels, 4);
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    EXPECT_TRUE(same_bits(read->pixels[i], image.pixels[i])) << i << ": " << read->pixels[i];
}

// One channel is Y; two to four are R, G, B, A in order; beyond, channelN.
TEST_F(ExrFile, ChannelsAreNamedAsOpenImageIoNamesThem) {
  for (int channels : {1, 2, 3, 4, 6}) {
    Image image{2, 1, channels, {}};
    for (int i = 0; i < 2 * channels; ++i) image.pixels.push_back(static_cast<float>(i));
    const std::string file = path("c.exr");
    ASSERT_EQ(write_exr(image, file), "");
    const std::string header = bytes(file).substr(0, 400);
    EXPECT_EQ(header.find(std::string("Y\0", 2)) != std::string::npos, channels == 1) << channels;
    EXPECT_EQ(header.find(std::string("G\0", 2)) != std::string::npos, channels >= 2) << channels;
    EXPECT_EQ(header.find(std::string("A\0", 2)) != std::string::npos, channels >= 4) << channels;
    EXPECT_EQ(header.find("channel5") != std::string::npos, channels == 6) << channels;
    Result<Image> read = read_image(file);
    ASSERT_TRUE(read.ok()) << read.error().to_string();
    ASSERT_EQ(read->channels, std::min(channels, 4));
    for (int x = 0; x < 2; ++x)
      for (int c = 0; c < read->channels; ++c)
        EXPECT_EQ(read->pixels[x * read->channels + c], static_cast<float>(x * channels + c)) << channels;
  }
}

// capDate is SOURCE_DATE_EPOCH's time when it is set, so that two renders
// are the same bytes; without it, the time of writing.
TEST_F(ExrFile, TheCaptureDateFollowsSourceDateEpoch) {
  const Image image{1, 1, 3, {0.f, 0.f, 0.f}};
  ::setenv("SOURCE_DATE_EPOCH", "86400", 1);
  ASSERT_EQ(write_exr(image, path("a.exr")), "");
  ::setenv("SOURCE_DATE_EPOCH", "not a number", 1);
  ASSERT_EQ(write_exr(image, path("b.exr")), "");
  ::unsetenv("SOURCE_DATE_EPOCH");
  EXPECT_NE(bytes(path("a.exr")).find("1970:01:02 00:00:00"), std::string::npos);
  EXPECT_EQ(bytes(path("b.exr")).find("1970:01:02"), std::string::npos);
  EXPECT_NE(bytes(path("b.exr")).find("capDate"), std::string::npos);
  EXPECT_NE(bytes(path("a.exr")).find(std::string("software\0string", 15)), std::string::npos);
}

TEST_F(ExrFile, FailuresAreOneLineReasons) {
  const std::string missing = write_exr(Image{1, 1, 3, {0.f, 0.f, 0.f}}, path("missing/x.exr"));
  EXPECT_EQ(missing.rfind("write failed: ", 0), 0u) << missing;
  EXPECT_EQ(missing.find('\n'), std::string::npos) << missing;
  EXPECT_EQ(write_exr(Image{1, 1, 0, {}}, path("x.exr")), "an image without channels");
}

}  // namespace
}  // namespace shadetree
