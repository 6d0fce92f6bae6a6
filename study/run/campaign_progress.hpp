#pragma once
// The progress `study run` shows while GNU Parallel runs the members (instead of its bar):
//   campaign demo [######--------------] 31% | 1 done, 2 running, 1 left | 1m05s elapsed, ETA 2m20s
// Done / running / left come from the members' own files (member.h5, and the live capsule's
// member.h5.progress); the share done weighs each member by its estimated seconds (a running
// member by the share of its steps done); the ETA comes from the running members' own progress
// and, for those not started, the cost model corrected by the speed measured on the members
// that have run, smoothed (eta_smoothing.hpp) so that it does not swing as members report.
// On a terminal the line is redrawn in place about once a second; otherwise a plain line (no
// bar) is printed when a member starts or ends, and every 5 minutes between.
#include <ostream>
#include <string>
#include <vector>

#include "study/state/campaign_survey.hpp"
#include "study/state/member_state.hpp"
#include "study/plan/cost_estimate.hpp"
#include "study/plan/measured_speed.hpp"
#include "study/run/eta_smoothing.hpp"

namespace capsule::study {

// Seconds left for a running member. Its own ETA, except where that ETA runs to a cap (a phase
// that ends on a condition: steady shear, settled recovery), which is an upper bound, often
// several times the real end (a recovery capped at kt 56 that settles near kt 9): then the
// member's expected end (the cost model's, corrected by the phase lengths measured so far:
// SpeedCalibration::expected_steps), at the member's own measured speed, never beyond its cap.
// `fallback` (the model's seconds) where the member has not measured its speed yet.
double running_member_seconds_left(const MemberProgress& progress, const CostEstimate& cost,
                                   const SpeedCalibration& speed, double fallback);

struct ProgressCounts {
  std::size_t done = 0, running = 0, left = 0;
  double eta_seconds = 0;  // raw: as the members' files say now
  double fraction_done = 0;  // of the estimated work, 0..1
  bool reported = false;     // some member has measured its speed or ended
};

// The line: with the bar (a terminal) or without.
std::string progress_line(const std::string& campaign, const ProgressCounts& c, double elapsed_seconds,
                          double eta_seconds, bool bar);

class CampaignProgress {
 public:
  CampaignProgress(const CampaignSurvey& survey, std::vector<std::size_t> to_run, int jobs, int threads,
                   bool terminal, std::ostream& out);
  void tick();    // call about once a second
  void finish();  // ends the redrawn line

  using Counts = ProgressCounts;
  Counts count();  // reads the members' files now

  // Prints the line for these counts at `elapsed` seconds when it is due (terminal: once a
  // second; otherwise when the counts change, or 5 minutes after the last line).
  void show(const Counts& c, double elapsed);

 private:
  const CampaignSurvey& survey_;
  std::vector<std::size_t> to_run_;
  std::vector<CostEstimate> cost_;
  std::vector<bool> measured_;
  MeasuredSpeed speed_;
  int jobs_, threads_;
  bool terminal_;
  std::ostream& out_;
  double start_ = 0, last_tick_ = -1e300, last_print_ = -1e300;
  std::size_t last_done_ = 0, last_running_ = 0;
  bool printed_ = false, drew_ = false;
  EtaSmoother eta_;
};

}  // namespace capsule::study
