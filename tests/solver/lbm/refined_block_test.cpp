// The refined block's geometry: a block that does not fit is refused with the axis and the
// allowed range; the fine lattice maps onto the coarse cells it refines.
#include <catch2/catch.hpp>

#include <string>

#include "solver/lbm/refinement/refined_block.hpp"

using namespace capsule::lbm::refinement;

namespace {
std::string refusal(int nx, int ny, const BlockExtent& e) {
  try {
    RefinedBlock<2> block(nx, ny, 1, e);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}
}  // namespace

TEST_CASE("refined block: a block that does not fit is refused", "[lbm][refinement]") {
  // Three coarse cells between the block and the walls (ring and one-sided derivatives).
  CHECK_THAT(refusal(16, 16, BlockExtent{{4, 2, 0}, {8, 10, 1}}),
             Catch::Contains("refined block y = [2, 10)") && Catch::Contains("[0, 16)"));
  CHECK_THAT(refusal(16, 16, BlockExtent{{4, 3, 0}, {8, 14, 1}}), Catch::Contains("refined block y"));
  CHECK_THAT(refusal(16, 16, BlockExtent{{2, 4, 0}, {8, 10, 1}}),
             Catch::Contains("refined block x = [2, 8)") && Catch::Contains("span the whole axis"));
  CHECK_THAT(refusal(16, 16, BlockExtent{{6, 4, 0}, {6, 10, 1}}), Catch::Contains("begin must be below end"));
  // The y axis (walls) can never be spanned.
  CHECK_THAT(refusal(16, 16, BlockExtent{{0, 0, 0}, {16, 16, 1}}), Catch::Contains("refined block y"));
  CHECK(refusal(16, 16, BlockExtent{{3, 3, 0}, {13, 13, 1}}).empty());
  CHECK(refusal(16, 16, BlockExtent{{0, 3, 0}, {16, 13, 1}}).empty());
}

TEST_CASE("refined block: fine lattice over the block and its ring", "[lbm][refinement]") {
  RefinedBlock<2> block(16, 16, 1, BlockExtent{{4, 5, 0}, {8, 10, 1}});
  CHECK(block.fine_n(0) == 2 * (4 + 2));
  CHECK(block.fine_n(1) == 2 * (5 + 2));
  CHECK(block.covered({4, 5, 0}));
  CHECK(!block.covered({3, 5, 0}));
  CHECK(block.ring({3, 4, 0}));
  CHECK(block.ring({8, 10, 0}));
  CHECK(!block.ring({9, 10, 0}));
  // Fine (2, 2) is the first block cell, a child of the first covered coarse cell, at 4.25, 5.25.
  CHECK(block.fine_in_block({2, 2, 0}));
  CHECK(!block.fine_in_block({1, 2, 0}));
  CHECK(block.parent({2, 2, 0}) == std::array<int, 3>{4, 5, 0});
  CHECK(block.fine_centre({2, 2, 0})[0] == 4.25);
  CHECK(block.first_child({3, 4, 0}) == std::array<int, 3>{0, 0, 0});
  // A spanned axis is periodic on the fine lattice.
  RefinedBlock<2> band(4, 16, 1, BlockExtent{{0, 5, 0}, {4, 10, 1}});
  CHECK(band.spans(0));
  std::array<int, 3> f{-1, 3, 0};
  CHECK(band.wrap_fine(f));
  CHECK(f[0] == 7);
}
