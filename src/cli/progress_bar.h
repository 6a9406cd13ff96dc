// A one-line progress bar on stderr, drawn only when stderr is a terminal.
#pragma once

#include <chrono>
#include <string>

namespace autoblock::cli {

class ProgressBar {
 public:
  // Inputs: total, the number of steps; label, shown before the bar.
  ProgressBar(long total, std::string label);
  ~ProgressBar();
  // Inputs: done, steps finished so far; note, shown after the bar (e.g. the current file).
  void update(long done, const std::string& note = "");
  // Clears the line.
  void finish();
  // True when the bar is drawn (stderr is a terminal).
  bool drawn() const { return enabled_; }

 private:
  long total_;
  std::string label_;
  bool enabled_;
  bool finished_ = false;
  std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace autoblock::cli
