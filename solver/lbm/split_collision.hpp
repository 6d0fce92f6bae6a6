#pragma once
// The MRT collision of collision.hpp, rewritten for speed on shifted populations
// g_i = f_i - w_i (w_i the rest equilibrium, so a Stokes flow's small deviations keep their
// digits in single precision) and in arithmetic type A (double or float).
//
// Algebra. In the MRT of collision.hpp every non-conserved moment relaxes at s_nu except a
// few "extra" moments: D3Q19 the five ghost moments pi_xx, pi_ww, m_x, m_y, m_z (rate 1.8),
// D2Q9 the heat fluxes q_x, q_y (rate (9)). With d = m - m_eq(rho, j') (22), the reference
// computes m* = m - S d (+F on j, (23)), i.e.
//     f* = f - s_nu (f - f_eq(rho, j'))                           (BGK at s_nu)
//            - sum_{k extra} (s_k - s_nu) d_k M_k / |M_k|^2        (the extra moments)
//            + (1 - s_nu/2) sum_a F_a c_a / |M_ja|^2               (momentum: BGK took s_nu F/2 of it)
// because M is orthogonal, the BGK part relaxes every moment at s_nu, and d_rho = 0,
// d_ja = -F_a/2. Same equilibrium (5), same rates: equal to Collision<L> up to round-off
// (tests/solver/lbm/split_collision_test.cpp). It costs ~1/3 of the full moment transform: the
// equilibrium is per pair of opposite populations, and only the extra moments are
// transformed (D3Q19 ~ 230 flops a node instead of ~800).
//
// With force = false the force is zero (the kernel skips reading it where nothing spreads).
//
// With trt = true (CollisionModel::trt, relaxation.hpp): no extra moments; the even part of
// every pair, (g_i + g_opp)/2, relaxes at s_nu as above, the odd part (g_i - g_opp)/2 at
// s_minus = trt_odd_rate(s_nu) towards 3 w_i c_i.j', and the momentum term becomes
// (1 - s_minus/2) F (the odd relaxation took s_minus F/2 of j + F). The same as Collision<L>
// with model trt up to round-off (tests/solver/lbm/split_collision_test.cpp).
#include <type_traits>

#include "solver/lbm/lattice.hpp"
#include "solver/lbm/moment_basis.hpp"
#include "solver/lbm/relaxation.hpp"
#include "solver/lbm/static_for.hpp"

namespace capsule::lbm {

template <class L, class A>
struct SplitCollision {
  using B = MomentBasis<L>;
  static constexpr int Q = L::Q;
  static constexpr int D = L::D;
  static constexpr int P = B::P;

  // Moments relaxed at a rate other than s_nu (compile-time).
  static constexpr bool extra(int k) {
    const RateGroup g = L::rate_group[k];
    return g == RateGroup::fixed || (g == RateGroup::heat_flux && !L::heat_flux_rate_is_shear_rate);
  }

  template <int coef>
  [[gnu::always_inline]] static inline void add(A& s, A x) {
    if constexpr (coef == 1) s += x;
    else if constexpr (coef == -1) s -= x;
    else if constexpr (coef != 0) s += A(coef) * x;
  }

