// The processor's name for benchmark reports (platform/cpu_model.h): the
// value of /proc/cpuinfo's first "model name" line, without its key.
#include "platform/cpu_model.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace shadetree {
namespace {

TEST(CpuModel, IsTheValueOfTheModelNameLine) {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::stringstream text;
  text << cpuinfo.rdbuf();
  const std::string name = cpu_model_name();
  ASSERT_FALSE(name.empty());
  if (text.str().find("model name") == std::string::npos) {
    EXPECT_EQ(name, "an unnamed CPU");
    return;
  }
  EXPECT_EQ(name.find('\n'), std::string::npos) << name;
  EXPECT_NE(name.front(), ' ') << name;
  EXPECT_EQ(name.find("model name"), std::string::npos) << name;
  // The whole line is "model name<tabs>: " and the name.
  EXPECT_NE(text.str().find(": " + name + "\n"), std::string::npos) << name;
}

}  // namespace
}  // namespace shadetree
