// Thread time of a driver's stages: a clock that adds the time of its
// scope to a total shared by the threads.
#pragma once

#include <atomic>
#include <chrono>

namespace shadetree {

class StageClock {
 public:
  explicit StageClock(std::atomic<long long>& total_nanoseconds)
      : total_(total_nanoseconds), start_(std::chrono::steady_clock::now()) {}
  ~StageClock() {
    total_ += std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - start_).count();
  }
  StageClock(const StageClock&) = delete;
  StageClock& operator=(const StageClock&) = delete;

 private:
  std::atomic<long long>& total_;
  std::chrono::steady_clock::time_point start_;
};

inline double seconds(const std::atomic<long long>& nanoseconds) { return static_cast<double>(nanoseconds.load()) * 1e-9; }

}  // namespace shadetree
