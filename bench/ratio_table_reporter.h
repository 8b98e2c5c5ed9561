// A Google Benchmark display reporter that passes every run on to the
// reporter the flags chose (console, JSON, ...), and at the end prints a
// table of ratios for the runs named <prefix><kernel>/<variant>: the
// reference variant's samples per second over each other variant's, per
// kernel, from the medians where repetitions give them. The CPU's model
// name heads the table; each run's label (what the benchmark says about
// it) and any error follow it.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include <benchmark/benchmark.h>

namespace shadetree {

class RatioTableReporter : public benchmark::BenchmarkReporter {
 public:
  // `display` is not owned; `caption` says what was measured.
  RatioTableReporter(benchmark::BenchmarkReporter* display, std::string prefix, std::string reference,
                     std::string caption);

  bool ReportContext(const Context& context) override;
  void ReportRuns(const std::vector<Run>& runs) override;
  void Finalize() override;

 private:
  struct Measurement {
    double items_per_second = 0.0;
    bool median = false;  // items_per_second is the median of repetitions
    std::string label;
    std::string error;
  };

  void record(const Run& run);
  void print_table(std::ostream& out) const;

  benchmark::BenchmarkReporter* display_;
  std::string prefix_, reference_, caption_;
  std::vector<std::string> kernels_, variants_;  // in the order they first ran
  std::map<std::pair<std::string, std::string>, Measurement> measurements_;
};

}  // namespace shadetree
