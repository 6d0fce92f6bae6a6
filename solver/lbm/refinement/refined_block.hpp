#pragma once
// Geometry of a static refined block (factor 2) inside the coarse channel of fluid.hpp
// (docs/guide/refinement.md): which coarse cells the block covers, the ring of coarse cells
// around it, and the fine lattice that holds the block plus a ghost layer two fine cells
// (one coarse cell) thick over that ring.
//
// Coordinates: coarse cell (i, j, k) sits at (i + 1/2, j + 1/2, k + 1/2) in coarse spacings
// (fluid.hpp); its 2^D fine children sit at (i + 1/4 + c/2, ...) with c = 0, 1 per axis.
// The block covers the coarse cells begin[a] <= i_a < end[a] on the refined axes a < D.
// An axis may be spanned whole (begin 0, end n; x and z only, which are periodic): the
// fine lattice is then periodic on it and has no ghost cells there. Otherwise the block,
// its ring and two more coarse cells must lie inside the box without wrapping (the ring's
// one-sided derivatives need them, explosion.hpp): begin >= 3, end <= n - 3. In y (walls)
// always so.
#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>

namespace capsule::lbm::refinement {

struct BlockExtent {
  std::array<int, 3> begin{0, 0, 0};  // first covered coarse cell per axis
  std::array<int, 3> end{1, 1, 1};    // one past the last
};

template <int D>
class RefinedBlock {
 public:
  RefinedBlock(int nx, int ny, int nz, const BlockExtent& block) : n_{nx, ny, nz}, begin_(block.begin), end_(block.end) {
    static const char* axis_name[3] = {"x", "y", "z"};
    for (int a = 0; a < 3; ++a) {
      if (a >= D) {
        if (n_[a] != 1) throw std::invalid_argument("refined block: a 2D lattice has nz = 1");
        begin_[a] = 0;
        end_[a] = 1;
        span_[a] = true;
        first_[a] = 0;
        nf_[a] = 1;
        continue;
      }
      const std::string key = std::string("refined block ") + axis_name[a];
      if (!(begin_[a] < end_[a])) throw std::invalid_argument(key + ": begin must be below end");
      span_[a] = a != 1 && begin_[a] == 0 && end_[a] == n_[a];
      if (span_[a]) {
        first_[a] = 0;
        nf_[a] = 2 * n_[a];
      } else {
        if (begin_[a] < 3 || end_[a] > n_[a] - 3)
          throw std::invalid_argument(key + " = [" + std::to_string(begin_[a]) + ", " + std::to_string(end_[a]) +
                                      "): the block and three coarse cells around it must fit in [0, " +
                                      std::to_string(n_[a]) + ")" + (a == 1 ? "" : " (or span the whole axis)"));
        first_[a] = begin_[a] - 1;
        nf_[a] = 2 * (end_[a] - begin_[a] + 2);
      }
    }
  }

  int coarse_n(int a) const { return n_[a]; }
  // The covered coarse cells along axis a: [begin(a), end(a)).
  int begin(int a) const { return begin_[a]; }
  int end(int a) const { return end_[a]; }
  int fine_n(int a) const { return nf_[a]; }
  bool spans(int a) const { return span_[a]; }
  std::size_t coarse_size() const { return std::size_t(n_[0]) * std::size_t(n_[1]) * std::size_t(n_[2]); }
  std::size_t fine_size() const { return std::size_t(nf_[0]) * std::size_t(nf_[1]) * std::size_t(nf_[2]); }
  std::size_t coarse_index(int x, int y, int z) const {
    return std::size_t(x) + std::size_t(n_[0]) * (std::size_t(y) + std::size_t(n_[1]) * std::size_t(z));
  }
  std::size_t fine_index(int x, int y, int z) const {
    return std::size_t(x) + std::size_t(nf_[0]) * (std::size_t(y) + std::size_t(nf_[1]) * std::size_t(z));
  }

  // Where population i of a cell lies: the populations are stored by direction, each
  // direction's cells contiguous (x fastest), so that streaming reads and writes in order.
  std::size_t coarse_at(std::size_t cell, int i) const { return std::size_t(i) * coarse_size() + cell; }
  std::size_t fine_at(std::size_t cell, int i) const { return std::size_t(i) * fine_size() + cell; }

  // Coarse cell covered by the block (its populations are not used).
  bool covered(const std::array<int, 3>& c) const {
    for (int a = 0; a < D; ++a)
      if (c[a] < begin_[a] || c[a] >= end_[a]) return false;
    return true;
  }
  // Block or ring: the coarse cells the fine lattice overlaps.
  bool in_fine_lattice(const std::array<int, 3>& c) const {
    for (int a = 0; a < D; ++a)
      if (!span_[a] && (c[a] < begin_[a] - 1 || c[a] > end_[a])) return false;
    return true;
  }
  bool ring(const std::array<int, 3>& c) const { return in_fine_lattice(c) && !covered(c); }

  // Fine cell of the block (collided), as opposed to a ghost cell of the ring.
  bool fine_in_block(const std::array<int, 3>& f) const {
    for (int a = 0; a < D; ++a)
      if (!span_[a] && (f[a] < 2 || f[a] >= nf_[a] - 2)) return false;
    return true;
  }
  // Fine coordinate, possibly outside the fine lattice, wrapped on spanned axes; false if outside.
  bool wrap_fine(std::array<int, 3>& f) const {
    for (int a = 0; a < D; ++a) {
      if (span_[a]) f[a] = (f[a] % nf_[a] + nf_[a]) % nf_[a];
      else if (f[a] < 0 || f[a] >= nf_[a]) return false;
    }
    return true;
  }
  // First fine child (child offset 0 on every axis) of a coarse cell in the fine lattice.
  std::array<int, 3> first_child(const std::array<int, 3>& c) const {
    std::array<int, 3> f{0, 0, 0};
    for (int a = 0; a < D; ++a) f[a] = 2 * (c[a] - first_[a]);
    return f;
  }
  // Coarse parent of a fine cell.
  std::array<int, 3> parent(const std::array<int, 3>& f) const {
    std::array<int, 3> c{0, 0, 0};
    for (int a = 0; a < D; ++a) c[a] = first_[a] + f[a] / 2;
    return c;
  }
  // Centre of fine cell f in coarse spacings.
  std::array<double, 3> fine_centre(const std::array<int, 3>& f) const {
    std::array<double, 3> x{0.5, 0.5, 0.5};
    for (int a = 0; a < D; ++a) x[a] = first_[a] + 0.5 * (f[a] + 0.5);
    return x;
  }

 private:
  std::array<int, 3> n_;
  std::array<int, 3> begin_, end_;
  std::array<bool, 3> span_{};
  std::array<int, 3> first_{};  // coarse cell of fine index 0
  std::array<int, 3> nf_{};
};

}  // namespace capsule::lbm::refinement
