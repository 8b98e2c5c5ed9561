// Output files written through a temporary and renamed into place
// (io/output_file.h): concurrent writes of one file, the temporary's
// extension and length, and failed writes.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <mutex>
#include <set>
#include <sstream>
#include <thread>
#include <vector>

#include "graph/file_path.h"
#include "io/output_file.h"

namespace shadetree {
namespace {

namespace fs = std::filesystem;

class WriteThenRename : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() /
              ("shadetree-output-file-test-" + std::to_string(::getpid()) + "-" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(folder_);
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }

  static std::string text_of(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
  }

  // Writes `text` to the temporary, and remembers the temporary's name.
  std::function<std::string(const std::string&)> writer(const std::string& text) {
    return [this, text](const std::string& temporary) -> std::string {
      {
        std::lock_guard lock(mutex_);
        temporaries_.push_back(temporary);
      }
      std::ofstream file(temporary, std::ios::binary);
      file << text;
      file.close();
      return file ? "" : "cannot write " + temporary;
    };
  }

  fs::path folder_;
  std::mutex mutex_;
  std::vector<std::string> temporaries_;
};

// Issue 21: the temporary was named after the pid alone, so two saves of
// one file at once wrote, renamed and removed each other's temporary, and
// 6 of 100 concurrent saves failed.
TEST_F(WriteThenRename, ConcurrentWritesOfOneFileEachUseATemporaryOfTheirOwn) {
  const fs::path target = folder_ / "graph.json";
  const int threads = 8, writes_per_thread = 25;
  std::vector<std::thread> writers;
  std::vector<int> failures(threads, 0);
  for (int t = 0; t < threads; ++t)
    writers.emplace_back([&, t] {
      for (int w = 0; w < writes_per_thread; ++w)
        if (!write_then_rename(target.string(), writer(std::string(4096, static_cast<char>('a' + t)))))
          ++failures[t];
    });
  for (std::thread& thread : writers) thread.join();
  for (int t = 0; t < threads; ++t) EXPECT_EQ(failures[t], 0) << "writer " << t;
  const std::set<std::string> distinct(temporaries_.begin(), temporaries_.end());
  EXPECT_EQ(distinct.size(), temporaries_.size()) << "a temporary name was used twice";
  const std::string text = text_of(target);
  EXPECT_EQ(text, std::string(4096, text.empty() ? '?' : text[0])) << "one whole write, the last renamed";
  EXPECT_EQ(std::distance(fs::directory_iterator(folder_), fs::directory_iterator()), 1) << "no temporary is left";
}

TEST_F(WriteThenRename, TheTemporaryKeepsTheTargetsExtension) {
  ASSERT_TRUE(write_then_rename((folder_ / "render.exr").string(), writer("pixels")));
  ASSERT_EQ(temporaries_.size(), 1u);
  const fs::path temporary(temporaries_[0]);
  EXPECT_EQ(temporary.extension(), ".exr");
  EXPECT_EQ(temporary.parent_path(), folder_) << "in the target's folder, so the rename stays on one file system";
  EXPECT_EQ(text_of(folder_ / "render.exr"), "pixels");
}

// Issue 21: a name of 255 bytes is a valid file name, but its temporary
// (the name and a suffix) was not, and the save failed.
TEST_F(WriteThenRename, ANameOfTheLongestLengthStillHasATemporary) {
  const std::string name = std::string(max_file_name_bytes - 5, 'n') + ".json";
  ASSERT_TRUE(write_then_rename((folder_ / name).string(), writer("{}")));
  EXPECT_EQ(text_of(folder_ / name), "{}");
  ASSERT_EQ(temporaries_.size(), 1u);
  EXPECT_LE(fs::path(temporaries_[0]).filename().string().size(), max_file_name_bytes);
  EXPECT_EQ(fs::path(temporaries_[0]).extension(), ".json");
}

TEST_F(WriteThenRename, AFailedWriteLeavesNeitherTargetNorTemporary) {
  Status written = write_then_rename((folder_ / "image.png").string(), [](const std::string& temporary) {
    std::ofstream(temporary) << "half";
    return std::string("the writer gave up");
  });
  ASSERT_FALSE(written);
  EXPECT_NE(written.error().message.find("the writer gave up"), std::string::npos) << written.error().message;
  EXPECT_TRUE(fs::is_empty(folder_));
}

}  // namespace
}  // namespace shadetree
