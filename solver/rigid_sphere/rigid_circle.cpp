#include "solver/rigid_sphere/rigid_circle.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "solver/rigid_sphere/tethered_markers.hpp"

namespace capsule::rigid_sphere {

namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("rigid circle: " + what);
}

}  // namespace

void validate(const RigidCircleOptions& o) {
  require(o.a >= 2 && o.a <= 200, "a must be in [2, 200] lattice units, got " + std::to_string(o.a));
  require(o.segments >= 16 && o.segments <= 100000, "segments must be in [16, 100000], got " + std::to_string(o.segments));
  for (double d : o.domain) require(d >= 3 && d <= 100, "each domain side must be in [3, 100] a, got " + std::to_string(d));
  validate_tethered_options(o, "rigid circle");
  require(o.refine_margin >= 0 && o.refine_margin <= 20, "refine_margin must be in [0, 20] coarse cells, got " +
                                                             std::to_string(o.refine_margin));
  if (o.refine_margin > 0)
    for (int d = 0; d < 2; ++d)
      require(std::lround(o.domain[d] * o.a) % 2 == 0,
              "a refined channel needs an even number of fine nodes per axis, domain x a gives " +
                  std::to_string(std::lround(o.domain[d] * o.a)));
}

RigidShellResult run_rigid_circle(const RigidCircleOptions& o) {
  validate(o);
  const double a = o.a, r_m = o.marker_radius > 0 ? o.marker_radius : o.a;
  TetheredMarkers s = tethered_markers_from(o, 2, "rigid circle");
  s.refine_margin = o.refine_margin;
  RigidShellResult result;
  result.grid[0] = s.grid[0] = static_cast<int>(std::lround(o.domain[0] * a));
  result.grid[1] = s.grid[1] = static_cast<int>(std::lround(o.domain[1] * a));
  result.grid[2] = s.grid[2] = 1;
  const double cx = 0.5 * s.grid[0], cy = 0.5 * s.grid[1];
  for (int i = 0; i < o.segments; ++i) {
    // Offset by half a segment from the axes, as the 2D capsule's nodes inclined 45 degrees are not aligned either.
    const double phi = 2.0 * std::numbers::pi * (i + 0.5) / o.segments;
    s.anchors.push_back(cx + r_m * std::cos(phi));
    s.anchors.push_back(cy + r_m * std::sin(phi));
  }
  // Unbounded values per unit length: torque 2 pi mu a^2 k (1 + 2 spin), stresslet 2 pi mu a^2 k.
  s.torque_unit = s.stresslet_unit = 2.0 * std::numbers::pi * s.nu * a * a * s.k;
  result.torque_exact = 1.0 + 2.0 * o.spin;
  run_tethered_markers(s, result);
  return result;
}

}  // namespace capsule::rigid_sphere
