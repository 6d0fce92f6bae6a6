// Restart-point files (solver/io/state_archive.hpp): exact round trip, atomic write, refusals.
#include <catch2/catch.hpp>

#include "tests/solver/io/scratch_dir.hpp"

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

#include "solver/io/member_file.hpp"
#include "solver/io/state_archive.hpp"
#include "solver/common/atomic_write.hpp"

namespace fs = std::filesystem;
using capsule::io::StateArchive;

namespace {
using capsule::io::testing::fresh_dir;
bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}
}  // namespace

TEST_CASE("a restart point keeps doubles bit for bit, integers and texts exactly", "[io][restart]") {
  const fs::path path = fresh_dir("roundtrip") / "m.h5.restart";
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> values{0.1, -0.0, nan, 1e-310, std::numeric_limits<double>::infinity(), 1.0 / 3.0};
  StateArchive a;
  a.put("fluid.populations", values);
  a.put("empty", std::vector<double>{});
  a.put("contrast.band", std::vector<std::int64_t>{3, 1, 1L << 40});
  a.put_text("identity.scene", "{\"a\": 1,\n \"b\": \"\xc3\xa9\"}");
  a.put_text("blank", "");
  a.put_number("loop.D_xy", nan);
  a.put_integer("sim.steps", 123456789012L);
  a.write(path.string());
  CHECK(!fs::exists(capsule::temporary_path(path.string())));  // renamed into place, nothing left behind

  StateArchive b = StateArchive::read(path.string());
  CHECK(same_bits(b.doubles("fluid.populations"), values));
  CHECK(b.doubles("empty").empty());
  CHECK(b.ints("contrast.band") == std::vector<std::int64_t>{3, 1, 1L << 40});
  CHECK(b.text("identity.scene") == a.text("identity.scene"));
  CHECK(b.text("blank").empty());
  CHECK(std::isnan(b.number("loop.D_xy")));
  CHECK(b.integer("sim.steps") == 123456789012L);
  CHECK(b.payload_bytes() == a.payload_bytes());
  CHECK_THROWS_WITH(b.doubles("membrane.x"), Catch::Contains("restart point has no membrane.x"));
  CHECK_THROWS_WITH(b.text("sim.steps"), Catch::Contains("no sim.steps"));
  CHECK(b.take_doubles("fluid.populations").size() == values.size());
}

TEST_CASE("a member file or a damaged file is not taken for a restart point", "[io][restart]") {
  const fs::path dir = fresh_dir("refuse");
  CHECK_THROWS_WITH(StateArchive::read((dir / "missing").string()), Catch::Contains("no such restart point"));
  std::ofstream(dir / "junk") << "junk";
  CHECK_THROWS_WITH(StateArchive::read((dir / "junk").string()), Catch::Contains("not a readable HDF5 file"));
  capsule::io::MemberWriter w((dir / "m.h5").string());
  w.append({{"kt", 0.0}});
  w.checkpoint();
  CHECK_THROWS_WITH(StateArchive::read((dir / "m.h5.partial").string()), Catch::Contains("not a capsule restart point"));
}

TEST_CASE("a member writer's rows and shapes survive a restart point", "[io][restart]") {
  const fs::path dir = fresh_dir("rows");
  capsule::io::MemberWriter w((dir / "m.h5").string());
  w.append({{"kt", 0.0}, {"D_xy", 0.1}}, {0.5, 0.25});
  w.append({{"kt", 0.05}, {"D_xy", 0.2}}, {0.6, 0.35});
  w.add_shape(0.05, {1, 2, 3, 4, 5, 6}, 3, {0, 1, 2});
  StateArchive a;
  w.save_rows(a);
  a.write((dir / "r").string());
  StateArchive b = StateArchive::read((dir / "r").string());
  capsule::io::MemberWriter v((dir / "v.h5").string());
  v.restore_rows(b);
  CHECK(v.rows() == 2);
  v.append({{"kt", 0.1}, {"D_xy", 0.3}}, {0.7, 0.45});
  v.finish("complete");
  const auto m = capsule::io::read_member((dir / "v.h5").string());
  CHECK(m.series.at("D_xy") == std::vector<double>{0.1, 0.2, 0.3});
  CHECK(m.beta.size() == 3);
  CHECK(m.beta[2] == std::vector<double>{0.7, 0.45});
  REQUIRE(m.shapes.size() == 1);
  CHECK(m.shapes[0].xyz == std::vector<double>{1, 2, 3, 4, 5, 6});
  CHECK(m.triangles == std::vector<int>{0, 1, 2});
}
