#include "solver/run/protocol.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace capsule {
namespace {
constexpr double nan_v = std::numeric_limits<double>::quiet_NaN();
// Observations come at output intervals: compare times with a small slack so a phase of
// kt = 5 ends at the row written at kt = 5 even when rounding puts it at 4.999999999.
constexpr double time_slack = 1e-9;

std::string num(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}
std::string after_note(double after_kt) { return after_kt > 0 ? " (crossings counted from kt = " + num(after_kt) + ")" : ""; }
}  // namespace

Protocol::Protocol(const Scene& scene)
    : shear_(scene.protocol.shear), recover_(scene.protocol.recover), stretch_(scene.protocol.stretch.has_value()),
      first_(stretch_ ? "stretch" : "shear"), measure_(stretch_ ? "D_axial" : "D_xy"),
      t_max_(nan_v), D_max_(nan_v), t_stop_(nan_v), D_stop_(nan_v),
      t_min_(nan_v), D_min_(nan_v), t_end_(nan_v), D_inf_(nan_v) {}

double Protocol::shear_factor(double kt) const {
  if (phase_ != Phase::shear || stretch_) return 0.0;
  if (shear_.oscillatory_period_kt > 0) return std::sin(std::numbers::pi * kt / shear_.oscillatory_period_kt);
  return 1.0;
}

double Protocol::max_total_kt() const {
  double s = shear_.until == StopCondition::time ? shear_.kt : shear_.max_kt;
  double r = recover_.until == StopCondition::time ? recover_.kt : recover_.max_kt;
  return s + r;
}

bool Protocol::steady(double window_kt, double tolerance, double since_kt) const {
  double now = kt_.back();
  if (now - since_kt < window_kt - time_slack) return false;
  double lo = D_.back(), hi = D_.back();
  for (std::size_t i = kt_.size(); i-- > 0 && kt_[i] >= now - window_kt - time_slack;) {
    lo = std::min(lo, D_[i]);
    hi = std::max(hi, D_[i]);
  }
  return hi - lo < tolerance;
}

bool Protocol::crossed(double previous, double current, double value, double period) {
  // A jump of more than half the angle's period is a wrap, not a crossing: theta (an axis)
  // lives in (-pi/2, pi/2] and wraps by pi; beta (a position) wraps by 2 pi.
  if (std::abs(current - previous) > period / 2) return false;
  return (previous - value) * (current - value) <= 0 && previous != value;
}

void Protocol::observe(double kt, double D, double theta, double beta) {
  if (phase_ == Phase::done) return;
  kt_.push_back(kt);
  D_.push_back(D);
  if (phase_ == Phase::shear) observe_shear(kt, D, theta, beta);
  else observe_recovery(kt, D);
  prev_theta_ = theta;
  prev_beta_ = beta;
  have_prev_ = true;
}

bool Protocol::shear_condition_met(double kt, double theta, double beta) {
  if (shear_.until == StopCondition::time) {
    if (kt >= shear_.kt - time_slack) { note_ = first_ + " stopped at kt = " + num(shear_.kt); return true; }
  } else if (shear_.until == StopCondition::steady) {
    if (steady(shear_.window_kt, shear_.tolerance, 0.0)) {
      note_ = first_ + " stopped when " + measure_ + " was steady (range < " + num(shear_.tolerance) + " over " +
              num(shear_.window_kt) + " kt)";
      return true;
    }
  } else if (shear_.until == StopCondition::theta) {
    if (have_prev_ && kt >= shear_.after_kt - time_slack && crossed(prev_theta_, theta, shear_.value, std::numbers::pi)) {
      note_ = "shear stopped when theta reached " + num(shear_.value) + after_note(shear_.after_kt);
      return true;
    }
  } else if (shear_.until == StopCondition::beta) {
    if (have_prev_ && kt >= shear_.after_kt - time_slack && crossed(prev_beta_, beta, shear_.value, 2 * std::numbers::pi)) {
      note_ = "shear stopped when beta reached " + num(shear_.value) + after_note(shear_.after_kt);
      return true;
    }
  }
  return false;
}

