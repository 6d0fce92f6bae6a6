// Fluid::set_macroscopic_region: with rho/u written and the force read only on the rows
// around a membrane (ib::support_rows, as the 3D driver does), the membrane reads bitwise
// the same velocities as with the full fields, and the populations are bitwise the same
// everywhere. Both precisions.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <vector>

#include "solver/ib/interpolation.hpp"
#include "solver/ib/support_rows.hpp"
#include "solver/lbm/fluid.hpp"
#include "tests/solver/lbm/flow_helpers.hpp"

using namespace capsule;
using namespace capsule::lbm;

namespace {

// A ring of "membrane" points (radius 4, centred off the lattice centre, crossing z = 0 so
// the periodic wrap of the rows is used) pushed by a radial force, advected by the fluid.
std::vector<double> ring(const ib::Grid& g) {
  std::vector<double> X;
  for (int k = 0; k < 60; ++k) {
    const double a = 2.0 * M_PI * k / 60.0;
    X.insert(X.end(), {0.5 * g.nx + 4.0 * std::cos(a), 0.5 * g.ny + 4.0 * std::sin(a), 1.0 + 2.0 * std::sin(3 * a)});
  }
  return X;
}

void run_pair(Precision prec) {
  const ib::Grid g{16, 40, 24};
  Fluid<D3Q19> full(g.nx, g.ny, g.nz, 0.1, prec), part(g.nx, g.ny, g.nz, 0.1, prec);
  for (auto* f : {&full, &part}) {
    f->set_wall_velocity(-0.02, 0.02);
    f->initialise_velocity([&](double, double y, double) { return std::array<double, 3>{0.04 * (y / g.ny - 0.5), 0.0, 0.0}; });
  }
  std::vector<double> Xa = ring(g), Xb = Xa, P(Xa.size()), Ua(Xa.size()), Ub(Xa.size());
  const std::size_t n = Xa.size() / 3;
  const ib::Delta kernel = ib::Delta::peskin4;
  double fraction = 0;
  for (int s = 0; s < 60; ++s) {
    for (std::size_t c = 0; c < n; ++c)
      for (int d = 0; d < 3; ++d) P[3 * c + d] = 1e-4 * (Xa[3 * c + d] - (d == 0 ? 0.5 * g.nx : d == 1 ? 0.5 * g.ny : 1.0));
    // Every 20th step full fields, as the driver does before an output row.
    if (s % 20 == 19) part.set_macroscopic_everywhere();
    else {
      const ib::RowRange r = ib::support_rows(g, Xb.data(), n, 5);
      part.set_macroscopic_region({{r.y_begin, r.y_end, r.z_begin, r.z_end}});
      fraction = part.macroscopic_fraction();
    }
    for (auto* f : {&full, &part}) f->clear_force();
    double* pa[3] = {full.force(0), full.force(1), full.force(2)};
    double* pb[3] = {part.force(0), part.force(1), part.force(2)};
    ib::spread<3>(g, Xa.data(), P.data(), n, pa, kernel);
    ib::spread<3>(g, Xb.data(), P.data(), n, pb, kernel);
    full.step();
    part.step();
    const double* ua[3] = {full.velocity(0), full.velocity(1), full.velocity(2)};
    const double* ub[3] = {part.velocity(0), part.velocity(1), part.velocity(2)};
    ib::interpolate<3>(g, ua, Xa.data(), n, Ua.data(), kernel);
    ib::interpolate<3>(g, ub, Xb.data(), n, Ub.data(), kernel);
    double du = 0;
    for (std::size_t k = 0; k < Ua.size(); ++k) du = std::max(du, std::abs(Ua[k] - Ub[k]));
    INFO("precision " << capsule::choice_name(prec) << " step " << s << " max |dU| " << du);
    REQUIRE(std::memcmp(Ua.data(), Ub.data(), Ua.size() * sizeof(double)) == 0);
    ib::advance<3>(Xa.data(), Ua.data(), n, 1.0);
    ib::advance<3>(Xb.data(), Ub.data(), n, 1.0);
  }
  INFO("precision " << capsule::choice_name(prec) << ", rows written " << fraction);
  CHECK(fraction < 0.5);  // the region really is restricted
  CHECK(std::memcmp(Xa.data(), Xb.data(), Xa.size() * sizeof(double)) == 0);
  bool same = true;
  for (int i = 0; i < D3Q19::Q; ++i)
    for (std::size_t node = 0; node < full.size(); ++node) same = same && full.population(i, node) == part.population(i, node);
  CHECK(same);
  // The last step wrote everything: the fields agree everywhere.
  bool same_u = true;
  for (int d = 0; d < 3; ++d)
    for (std::size_t node = 0; node < full.size(); ++node) same_u = same_u && full.velocity(d)[node] == part.velocity(d)[node];
  CHECK(same_u);
}

}  // namespace

TEST_CASE("Velocity where the membrane reads it is the same with the macroscopic region", "[lbm]") {
  for (Precision p : test::both_precisions) run_pair(p);
}

// support_rows with margin 5 covers the delta support at X and at X moved by up to one node,
// widened by the +-1 of a centred-difference gradient.
TEST_CASE("support_rows covers the delta support, the motion and the gradient stencil", "[lbm]") {
  const ib::Grid g{30, 28, 20};
  std::vector<double> X;
  for (int k = 0; k < 40; ++k) X.insert(X.end(), {15.0 + 3 * std::sin(k), 14.0 + 5 * std::cos(1.3 * k), 0.2 * k - 3.0});  // z crosses 0
  const std::size_t n = X.size() / 3;
  const ib::RowRange r = ib::support_rows(g, X.data(), n, 5);
  auto in_rows = [&](int y, int z) {
    const int zz = ((z - r.z_begin) % g.nz + g.nz) % g.nz + r.z_begin;  // the periodic image inside or above z_begin
    return y >= r.y_begin && y < r.y_end && zz >= r.z_begin && zz < r.z_end;
  };
  bool covered = true;
  for (std::size_t c = 0; c < n; ++c)
    for (double dy : {-1.0, 0.0, 1.0})
      for (double dz : {-1.0, 0.0, 1.0}) {
        const double Y[3] = {X[3 * c], X[3 * c + 1] + dy, X[3 * c + 2] + dz};
        // delta support floor(x - 1/2) - 1 .. + 2, widened by the gradient's +-1
        for (int oy = -2; oy <= 3; ++oy)
          for (int oz = -2; oz <= 3; ++oz) {
            const int y = int(std::floor(Y[1] - 0.5)) + oy, z = int(std::floor(Y[2] - 0.5)) + oz;
            if (y >= 0 && y < g.ny) covered = covered && in_rows(y, z);
          }
      }
  CHECK(covered);
  const ib::RowRange none = ib::support_rows(g, X.data(), 0, 5);
  CHECK(none.y_begin == none.y_end);
}
