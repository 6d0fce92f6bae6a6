#pragma once
// Memory layout of the population arrays: every x-row (fixed y, z) is stored with a
// ghost slot on each side, so the fused kernel streams a whole row in one vector loop
// (x - 1 and x + 1 stay inside the padded row) and then moves the two ghost values to
// the periodic partners (x = nx-1 and x = 0). Rows start at a 32-byte boundary.
// The public fields (force, velocity, density) are unpadded: index x + nx*(y + ny*z).
#include <cstddef>

namespace capsule::lbm {

struct PaddedRows {
  static constexpr std::size_t first = 4;  // x = 0 sits at slot 4, the left ghost at 3
  std::size_t nx = 0, rows = 0, stride = 0;

  PaddedRows() = default;
  PaddedRows(std::size_t nx_, std::size_t rows_)
      : nx(nx_), rows(rows_), stride(((first + nx_ + 1) + 3) / 4 * 4) {}

  std::size_t per_population() const { return rows * stride; }
  // Slot of (row, x) inside one population's array; x = -1 and x = nx are the ghosts.
  std::size_t index(std::size_t row, std::size_t x) const { return row * stride + first + x; }
};

}  // namespace capsule::lbm
