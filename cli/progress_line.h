// The work done, on a terminal, as GDAL's command-line tools show it.
#pragma once

#include <algorithm>
#include <ostream>

namespace tsk::cli {

// GDAL's progress line on a terminal, 0...10...20...30 up to 100 - done., a dot every 2.5 %.
class ProgressLine {
 public:
  explicit ProgressLine(std::ostream& err) : err_(err) {}
  void show(double fraction) {
    const int step = static_cast<int>(std::clamp(fraction, 0.0, 1.0) * kSteps);
    if (step <= shown_) return;
    while (shown_ < step) {
      ++shown_;
      if (shown_ % 4 == 0) {
        err_ << shown_ / 4 * 10;
      } else {
        err_ << '.';
      }
    }
    if (step == kSteps) err_ << " - done.\n";
    err_.flush();
  }
  bool started() const { return shown_ >= 0 && shown_ < kSteps; }

 private:
  static constexpr int kSteps = 40;
  std::ostream& err_;
  int shown_ = -1;  // the last step shown
};

}  // namespace tsk::cli
