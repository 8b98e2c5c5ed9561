// Progress of long renders: how many of a render's parts (tiles, slices)
// are done and how much work (rays, samples, voxels) they held, and its
// display on stderr, shown only when stderr is a terminal and the render
// has run for more than a second.
#pragma once

#include <chrono>
#include <functional>
#include <mutex>
#include <string>

namespace shadetree {

struct ProgressCount {
  long done = 0, total = 0;  // parts
  long items = 0;            // the work in the parts done
};

using ProgressCallback = std::function<void(const ProgressCount&)>;

class ProgressReporter {
 public:
  // "marching f.json  37% (96/256 tiles), 41.2 k rays/s, 3 s elapsed, about 5 s left"
  ProgressReporter(std::string label, std::string parts, std::string items);
  ~ProgressReporter();
  void update(const ProgressCount& count);  // thread-safe
  ProgressCallback callback() {
    return [this](const ProgressCount& count) { update(count); };
  }

 private:
  std::string label_, parts_, items_;
  std::chrono::steady_clock::time_point start_;
  std::mutex mutex_;
  bool enabled_;
  bool shown_ = false;
  int last_percent_ = -1;
};

}  // namespace shadetree
