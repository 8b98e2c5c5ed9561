// Every arrow between folders points down the pipeline: a folder includes
// only its own headers and those of the folders below it, so that nodes/
// stands alone, the backends see ir/ but not each other, and only the
// composition root (pipeline/) and what sits above it see every stage.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <string>

namespace {

// Rank of each source folder: a file may include from folders of lower rank.
// interp/, codegen/, cppgen/ and glslgen/ share a rank, so no backend sees
// another;
// so do scene/ and schedule/, and server/ and api/. platform/ (what the
// operating system offers, such as loadable modules) is below everything.
const std::map<std::string, int> folder_rank = {
    {"platform", 0}, {"nodes", 0}, {"graph", 1},    {"ir", 2},       {"interp", 3}, {"codegen", 3}, {"cppgen", 3}, {"glslgen", 3},
    {"jit", 4},   {"pipeline", 5}, {"io", 6},       {"schedule", 7}, {"scene", 7},  {"render", 8},
    {"server", 9}, {"api", 9},     {"cli", 10},
};

TEST(Layering, IncludesPointDownThePipeline) {
  const std::filesystem::path root = SHADETREE_SOURCE_DIR;
  const std::regex include_line(R"(^\s*#\s*include\s+"([a-z_]+)/)");
  int files = 0;
  for (const auto& [folder, rank] : folder_rank) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root / folder)) {
      const std::string extension = entry.path().extension().string();
      if (extension != ".h" && extension != ".cpp") continue;
      ++files;
      std::ifstream file(entry.path());
      std::string line;
      for (int number = 1; std::getline(file, line); ++number) {
        std::smatch match;
        if (!std::regex_search(line, match, include_line)) continue;
        const std::string target = match[1];
        auto found = folder_rank.find(target);
        ASSERT_NE(found, folder_rank.end()) << entry.path() << ":" << number << " includes unknown folder " << target;
        EXPECT_TRUE(target == folder || found->second < rank)
            << std::filesystem::relative(entry.path(), root).string() << ":" << number << ": " << folder
            << "/ must not include " << target << "/ (" << line << ")";
      }
    }
  }
  EXPECT_GT(files, 50);
}

}  // namespace
