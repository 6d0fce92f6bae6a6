#include "solver/rigid_sphere/rigid_shell.hpp"

#include <cmath>
#include <numbers>
#include <ostream>
#include <stdexcept>

#include "solver/membrane3d/mesh.hpp"
#include "solver/membrane3d/shapes.hpp"
#include "solver/rigid_sphere/tethered_markers.hpp"

namespace capsule::rigid_sphere {

namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("rigid shell: " + what);
}

}  // namespace

void validate(const RigidShellOptions& o) {
  require(o.a >= 2 && o.a <= 64, "a must be in [2, 64] lattice units, got " + std::to_string(o.a));
  require(o.level >= 1 && o.level <= 6, "level must be in [1, 6], got " + std::to_string(o.level));
  for (double d : o.domain) require(d >= 3 && d <= 40, "each domain side must be in [3, 40] a, got " + std::to_string(d));
  validate_tethered_options(o, "rigid shell");
  require(o.refine_margin >= 0 && o.refine_margin <= 20, "refine_margin must be in [0, 20] coarse cells, got " +
                                                             std::to_string(o.refine_margin));
  if (o.refine_margin > 0) {
    for (int d = 0; d < 3; ++d)
      require(std::lround(o.domain[d] * o.a) % 2 == 0,
              "a refined box needs an even number of fine nodes per axis, domain x a gives " +
                  std::to_string(std::lround(o.domain[d] * o.a)));
    require(o.precision == lbm::Precision::double_precision, "a refined run holds its populations in double");
  }
}

RigidShellResult run_rigid_shell(const RigidShellOptions& o) {
  validate(o);
  const double a = o.a, r_m = o.marker_radius > 0 ? o.marker_radius : o.a;
  TetheredMarkers s = tethered_markers_from(o, 3, "rigid shell");
  s.refine_margin = o.refine_margin;
  RigidShellResult result;
  for (int d = 0; d < 3; ++d) result.grid[d] = s.grid[d] = static_cast<int>(std::lround(o.domain[d] * a));
  // The capsule's own icosphere at the marker radius, centred in the box.
  const membrane3d::Mesh shell = membrane3d::sphere_mesh(membrane3d::unit_icosphere(o.level), r_m);
  for (const auto& x : shell.x)
    for (int d = 0; d < 3; ++d) s.anchors.push_back(x(d) + 0.5 * s.grid[d]);
  // Unbounded values: torque 4 pi mu a^3 k (1 + 2 spin), stresslet (10/3) pi mu a^3 k.
  s.torque_unit = 4.0 * std::numbers::pi * s.nu * a * a * a * s.k;
  s.stresslet_unit = (10.0 / 3.0) * std::numbers::pi * s.nu * a * a * a * s.k;
  result.torque_exact = 1.0 + 2.0 * o.spin;
  run_tethered_markers(s, result);
  return result;
}

void write_series_csv(const RigidShellResult& r, std::ostream& out) {
  out << "kt,torque,stresslet,leakage,lag,slip,slip_rms\n";
  out.precision(8);
  for (const auto& s : r.series)
    out << s.kt << "," << s.torque << "," << s.stresslet << "," << s.leakage << "," << s.lag << "," << s.slip << "," << s.slip_rms << "\n";
}

}  // namespace capsule::rigid_sphere
