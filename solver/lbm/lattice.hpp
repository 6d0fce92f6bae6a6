#pragma once
// Lattice descriptors D2Q9 (3) and D3Q19 (4): discrete velocities in the
// dissertation's order, integer weights (w_i = weight_numerator[i] / weight_denominator,
// eq. (5)), and the velocity polynomials that define the MRT moments
// (Lallemand & Luo 2000 for D2Q9, which reproduces (6); d'Humieres et al. 2002
// for D3Q19, replacing the damaged matrix (11)).
//
// Everything here is constexpr: the moment matrix M is built from the
// polynomials at compile time (see moment_basis.hpp).
#include <array>

namespace capsule::lbm {

// Which relaxation rate a moment uses (docs/guide/model.md "Fluid").
enum class RateGroup {
  conserved,  // rho, j: not relaxed
  shear,      // stress moments: s_nu, nu = (1/s_nu - 1/2)/3  (8), (13)
  energy,     // e (bulk viscosity (10), (14)) and eps (energy square): s_nu (relaxation.hpp)
  heat_flux,  // q: (9) in D2Q9, s_q = s_nu in D3Q19
  fixed       // higher-order moments with a constant rate
};

struct D2Q9 {
  static constexpr int D = 2;
  static constexpr int Q = 9;
  // (3): i = 1..4 axis directions at angles (i-1) pi/2, i = 5..8 diagonals at (2i-9) pi/4.
  static constexpr std::array<std::array<int, 3>, Q> c{{
      {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0},
      {1, 1, 0}, {-1, 1, 0}, {-1, -1, 0}, {1, -1, 0}}};
  // (5): 4/9, 1/9, 1/36.
  static constexpr int weight_denominator = 36;
  static constexpr std::array<int, Q> weight_numerator{16, 4, 4, 4, 4, 1, 1, 1, 1};

  // Moment polynomials of Lallemand & Luo (2000), rows of (6):
  // rho, e, eps, jx, qx, jy, qy, pxx, pxy.
  static constexpr int moment_polynomial(int k, int cx, int cy, int /*cz*/) {
    const int c2 = cx * cx + cy * cy;
    switch (k) {
      case 0: return 1;
      case 1: return 3 * c2 - 4;
      case 2: return (9 * c2 * c2 - 21 * c2 + 8) / 2;
      case 3: return cx;
      case 4: return (3 * c2 - 5) * cx;
      case 5: return cy;
      case 6: return (3 * c2 - 5) * cy;
      case 7: return cx * cx - cy * cy;
      case 8: return cx * cy;
      default: return 0;
    }
  }
  // (7)-(10): s0, s3, s5 conserved; s7 = s8 = s_nu; s4 = s6 from (9); s1 from (10) with
  // s1 = s_nu; s2 = s_nu, not the text's 1.64 (relaxation.hpp: 1.64 is unstable for tau >~ 1.9).
  static constexpr std::array<RateGroup, Q> rate_group{
      RateGroup::conserved, RateGroup::energy,    RateGroup::energy,
      RateGroup::conserved, RateGroup::heat_flux, RateGroup::conserved,
      RateGroup::heat_flux, RateGroup::shear,     RateGroup::shear};
  static constexpr double fixed_rate = 1.64;  // unused in D2Q9 (no moment is in RateGroup::fixed)
  // (9): s4 = s6 = 3 (2 - s_nu) / (3 - s_nu).
  static constexpr double heat_flux_rate(double s_nu) { return 3.0 * (2.0 - s_nu) / (3.0 - s_nu); }
  static constexpr bool heat_flux_rate_is_shear_rate = false;  // split_collision.hpp
};

struct D3Q19 {
  static constexpr int D = 3;
  static constexpr int Q = 19;
  // (4), columns c_1 ... c_19 (index 0 is the rest particle).
  static constexpr std::array<std::array<int, 3>, Q> c{{
      {0, 0, 0},
      {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1},
      {1, 1, 0}, {1, -1, 0}, {-1, 1, 0}, {-1, -1, 0},
      {1, 0, 1}, {-1, 0, 1}, {1, 0, -1}, {-1, 0, -1},
      {0, 1, 1}, {0, 1, -1}, {0, -1, 1}, {0, -1, -1}}};
  // (5): 1/3, 1/18, 1/36.
  static constexpr int weight_denominator = 36;
  static constexpr std::array<int, Q> weight_numerator{
      12, 2, 2, 2, 2, 2, 2, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1};

  // Moment polynomials of d'Humieres et al. (2002), in the order of (12):
  // rho, e, eps, jx, qx, jy, qy, jz, qz, 3pxx, 3pixx, pww, piww, pxy, pyz, pxz, mx, my, mz.
  static constexpr int moment_polynomial(int k, int cx, int cy, int cz) {
    const int c2 = cx * cx + cy * cy + cz * cz;
    switch (k) {
      case 0: return 1;
      case 1: return 19 * c2 - 30;
      case 2: return (21 * c2 * c2 - 53 * c2 + 24) / 2;
      case 3: return cx;
      case 4: return (5 * c2 - 9) * cx;
      case 5: return cy;
      case 6: return (5 * c2 - 9) * cy;
      case 7: return cz;
      case 8: return (5 * c2 - 9) * cz;
      case 9: return 3 * cx * cx - c2;
      case 10: return (3 * c2 - 5) * (3 * cx * cx - c2);
      case 11: return cy * cy - cz * cz;
      case 12: return (3 * c2 - 5) * (cy * cy - cz * cz);
      case 13: return cx * cy;
      case 14: return cy * cz;
      case 15: return cx * cz;
      case 16: return cx * (cy * cy - cz * cz);
      case 17: return cy * (cz * cz - cx * cx);
      case 18: return cz * (cx * cx - cy * cy);
      default: return 0;
    }
  }
  // (12)-(14): s9 = s11 = s13 = s14 = s15 = s_nu; s4 = s6 = s8 = s_nu; s1 from (14) with
  // s1 = s_nu; s2 = s_nu, not the text's 1.8 (relaxation.hpp); s10, s12, s16, s17, s18 = 1.8.
  static constexpr std::array<RateGroup, Q> rate_group{
      RateGroup::conserved, RateGroup::energy,    RateGroup::energy,
      RateGroup::conserved, RateGroup::heat_flux, RateGroup::conserved,
      RateGroup::heat_flux, RateGroup::conserved, RateGroup::heat_flux,
      RateGroup::shear,     RateGroup::fixed,     RateGroup::shear,
      RateGroup::fixed,     RateGroup::shear,     RateGroup::shear,
      RateGroup::shear,     RateGroup::fixed,     RateGroup::fixed,
      RateGroup::fixed};
  static constexpr double fixed_rate = 1.8;  // Sec. 2.1: "set equal to 1.8" (pi and m moments)
  // Sec. 2.1: s4 = s6 = s8 = s9 for isotropy.
  static constexpr double heat_flux_rate(double s_nu) { return s_nu; }
  static constexpr bool heat_flux_rate_is_shear_rate = true;  // split_collision.hpp
};

}  // namespace capsule::lbm
