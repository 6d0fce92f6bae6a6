// `capsule units` and a member of a cell given in physical units (solver/scene/physical_cell.hpp).
#include <catch2/catch.hpp>

#include "capsule_process.hpp"

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

#include "solver/io/member_file.hpp"

namespace fs = std::filesystem;
using capsule_test::quote;
using capsule_test::Result;
using capsule_test::run_capsule;

namespace {


fs::path scratch() {
  const fs::path d = fs::temp_directory_path() / ("units_command_test_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

}  // namespace

TEST_CASE("capsule units prints a physical cell's groups and lattice - its member file records both ways", "[capsule3d]") {
  const std::string rbc = quote(std::string(CAPSULE_SOURCE_DIR) + "/tests/data/scenes/rbc_physical_3d.json");
  const Result units = run_capsule("units " + rbc);
  INFO(units.output);
  REQUIRE(units.exit_code == 0);
  // Skalak: Ca = 1.2e-3 Pa s * 180/s * 2.82e-6 m / 6e-6 N/m; a = 5 spacings of 2.82 um / 5.
  CHECK(units.output.find("Ca  = mu_a k a / E_s      0.10152") != std::string::npos);
  CHECK(units.output.find("dx = 0.564 um") != std::string::npos);
  CHECK(units.output.find("kt = 1 is 0.00555556 s") != std::string::npos);
  CHECK(run_capsule("units " + quote(std::string(CAPSULE_SOURCE_DIR) + "/tests/data/scenes/circle_quick_2d.json"))
            .output.find("no physical block") != std::string::npos);
  CHECK(run_capsule("units /nonexistent.json").exit_code == 2);
  // The member: the scene holds the physical block beside its groups; kt and a in s and um.
  const fs::path out = scratch() / "rbc.h5";
  const Result run = run_capsule(rbc + " -o " + quote(out.string()) + " --quiet --threads 1");
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  const capsule::io::MemberData d = capsule::io::read_member(out.string());
  CHECK(d.attributes["scene"]["physical"]["shear_rate_per_s"] == 180.0);
  CHECK(d.attributes["scene"]["Ca"].get<double>() == Approx(0.10152).epsilon(1e-12));
  CHECK(d.attributes["seconds_per_kt"].get<double>() == Approx(1.0 / 180).epsilon(1e-12));
  CHECK(d.attributes["micrometres_per_a"].get<double>() == 2.82);
  fs::remove_all(out.parent_path());
}
