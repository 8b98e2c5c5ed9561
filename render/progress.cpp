#include "render/progress.h"

#include <unistd.h>

#include <cstdio>

namespace shadetree {

ProgressReporter::ProgressReporter(std::string label)
    : label_(std::move(label)), start_(std::chrono::steady_clock::now()), enabled_(::isatty(2) != 0) {}

ProgressReporter::~ProgressReporter() {
  if (shown_) std::fprintf(stderr, "\r\033[K");
}

void ProgressReporter::update(double fraction_done) {
  if (!enabled_) return;
  const auto elapsed = std::chrono::steady_clock::now() - start_;
  if (elapsed < std::chrono::seconds(1)) return;
  std::lock_guard lock(mutex_);
  const int percent = static_cast<int>(fraction_done * 100.0);
  if (percent == last_percent_) return;
  last_percent_ = percent;
  shown_ = true;
  // The time left if the rest goes as fast as what is done.
  const double seconds = std::chrono::duration<double>(elapsed).count();
  const double left = fraction_done > 0.0 ? seconds * (1.0 - fraction_done) / fraction_done : 0.0;
  std::fprintf(stderr, "\r%s %3d%%, %.0f s elapsed, about %.0f s left\033[K", label_.c_str(), percent, seconds, left);
  std::fflush(stderr);
}

}  // namespace shadetree
