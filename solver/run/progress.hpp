#pragma once
// Progress of a running member (docs/guide/running.md "Progress"): every `interval` seconds of wall time a
// line on stderr (unless quiet)
//   capsule: shear  kt 1.250 / 3.000  D_xy 0.1834  412 steps/s  7.9 MLUPS  ETA 5m12s (end of shear)
// (D_axial in a stretch: the series the protocol watches)
// and the same facts as JSON in <member>.progress (written atomically), which `study` reads to
// show running members: pid, host, phase, kt, D_xy, steps per second, ETA to the end of the
// phase and of the member ("<=" when a phase ends on a condition: the ETA is then to its cap).
#include <string>

#include "solver/run/protocol.hpp"

namespace capsule {

std::string progress_path_for(const std::string& member_path);  // <member>.progress

// The first progress file, before the member file's .partial exists: names this process, so
// `study` never takes a starting member for a dead one (or a dead one for a starting one).
void write_starting_progress(const std::string& file);

// "2h05m", "5m12s", "42s".
std::string format_duration(double seconds);

class ProgressReporter {
 public:
  // nodes: lattice nodes (for MLUPS); steps_per_kt: 1/k. file: "" for no progress file.
  ProgressReporter(bool print, double interval_seconds, std::string file, double nodes, double steps_per_kt);
  // The progress file stays when the reporter goes (a killed run's file names its dead pid);
  // run_member() removes it when the member ends.
  ProgressReporter(const ProgressReporter&) = delete;
  ProgressReporter& operator=(const ProgressReporter&) = delete;

  void set_D(double D_xy) { D_ = D_xy; }
  // Cheap when not due (one clock read); reports when `interval` has passed since the last one.
  void tick(long step, double kt, const Protocol& protocol);

 private:
  void report(long step, double kt, const Protocol& protocol, double now);
  void write_file(long step, double kt, const Protocol& protocol, double eta_phase, double eta_member);

  bool print_;
  double interval_;
  std::string file_;
  double nodes_, steps_per_kt_;
  double D_ = 0;
  long first_step_ = -1;
  double window_start_ = 0, last_report_ = 0;
  long window_steps_ = 0;
  double rate_ = 0;  // steps per second over the last window
};

}  // namespace capsule
