#include "solver/run/progress.hpp"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <stdexcept>
#include <iostream>
#include <nlohmann/json.hpp>

#include "solver/common/atomic_write.hpp"
#include "solver/io/write_guard.hpp"
#include "solver/run/checkpoint.hpp"

namespace capsule {

std::string progress_path_for(const std::string& member_path) { return member_path + ".progress"; }

std::string format_duration(double s) {
  if (!std::isfinite(s) || s < 0) return "?";
  char text[32];
  const long t = std::lround(s);
  if (t >= 3600) std::snprintf(text, sizeof text, "%ldh%02ldm", t / 3600, (t % 3600) / 60);
  else if (t >= 60) std::snprintf(text, sizeof text, "%ldm%02lds", t / 60, t % 60);
  else std::snprintf(text, sizeof text, "%lds", t);
  return text;
}

namespace {
std::string host() {
  char buf[256] = {};
  if (gethostname(buf, sizeof buf - 1) != 0) return "unknown";
  return buf;
}
}  // namespace

namespace {
void write_json_atomically(const std::string& file, const nlohmann::json& j) {
  io::require_ownership("write " + file);
  try {
    write_file_atomically(file, j.dump() + "\n", [&] { io::require_ownership("rename over " + file); });
  } catch (const std::runtime_error&) {  // progress is best effort: a full disk must not end the member
  }
}
}  // namespace

void write_starting_progress(const std::string& file) {
  write_json_atomically(file, {{"pid", static_cast<long>(::getpid())},
                               {"host", host()},
                               {"updated", static_cast<double>(std::time(nullptr))},
                               {"phase", "starting"},
                               {"kt", 0.0},
                               {"steps", 0},
                               {"D_xy", nullptr},
                               {"steps_per_second", 0.0},
                               {"mlups", 0.0},
                               {"phase_end_kt", 0.0},
                               {"phase_end_is_cap", false},
                               {"member_end_kt", 0.0},
                               {"member_end_is_cap", false},
                               {"eta_phase_seconds", nullptr},
                               {"eta_member_seconds", nullptr}});
}

ProgressReporter::ProgressReporter(bool print, double interval, std::string file, double nodes, double steps_per_kt)
    : print_(print), interval_(interval), file_(std::move(file)), nodes_(nodes), steps_per_kt_(steps_per_kt),
      window_start_(steady_seconds()), last_report_(window_start_) {}

void ProgressReporter::tick(long step, double kt, const Protocol& protocol) {
  if (first_step_ < 0) {  // the first step: the progress file exists from now on (pid for `study`)
    first_step_ = step;
    window_steps_ = step;
    window_start_ = steady_seconds();
    write_file(step, kt, protocol, NAN, NAN);
    return;
  }
  const double now = steady_seconds();
  if (interval_ <= 0 || now - last_report_ < interval_) return;
  report(step, kt, protocol, now);
}

void ProgressReporter::report(long step, double kt, const Protocol& protocol, double now) {
  if (now > window_start_) rate_ = (step - window_steps_) / (now - window_start_);
  window_start_ = now;
  window_steps_ = step;
  last_report_ = now;
  const Protocol::Outlook o = protocol.outlook();
  const double eta_phase = rate_ > 0 ? std::max(0.0, o.phase_end_kt - kt) * steps_per_kt_ / rate_ : NAN;
  const double eta_member = rate_ > 0 ? std::max(0.0, o.member_end_kt - kt) * steps_per_kt_ / rate_ : NAN;
  const double mlups = rate_ * nodes_ / 1e6;
  if (print_) {
    char line[256];
    std::snprintf(line, sizeof line, "capsule: %-7s kt %.3f / %s%.3f  %s %.4f  %.0f steps/s  %.1f MLUPS  ETA %s%s (end of %s)\n",
                  o.phase.c_str(), kt, o.phase_end_is_cap ? "<=" : "", o.phase_end_kt, protocol.watched().c_str(), D_,
                  rate_, mlups,
                  o.phase_end_is_cap ? "<=" : "", format_duration(eta_phase).c_str(), o.phase.c_str());
    std::cerr << line << std::flush;
  }
  write_file(step, kt, protocol, eta_phase, eta_member);
}

void ProgressReporter::write_file(long step, double kt, const Protocol& protocol, double eta_phase, double eta_member) {
  if (file_.empty()) return;
  const Protocol::Outlook o = protocol.outlook();
  const double mlups = rate_ * nodes_ / 1e6;
  nlohmann::json j = {{"pid", static_cast<long>(::getpid())},
                      {"host", host()},
                      {"updated", static_cast<double>(std::time(nullptr))},
                      {"phase", o.phase},
                      {"kt", kt},
                      {"steps", step},
                      {"D_xy", std::isfinite(D_) ? nlohmann::json(D_) : nlohmann::json()},  // the watched series' value
                      {"watched", protocol.watched()},  // its name: D_xy, or D_axial in a stretch
                      {"steps_per_second", rate_},
                      {"mlups", mlups},
                      {"phase_end_kt", o.phase_end_kt},
                      {"phase_end_is_cap", o.phase_end_is_cap},
                      {"member_end_kt", o.member_end_kt},
                      {"member_end_is_cap", o.member_end_is_cap},
                      {"eta_phase_seconds", std::isfinite(eta_phase) ? nlohmann::json(eta_phase) : nlohmann::json()},
                      {"eta_member_seconds", std::isfinite(eta_member) ? nlohmann::json(eta_member) : nlohmann::json()}};
  write_json_atomically(file_, j);
}

}  // namespace capsule
