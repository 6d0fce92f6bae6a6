#pragma once
// The MRT moment basis of a lattice L, built at compile time:
//  - M (6)/(11): M[k][i] = P_k(c_i), the k-th velocity polynomial at c_i
//    (the damaged matrix (11) is replaced by d'Humieres et al. 2002, docs/guide/model.md "Fluid");
//  - the squared row norms |M_k|^2 (rows are orthogonal, so M^-1 = M^T diag(1/|M_k|^2));
//  - opposite directions and the parity of each moment (even moments depend only on
//    f_i + f_opp(i), odd ones only on f_i - f_opp(i)), used by the collision kernel;
//  - the equilibrium moments m_eq = M f_eq with f_eq from (5), as exact integer
//    coefficients of the quadratic polynomial in (rho, j):
//      m_eq_k = [ A_k rho + sum_a B_ka j_a + sum_ab C_kab j_a j_b / (2 rho) ] / weight_denominator.
#include <array>

namespace capsule::lbm {

template <class L>
struct MomentBasis {
  static constexpr int Q = L::Q;
  using IntMatrix = std::array<std::array<int, Q>, Q>;

  static constexpr IntMatrix build_matrix() {
    IntMatrix m{};
    for (int k = 0; k < Q; ++k)
      for (int i = 0; i < Q; ++i) m[k][i] = L::moment_polynomial(k, L::c[i][0], L::c[i][1], L::c[i][2]);
    return m;
  }
  static constexpr IntMatrix M = build_matrix();

  static constexpr std::array<int, Q> build_norm2() {
    std::array<int, Q> n{};
    for (int k = 0; k < Q; ++k)
      for (int i = 0; i < Q; ++i) n[k] += M[k][i] * M[k][i];
    return n;
  }
  static constexpr std::array<int, Q> norm2 = build_norm2();

  static constexpr std::array<int, Q> build_opposite() {
    std::array<int, Q> o{};
    for (int i = 0; i < Q; ++i)
      for (int j = 0; j < Q; ++j)
        if (L::c[j][0] == -L::c[i][0] && L::c[j][1] == -L::c[i][1] && L::c[j][2] == -L::c[i][2]) o[i] = j;
    return o;
  }
  static constexpr std::array<int, Q> opposite = build_opposite();

  // Pairs (i, opposite(i)) with i < opposite(i); there are (Q-1)/2 of them.
  static constexpr int P = (Q - 1) / 2;
  static constexpr std::array<int, P> build_pair_first() {
    std::array<int, P> p{};
    int n = 0;
    for (int i = 1; i < Q; ++i)
      if (i < opposite[i]) p[n++] = i;
    return p;
  }
  static constexpr std::array<int, P> pair_first = build_pair_first();

  // +1 if P_k(-c) = P_k(c) for every c, -1 if odd.
  static constexpr std::array<int, Q> build_parity() {
    std::array<int, Q> par{};
    for (int k = 0; k < Q; ++k) {
      bool even = true, odd = true;
      for (int i = 0; i < Q; ++i) {
        even = even && (M[k][i] == M[k][opposite[i]]);
        odd = odd && (M[k][i] == -M[k][opposite[i]]);
      }
      par[k] = even ? 1 : (odd ? -1 : 0);
    }
    return par;
  }
  static constexpr std::array<int, Q> parity = build_parity();
  static constexpr bool all_moments_have_parity() {
    for (int k = 0; k < Q; ++k)
      if (parity[k] == 0) return false;
    return true;
  }
  static_assert(all_moments_have_parity(), "the collision kernel needs even or odd moments");

  // Component a (0..D-1) if moment k is the momentum j_a = sum f c_a, else -1.
  static constexpr int momentum_component(int k) {
    for (int a = 0; a < L::D; ++a) {
      bool same = true;
      for (int i = 0; i < Q; ++i) same = same && (M[k][i] == L::c[i][a]);
      if (same) return a;
    }
    return -1;
  }

  // Equilibrium coefficients (exact integers), from f_eq_i = w_i [rho + 3 c.j + (9/2)(c.j)^2/rho - (3/2) j.j/rho] (5).
  static constexpr std::array<int, Q> build_eq_A() {
    std::array<int, Q> a{};
    for (int k = 0; k < Q; ++k)
      for (int i = 0; i < Q; ++i) a[k] += M[k][i] * L::weight_numerator[i];
    return a;
  }
  static constexpr std::array<int, Q> eq_A = build_eq_A();

  static constexpr std::array<std::array<int, 3>, Q> build_eq_B() {
    std::array<std::array<int, 3>, Q> b{};
    for (int k = 0; k < Q; ++k)
      for (int a = 0; a < 3; ++a)
        for (int i = 0; i < Q; ++i) b[k][a] += 3 * M[k][i] * L::weight_numerator[i] * L::c[i][a];
    return b;
  }
  static constexpr std::array<std::array<int, 3>, Q> eq_B = build_eq_B();

  // C_kab multiplies j_a j_b / (2 rho): 9 sum M w c_a c_b - 3 delta_ab sum M w.
  static constexpr std::array<std::array<std::array<int, 3>, 3>, Q> build_eq_C() {
    std::array<std::array<std::array<int, 3>, 3>, Q> cc{};
    for (int k = 0; k < Q; ++k)
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) {
          int s = 0;
          for (int i = 0; i < Q; ++i) s += 9 * M[k][i] * L::weight_numerator[i] * L::c[i][a] * L::c[i][b];
          if (a == b) s -= 3 * eq_A[k];
          cc[k][a][b] = s;
        }
    return cc;
  }
  static constexpr std::array<std::array<std::array<int, 3>, 3>, Q> eq_C = build_eq_C();
};

}  // namespace capsule::lbm
