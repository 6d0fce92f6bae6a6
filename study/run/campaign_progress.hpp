#pragma once
// The one line `study run` shows while GNU Parallel runs the members (instead of its bar):
//   campaign demo: 3 done, 2 running, 7 left; ETA 4m10s
// Done / running / left come from the members' own files (member.h5, and the live capsule's
// member.h5.progress); the ETA from the running members' own progress and, for those not
// started, the cost model corrected by the speed measured on the members that have run.
// On a terminal the line is redrawn in place; otherwise a line is printed every 30 s.
#include <ostream>
#include <vector>

#include "study/state/campaign_survey.hpp"
#include "study/state/member_state.hpp"
#include "study/plan/cost_estimate.hpp"
#include "study/plan/measured_speed.hpp"

namespace capsule::study {

// Seconds left for a running member. Its own ETA, except where that ETA runs to a cap (a phase
// that ends on a condition: steady shear, settled recovery), which is an upper bound, often
// several times the real end (a recovery capped at kt 56 that settles near kt 9): then the
// member's expected end (the cost model's, corrected by the phase lengths measured so far:
// SpeedCalibration::expected_steps), at the member's own measured speed, never beyond its cap.
// `fallback` (the model's seconds) where the member has not measured its speed yet.
double running_member_seconds_left(const MemberProgress& progress, const CostEstimate& cost,
                                   const SpeedCalibration& speed, double fallback);

class CampaignProgress {
 public:
  CampaignProgress(const CampaignSurvey& survey, std::vector<std::size_t> to_run, int jobs, int threads,
                   bool terminal, std::ostream& out);
  void tick();    // call about once a second
  void finish();  // ends the redrawn line

  struct Counts {
    std::size_t done = 0, running = 0, left = 0;
    double eta_seconds = 0;
  };
  Counts count();  // reads the members' files now

 private:
  const CampaignSurvey& survey_;
  std::vector<std::size_t> to_run_;
  std::vector<CostEstimate> cost_;
  std::vector<bool> measured_;
  MeasuredSpeed speed_;
  int jobs_, threads_;
  bool terminal_;
  std::ostream& out_;
  double last_print_ = -1e300;
  bool drew_ = false;
};

}  // namespace capsule::study
