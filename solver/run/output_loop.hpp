#pragma once
// What the 2D and 3D drivers share: the solver choices every member file records, and the
// output loop -- one row per output interval, the health check before a row is written
// (no row from a broken state), the protocol fed and its markers kept, shapes at the
// requested times, periodic rewrites of the .partial file, restart points and progress lines.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "solver/io/member_file.hpp"
#include "solver/io/state_archive.hpp"
#include "solver/run/checkpoint.hpp"
#include "solver/run/progress.hpp"
#include "solver/run/protocol.hpp"
#include "solver/run/run_control.hpp"
#include "solver/scene/scene.hpp"
#include "solver/scene/units.hpp"

namespace capsule {

// The lattice-unit choices of a member (docs/guide/member-files.md "Layout").
inline void record_units(io::MemberWriter& out, const Scene& scene, const Units& u) {
  out.set_attribute("tau", u.tau);
  out.set_attribute("tau_rule", scene.resolution.tau > 0 ? std::string("from the scene") : std::string("choose_tau (README)"));
  out.set_attribute("nu", u.nu);
  out.set_attribute("nu_inside", u.nu_inside);
  out.set_attribute("shear_rate", u.shear_rate);
  out.set_attribute("E_s", u.E_s);
  out.set_attribute("E_B", u.E_B);
  out.set_attribute("E_B_convention", scene.dim == 2 && scene.conventions.E_b_2d == BendingConvention2d::dissertation
                                          ? std::string("E_B = 2 E_b a^2 E_s: the dissertation's 2D E_b = E_B/(a E_s) with a = 0.5 (README Conventions)")
                                          : std::string("E_B = E_b a^2 E_s (README Conventions)"));
  if (scene.dim == 2 && scene.shape == Shape::biconcave)
    out.set_attribute("biconcave_size", scene.conventions.biconcave_2d == BiconcaveSize2d::dissertation
                                            ? std::string("(24)-(25) drawn with the printed a: equivalent radius 0.740 a (README Conventions)")
                                            : std::string("(24)-(25) scaled to equivalent radius a (README Conventions)"));
  out.set_attribute("mu_s", u.mu_s);
  out.set_attribute("steps_per_kt", u.steps_per_kt);
  out.set_attribute("precision", choice_name(scene.resolution.precision));  // of the fluid's populations
  const auto n = scene.grid();
  std::ostringstream grid;
  grid << n[0] << "x" << n[1];
  if (scene.dim == 3) grid << "x" << n[2];
  out.set_attribute("grid", grid.str());
  out.set_attribute("nx", static_cast<long>(n[0]));
  out.set_attribute("ny", static_cast<long>(n[1]));
  if (scene.dim == 3) out.set_attribute("nz", static_cast<long>(n[2]));
}

// Loop state a restart point holds besides the simulation, the protocol and the rows.
inline void save_protocol(io::StateArchive& a, const Protocol& p) {
  const Protocol::State s = p.state();
  a.put_integer("protocol.phase", s.phase);
  a.put("protocol.kt", s.kt);
  a.put("protocol.D", s.D);
  a.put("protocol.prev", std::vector<double>{s.prev_theta, s.prev_beta, s.have_prev ? 1.0 : 0.0});
  a.put("protocol.markers", s.markers);
  a.put_text("protocol.note", s.note);
}

inline void restore_protocol(const io::StateArchive& a, Protocol& p) {
  Protocol::State s;
  s.phase = static_cast<int>(a.integer("protocol.phase"));
  s.kt = a.doubles("protocol.kt");
  s.D = a.doubles("protocol.D");
  const auto& prev = a.doubles("protocol.prev");
  if (prev.size() != 3) throw std::runtime_error("restart point: protocol.prev is not 3 numbers");
  s.prev_theta = prev[0], s.prev_beta = prev[1], s.have_prev = prev[2] != 0.0;
  s.markers = a.doubles("protocol.markers");
  s.note = a.text("protocol.note");
  p.restore(s);
}

// Runs `sim` to the end of the protocol. `measure(beta)` returns the row of measures and
// fills the tracked phase angles; `write_shape(kt)` stores a shape. Sim provides kt(),
// steps(), health(row) (empty when healthy), step(shear_factor), save_state(archive),
// restore_state(archive) and optionally failure() (a problem found between outputs) and
// full_fields_next_step() (called before the last step of each output interval).
// Returns "complete", "unstable at kt = X: reason" or (control.stop_after_last_shape)
// kShapesWritten; throws SimulatedKill at the test step.
//
// Restart points are written between two steps (anywhere inside an output interval): they
// hold the simulation, the protocol, the rows so far and the step's place in its interval,
// so a resumed run takes the next step exactly where the first one would have.
template <class Sim, class Measure, class WriteShape>
std::string run_output_loop(Sim& sim, const Scene& scene, Protocol& protocol, io::MemberWriter& out,
                            const RunControl& control, double shear_rate, double nodes, Measure&& measure,
                            WriteShape&& write_shape) {
  using Clock = std::chrono::steady_clock;
  const long steps_per_output = std::max(1L, std::lround(scene.output.interval_kt / shear_rate));
  std::vector<double> shapes = scene.output.shapes_at_kt;
  std::sort(shapes.begin(), shapes.end());
  std::size_t next_shape = 0;
  auto last_partial = Clock::now();
  std::vector<double> beta;
  auto unstable = [&](const std::string& why) {
    std::ostringstream s;
    s << "unstable at kt = " << sim.kt() << ": " << why;
    return s.str();
  };
  ProgressReporter progress(!control.quiet, control.progress_seconds, control.progress_file, nodes, 1.0 / shear_rate);
  CheckpointClock clock(control.checkpoint);
  long checkpoints = 0;
  double checkpoint_seconds = 0;

  long first_step = 0;  // where in its output interval the loop starts
  bool resumed = false;
  double last_D = NAN;  // the watched D of the last row (Protocol::watched)
  if (control.resume) {
    io::StateArchive& a = *control.resume;
    try {
      if (a.integer("loop.steps_per_output") != steps_per_output)
        throw std::runtime_error("restart point: another output interval");
      sim.restore_state(a);
      restore_protocol(a, protocol);
      out.restore_rows(a);
      next_shape = static_cast<std::size_t>(a.integer("loop.next_shape"));
      if (control.stop_after_last_shape) {
        out.clear_shapes();
        const double last_row_kt = out.rows() > 0 ? out.series().at("kt").back() : -1.0;
        if (!shapes.empty() && shapes.front() <= last_row_kt + 0.5 * scene.output.interval_kt)
          throw std::runtime_error("restart point: its last row (kt = " + std::to_string(last_row_kt) +
                                   ") is past the first shape asked for");
        next_shape = 0;
      }
      first_step = static_cast<long>(a.integer("loop.interval_step"));
      last_D = a.number("loop.D_xy");
      checkpoints = static_cast<long>(a.integer("loop.checkpoints"));
      checkpoint_seconds = a.number("loop.checkpoint_seconds");
    } catch (const std::exception& e) {
      throw RestartRefused(e.what());
    }
    progress.set_D(last_D);
    out.checkpoint();
    resumed = true;
    if (!control.quiet)
      std::cerr << "capsule: continuing from the restart point at step " << sim.steps() << " (kt = " << sim.kt()
                << ", " << out.rows() << " rows)\n";
  }

  auto write_restart_point = [&](long interval_step) {
    const double t0 = steady_seconds();
    io::StateArchive a;
    if (control.add_run_state) control.add_run_state(a);
    sim.save_state(a);
    save_protocol(a, protocol);
    out.save_rows(a);
    a.put_integer("loop.steps_per_output", steps_per_output);
    a.put_integer("loop.interval_step", interval_step);
    a.put_integer("loop.next_shape", static_cast<std::int64_t>(next_shape));
    a.put_number("loop.D_xy", last_D);
    a.put_integer("loop.checkpoints", checkpoints + 1);
    a.put_number("loop.checkpoint_seconds", checkpoint_seconds);
    a.write(control.restart_path);
    const double dt = steady_seconds() - t0;
    ++checkpoints;
    checkpoint_seconds += dt;
    out.set_attribute("checkpoints_written", checkpoints);
    out.set_attribute("checkpoint_seconds", checkpoint_seconds);
    out.set_attribute("checkpoint_bytes", static_cast<long>(std::filesystem::file_size(control.restart_path)));
    clock.written();
    if (!control.quiet)
      std::cerr << "capsule: restart point at step " << sim.steps() << " (kt = " << sim.kt() << "): "
                << std::filesystem::file_size(control.restart_path) / 1e6 << " MB in " << dt << " s\n";
  };

  for (;;) {
    if (!resumed) {
      std::map<std::string, double> row = measure(beta);
      if (const std::string bad = sim.health(row); !bad.empty()) return unstable(bad);
      row["shear_on"] = protocol.shear_on() ? 1.0 : 0.0;
      row["shear_factor"] = protocol.shear_factor(sim.kt());
      if (scene.protocol.stretch) row["force_on"] = protocol.load_on() ? 1.0 : 0.0;
      out.append(row, beta);
      while (next_shape < shapes.size() && shapes[next_shape] <= sim.kt() + 0.5 * scene.output.interval_kt) {
        write_shape(sim.kt());
        ++next_shape;
      }
      if (control.stop_after_last_shape && next_shape == shapes.size()) return kShapesWritten;
      protocol.observe(sim.kt(), row[protocol.watched()], row["theta"], beta.empty() ? 0.0 : beta[0]);
      last_D = row[protocol.watched()];
      progress.set_D(last_D);
      if (out.rows() % 50 == 0 || std::chrono::duration<double>(Clock::now() - last_partial).count() > 30.0) {
        out.checkpoint();
        last_partial = Clock::now();
      }
      if (protocol.finished()) return "complete";
    }
    resumed = false;
    for (long i = first_step; i < steps_per_output; ++i) {
      bool healthy = true;
      if constexpr (requires { sim.failure(); }) healthy = sim.failure().empty();
      if constexpr (requires { sim.stopped(); }) healthy = healthy && sim.stopped().empty();
      if (stop_signal() != 0) {  // a job's time limit, scancel, Ctrl-C: keep the work done so far
        if (!control.restart_path.empty() && healthy) write_restart_point(i);
        throw StoppedBySignal{sim.steps(), stop_signal()};
      }
      if (!control.restart_path.empty() && healthy && clock.due(sim.steps())) write_restart_point(i);
      if (control.checkpoint.stop_after_step >= 0 && sim.steps() >= control.checkpoint.stop_after_step)
        throw SimulatedKill{sim.steps()};
      // A sim that writes the fluid's velocity only near the membrane is told which step
      // precedes a row, so the row sees the whole field (max_speed).
      if constexpr (requires { sim.full_fields_next_step(); })
        if (i == steps_per_output - 1) sim.full_fields_next_step();
      // A sim that pulls its membrane (a stretch protocol) is told whether the load is on.
      if constexpr (requires { sim.set_load(true); }) sim.set_load(protocol.load_on());
      sim.step(protocol.shear_factor(sim.kt()));
      progress.tick(sim.steps(), sim.kt(), protocol);
    }
    first_step = 0;
    if constexpr (requires { sim.failure(); }) {
      if (!sim.failure().empty()) return unstable(sim.failure());
    }
    // A healthy run that cannot go on (the capsule left a refined block): "stopped at kt = X: why".
    if constexpr (requires { sim.stopped(); }) {
      if (!sim.stopped().empty()) {
        std::ostringstream s;
        s << "stopped at kt = " << sim.kt() << ": " << sim.stopped();
        return s.str();
      }
    }
  }
}

}  // namespace capsule
