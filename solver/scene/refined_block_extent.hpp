#pragma once
// Where a scene's refined block lies (resolution.refine, docs/guide/refinement.md "In a
// scene"): the coarse cells that cover the cube of half-width R + margin a about the domain's
// centre, R the start shape's circumscribed radius. The cube holds the capsule in any
// orientation, so it does not depend on the start inclination nor on the protocol's direction;
// the margin is the room the capsule has to deform in.
#include <string>

#include "solver/lbm/refinement/refined_block.hpp"
#include "solver/scene/scene.hpp"

namespace capsule {

// The start shape's largest distance from its centre in lattice units (of the fine lattice
// under refinement): r_m = a - marker_inset for the sphere, the biconcave disc's rim radius
// (its mesh's farthest vertex) for the biconcave cell.
double start_shape_radius(const Scene& scene);

// The smallest margin (units of a) at which the start shape's kernel support lies on the
// block's collided cells: half the delta's width plus half a spacing, over a.
double refined_block_min_margin(const Scene::Resolution& resolution);

// The block in coarse cells. x and z are spanned whole (periodic) where the cube would come
// within three coarse cells of the box's ends; y never (the walls). A scene whose lattice or
// cube does not fit gets `why` set and an empty extent; the caller names the key.
struct RefinedBlockPlan {
  lbm::refinement::BlockExtent extent;
  std::string why;       // empty when the block fits
  double max_margin = 0;  // the largest margin (units of a) whose cube fits in y
};
RefinedBlockPlan refined_block_extent(const Scene& scene);

// The cells of both lattices (the fine one with its ghost layer), for the memory and cost
// estimates; zeros when the block does not fit.
struct RefinedCellCounts {
  double coarse = 0, fine = 0;
};
RefinedCellCounts refined_cell_counts(const Scene& scene);

}  // namespace capsule
