#pragma once
// The ETA `study run` shows, smoothed. The raw ETA (campaign_progress.hpp) jumps as members
// start, report their first speed and finish; the smoothed one follows the projected end of
// the campaign (elapsed + ETA): in log space, exponentially with a time constant, and clamped
// so that no two projected ends shown within a window differ by more than a factor. Before any
// member has reported (its own speed, or its end) the raw ETA is shown as it is.
// A projected end that has passed while work is left starts again from the raw ETA.
#include <deque>
#include <utility>

namespace capsule::study {

class EtaSmoother {
 public:
  // A projected end moves by at most `max_factor` within any `window_seconds`, and towards the
  // raw one with time constant `time_constant_seconds`.
  explicit EtaSmoother(double window_seconds = 60.0, double max_factor = 1.5, double time_constant_seconds = 20.0);

  // The ETA to show at `elapsed` seconds, for a raw ETA `raw_seconds`; `reported`: some member
  // has measured its speed or ended.
  double update(double elapsed, double raw_seconds, bool reported);

 private:
  double window_, max_factor_, time_constant_;
  bool started_ = false;
  double log_end_ = 0, last_elapsed_ = 0;
  std::deque<std::pair<double, double>> shown_;  // (elapsed, log projected end) within the window
};

}  // namespace capsule::study