void Protocol::observe_shear(double kt, double D, double theta, double beta) {
  if (std::isnan(D_max_) || D > D_max_) {
    D_max_ = D;
    t_max_ = kt;
  }
  bool stop = shear_condition_met(kt, theta, beta);
  if (!stop && shear_.until != StopCondition::time && kt >= shear_.max_kt - time_slack) {
    stop = true;
    note_ = first_ + " stopped at max_kt = " + num(shear_.max_kt) + " before its condition (" + choice_name(shear_.until) + ") was met";
  }
  if (!stop) return;
  t_stop_ = kt;
  D_stop_ = D;
  t_min_ = kt;
  D_min_ = D;
  phase_ = Phase::recover;
  if (recover_.until == StopCondition::time && recover_.kt <= 0) {
    phase_ = Phase::done;
    t_end_ = kt;
    D_inf_ = D;
    note_ += "; no recovery phase";
  }
}

void Protocol::observe_recovery(double kt, double D) {
  if (D < D_min_) {
    D_min_ = D;
    t_min_ = kt;
  }
  double since = kt - t_stop_;
  bool end = false;
  if (recover_.until == StopCondition::time) {
    end = since >= recover_.kt - time_slack;
    if (end) note_ += "; recovered for " + num(recover_.kt) + " kt";
  } else {
    // The window grows with the recovery (PhaseSpec::window_fraction): settled means no
    // change over a time long against the phase's own time scale, not a stationary point.
    const double window = std::max(recover_.window_kt, recover_.window_fraction * since);
    if (steady(window, recover_.tolerance, t_stop_)) {
      end = true;
      note_ += "; recovery ended when " + measure_ + " settled (range < " + num(recover_.tolerance) + " over the last " +
               num(window) + " kt)";
    }
  }
  if (!end && recover_.until != StopCondition::time && since >= recover_.max_kt - time_slack) {
    end = true;
    note_ += "; recovery ended at max_kt = " + num(recover_.max_kt) + " before " + measure_ + " settled";
  }
  if (end) {
    t_end_ = kt;
    D_inf_ = D;
    phase_ = Phase::done;
  }
}

Protocol::Outlook Protocol::outlook() const {
  Outlook o;
  const bool shear_capped = shear_.until != StopCondition::time;
  const bool recover_capped = recover_.until != StopCondition::time;
  const double shear_end = shear_capped ? shear_.max_kt : shear_.kt;
  const double recover_span = recover_capped ? recover_.max_kt : recover_.kt;
  switch (phase_) {
    case Phase::shear:
      o = {first_, shear_end, shear_capped, shear_end + recover_span, shear_capped || recover_capped};
      break;
    case Phase::recover:
      o = {"recover", t_stop_ + recover_span, recover_capped, t_stop_ + recover_span, recover_capped};
      break;
    case Phase::done:
      o = {"done", t_end_, false, t_end_, false};
      break;
  }
  return o;
}

Protocol::State Protocol::state() const {
  return {static_cast<int>(phase_), kt_, D_, prev_theta_, prev_beta_, have_prev_,
          {t_max_, D_max_, t_stop_, D_stop_, t_min_, D_min_, t_end_, D_inf_}, note_};
}

void Protocol::restore(const State& s) {
  if (s.phase < 0 || s.phase > 2 || s.markers.size() != 8 || s.kt.size() != s.D.size())
    throw std::invalid_argument("Protocol::restore: not a protocol state");
  phase_ = static_cast<Phase>(s.phase);
  kt_ = s.kt;
  D_ = s.D;
  prev_theta_ = s.prev_theta;
  prev_beta_ = s.prev_beta;
  have_prev_ = s.have_prev;
  t_max_ = s.markers[0], D_max_ = s.markers[1], t_stop_ = s.markers[2], D_stop_ = s.markers[3];
  t_min_ = s.markers[4], D_min_ = s.markers[5], t_end_ = s.markers[6], D_inf_ = s.markers[7];
  note_ = s.note;
}

std::map<std::string, double> Protocol::markers() const {
  return {{"t_max", t_max_}, {"D_max", D_max_}, {"t_stop", t_stop_}, {"D_stop", D_stop_},
          {"t_min", t_min_}, {"D_min", D_min_}, {"t_end", t_end_}, {"D_inf", D_inf_}};
}

}  // namespace capsule
