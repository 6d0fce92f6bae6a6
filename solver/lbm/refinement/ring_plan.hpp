#pragma once
// The geometry of the ring's transfers (explosion.hpp, coalescence.hpp), worked out once when the
// fluid is built: for every ring cell, the coarse cells its Taylor coefficients read and with
// which formula, its fine children, and per direction which channels feed the fine lattice or
// come from it and the shift of each child. A step then does only the arithmetic (a step of the
// fluid spent half its time in these tests before).
#include <array>
#include <cstddef>
#include <vector>

#include "solver/lbm/refinement/refined_block.hpp"

namespace capsule::lbm::refinement {

template <class L>
struct RingPlan {
  static constexpr int Q = L::Q, D = L::D, children = 1 << L::D;
  // Per axis, the Taylor formula of coarse_taylor (explosion.hpp): none (a covered axis on
  // both sides, never in a ring), central from R - 1 and R + 1, or one-sided over two cells
  // away from the block (R + 1, R + 2 forward; R - 1, R - 2 backward).
  enum Kind : signed char { none, central, forward, backward };
  struct Axis {
    Kind kind = none;
    std::size_t m1 = 0, m2 = 0;  // central: R - 1, R + 1; forward: R + 1, R + 2; backward: R - 1, R - 2
  };
  struct Cell {
    std::size_t coarse = 0;
    std::array<Axis, 3> axis{};
    std::array<std::size_t, 1 << L::D> child{};  // fine index of child k (offset bit a of k on axis a)
  };
  std::vector<Cell> cells;                   // the ring, ascending coarse index
  std::vector<int> ring_of;                  // coarse index -> position in cells, or -1
  std::vector<signed char> explode_shift;    // (cell, i, k): the child's shift in units of c_i / 4
  std::vector<signed char> coalesce_shift;   // (cell, i, k): the origin's shift in units of c_i / 4
  std::vector<unsigned char> feeds;          // (cell, i): R + c_i lies in the fine lattice
  std::vector<unsigned char> from_fine;      // (cell, i): R - c_i lies in the fine lattice

  explicit RingPlan(const RefinedBlock<D>& block) {
    ring_of.assign(block.coarse_size(), -1);
    for (int z = 0; z < block.coarse_n(2); ++z)
      for (int y = 0; y < block.coarse_n(1); ++y)
        for (int x = 0; x < block.coarse_n(0); ++x) {
          const std::array<int, 3> R{x, y, z};
          if (!block.ring(R)) continue;
          ring_of[block.coarse_index(x, y, z)] = int(cells.size());
          cells.push_back(cell(block, R));
          for (int i = 0; i < Q; ++i) {
            feeds.push_back(in_fine_lattice(block, R, i, +1) ? 1 : 0);
            from_fine.push_back(in_fine_lattice(block, R, i, -1) ? 1 : 0);
            const std::array<int, 3> f0 = block.first_child(R);
            for (int k = 0; k < children; ++k) {
              std::array<int, 3> o = f0;
              for (int a = 0; a < D; ++a) o[a] += (k >> a) & 1;
              explode_shift.push_back(enters_block(block, o, i, +1));
              coalesce_shift.push_back(static_cast<signed char>(-enters_block(block, o, i, -1)));
            }
          }
        }
  }

 private:
  static Cell cell(const RefinedBlock<D>& block, const std::array<int, 3>& R) {
    Cell c;
    c.coarse = block.coarse_index(R[0], R[1], R[2]);
    for (int a = 0; a < D; ++a) {
      std::size_t at[5] = {0, 0, 0, 0, 0};
      bool ok[5] = {false, false, true, false, false};
      for (int k = -2; k <= 2; ++k) {
        if (k == 0) continue;
        std::array<int, 3> N = R;
        N[a] += k;
        if (a != 1) N[a] = (N[a] % block.coarse_n(a) + block.coarse_n(a)) % block.coarse_n(a);
        ok[k + 2] = N[a] >= 0 && N[a] < block.coarse_n(a) && !block.covered(N);
        if (ok[k + 2]) at[k + 2] = block.coarse_index(N[0], N[1], N[2]);
      }
      if (ok[1] && ok[3]) c.axis[a] = {central, at[1], at[3]};
      else if (ok[3] && ok[4]) c.axis[a] = {forward, at[3], at[4]};
      else if (ok[1] && ok[0]) c.axis[a] = {backward, at[1], at[0]};
    }
    const std::array<int, 3> f0 = block.first_child(R);
    for (int k = 0; k < children; ++k) {
      std::array<int, 3> o = f0;
      for (int a = 0; a < D; ++a) o[a] += (k >> a) & 1;
      c.child[std::size_t(k)] = block.fine_index(o[0], o[1], o[2]);
    }
    return c;
  }

  // R + sign c_i (wrapped on x and z) inside the channel and the fine lattice.
  static bool in_fine_lattice(const RefinedBlock<D>& block, const std::array<int, 3>& R, int i, int sign) {
    std::array<int, 3> S = R;
    for (int a = 0; a < D; ++a) {
      S[a] += sign * L::c[i][a];
      if (a != 1) S[a] = (S[a] % block.coarse_n(a) + block.coarse_n(a)) % block.coarse_n(a);
    }
    return S[1] >= 0 && S[1] < block.coarse_n(1) && block.in_fine_lattice(S);
  }

  // -1 when o + sign c_i is a block cell (the population crosses at the first sub-step), +1
  // when o + 2 sign c_i is (at the second), 0 otherwise; explosion.hpp and coalescence.hpp
  // read it with their signs.
  static signed char enters_block(const RefinedBlock<D>& block, const std::array<int, 3>& o, int i, int sign) {
    std::array<int, 3> o1 = o, o2 = o;
    for (int a = 0; a < D; ++a) {
      o1[a] += sign * L::c[i][a];
      o2[a] += 2 * sign * L::c[i][a];
    }
    if (block.wrap_fine(o1) && block.fine_in_block(o1)) return -1;
    if (block.wrap_fine(o2) && block.fine_in_block(o2)) return 1;
    return 0;
  }
};

}  // namespace capsule::lbm::refinement
