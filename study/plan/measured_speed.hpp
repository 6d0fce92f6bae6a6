#pragma once
// The cost model corrected by what this machine measured: the members of a campaign that have
// run record wall_seconds, steps and threads; their sum against the model's seconds for the
// same steps gives one correction factor per dimension (docs/guide/running.md "Time and memory estimates").
#include "study/state/campaign_survey.hpp"
#include "study/plan/cost_estimate.hpp"

namespace capsule::study {

struct MeasuredSpeed {
  SpeedCalibration d2, d3;
  // The phase lengths of every finished member in the results folder (the campaign's own and
  // the others'): what estimate_cost expects a phase that ends on a condition to take.
  PhaseLengths lengths;
  const SpeedCalibration& for_dim(int dim) const { return dim == 3 ? d3 : d2; }
  SpeedCalibration& for_dim(int dim) { return dim == 3 ? d3 : d2; }
};

// From every member of the survey whose member.h5 records its wall time (complete, unstable),
// with the phase lengths of the finished members under the survey's results folder.
MeasuredSpeed measure_speed(const CampaignSurvey& survey);

// One member's measured figures into `speed` (false when the file records none).
bool add_measurement(MeasuredSpeed& speed, const Member& member, const MemberPaths& paths);

}  // namespace capsule::study
