#include "study/run/campaign_progress.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "study/state/duration_text.hpp"
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

std::string progress_line(const std::string& campaign, const ProgressCounts& c, double elapsed_seconds,
                          double eta_seconds, bool bar) {
  const double fraction = std::clamp(c.fraction_done, 0.0, 1.0);
  const int percent = c.running + c.left == 0 ? 100 : std::min(99, static_cast<int>(std::floor(100.0 * fraction)));
  std::ostringstream line;
  line << "campaign " << campaign << " ";
  if (bar) {
    constexpr int width = 20;
    const int filled = std::min(width, static_cast<int>(std::floor(width * percent / 100.0)));
    line << "[" << std::string(filled, '#') << std::string(width - filled, '-') << "] ";
  }
  line << percent << "% | " << c.done << " done, " << c.running << " running, " << c.left << " left | "
       << format_duration(elapsed_seconds) << " elapsed, ETA "
       << (c.running + c.left == 0 ? "0s" : eta_seconds < 0.5 ? "<1s" : format_duration(eta_seconds));
  return line.str();
}

CampaignProgress::CampaignProgress(const CampaignSurvey& survey, std::vector<std::size_t> to_run, int jobs, int threads,
                                   bool terminal, std::ostream& out)
    : survey_(survey), to_run_(std::move(to_run)), measured_(to_run_.size(), false), speed_(measure_speed(survey)),
      jobs_(std::max(1, jobs)), threads_(std::max(1, threads)), terminal_(terminal), out_(out), start_(now_seconds()) {
  for (std::size_t i : to_run_) cost_.push_back(estimate_cost(survey.members[i].scene, &speed_.lengths));
}

CampaignProgress::Counts CampaignProgress::count() {
  Counts c;
  double remaining = 0, longest = 0, work = 0, work_done = 0;
  for (std::size_t k = 0; k < to_run_.size(); ++k) {
    const Member& m = survey_.members[to_run_[k]];
    const MemberPaths p = survey_.layout.member(m);
    const int dim = m.scene.at("dim").get<int>();
    const double estimate = estimated_member_seconds(cost_[k], dim, threads_, speed_);
    work += estimate;
    std::error_code ec;
    if (std::filesystem::exists(p.h5, ec)) {
      ++c.done;
      c.reported = true;
      work_done += estimate;
      if (!measured_[k]) measured_[k] = add_measurement(speed_, m, p);  // later estimates learn from it
      continue;
    }
    const MemberCondition cond = inspect_member(p, m.id);
    if (cond.state == MemberState::running) {
      ++c.running;
      const double eta =
          running_member_seconds_left(cond.progress, cost_[k], speed_.for_dim(dim), estimate);
      remaining += eta;
      longest = std::max(longest, eta);
      if (cond.progress.steps_per_second > 0) {
        c.reported = true;
        // The share of its steps done: those behind it against those its ETA leaves.
        const double steps_done = cond.progress.kt * cost_[k].steps_per_kt;
        const double steps_left = eta * cond.progress.steps_per_second;
        if (steps_done + steps_left > 0) work_done += estimate * steps_done / (steps_done + steps_left);
      }
    } else {
      ++c.left;
      remaining += estimate;
    }
  }
  c.eta_seconds = std::max(longest, remaining / jobs_);
  c.fraction_done = work > 0 ? work_done / work : 0.0;
  return c;
}

void CampaignProgress::tick() {
  const double now = now_seconds();
  if (now - last_tick_ < 1.0) return;
  last_tick_ = now;
  show(count(), now - start_);
}

void CampaignProgress::show(const Counts& c, double elapsed) {
  const double eta = eta_.update(elapsed, c.eta_seconds, c.reported);  // every tick, so it smooths in time
  const bool changed = !printed_ || c.done != last_done_ || c.running != last_running_;
  if (!terminal_ && !changed && elapsed - last_print_ < 300.0) return;
  last_print_ = elapsed;
  last_done_ = c.done;
  last_running_ = c.running;
  printed_ = true;
  const std::string line = progress_line(survey_.campaign.name, c, elapsed, eta, terminal_);
  if (terminal_) {
    out_ << "\r" << line << "\033[K" << std::flush;
    drew_ = true;
  } else {
    out_ << line << "\n" << std::flush;
  }
}

void CampaignProgress::finish() {
  if (drew_) out_ << "\n" << std::flush;
  drew_ = false;
}

}  // namespace capsule::study
