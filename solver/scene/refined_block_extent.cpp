#include "solver/scene/refined_block_extent.hpp"

#include <algorithm>
#include <cmath>

#include "solver/membrane3d/mesh.hpp"
#include "solver/membrane3d/shapes.hpp"

namespace capsule {

double start_shape_radius(const Scene& scene) {
  const double r_m = scene.resolution.a - scene.resolution.marker_inset;
  if (scene.shape != Shape::biconcave) return r_m;
  const membrane3d::Mesh m = membrane3d::biconcave_mesh(membrane3d::unit_icosphere(scene.resolution.mesh_level), r_m);
  double r = 0.0;
  for (const auto& x : m.x) r = std::max(r, x.norm());
  return r;
}

double refined_block_min_margin(const Scene::Resolution& resolution) {
  return (0.5 + 0.5 * ib::delta_width(resolution.delta)) / resolution.a;
}

RefinedBlockPlan refined_block_extent(const Scene& scene) {
  RefinedBlockPlan plan;
  const std::vector<int> n = scene.grid();
  static const char* axis[3] = {"x", "y", "z"};
  for (int d = 0; d < 3; ++d)
    if (n[d] % 2 != 0) {
      plan.why = "the domain holds " + std::to_string(n[d]) + " fine nodes along " + axis[d] +
                 ": the coarse lattice needs an even count (a x domain even on every axis)";
      return plan;
    }
  const double R = start_shape_radius(scene), a = scene.resolution.a;
  const double half = R + scene.resolution.refine->margin * a;
  // In y the cube [c - half, c + half] (fine spacings, c = ny / 2) rounded outward to whole
  // coarse cells must leave three coarse cells (six fine spacings) to each wall: half <= c - 6.
  const int ny_c = n[1] / 2;
  plan.max_margin = std::max(0.0, (0.5 * n[1] - 6.0 - R) / a);
  for (int d = 0; d < 3; ++d) {
    const int nc = n[d] / 2;
    const double c = 0.5 * n[d];
    int begin = static_cast<int>(std::floor(0.5 * (c - half)));
    int end = static_cast<int>(std::ceil(0.5 * (c + half)));
    if (begin < 3 || end > nc - 3) {
      if (d == 1) {
        plan.why = "the block [" + std::to_string(begin) + ", " + std::to_string(end) + ") of coarse cells in y (start shape radius " +
                   std::to_string(R / a) + " a plus the margin) comes within three coarse cells of a wall (the channel has " +
                   std::to_string(ny_c) + ")";
        return plan;
      }
      begin = 0, end = nc;  // periodic x or z: the block spans the axis
    }
    plan.extent.begin[d] = begin;
    plan.extent.end[d] = end;
  }
  return plan;
}

RefinedCellCounts refined_cell_counts(const Scene& scene) {
  const RefinedBlockPlan plan = refined_block_extent(scene);
  if (!plan.why.empty()) return {};
  const std::vector<int> n = scene.grid();
  RefinedCellCounts c{1.0, 1.0};
  for (int d = 0; d < 3; ++d) {
    const int nc = n[d] / 2;
    c.coarse *= nc;
    const bool spans = plan.extent.begin[d] == 0 && plan.extent.end[d] == nc && d != 1;
    c.fine *= spans ? 2.0 * nc : 2.0 * (plan.extent.end[d] - plan.extent.begin[d] + 2);
  }
  return c;
}

}  // namespace capsule
