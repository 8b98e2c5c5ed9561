// The comma-separated numbers of --set values and command-line points.
#include <gtest/gtest.h>

#include "graph/number_list.h"

namespace shadetree {
namespace {

TEST(NumberList, ReadsPlainDecimalNumbers) {
  EXPECT_EQ(*parse_number_list("1,2.5,-3e2"), (std::vector<float>{1.0f, 2.5f, -300.0f}));
  EXPECT_EQ(*parse_number_list("0.125"), (std::vector<float>{0.125f}));
}

TEST(NumberList, RefusesAnythingElse) {
  for (const char* text : {"", ",", "1,", ",1", "1,,2", " 3", "3 ", "0x10", "inf", "nan", "1e39", "abc", "1;2"})
    EXPECT_FALSE(parse_number_list(text).has_value()) << '"' << text << '"';
}

}  // namespace
}  // namespace shadetree
