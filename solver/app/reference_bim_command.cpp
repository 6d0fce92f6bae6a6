// `capsule reference-bim`: the boundary-integral reference capsule (solver/boundary_integral/).
#include "solver/app/reference_bim_command.hpp"

#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>

#include "solver/app/choice_option.hpp"
#include "common/cli_support.hpp"
#include "solver/boundary_integral/reference_run.hpp"

namespace capsule::cli {

Command add_reference_bim_command(CLI::App& capsule) {
  auto options = std::make_shared<boundary_integral::ReferenceRunOptions>();
  boundary_integral::ReferenceRunOptions& o = *options;
  CLI::App& app = *capsule.add_subcommand("reference-bim", "boundary-integral reference capsule");
  app.footer("A capsule in unbounded simple shear by the boundary-integral method (V = 1, Stokes flow, no walls;\n"
             "units a = k = mu = 1). Prints a summary row (CSV with header).\n"
             "Example: capsule reference-bim --ca 0.1 --level 3 --steady 1e-4\n"
             "Exit status: 0 done, 1 the run failed (unstable or a file could not be written), 2 bad command line.");
  auto& c = o.capsule;
  app.add_option("--ca", c.Ca, "capillary number mu k a / E_s (34)")->required()->check(capsule::cli::finite_number_in(1e-5, 10.0, true));
  add_choice_option(app, "--law", c.law, "membrane law");
  app.add_option("--C", c.C, "Skalak area-dilation constant")->capture_default_str()->check(capsule::cli::finite_number_in(0, 1e3));
  app.add_option("--eb", c.E_b, "bending modulus E_B / (a^2 E_s)")->capture_default_str()->check(capsule::cli::finite_number_in(0.0, 10.0, true));
  app.add_option("--level", c.level, "icosphere level (2: 162, 3: 642, 4: 2562, 5: 10242 vertices)")
      ->capture_default_str()->check(CLI::Range(1, 6));
  app.add_option("--kt", o.kt_end, "shear until this kt (with --steady: at most)")->capture_default_str()->check(capsule::cli::finite_number_in(1e-3, 1000.0, true));
  app.add_option("--steady", o.steady_tolerance,
                 "stop once the range of D over the last --steady-window kt is below this (0: run to --kt)")
      ->capture_default_str()->check(capsule::cli::finite_number_in(0.0, 1.0, true));
  app.add_option("--steady-window", o.steady_window_kt, "window of --steady, in kt")->capture_default_str()->check(capsule::cli::finite_number_in(0.05, 100.0, true));
  app.add_option("--cfl", c.cfl, "time step as a fraction of the explicit limit")->capture_default_str()->check(capsule::cli::finite_number_in(1e-3, 2.0, true));
  app.add_option("--dt", c.dt, "time step in kt units (overrides --cfl)")->check(capsule::cli::finite_number_in(1e-7, 1.0, true));
  app.add_option("--every", o.every, "series interval in kt")->capture_default_str()->check(capsule::cli::finite_number_in(1e-4, 100.0, true));
  app.add_option("--singular-gauss", c.quadrature.singular_gauss_points, "Gauss points per direction on the target's own triangles")
      ->capture_default_str()->check(CLI::IsMember({4, 6, 8, 12, 16}));
  app.add_option("--near-gauss", c.quadrature.near_gauss_points, "Gauss points per direction on the other near triangles")
      ->capture_default_str()->check(CLI::IsMember({4, 6, 8, 12, 16}));
  app.add_option("--near", c.quadrature.near_factor, "near zone, in longest edges of a triangle")
      ->capture_default_str()->check(capsule::cli::finite_number_in(0.0, 20.0, true));
  app.add_option("--near-radius", c.quadrature.near_radius, "near zone, in units of a (the larger of the two applies)")
      ->capture_default_str()->check(capsule::cli::finite_number_in(0.0, 4.0, true));
  app.add_option("-o,--series", o.series_path, "CSV file for the shape series (kt, D, theta, ...)");
  return {&app, [options] {
    try {
      boundary_integral::run_reference(*options, std::cout);
      return 0;
    } catch (const std::exception& e) {
      std::cerr << "capsule reference-bim: " << e.what() << "\n";
      return 1;
    }
  }};
}

}  // namespace capsule::cli
