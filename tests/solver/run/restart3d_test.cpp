// Restart points inside a 3D member (docs/guide/running.md "Checkpoints"): the fluid, the membrane positions,
// the standard-linear-solid memory, the viscosity contrast and the power-law support survive a
// kill, and the resumed member is bitwise the uninterrupted one.
#include <catch2/catch.hpp>

#include "tests/solver/run/member_compare.hpp"
#include "tests/solver/run/tiny_scenes.hpp"

using namespace capsule;
using namespace capsule::testing;
namespace fs = std::filesystem;

namespace {

nlohmann::json tiny_3d() { return tiny_3d_scene({0.1, 0.35}); }

}  // namespace

TEST_CASE("3D restart: viscosity contrast and standard linear solid, bitwise after a kill", "[capsule3d][restart]") {
  const fs::path dir = scratch("3d_sls");
  nlohmann::json s = tiny_3d();
  s["V"] = 2;
  s["eta"] = 2;
  require_restart_is_bitwise(dir, write_scene(dir, "s", s), 167, 250);  // of 384 steps (tau = 1.5)
}

TEST_CASE("3D restart: power-law membrane viscosity, bitwise after a kill", "[capsule3d][restart]") {
  const fs::path dir = scratch("3d_power");
  nlohmann::json s = tiny_3d();
  s["E_b"] = 0;
  s["power_law"] = {{"K", 5}, {"n", 0.7}};
  require_restart_is_bitwise(dir, write_scene(dir, "s", s), 201, 202);  // of 384 steps (tau = 1.5)
}

TEST_CASE("3D restart: power law in the membrane, bitwise after a kill", "[capsule3d][restart]") {
  // Its memory holds C of the last step as well (the surface shear rate (101) is a difference).
  const fs::path dir = scratch("3d_power_membrane");
  nlohmann::json s = tiny_3d();
  s["E_b"] = 0;
  s["power_law"] = {{"K", 5}, {"n", 0.7}, {"model", "membrane"}};
  require_restart_is_bitwise(dir, write_scene(dir, "s", s), 201, 202);  // of 384 steps (tau = 1.5)
}

TEST_CASE("3D restart: the Adams-Bashforth position update keeps its velocity history", "[capsule3d][restart]") {
  // adams_bashforth2 reads the last step's U: a restart point that lost it would take an Euler
  // step after the restart and the series would differ in the last bits.
  const fs::path dir = scratch("3d_ab2");
  nlohmann::json s = tiny_3d();
  s["resolution"]["membrane_update"] = "adams_bashforth2";
  require_restart_is_bitwise(dir, write_scene(dir, "s", s), 201, 202);  // of 384 steps (tau = 1.5)
}