  // g: shifted populations (in place -> post-collision, still shifted). Returns rho (full,
  // not shifted) and u = (sum f c + F/2)/rho.
  template <bool with_force, bool trt = false>
  [[gnu::always_inline]] static inline void collide(A (&g)[Q], const A (&force)[3], A s_nu, A& rho, A (&u)[3]) {
    A sum[P], diff[P];
    static_for<P>([&](auto p) __attribute__((always_inline)) {
      constexpr int i = B::pair_first[p];
      constexpr int o = B::opposite[i];
      sum[p] = g[i] + g[o];
      diff[p] = g[i] - g[o];
    });
    A drho = g[0];  // rho - 1 (the weights sum to one)
    static_for<P>([&](auto p) __attribute__((always_inline)) { drho += sum[p]; });
    rho = A(1) + drho;
    A jp[3] = {A(0), A(0), A(0)};
    static_for<D>([&](auto a) __attribute__((always_inline)) {
      static_for<P>([&](auto p) __attribute__((always_inline)) { add<L::c[B::pair_first[p]][a]>(jp[a], diff[p]); });
      if constexpr (with_force) jp[a] += A(0.5) * force[a];  // (22)
    });
    const A inv_rho = A(1) / rho;
    static_for<D>([&](auto a) __attribute__((always_inline)) { u[a] = jp[a] * inv_rho; });
    A jj = A(0);
    static_for<D>([&](auto a) __attribute__((always_inline)) { jj += jp[a] * jp[a]; });
    // Shifted equilibrium g_eq_i = w_i [drho + 3 c.j' + (9/2)(c.j')^2/rho - (3/2) j'.j'/rho].
    const A base = drho - A(1.5) * jj * inv_rho;

    // Extra moments: d_k = m_k(g) - m_eq_k(drho, j') (M w = eq_A/36 cancels the rho = 1 part),
    // and their share G_k = -(s_k - s_nu) d_k / |M_k|^2 of the back-transform.
    A G[Q];
    static_for<Q>([&](auto kk) __attribute__((always_inline)) {
      constexpr int k = kk;
      if constexpr (!trt && extra(k)) {
        A m = A(0);
        if constexpr (B::parity[k] == 1) {
          add<B::M[k][0]>(m, g[0]);
          static_for<P>([&](auto p) __attribute__((always_inline)) { add<B::M[k][B::pair_first[p]]>(m, sum[p]); });
        } else {
          static_for<P>([&](auto p) __attribute__((always_inline)) { add<B::M[k][B::pair_first[p]]>(m, diff[p]); });
        }
        A meq = A(0);
        add<B::eq_A[k]>(meq, drho);
        static_for<D>([&](auto a) __attribute__((always_inline)) { add<B::eq_B[k][a]>(meq, jp[a]); });
        A quad = A(0);
        static_for<D>([&](auto a) __attribute__((always_inline)) {
          static_for<D>([&](auto b) __attribute__((always_inline)) { add<B::eq_C[k][a][b]>(quad, jp[a] * jp[b]); });
        });
        meq += quad * (A(0.5) * inv_rho);
        meq *= A(1.0 / double(L::weight_denominator));
        const A rate = A(relaxation_rate<L>(L::rate_group[k], double(s_nu)));
        G[k] = (s_nu - rate) * (m - meq) * A(1.0 / double(B::norm2[k]));
      } else {
        G[k] = A(0);
      }
    });

    // Per weight class: s w (the BGK weight), and the odd part's vector
    // 3 s w j' + (1 - s/2) F / |M_j|^2 (the equilibrium's 3 w c.j' and the momentum term).
    constexpr double wden = double(L::weight_denominator);
    constexpr int jn = B::norm2[momentum_row(0)];
    const A one_minus_s = A(1) - s_nu;
    // trt: the odd part's rate and its momentum term (unused otherwise).
    const A s_odd = trt ? trt_odd_rate(s_nu) : s_nu;
    const A one_minus_s_odd = A(1) - s_odd;
    const A fscale = (A(1) - A(0.5) * s_odd) * A(1.0 / double(jn));
    A eq_shift;  // rest population: only the even part
    {
      constexpr double w0 = double(L::weight_numerator[0]) / wden;
      const A sw = s_nu * A(w0);
      A E0 = A(0);
      static_for<Q>([&](auto kk) __attribute__((always_inline)) {
        constexpr int k = kk;
        if constexpr (!trt && extra(k) && B::parity[k] == 1) add<B::M[k][0]>(E0, G[k]);
      });
      eq_shift = sw * base + E0;
      g[0] = one_minus_s * g[0] + eq_shift;
    }
    static_for<P>([&](auto p) __attribute__((always_inline)) {
      constexpr int i = B::pair_first[p];
      constexpr int o = B::opposite[i];
      constexpr double w = double(L::weight_numerator[i]) / wden;
      A cj = A(0), cF = A(0);
      static_for<D>([&](auto a) __attribute__((always_inline)) {
        add<L::c[i][a]>(cj, jp[a]);
        if constexpr (with_force) add<L::c[i][a]>(cF, force[a]);
      });
      const A sw = s_nu * A(w);
      // s * even part of g_eq + extra even moments
      A even = sw * (base + A(4.5) * inv_rho * (cj * cj));
      static_for<Q>([&](auto kk) __attribute__((always_inline)) {
        constexpr int k = kk;
        if constexpr (!trt && extra(k) && B::parity[k] == 1) add<B::M[k][i]>(even, G[k]);
      });
      if constexpr (trt) {
        // Even part at s_nu, odd part at s_odd: g*_i = (1 - s_nu) g+ + even + (1 - s_odd) g- + odd.
        A odd = (A(3) * s_odd * A(w)) * cj;
        if constexpr (with_force) odd += fscale * cF;
        const A ev = one_minus_s * (A(0.5) * sum[p]) + even;
        const A od = one_minus_s_odd * (A(0.5) * diff[p]) + odd;
        g[i] = ev + od;
        g[o] = ev - od;
      } else {
        // s * odd part of g_eq + momentum + extra odd moments
        A odd = (A(3) * sw) * cj;
        if constexpr (with_force) odd += fscale * cF;
        static_for<Q>([&](auto kk) __attribute__((always_inline)) {
          constexpr int k = kk;
          if constexpr (extra(k) && B::parity[k] == -1) add<B::M[k][i]>(odd, G[k]);
        });
        g[i] = one_minus_s * g[i] + (even + odd);
        g[o] = one_minus_s * g[o] + (even - odd);
      }
    });
  }

 private:
  static constexpr int momentum_row(int a) {
    for (int k = 0; k < Q; ++k)
      if (B::momentum_component(k) == a) return k;
    return -1;
  }
};

}  // namespace capsule::lbm
