#pragma once
// MRT collision of one node with a body force, computed in moment space: (2) with the
// forcing (22)-(23) (Peng & Luo: the momentum shifted by F/2 before the equilibrium and
// again after; no force terms in the other moments).
//   m = M f;  j' = j + F/2 (22);  m_eq = m_eq(rho, j') (5);
//   non-conserved moments: m*_k = m_k - s_k (m_k - m_eq_k);
//   momentum: j'' = j' + F/2 = j + F (23);
//   f* = f + M^-1 (m* - m).
// The physical velocity is u = j'/rho = (sum f c + F/2)/rho.
//
// Every coefficient is a compile-time integer of MomentBasis<L>, so the sparse
// transforms unroll into adds of f_i +- f_opp(i) without multiplications by 0 or 1.
#include <array>

#include "solver/lbm/lattice.hpp"
#include "solver/lbm/moment_basis.hpp"
#include "solver/lbm/relaxation.hpp"
#include "solver/lbm/static_for.hpp"

namespace capsule::lbm {

template <class L>
struct Collision {
  using B = MomentBasis<L>;
  static constexpr int Q = L::Q;
  static constexpr int D = L::D;
  static constexpr int P = B::P;

  // Collides populations f (in place -> post-collision) at one node.
  // force: body-force density F; s_nu: shear rate of this node. Model: relaxation.hpp (trt:
  // even non-conserved moments at s_nu, odd ones at trt_odd_rate(s_nu)).
  // Returns rho and u = (sum f c + F/2)/rho through the references.
  template <CollisionModel model = CollisionModel::mrt>
  [[gnu::always_inline]] static inline void collide(double (&f)[Q], const double (&force)[3], double s_nu,
                                                    double& rho, double (&u)[3]) {
    // Pair sums and differences: even moments need only sum, odd only diff.
    double sum[P], diff[P];
    static_for<P>([&](auto p) __attribute__((always_inline)) {
      constexpr int i = B::pair_first[p];
      constexpr int o = B::opposite[i];
      sum[p] = f[i] + f[o];
      diff[p] = f[i] - f[o];
    });
    rho = f[0];
    static_for<P>([&](auto p) __attribute__((always_inline)) { rho += sum[p]; });
    double j[3] = {0.0, 0.0, 0.0};
    static_for<D>([&](auto a) __attribute__((always_inline)) {
      static_for<P>([&](auto p) __attribute__((always_inline)) { add_term<L::c[B::pair_first[p]][a]>(j[a], diff[p]); });
    });
    // (22): j' = j + F/2; the physical velocity.
    double jp[3] = {0.0, 0.0, 0.0};
    const double inv_rho = 1.0 / rho;
    static_for<D>([&](auto a) __attribute__((always_inline)) {
      jp[a] = j[a] + 0.5 * force[a];
      u[a] = jp[a] * inv_rho;
    });
    const double half_inv_rho = 0.5 * inv_rho;

    // g_k = (m*_k - m_k) / |M_k|^2, so that f* = f + sum_k M_ki g_k.
    double g[Q];
    static_for<Q>([&](auto kk) __attribute__((always_inline)) {
      constexpr int k = kk;
      constexpr RateGroup group = L::rate_group[k];
      constexpr double inv_norm = 1.0 / double(B::norm2[k]);
      if constexpr (group == RateGroup::conserved) {
        constexpr int a = B::momentum_component(k);
        if constexpr (a >= 0) g[k] = force[a] * inv_norm;  // (23): j'' - j = F
        else g[k] = 0.0;                                   // density
      } else {
        // m_k from the pair sums/differences.
        double m = 0.0;
        if constexpr (B::parity[k] == 1) {
          add_term<B::M[k][0]>(m, f[0]);
          static_for<P>([&](auto p) __attribute__((always_inline)) { add_term<B::M[k][B::pair_first[p]]>(m, sum[p]); });
        } else {
          static_for<P>([&](auto p) __attribute__((always_inline)) { add_term<B::M[k][B::pair_first[p]]>(m, diff[p]); });
        }
        // m_eq_k(rho, j') from (5), exact integer coefficients.
        double meq = 0.0;
        add_term<B::eq_A[k]>(meq, rho);
        static_for<D>([&](auto a) __attribute__((always_inline)) { add_term<B::eq_B[k][a]>(meq, jp[a]); });
        double quad = 0.0;
        static_for<D>([&](auto a) __attribute__((always_inline)) {
          static_for<D>([&](auto b) __attribute__((always_inline)) { add_term<B::eq_C[k][a][b]>(quad, jp[a] * jp[b]); });
        });
        meq += quad * half_inv_rho;
        meq *= 1.0 / double(L::weight_denominator);
        double s = relaxation_rate<L>(group, s_nu);  // group is a constant: folds away
        if constexpr (model == CollisionModel::trt) s = B::parity[k] == 1 ? s_nu : trt_odd_rate(s_nu);
        g[k] = -s * (m - meq) * inv_norm;
      }
    });

    // f* = f + M^T g, split into the part even and odd under c -> -c.
    add_even_to_rest(f, g);
    static_for<P>([&](auto p) __attribute__((always_inline)) {
      constexpr int i = B::pair_first[p];
      constexpr int o = B::opposite[i];
      double even = 0.0, odd = 0.0;
      static_for<Q>([&](auto kk) __attribute__((always_inline)) {
        constexpr int k = kk;
        if constexpr (B::parity[k] == 1) add_term<B::M[k][i]>(even, g[k]);
        else add_term<B::M[k][i]>(odd, g[k]);
      });
      f[i] += even + odd;
      f[o] += even - odd;
    });
  }

 private:
  [[gnu::always_inline]] static inline void add_even_to_rest(double (&f)[Q], const double (&g)[Q]) {
    double even = 0.0;
    static_for<Q>([&](auto kk) __attribute__((always_inline)) {
      constexpr int k = kk;
      if constexpr (B::parity[k] == 1) add_term<B::M[k][0]>(even, g[k]);
    });
    f[0] += even;
  }
};

}  // namespace capsule::lbm
