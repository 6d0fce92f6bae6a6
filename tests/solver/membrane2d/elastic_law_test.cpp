// The 2D membrane law (solver/membrane2d/laws/): Hooke's tension (30) of one stretched segment,
// and the law the membrane carries.
#include <catch2/catch.hpp>
#include <cmath>

#include "solver/membrane2d/elastic_law.hpp"
#include "solver/membrane2d/membrane.hpp"
#include "solver/membrane2d/shape.hpp"

using namespace capsule::membrane2d;

TEST_CASE("Hooke's law: a segment stretched to lambda carries E_s (lambda - 1) (30)", "[membrane2d]") {
  const Hooke law{2e-3};
  CHECK(law.tension(1.0) == 0.0);
  CHECK(law.tension(1.25) == Approx(2e-3 * 0.25).epsilon(1e-15));
  CHECK(law.tension(0.5) == Approx(-2e-3 * 0.5).epsilon(1e-15));
  CHECK(visit_law(ElasticLaw::hooke, 3.0, [](const auto& l) { return l.tension(2.0); }) == 3.0);
}

TEST_CASE("a membrane without viscosity carries its law's tension of each segment's stretch", "[membrane2d]") {
  const double a = 10.0, E_s = 1e-3;
  Membrane m(circle(64, a, 0.0, 0.0, 0.0), Moduli{E_s, 0.0, 0.0}, ElasticLaw::hooke);
  // An uneven deformation: each segment stretched differently.
  for (std::size_t i = 0; i < m.size(); ++i) m.positions()[2 * i] *= 1.3;
  m.compute_forces(1.0);
  double spread = 0;
  for (std::size_t i = 0; i < m.size(); ++i) {
    CHECK(m.stretch()[i] == Approx(std::hypot(m.positions()[2 * ((i + 1) % m.size())] - m.positions()[2 * i],
                                              m.positions()[2 * ((i + 1) % m.size()) + 1] - m.positions()[2 * i + 1]) /
                                   m.reference_lengths()[i]).epsilon(1e-14));
    CHECK(m.tension()[i] == Hooke{E_s}.tension(m.stretch()[i]));
    spread = std::max(spread, std::abs(m.stretch()[i] - m.stretch()[0]));
  }
  CHECK(spread > 0.1);  // the stretches do differ
}
