// Damage is refused, not read: every dataset carries HDF5's Fletcher32 checksum, member files a
// content hash over attributes and datasets as well (solver/io/hdf5_dataset.hpp,
// solver/io/member_file.hpp). Files written without them (before they existed) still read.
#include <catch2/catch.hpp>

#include "tests/solver/io/scratch_dir.hpp"

#include <hdf5.h>

#include <cmath>
#include <filesystem>

#include "solver/io/member_file.hpp"
#include "solver/io/state_archive.hpp"
#include "tests/support/hdf5_damage.hpp"

namespace fs = std::filesystem;
using capsule::io::MemberWriter;
using capsule::io::read_member;
using capsule::io::StateArchive;

namespace {

using capsule::io::testing::fresh_dir;

std::string write_member(const fs::path& dir) {
  const std::string path = (dir / "member.h5").string();
  MemberWriter w(path);
  w.set_scene({{"dim", 3}, {"Ca", 0.05}});
  w.set_attribute("member_id", "0123456789abcdef");
  w.set_attribute("steps", 4321L);
  w.set_attribute("tau", 1.5);
  for (int i = 0; i < 200; ++i)
    w.append({{"kt", 0.05 * i}, {"D_xy", 0.3 * (1 - std::exp(-0.05 * i))}, {"theta", 0.7}}, {0.1 * i, 0.2 * i});
  w.set_markers({{"D_max", 0.29}, {"t_max", 9.95}});
  w.add_shape(1.0, std::vector<double>(3 * 162, 0.5), 3, std::vector<int>(3 * 320, 1));
  w.finish("complete");
  return path;
}

std::string refusal(const std::string& path) {
  try {
    read_member(path);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

// Sets a root or group attribute of an existing file to a new double (as a stray editor would).
void overwrite_double_attribute(const std::string& path, const std::string& group, const std::string& name, double v) {
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  const hid_t g = H5Gopen2(f, group.c_str(), H5P_DEFAULT);
  const hid_t a = H5Aopen(g, name.c_str(), H5P_DEFAULT);
  H5Awrite(a, H5T_NATIVE_DOUBLE, &v);
  H5Aclose(a);
  H5Gclose(g);
  H5Fclose(f);
}

}  // namespace

TEST_CASE("a member file records a content hash and reads back whole", "[io][checksum]") {
  const auto dir = fresh_dir("whole");
  const std::string path = write_member(dir);
  const auto m = read_member(path);
  CHECK(m.attributes.contains(capsule::io::kContentHashAttribute));
  CHECK(m.series.at("D_xy").size() == 200);
  CHECK(capsule::io::missing_series(m).empty());
  fs::remove_all(dir);
}

TEST_CASE("one flipped bit in a member file's series, shapes or markers is refused with the file's name", "[io][checksum]") {
  const auto dir = fresh_dir("flip");
  const std::string path = write_member(dir);
  SECTION("a series (Fletcher32 of its chunk)") {
    capsule::testing::flip_bit_in_dataset(path, "series/D_xy");
    const std::string why = refusal(path);
    CHECK(why.find(path) != std::string::npos);
    CHECK(why.find("dataset series/D_xy cannot be read: its checksum does not match") != std::string::npos);
  }
  SECTION("a shape") {
    capsule::testing::flip_bit_in_dataset(path, "shapes/0000");
    CHECK(refusal(path).find("dataset shapes/0000 cannot be read") != std::string::npos);
  }
  SECTION("a marker attribute (the content hash: attributes have no Fletcher32)") {
    overwrite_double_attribute(path, "markers", "D_max", 0.2900000001);
    const std::string why = refusal(path);
    CHECK(why.find("content hash does not match") != std::string::npos);
  }
  SECTION("a deleted series") {
    const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    H5Ldelete(f, "series/theta", H5P_DEFAULT);
    H5Fclose(f);
    CHECK(refusal(path).find("content hash does not match") != std::string::npos);
  }
  fs::remove_all(dir);
}

TEST_CASE("a member file without a content hash is refused unless legacy files are asked for - a missing series is named",
          "[io][checksum]") {
  const auto dir = fresh_dir("old");
  const std::string path = write_member(dir);
  {  // An older writer: no content hash. Then a stray edit removes D_xy, unnoticed by the file.
    const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    H5Adelete(f, capsule::io::kContentHashAttribute);
    H5Ldelete(f, "series/D_xy", H5P_DEFAULT);
    H5Fclose(f);
  }
  // A deleted hash reads like an old file: its content cannot be checked, so it is refused...
  CHECK_THROWS_WITH(read_member(path), Catch::Contains(path) && Catch::Contains("no content hash") &&
                                           Catch::Contains("--legacy-member-files"));
  // ...unless legacy files are asked for explicitly.
  capsule::io::accept_files_without_content_hash(true);
  const auto m = read_member(path);
  capsule::io::accept_files_without_content_hash(false);
  CHECK(m.series.count("D_xy") == 0);
  CHECK(m.series.at("theta").size() == 200);
  CHECK(capsule::io::missing_series(m) == path + ": no series D_xy");
  fs::remove_all(dir);
}

TEST_CASE("one flipped bit in a restart point is refused naming the dataset", "[io][restart][checksum]") {
  const auto dir = fresh_dir("restart");
  const std::string path = (dir / "m.h5.restart").string();
  StateArchive a;
  a.put("fluid.populations", std::vector<double>(300000, 0.125));  // three chunks
  a.put_text("identity.scene", "{\"dim\": 2}");
  a.put_integer("run.step", 700);
  a.write(path);
  REQUIRE(StateArchive::read(path).doubles("fluid.populations").size() == 300000);
  capsule::testing::flip_bit_in_dataset(path, "fluid.populations");
  try {
    StateArchive::read(path);
    FAIL("a damaged restart point was read");
  } catch (const std::runtime_error& e) {
    CHECK(std::string(e.what()).find("dataset fluid.populations cannot be read: its checksum does not match") !=
          std::string::npos);
  }
  fs::remove_all(dir);
}
