#include "study/run/campaign_progress.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "study/plan/duration_text.hpp"
#include "study/plan/plan_table.hpp"

namespace capsule::study {

namespace {
double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
}  // namespace

double running_member_seconds_left(const MemberProgress& progress, const CostEstimate& cost,
                                   const SpeedCalibration& speed, double fallback) {
  const double own = progress.eta_member_seconds >= 0 ? progress.eta_member_seconds : fallback;
  if (!progress.member_end_is_cap || progress.steps_per_second <= 0 || cost.steps_per_kt <= 0) return own;
  const double steps_left = std::max(0.0, speed.expected_steps(cost) - progress.kt * cost.steps_per_kt);
  return std::min(own, steps_left / progress.steps_per_second);
}

CampaignProgress::CampaignProgress(const CampaignSurvey& survey, std::vector<std::size_t> to_run, int jobs, int threads,
                                   bool terminal, std::ostream& out)
    : survey_(survey), to_run_(std::move(to_run)), measured_(to_run_.size(), false), speed_(measure_speed(survey)),
      jobs_(std::max(1, jobs)), threads_(std::max(1, threads)), terminal_(terminal), out_(out) {
  for (std::size_t i : to_run_) cost_.push_back(estimate_cost(survey.members[i].scene, &speed_.lengths));
}

CampaignProgress::Counts CampaignProgress::count() {
  Counts c;
  double remaining = 0, longest = 0;
  for (std::size_t k = 0; k < to_run_.size(); ++k) {
    const Member& m = survey_.members[to_run_[k]];
    const MemberPaths p = survey_.layout.member(m);
    std::error_code ec;
    if (std::filesystem::exists(p.h5, ec)) {
      ++c.done;
      if (!measured_[k]) measured_[k] = add_measurement(speed_, m, p);  // later estimates learn from it
      continue;
    }
    const int dim = m.scene.at("dim").get<int>();
    const double estimate = estimated_member_seconds(cost_[k], dim, threads_, speed_);
    const MemberCondition cond = inspect_member(p, m.id);
    if (cond.state == MemberState::running) {
      ++c.running;
      const double eta =
          running_member_seconds_left(cond.progress, cost_[k], speed_.for_dim(dim), estimate);
      remaining += eta;
      longest = std::max(longest, eta);
    } else {
      ++c.left;
      remaining += estimate;
    }
  }
  c.eta_seconds = std::max(longest, remaining / jobs_);
  return c;
}

void CampaignProgress::tick() {
  const double now = now_seconds();
  if (now - last_print_ < (terminal_ ? 1.0 : 30.0)) return;
  last_print_ = now;
  const Counts c = count();
  std::ostringstream line;
  line << "campaign " << survey_.campaign.name << ": " << c.done << " done, " << c.running << " running, " << c.left
       << " left; ETA " << (c.done + c.running + c.left == c.done ? "0s" : format_duration(c.eta_seconds));
  if (terminal_) {
    out_ << "\r" << line.str() << "\033[K" << std::flush;
    drew_ = true;
  } else {
    out_ << line.str() << "\n" << std::flush;
  }
}

void CampaignProgress::finish() {
  if (drew_) out_ << "\n" << std::flush;
  drew_ = false;
}

}  // namespace capsule::study
