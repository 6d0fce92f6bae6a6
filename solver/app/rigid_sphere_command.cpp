// `capsule rigid-sphere` and `capsule rigid-circle`: a rigid shell (3D) or circle (2D) of
// immersed-boundary markers in the lattice shear flow, its torque and stresslet against the exact
// Stokes values (solver/rigid_sphere/).
#include "solver/app/rigid_sphere_command.hpp"

#include <CLI/CLI.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include "solver/app/choice_option.hpp"
#include "common/cli_support.hpp"
#include "solver/common/atomic_write.hpp"
#include "solver/rigid_sphere/rigid_circle.hpp"
#include "solver/rigid_sphere/rigid_shell.hpp"

namespace capsule::cli {

namespace {

// The series CSV (written under a temporary name, then renamed) and the summary row: the run's
// settings (columns, values), then the last row and the change over the last kt against the row
// one kt before it.
void write_result(const rigid_sphere::RigidShellResult& r, const std::string& series, const std::string& columns,
                  const std::string& values) {
  if (!series.empty()) {
    replace_atomically(series, [&](const std::string& tmp) {
      std::ofstream out(tmp);
      rigid_sphere::write_series_csv(r, out);
      if (!out) throw std::runtime_error("cannot write " + tmp);
    });
  }
  const auto& last = r.series.back();
  const rigid_sphere::RigidShellRow* before = &r.series.front();
  for (const auto& row : r.series)
    if (row.kt <= last.kt - 1.0 + 1e-9) before = &row;
  std::cout << columns << ",kt,torque,torque_exact,torque_change,stresslet,stresslet_change,leakage,lag,steps,seconds\n";
  std::cout.precision(7);
  std::cout << values << "," << last.kt << "," << last.torque
            << "," << r.torque_exact << "," << last.torque - before->torque << "," << last.stresslet << ","
            << last.stresslet - before->stresslet << "," << last.leakage << "," << last.lag << "," << r.steps << ","
            << r.seconds << "\n";
}

}  // namespace

Command add_rigid_sphere_command(CLI::App& capsule) {
  struct Settings {
    rigid_sphere::RigidShellOptions o;
    std::string series;
    std::vector<double> domain;
  };
  auto settings = std::make_shared<Settings>();
  auto& [o, series, domain] = *settings;
  CLI::App& app = *capsule.add_subcommand("rigid-sphere", "rigid IB shell: torque and stresslet against Stokes");
  app.footer("A rigid spherical shell of IB markers in the capsule's shear box (no membrane mechanics). Prints one CSV\n"
             "row: the torque and stresslet at the end against the unbounded Stokes values (4 pi mu a^3 k (1 + 2 spin),\n"
             "(10/3) pi mu a^3 k), their change over the last kt, and the leakage.\n"
             "Example: capsule rigid-sphere --a 7 --level 3 -o series.csv\n"
             "Exit status: 0 done, 1 the run failed (blow-up, or a file could not be written), 2 bad command line.");
  app.add_option("--a", o.a, "sphere radius in lattice nodes")->capture_default_str()->check(capsule::cli::finite_number_in(2.0, 64.0, true));
  app.add_option("--marker-radius", o.marker_radius, "radius of the markers (default: a)")->check(capsule::cli::finite_number_in(1.0, 96.0, true));
  app.add_option("--level", o.level, "icosphere level (3: 642, 4: 2562 markers)")->capture_default_str()->check(CLI::Range(1, 6));
  app.add_option("--domain", domain, "box in units of a: x y z (default 10 10 8, the 3D capsule's)")->expected(3)
      ->check(capsule::cli::finite_number_in(3.0, 40.0, true));
  app.add_option("--re", o.Re, "Reynolds number k a^2 / nu")->capture_default_str()->check(capsule::cli::finite_number_in(1e-4, 1.0, true));
  app.add_option("--tau", o.tau, "relaxation time")->capture_default_str()->check(capsule::cli::finite_number_in(0.51, 5.0, true));
  app.add_option("--spin", o.spin, "rotation rate of the shell about z, in units of k (0 held, -0.5 free)")
      ->capture_default_str()->check(capsule::cli::finite_number_in(-2.0, 2.0, true));
  app.add_option("--kt", o.kt, "run until this kt")->capture_default_str()->check(capsule::cli::finite_number_in(0.01, 100.0, true));
  app.add_option("--gain", o.gain, "tether gain: force per unit lag of a marker behind its anchor")
      ->capture_default_str()->check(capsule::cli::finite_number_in(1e-5, 1.0, true));
  add_choice_option(app, "--kernel", o.delta, "IB delta");
  add_choice_option(app, "--precision", o.precision, "fluid populations");
  app.add_option("--every", o.every, "series interval in kt")->capture_default_str()->check(capsule::cli::finite_number_in(1e-3, 100.0, true));
  app.add_option("--refine-margin", o.refine_margin,
                 "refine the fluid by a factor 2 in a block around the shell, this many coarse cells wider on each "
                 "side (0: uniform); --a is then the fine lattice's radius")
      ->capture_default_str()->check(CLI::Range(0, 20));
  app.add_option("-o,--series", series, "CSV file for the series (kt, torque, stresslet, leakage, lag)");
  return {&app, [settings] {
    auto& [o, series, domain] = *settings;
    if (!domain.empty()) o.domain = {domain[0], domain[1], domain[2]};
    try {
      rigid_sphere::validate(o);
    } catch (const std::exception& e) {
      std::cerr << "capsule rigid-sphere: " << e.what() << "\n";
      return 2;
    }
    try {
      const auto r = rigid_sphere::run_rigid_shell(o);
      std::ostringstream values;
      values.precision(7);
      values << o.a << "," << (o.marker_radius > 0 ? o.marker_radius : o.a) << "," << o.level << "," << r.grid[0] << ","
             << r.grid[1] << "," << r.grid[2] << "," << o.spin << "," << choice_name(o.delta) << "," << choice_name(o.precision) << ","
             << o.refine_margin;
      write_result(r, series, "a,marker_radius,level,nx,ny,nz,spin,kernel,precision,refine_margin", values.str());
      return 0;
    } catch (const std::exception& e) {
      std::cerr << "capsule rigid-sphere: " << e.what() << "\n";
      return 1;
    }
  }};
}

Command add_rigid_circle_command(CLI::App& capsule) {
  struct Settings {
    rigid_sphere::RigidCircleOptions o;
    std::string series;
    std::vector<double> domain;
  };
  auto settings = std::make_shared<Settings>();
  auto& [o, series, domain] = *settings;
  CLI::App& app = *capsule.add_subcommand("rigid-circle", "rigid IB circle (2D): torque and stresslet against Stokes");
  app.footer("A rigid circle of IB markers in the 2D capsule's shear channel (no membrane mechanics). Prints one CSV\n"
             "row: the torque and stresslet per unit length at the end against the unbounded Stokes values\n"
             "(2 pi mu a^2 k (1 + 2 spin), 2 pi mu a^2 k), their change over the last kt, and the leakage.\n"
             "Example: capsule rigid-circle --a 10 --kt 5\n"
             "Exit status: 0 done, 1 the run failed (blow-up, or a file could not be written), 2 bad command line.");
  app.add_option("--a", o.a, "circle radius in lattice nodes")->capture_default_str()->check(capsule::cli::finite_number_in(2.0, 200.0, true));
  app.add_option("--marker-radius", o.marker_radius, "radius of the markers (default: a)")->check(capsule::cli::finite_number_in(1.0, 300.0, true));
  app.add_option("--segments", o.segments, "markers on the circle (the 2D capsule's default 140)")->capture_default_str()
      ->check(CLI::Range(16, 100000));
  app.add_option("--domain", domain, "channel in units of a: x y (default 16 12, the 2D capsule's)")->expected(2)
      ->check(capsule::cli::finite_number_in(3.0, 100.0, true));
  app.add_option("--re", o.Re, "Reynolds number k a^2 / nu")->capture_default_str()->check(capsule::cli::finite_number_in(1e-4, 1.0, true));
  app.add_option("--tau", o.tau, "relaxation time")->capture_default_str()->check(capsule::cli::finite_number_in(0.51, 5.0, true));
  app.add_option("--spin", o.spin, "rotation rate of the circle, in units of k (0 held, -0.5 free)")
      ->capture_default_str()->check(capsule::cli::finite_number_in(-2.0, 2.0, true));
  app.add_option("--kt", o.kt, "run until this kt")->capture_default_str()->check(capsule::cli::finite_number_in(0.01, 100.0, true));
  app.add_option("--gain", o.gain, "tether gain: force per unit lag of a marker behind its anchor")
      ->capture_default_str()->check(capsule::cli::finite_number_in(1e-5, 1.0, true));
  add_choice_option(app, "--kernel", o.delta, "IB delta");
  add_choice_option(app, "--precision", o.precision, "fluid populations");
  app.add_option("--every", o.every, "series interval in kt")->capture_default_str()->check(capsule::cli::finite_number_in(1e-3, 100.0, true));
  app.add_option("--refine-margin", o.refine_margin,
                 "refine the fluid by a factor 2 in a block around the circle, this many coarse cells wider on each "
                 "side (0: uniform); --a is then the fine lattice's radius")
      ->capture_default_str()->check(CLI::Range(0, 20));
  app.add_option("-o,--series", series, "CSV file for the series (kt, torque, stresslet, leakage, lag)");
  return {&app, [settings] {
    auto& [o, series, domain] = *settings;
    if (!domain.empty()) o.domain[0] = domain[0], o.domain[1] = domain[1];
    try {
      rigid_sphere::validate(o);
    } catch (const std::exception& e) {
      std::cerr << "capsule rigid-circle: " << e.what() << "\n";
      return 2;
    }
    try {
      const auto r = rigid_sphere::run_rigid_circle(o);
      std::ostringstream values;
      values.precision(7);
      values << o.a << "," << (o.marker_radius > 0 ? o.marker_radius : o.a) << "," << o.segments << "," << r.grid[0] << ","
             << r.grid[1] << "," << o.spin << "," << choice_name(o.delta) << "," << choice_name(o.precision) << ","
             << o.refine_margin;
      write_result(r, series, "a,marker_radius,segments,nx,ny,spin,kernel,precision,refine_margin", values.str());
      return 0;
    } catch (const std::exception& e) {
      std::cerr << "capsule rigid-circle: " << e.what() << "\n";
      return 1;
    }
  }};
}

}  // namespace capsule::cli
