// Member files: round trip, atomic completion, readable partial checkpoints.
#include <catch2/catch.hpp>

#include "tests/solver/io/scratch_dir.hpp"

#include <cmath>
#include <filesystem>

#include "solver/io/member_file.hpp"

namespace fs = std::filesystem;
using capsule::io::MemberWriter;
using capsule::io::read_member;

namespace {
using capsule::io::testing::fresh_dir;
}  // namespace

TEST_CASE("member file round trip keeps attributes, series, beta, markers, shapes", "[io]") {
  auto dir = fresh_dir("roundtrip");
  std::string path = (dir / "member.h5").string();
  MemberWriter w(path);
  w.set_scene({{"dim", 2}, {"Ca", 0.04}});
  w.set_attribute("member_id", "abc123");
  w.set_attribute("tau", 0.8);
  w.set_attribute("steps", 1234L);
  for (int i = 0; i < 5; ++i)
    w.append({{"kt", 0.1 * i}, {"D_xy", 0.01 * i * i}}, {0.5 * i, -0.5 * i});
  w.set_markers({{"t_max", 0.4}, {"D_max", 0.16}, {"t_min", std::nan("")}});
  w.add_shape(0.2, {1, 2, 3, 4, 5, 6}, 2);
  w.finish("complete");

  REQUIRE(fs::exists(path));
  REQUIRE_FALSE(fs::exists(path + ".partial"));
  auto m = read_member(path);
  CHECK(m.complete());
  CHECK(m.attributes["member_id"] == "abc123");
  CHECK(m.attributes["tau"].get<double>() == 0.8);
  CHECK(m.attributes["steps"].get<long>() == 1234);
  CHECK(m.attributes["scene"]["Ca"].get<double>() == 0.04);
  REQUIRE(m.series["kt"].size() == 5);
  CHECK(m.series["D_xy"][3] == Approx(0.09).margin(1e-15));
  REQUIRE(m.beta.size() == 5);
  CHECK(m.beta[4][1] == -2.0);
  CHECK(m.markers["t_max"] == 0.4);
  CHECK(std::isnan(m.markers["t_min"]));
  REQUIRE(m.shapes.size() == 1);
  CHECK(m.shapes[0].kt == 0.2);
  CHECK(m.shapes[0].dim == 2);
  CHECK(m.shapes[0].xyz[5] == 6.0);
  fs::remove_all(dir);
}

TEST_CASE("a member that has not finished leaves only a readable .partial marked running", "[io]") {
  auto dir = fresh_dir("partial");
  std::string path = (dir / "member.h5").string();
  {
    MemberWriter w(path);
    w.append({{"kt", 0.0}, {"D_xy", 0.0}});
    w.checkpoint();
    // The writer goes away without finish(), as a killed process would.
  }
  CHECK_FALSE(fs::exists(path));
  REQUIRE(fs::exists(path + ".partial"));
  auto m = read_member(path + ".partial");
  CHECK(m.status == "running");
  CHECK_FALSE(m.complete());
  fs::remove_all(dir);
}

TEST_CASE("an unstable member keeps what it wrote and says so", "[io]") {
  auto dir = fresh_dir("unstable");
  std::string path = (dir / "member.h5").string();
  MemberWriter w(path);
  w.append({{"kt", 0.0}, {"D_xy", 0.0}});
  w.append({{"kt", 0.1}, {"D_xy", 0.2}});
  w.finish("unstable at kt = 0.15: NaN in the membrane positions");
  auto m = read_member(path);
  CHECK(m.unstable());
  CHECK(m.series["kt"].size() == 2);
  CHECK(capsule::io::read_member_status(path).status.rfind("unstable at kt = 0.15", 0) == 0);
  fs::remove_all(dir);
}

TEST_CASE("rows must keep their columns and reading a non-member file is refused by name", "[io]") {
  auto dir = fresh_dir("bad");
  MemberWriter w((dir / "m.h5").string());
  w.append({{"kt", 0.0}, {"D_xy", 0.0}});
  CHECK_THROWS_AS(w.append({{"kt", 0.1}}), std::logic_error);
  CHECK_THROWS_WITH(read_member((dir / "none.h5").string()), Catch::Contains("none.h5"));
  fs::remove_all(dir);
}
