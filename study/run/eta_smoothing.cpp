#include "study/run/eta_smoothing.hpp"

#include <algorithm>
#include <cmath>

namespace capsule::study {

EtaSmoother::EtaSmoother(double window_seconds, double max_factor, double time_constant_seconds)
    : window_(window_seconds), max_factor_(max_factor), time_constant_(time_constant_seconds) {}

double EtaSmoother::update(double elapsed, double raw_seconds, bool reported) {
  raw_seconds = std::max(0.0, raw_seconds);
  if (!reported) return raw_seconds;
  // Projected ends in seconds since the start, never below one second (log space).
  const double target = std::log(std::max(1.0, elapsed + raw_seconds));
  if (!started_) {
    started_ = true;
    log_end_ = target;
  } else {
    const double dt = std::max(0.0, elapsed - last_elapsed_);
    log_end_ += (1.0 - std::exp(-dt / time_constant_)) * (target - log_end_);
    // Every projected end shown within the window lies within max_factor of every other.
    while (!shown_.empty() && shown_.front().first < elapsed - window_) shown_.pop_front();
    if (!shown_.empty()) {
      double lowest = shown_.front().second, highest = lowest;
      for (const auto& entry : shown_) {
        lowest = std::min(lowest, entry.second);
        highest = std::max(highest, entry.second);
      }
      const double span = std::log(max_factor_);
      log_end_ = std::clamp(log_end_, highest - span, lowest + span);
    }
    if (raw_seconds > 0 && std::exp(log_end_) <= elapsed) {  // the end shown has passed: start again
      shown_.clear();
      log_end_ = target;
    }
  }
  last_elapsed_ = elapsed;
  shown_.emplace_back(elapsed, log_end_);
  return raw_seconds == 0 ? 0.0 : std::max(0.0, std::exp(log_end_) - elapsed);
}

}  // namespace capsule::study
