// The stretch protocol end to end (solver/run/simulation3d.cpp, protocol.stretch): a neo-Hookean
// sphere pulled by two patches in a fluid at rest, against the linear membrane theory of a
// spherical shell, at CI size (a = 6, a box of 4a, icosphere levels 2 and 3: seconds).
//
// Linear theory (derived here; no published closed form was found for a fluid-filled membrane
// sphere under patch loads): an axisymmetric membrane without bending is statically determinate.
// Between the patches the meridional tension is N_phi = F / (2 pi R sin^2 phi) and the hoop
// tension N_theta = -N_phi (no normal load there); the volume is conserved, which with Hooke's law
// (E, nu of the membrane in 2D) fixes the pressure jump: Delta p R = -F (1 + cos phi_c) / (4 pi R),
// phi_c the half-angle of the cap with the patch's area. At the equator (v = 0 by symmetry)
// w = R eps_theta, so
//   D_T / (2R) - 1 = -F / (2 pi E R) [(1 + nu) + (1 - nu)(1 + cos phi_c) / 4].
// The neo-Hookean membrane has E = 3 G_s = E_s (the E_s of Ca) and nu = 1/2. The transverse
// diameter hardly depends on the patch (through cos phi_c only); the axial one does, as
// 1/phi_c^2 at the cap's edge, and a membrane without bending is geometrically nonlinear there
// at any force that moves a vertex measurably: it is recorded, not compared with theory.
#include <catch2/catch.hpp>
#include <omp.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <sstream>
#include <string>

#include "solver/io/member_file.hpp"
#include "solver/run/simulation3d.hpp"
#include "solver/scene/scene.hpp"
#include "tests/solver/run/run_scene3d.hpp"

using namespace capsule;

namespace {

io::MemberData run(double force, int level, double recover_kt, const std::string& name) {
  omp_set_num_threads(1);  // small runs, side by side on the 2-core CI machine
  std::ostringstream j;
  j << R"({"dim": 3, "shape": "sphere", "law": "neo-hookean", "Ca": 0.02, "E_b": 0, "V": 1, "eta": 0,
           "resolution": {"a": 6, "domain": [4, 4, 4], "mesh_level": )" << level << R"(},
           "protocol": {"stretch": {"force": )" << force << R"(, "patch_fraction": 0.02, "until": "time", "kt": 4},
                        "recover": {"until": "time", "kt": )" << recover_kt << R"(}},
           "output": {"interval_kt": 0.1}})";
  const Scene scene = Scene::from_json(nlohmann::json::parse(j.str()), name);
  io::MemberData d = testing::run_scene3d(scene, "stretch3d_test_" + name);
  REQUIRE(d.status == "complete");
  return d;
}

// The row where the beads let go (the last with force_on = 1).
std::size_t release_row(const io::MemberData& d) {
  const auto& on = d.series.at("force_on");
  std::size_t i = 0;
  while (i + 1 < on.size() && on[i + 1] == 1.0) ++i;
  return i;
}

// D_T / (2R) - 1 of the linear theory above, for the neo-Hookean membrane (E = E_s, nu = 1/2),
// F = force E_s R, the cap of the patch's area A_c = 2 pi R^2 (1 - cos phi_c).
double transverse_strain_theory(double force, double patch_area) {
  const double nu = 0.5, cos_c = 1.0 - patch_area / (2.0 * std::numbers::pi);
  return -force / (2.0 * std::numbers::pi) * ((1.0 + nu) + (1.0 - nu) * (1.0 + cos_c) / 4.0);
}

}  // namespace

