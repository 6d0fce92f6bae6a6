#pragma once
// What the 2D and 3D drivers share: the solver choices every member file records, and the
// output loop -- one row per output interval, the health check before a row is written
// (no row from a broken state), the protocol fed and its markers kept, shapes at the
// requested times, periodic checkpoints of the .partial file.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "solver/io/member_file.hpp"
#include "solver/run/protocol.hpp"
#include "solver/scene/scene.hpp"
#include "solver/scene/units.hpp"

namespace capsule {

// The lattice-unit choices of a member (README "Member files").
inline void record_units(io::MemberWriter& out, const Scene& scene, const Units& u) {
  out.set_attribute("tau", u.tau);
  out.set_attribute("tau_rule", scene.tau > 0 ? std::string("from the scene") : std::string("choose_tau (README)"));
  out.set_attribute("nu", u.nu);
  out.set_attribute("nu_inside", u.nu_inside);
  out.set_attribute("shear_rate", u.shear_rate);
  out.set_attribute("E_s", u.E_s);
  out.set_attribute("E_B", u.E_B);
  out.set_attribute("E_B_convention", std::string("E_B = E_b a^2 E_s (README Conventions)"));
  out.set_attribute("mu_s", u.mu_s);
  out.set_attribute("steps_per_kt", u.steps_per_kt);
  out.set_attribute("precision", scene.precision);  // of the fluid's populations
  const auto n = scene.grid();
  std::ostringstream grid;
  grid << n[0] << "x" << n[1];
  if (scene.dim == 3) grid << "x" << n[2];
  out.set_attribute("grid", grid.str());
  out.set_attribute("nx", static_cast<long>(n[0]));
  out.set_attribute("ny", static_cast<long>(n[1]));
  if (scene.dim == 3) out.set_attribute("nz", static_cast<long>(n[2]));
}

// Runs `sim` to the end of the protocol. `measure(beta)` returns the row of measures and
// fills the tracked phase angles; `write_shape(kt)` stores a shape. Sim provides kt(),
// health(row) (empty when healthy), step(shear_factor) and optionally failure() (a
// problem found between outputs) and full_fields_next_step() (called before the last step
// of each output interval). Returns "complete" or "unstable at kt = X: reason".
template <class Sim, class Measure, class WriteShape>
std::string run_output_loop(Sim& sim, const Scene& scene, Protocol& protocol, io::MemberWriter& out, bool quiet,
                            double shear_rate, Measure&& measure, WriteShape&& write_shape) {
  using Clock = std::chrono::steady_clock;
  const long steps_per_output = std::max(1L, std::lround(scene.output_interval_kt / shear_rate));
  std::vector<double> shapes = scene.shapes_at_kt;
  std::sort(shapes.begin(), shapes.end());
  std::size_t next_shape = 0;
  auto last_checkpoint = Clock::now();
  double next_progress = 0.0;
  std::vector<double> beta;
  auto unstable = [&](const std::string& why) {
    std::ostringstream s;
    s << "unstable at kt = " << sim.kt() << ": " << why;
    return s.str();
  };
  for (;;) {
    std::map<std::string, double> row = measure(beta);
    if (const std::string bad = sim.health(row); !bad.empty()) return unstable(bad);
    row["shear_on"] = protocol.shear_on() ? 1.0 : 0.0;
    row["shear_factor"] = protocol.shear_factor(sim.kt());
    out.append(row, beta);
    while (next_shape < shapes.size() && shapes[next_shape] <= sim.kt() + 0.5 * scene.output_interval_kt) {
      write_shape(sim.kt());
      ++next_shape;
    }
    protocol.observe(sim.kt(), row["D_xy"], row["theta"], beta.empty() ? 0.0 : beta[0]);
    if (!quiet && sim.kt() >= next_progress) {
      std::cerr << "kt = " << sim.kt() << "  D_xy = " << row["D_xy"] << "  theta = " << row["theta"]
                << (protocol.shear_on() ? "  shear" : "  recover") << "\n";
      next_progress += 1.0;
    }
    if (out.rows() % 50 == 0 ||
        std::chrono::duration<double>(Clock::now() - last_checkpoint).count() > 30.0) {
      out.checkpoint();
      last_checkpoint = Clock::now();
    }
    if (protocol.finished()) return "complete";
    for (long i = 0; i < steps_per_output; ++i) {
      // A sim that writes the fluid's velocity only near the membrane is told which step
      // precedes a row, so the row sees the whole field (max_speed).
      if constexpr (requires { sim.full_fields_next_step(); })
        if (i == steps_per_output - 1) sim.full_fields_next_step();
      sim.step(protocol.shear_factor(sim.kt()));
    }
    if constexpr (requires { sim.failure(); }) {
      if (!sim.failure().empty()) return unstable(sim.failure());
    }
  }
}

}  // namespace capsule
