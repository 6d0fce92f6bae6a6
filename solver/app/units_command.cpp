#include "solver/app/units_command.hpp"

#include <cstdio>
#include <iostream>
#include <memory>

#include "solver/scene/physical_cell.hpp"
#include "solver/scene/scene.hpp"
#include "solver/scene/units.hpp"

namespace capsule::cli {
namespace {

std::string fixed(const char* format, double a, double b = 0) {
  char buf[200];
  std::snprintf(buf, sizeof buf, format, a, b);
  return buf;
}

void print_units(const Scene& s) {
  const double tau = choose_tau(s);
  const Units u = units_for(s, tau);
  if (s.physical) {
    const PhysicalGroups g = physical_groups(*s.physical, s.law, s.conventions.sls_viscosity);
    std::cout << "The cell in physical units and the groups it gives:\n";
    for (const std::string& l : conversion_lines(*s.physical, g, s.law, s.conventions.sls_viscosity)) std::cout << "  " << l << "\n";
    std::cout << fixed("  lattice Re                %.6g   ", s.Re)
              << (s.Re > g.Re ? "(above the cell's own: the same Stokes flow up to O(Re))\n" : "(the cell's own)\n");
    std::cout << "The lattice:\n"
              << fixed("  a = %.6g lattice spacings: dx = %.6g um\n", s.resolution.a, s.physical->radius_um / s.resolution.a)
              << fixed("  tau = %.6g, %.6g steps per 1/k: ", tau, u.steps_per_kt)
              << fixed("dt = %.6g s\n", g.time_unit_s / u.steps_per_kt)
              << fixed("  kt = 1 is %.6g s; a length of 1 (in a) is %.6g um\n", g.time_unit_s, g.length_unit_um);
    return;
  }
  std::cout << "The scene gives its groups directly (no physical block: times are in units of 1/k, lengths of a):\n"
            << fixed("  Ca %.6g   E_b %.6g", s.Ca, s.E_b) << fixed("   V %.6g   eta %.6g", s.V, s.eta)
            << fixed("   Re %.6g\n", s.Re) << "The lattice:\n"
            << fixed("  a = %.6g lattice spacings, tau = %.6g, ", s.resolution.a, tau)
            << fixed("%.6g steps per 1/k\n", u.steps_per_kt);
}

}  // namespace

Command add_units_command(CLI::App& capsule) {
  auto scene = std::make_shared<std::string>();
  CLI::App& app = *capsule.add_subcommand(
      "units", "print a scene's groups, from its physical block when it has one, and its lattice in um and s");
  app.footer("Example: capsule units tests/data/scenes/rbc_physical_3d.json\n"
             "Exit status: 0 printed, 2 bad scene or command line.");
  app.add_option("scene", *scene, "scene JSON file")->required();
  return {&app, [scene] {
            try {
              print_units(Scene::load(*scene));
              return 0;
            } catch (const std::exception& e) {
              std::cerr << "capsule: " << e.what() << "\n";
              return 2;
            }
          }};
}

}  // namespace capsule::cli
