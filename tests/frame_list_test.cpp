// Frame lists as farms write them (cli/frame_list.h): ranges in both
// notations with steps, lists, chunks clamped to the list, and refusals.
#include <gtest/gtest.h>

#include "schedule/frame_list.h"

namespace shadetree {
namespace {

std::vector<int> frames(const std::string& text) {
  Result<std::vector<int>> listed = parse_frame_list(text);
  EXPECT_TRUE(listed.ok()) << text << ": " << listed.error().message;
  return listed ? *listed : std::vector<int>{};
}

TEST(FrameList, RangesInBothNotationsWithSteps) {
  EXPECT_EQ(frames("3..5"), (std::vector<int>{3, 4, 5}));
  EXPECT_EQ(frames("3-5"), (std::vector<int>{3, 4, 5}));
  EXPECT_EQ(frames("7"), (std::vector<int>{7}));
  EXPECT_EQ(frames("1-10x4"), (std::vector<int>{1, 5, 9}));
  EXPECT_EQ(frames("1..10x4"), (std::vector<int>{1, 5, 9}));
  EXPECT_EQ(frames("1-10:3"), (std::vector<int>{1, 4, 7, 10}));
  EXPECT_EQ(frames("0-0"), (std::vector<int>{0}));
  EXPECT_EQ(frames("1-240x4").size(), 60u);
}

TEST(FrameList, ListsAreSortedWithoutRepeats) {
  EXPECT_EQ(frames("20,1-3,2,10-12x2"), (std::vector<int>{1, 2, 3, 10, 12, 20}));
}

TEST(FrameList, RefusesWhatIsNotAList) {
  for (const char* text : {"", ",", "1,", ",1", "5..3", "5-3", "1-10x0", "1-10x", "-3", "1--3", "a-b", "1.5",
                           "1..", "1-2-3", "1 -3", "0-100000", "1-2000000000", "1-10x4x2", "1-\n3"}) {
    Result<std::vector<int>> listed = parse_frame_list(text);
    EXPECT_FALSE(listed.ok()) << "\"" << text << "\"";
    if (!listed) {
      EXPECT_EQ(listed.error().message.find('\n'), std::string::npos) << text;
    }
  }
  EXPECT_TRUE(parse_frame_list("0-99999").ok()) << "100000 frames is the limit";
}

TEST(FrameList, ChunksAreClampedToTheList) {
  const std::vector<int> shot = frames("1-240x4");
  Result<std::vector<int>> chunk = frame_chunk(shot, "1-10");
  ASSERT_TRUE(chunk.ok());
  EXPECT_EQ(*chunk, (std::vector<int>{1, 5, 9}));
  chunk = frame_chunk(shot, "230..500");
  ASSERT_TRUE(chunk.ok());
  EXPECT_EQ(*chunk, (std::vector<int>{233, 237}));
  chunk = frame_chunk(shot, "2-4");
  ASSERT_FALSE(chunk.ok()) << "no frame of the list between 2 and 4";
  EXPECT_NE(chunk.error().message.find("holds no frame"), std::string::npos);
  for (const char* text : {"5", "1-10x2", "9-1", "x"}) EXPECT_FALSE(frame_chunk(shot, text).ok()) << text;
}

}  // namespace
}  // namespace shadetree