TEST_CASE("a sphere pulled by two patches narrows as the linear membrane theory says and converges to it with the mesh",
          "[stretch3d]") {
  const double f = 0.002;  // F / (E_s R): a 0.05 % change of D_T, inside the linear range (checked below)
  const io::MemberData coarse = run(f, 2, 0, "level2");
  const io::MemberData fine = run(f, 3, 2, "level3");
  const auto strain = [&](const io::MemberData& d) { return d.series.at("D_transverse")[release_row(d)] / 2.0 - 1.0; };
  const double theory = transverse_strain_theory(f, fine.attributes.at("stretch_patch_area").get<double>());
  const double e2 = strain(coarse) / theory - 1.0, e3 = strain(fine) / theory - 1.0;
  INFO("D_T/2 - 1: theory " << theory << ", level 2 " << strain(coarse) << " (" << 100 * e2 << " %), level 3 "
                            << strain(fine) << " (" << 100 * e3 << " %)");
  // Measured -15.5 % (level 2, 3 patch vertices) and -6.0 % (level 3, 13 vertices); level 4 gives
  // -3.2 %, and the Richardson extrapolation of the three -2.0 % (docs/findings/stretching.md).
  // Bound 8 % at level 3: its discretisation error, which must also fall at least twofold from
  // level 2.
  CHECK(std::abs(e3) < 0.08);
  CHECK(std::abs(e3) < 0.5 * std::abs(e2));
  // The beads' forces balance: the cell does not drift.
  for (double x : fine.series.at("centroid_x")) CHECK(std::abs(x) < 1e-9);
  // Released, it recovers: 2 kt later D_axial - 2 is below a sixth of its value at the release
  // (measured 0.11 of it; the neo-Hookean sphere's own relaxation, no viscosity in the membrane).
  const auto& DA = fine.series.at("D_axial");
  const std::size_t r = release_row(fine);
  CHECK(DA[r] > 2.0 + 4.0 * f);
  CHECK(DA.back() - 2.0 < (DA[r] - 2.0) / 6.0);
  CHECK(fine.series.at("force_on").back() == 0.0);
  CHECK(fine.markers.at("D_stop") == Approx(DA[r]));  // the markers watch D_axial
}

TEST_CASE("the transverse narrowing doubles with the force at small forces", "[stretch3d]") {
  const io::MemberData one = run(0.002, 2, 0, "linear1"), two = run(0.004, 2, 0, "linear2");
  const auto strain = [&](const io::MemberData& d) { return d.series.at("D_transverse")[release_row(d)] / 2.0 - 1.0; };
  INFO("D_T/2 - 1 at F = 0.002 and 0.004: " << strain(one) << ", " << strain(two));
  // Linear to within 2 %: the second-order part (the patches' large local strain) grows as F^2.
  CHECK(strain(two) / strain(one) == Approx(2.0).epsilon(0.02));
}

TEST_CASE("a viscous Skalak cell with a large area constant stretches and recovers without blowing up", "[stretch3d]") {
  // The standard linear solid's Maxwell element takes Skalak's law without its area term
  // (solver/membrane3d/elasticity.cpp, maxwell_law_of): with C = 100 and G = 50 its instantaneous
  // area modulus was 50 x 201 times the shear modulus, and this member blew up within its first
  // output interval (at rest as in shear). The released cell must move back towards its rest shape.
  omp_set_num_threads(1);
  const Scene scene = Scene::from_json(nlohmann::json::parse(R"({"dim": 3, "shape": "biconcave", "law": "skalak", "C": 100,
      "Ca": 0.6, "E_b": 0.004, "V": 1, "eta": 20,
      "resolution": {"a": 4, "domain": [6, 4, 4], "mesh_level": 2, "tau": 0.8},
      "protocol": {"stretch": {"force": 0.5, "contact_diameter": 0.7, "until": "time", "kt": 1},
                   "recover": {"until": "time", "kt": 0.5}},
      "output": {"interval_kt": 0.1}})"), "viscous_skalak_stretch.json");
  const io::MemberData d = testing::run_scene3d(scene, "viscous_skalak_stretch");
  INFO(d.status);
  REQUIRE(d.status == "complete");
  const auto& L = d.series.at("D_axial");
  const std::size_t release = release_row(d);
  CHECK(L[release] > L.front());  // pulled longer
  CHECK(L.back() < L[release]);   // and recovering after the release
}
