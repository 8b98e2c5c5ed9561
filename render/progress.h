// Progress on stderr for long renders: the share done, the time spent and
// an estimate of the time left, shown only when stderr is a terminal and
// the render has run for more than a second.
#pragma once

#include <chrono>
#include <mutex>
#include <string>

namespace shadetree {

class ProgressReporter {
 public:
  explicit ProgressReporter(std::string label);
  ~ProgressReporter();
  void update(double fraction_done);  // thread-safe

 private:
  std::string label_;
  std::chrono::steady_clock::time_point start_;
  std::mutex mutex_;
  bool enabled_;
  bool shown_ = false;
  int last_percent_ = -1;
};

}  // namespace shadetree
