#pragma once
// The protocol of a member (docs/guide/scenes.md "Keys"): shear until a condition, then recover until
// a condition. Dimension-independent: the driver feeds one observation per output
// interval and asks how fast the walls move. It also keeps the markers the fits need
// (Sec. 3.1 and 4.1.1): t_max/D_max (largest D_xy under shear), t_stop/D_stop (shear
// stopped), t_min/D_min (smallest D_xy after the stop), t_end/D_inf (end of recovery).
// A stretch protocol (Scene::stretch) loads instead of shearing: the walls stay at rest, the
// first phase ends by Scene::shear's rule and every D above is the axial diameter D_axial.
#include <map>
#include <string>
#include <vector>

#include "solver/scene/scene.hpp"

namespace capsule {

class Protocol {
 public:
  explicit Protocol(const Scene& scene);

  // Factor on the wall speeds -+kH/2: 1 under steady shear, sin(pi kt/T) under
  // oscillatory shear (Sec. 5.2.2), 0 once the shear has stopped.
  double shear_factor(double kt) const;

  // One observation per output row. Advances the phase and updates the markers.
  void observe(double kt, double D, double theta, double beta);

  bool shear_on() const { return phase_ == Phase::shear && !stretch_; }
  // Stretch protocol: the patches are pulled (the first phase).
  bool load_on() const { return phase_ == Phase::shear && stretch_; }
  // The series the protocol watches: "D_xy", or "D_axial" under a stretch protocol.
  const std::string& watched() const { return measure_; }
  bool finished() const { return phase_ == Phase::done; }
  // Upper bound on the run's length in kt (both phases at their caps).
  double max_total_kt() const;

  // t_max, D_max, t_stop, D_stop, t_min, D_min, t_end, D_inf; NaN where not reached.
  std::map<std::string, double> markers() const;
  // Why the shear stopped and why the run ended, for the member file.
  std::string phase_note() const { return note_; }

  // Where the member stands, for progress lines: the phase ("shear", "recover", "done"), when
  // the phase ends at the latest (its set time, or its cap max_kt when it ends on a condition:
  // then phase_end_is_cap) and when the member ends at the latest.
  struct Outlook {
    std::string phase;
    double phase_end_kt = 0;
    bool phase_end_is_cap = false;
    double member_end_kt = 0;
    bool member_end_is_cap = false;
  };
  Outlook outlook() const;

  // Restart points: everything observe() reads and markers() reports.
  struct State {
    int phase = 0;  // 0 shear, 1 recover, 2 done
    std::vector<double> kt, D;
    double prev_theta = 0, prev_beta = 0;
    bool have_prev = false;
    std::vector<double> markers;  // t_max, D_max, t_stop, D_stop, t_min, D_min, t_end, D_inf
    std::string note;
  };
  State state() const;
  void restore(const State& s);

 private:
  enum class Phase { shear, recover, done };
  bool steady(double window_kt, double tolerance, double since_kt) const;
  // One output row in the shear phase (and the stop, when it comes) or in the recovery.
  void observe_shear(double kt, double D, double theta, double beta);
  void observe_recovery(double kt, double D);
  // The shear's stop condition (PhaseSpec::until) met at this row; sets the note.
  bool shear_condition_met(double kt, double theta, double beta);
  static bool crossed(double previous, double current, double value, double period);

  PhaseSpec shear_, recover_;
  bool stretch_ = false;
  std::string first_, measure_;  // the first phase's name ("shear" or "stretch") and the watched series
  Phase phase_ = Phase::shear;
  std::vector<double> kt_, D_;
  double prev_theta_ = 0, prev_beta_ = 0;
  bool have_prev_ = false;
  double t_max_, D_max_, t_stop_, D_stop_, t_min_, D_min_, t_end_, D_inf_;
  std::string note_;
};

}  // namespace capsule
