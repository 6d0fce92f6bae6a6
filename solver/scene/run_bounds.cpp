#include "solver/scene/run_bounds.hpp"

#include <sstream>

#include "solver/scene/units.hpp"
#include "solver/common/short_text.hpp"

namespace capsule {

namespace {

// The longest a phase can last: its kt when it runs for a time, else its max_kt.
double longest_kt(const PhaseSpec& p) { return p.until == StopCondition::time ? p.kt : p.max_kt; }

}  // namespace

void check_run_bounds(const Scene& s, const std::string& source) {
  const double tau = choose_tau(s);
  const Units u = units_for(s, tau);
  const std::string lattice = "a = " + number_text(s.resolution.a) + ", Re = " + number_text(s.Re) + ", tau = " + number_text(tau) +
                              (s.resolution.tau > 0 ? "" : " (chosen by the solver)");
  const double kt = longest_kt(s.protocol.shear) + longest_kt(s.protocol.recover);
  const double steps = kt * u.steps_per_kt;
  if (!(steps <= max_run_steps))
    throw SceneError(source + ": Re: the run takes up to " + number_text(steps) + " time steps (" + number_text(kt) + " kt at " +
                     number_text(u.steps_per_kt) + " steps per kt, a^2 / (Re nu) with " + lattice +
                     ") (allowed: at most " + number_text(max_run_steps) + " time steps: Re >= " +
                     number_text(s.Re * steps / max_run_steps) + " at this a and tau, or fewer kt)");
  const double rows = kt / s.output.interval_kt;
  if (rows > max_output_rows)
    throw SceneError(source + ": output.interval_kt: " + number_text(s.output.interval_kt) + " kt over a run of up to " +
                     number_text(kt) + " kt makes " + number_text(rows) + " rows (allowed: [" + number_text(kt / max_output_rows) +
                     ", 10] for this protocol, at most " + number_text(max_output_rows) + " rows)");
  // The inside's relaxation time 0.5 + 3 V nu (13); a zero inside viscosity is no capsule fluid.
  const double inside_tau = 0.5 + 3.0 * u.nu_inside;
  if (s.V != 1.0 && inside_tau < min_inside_tau)
    throw SceneError(source + ": V: the capsule's inside relaxes at tau = 0.5 + V (tau - 0.5) = " + number_text(inside_tau) +
                     " with " + lattice + ", which cannot be run stably (allowed: V >= " +
                     number_text((min_inside_tau - 0.5) / (tau - 0.5)) + " at this tau, up to 100)");
}

}  // namespace capsule
