#pragma once
// `study plan`: one line per member (index, state, directory, swept parameters, cost: nodes,
// kt, node-steps, estimated wall seconds and memory) and the totals, with the campaign's
// estimated wall time on this machine (jobs x threads as `study run` would choose them).
// Changes nothing. Members are expanded, inspected and printed one at a time
// (for_each_member, in two passes: measured speeds first, then the rows), so a
// 10^6-member grid plans in bounded memory.
#include "study/campaign/member_selection.hpp"
#include <filesystem>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "study/campaign/campaign.hpp"
#include "study/state/campaign_survey.hpp"
#include "study/plan/cost_estimate.hpp"
#include "study/plan/measured_speed.hpp"
#include "study/state/results_layout.hpp"

namespace capsule::study {

// What a plan found to run: per pending member (by id) its estimated wall seconds on `threads`
// threads, the concurrency `study run` would choose, and the largest member's memory.
struct PlanSummary {
  std::map<std::string, double> pending_seconds;  // member id -> estimated seconds
  int jobs = 1, threads = 1;
  double wall_seconds = 0, peak_memory = 0;
};

// With a selection (--case, --where), only the members it selects are listed and costed; a
// --where that matches no member is refused (CampaignError).
PlanSummary print_plan(const Campaign& campaign, const ResultsLayout& layout, std::ostream& out,
                       const MemberSelection& selection = {});

// Several campaigns planned together (several files, or a folder of them, e.g. campaigns/ch*.json): each
// one's plan, then the total with every member shared between campaigns counted once (the
// first campaign to run it runs it; the others copy it, state/member_reuse.hpp).
void print_plans(const std::vector<std::string>& campaign_files, const std::filesystem::path& results_dir,
                 std::ostream& out);

// Estimated wall seconds of one member with `threads` threads, corrected by measured speed.
double estimated_member_seconds(const CostEstimate& cost, int dim, int threads, const MeasuredSpeed& speed);

struct CampaignEstimate {
  double wall_seconds = 0;    // of the members that are not complete, with the run's concurrency
  double member_seconds = 0;  // their sum
  int jobs = 1, threads = 1;
  std::size_t pending = 0;
};
CampaignEstimate estimate_campaign(const CampaignSurvey& survey, const MeasuredSpeed& speed, int cores);

}  // namespace capsule::study
