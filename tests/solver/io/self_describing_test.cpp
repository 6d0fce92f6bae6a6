// Member files describe themselves (solver/io/quantities.hpp): every series and shape dataset
// carries `units` and `description`, every marker the attributes of its name on
// /markers/units and /markers/description, and kt is the dimension scale of every series'
// rows. The content hash covers the descriptions; files written before them read as they did.
#include <catch2/catch.hpp>

#include "tests/solver/io/scratch_dir.hpp"

#include <hdf5.h>
#include <hdf5_hl.h>

#include <filesystem>
#include <string>

#include "solver/io/member_file.hpp"
#include "solver/io/quantities.hpp"

namespace fs = std::filesystem;
using namespace capsule::io;

namespace {

using capsule::io::testing::fresh_dir;

std::string write_member(const fs::path& dir) {
  const std::string path = (dir / "member.h5").string();
  MemberWriter w(path);
  w.set_scene({{"dim", 2}});
  for (int i = 0; i < 5; ++i) w.append({{"kt", 0.1 * i}, {"D_xy", 0.01 * i}, {"tension", 0.5}}, {0.2 * i});
  w.set_markers({{"t_max", 0.4}, {"D_max", 0.04}});
  w.add_shape(0.0, std::vector<double>(2 * 4, 1.0), 2);
  w.finish("complete");
  return path;
}

std::string text_attribute(hid_t obj, const char* name) {
  const hid_t a = H5Aopen(obj, name, H5P_DEFAULT);
  if (a < 0) return "(none)";
  const hid_t t = H5Aget_type(a);
  char* c = nullptr;
  H5Aread(a, t, &c);
  std::string s = c ? c : "";
  H5free_memory(c);
  H5Tclose(t);
  H5Aclose(a);
  return s;
}

}  // namespace

TEST_CASE("every series, marker and shape of a member file says its units and what it is", "[io]") {
  const auto dir = fresh_dir("units");
  const std::string path = write_member(dir);
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t kt = H5Dopen2(f, "series/kt", H5P_DEFAULT);
  CHECK(H5DSis_scale(kt) > 0);
  for (const char* name : {"kt", "D_xy", "tension", "beta"}) {
    INFO(name);
    const hid_t set = H5Dopen2(f, (std::string("series/") + name).c_str(), H5P_DEFAULT);
    CHECK(text_attribute(set, "units") == quantity(series_quantities(), name).units);
    CHECK(text_attribute(set, "description") == quantity(series_quantities(), name).description);
    if (std::string(name) != "kt") CHECK(H5DSis_attached(set, kt, 0) > 0);
    H5Dclose(set);
  }
  const hid_t tension = H5Dopen2(f, "series/tension", H5P_DEFAULT);
  CHECK(text_attribute(tension, "units") == "E_s");
  H5Dclose(tension);
  const hid_t units = H5Gopen2(f, "markers/units", H5P_DEFAULT), about = H5Gopen2(f, "markers/description", H5P_DEFAULT);
  CHECK(text_attribute(units, "t_max") == "1/k");
  CHECK(text_attribute(about, "D_max") == quantity(marker_quantities(), "D_max").description);
  const hid_t shape = H5Dopen2(f, "shapes/0000", H5P_DEFAULT);
  CHECK(text_attribute(shape, "units") == "lattice");
  H5Dclose(shape);
  H5Gclose(units);
  H5Gclose(about);
  H5Dclose(kt);
  H5Fclose(f);
  // The reader sees the markers as before: the descriptions are not markers.
  const auto m = read_member(path);
  CHECK(m.markers.size() == 2);
  CHECK(m.series.size() == 3);
  fs::remove_all(dir);
}

TEST_CASE("a quantity without a row in the table is refused before anything is written", "[io]") {
  MemberWriter w("never_written.h5");
  CHECK_THROWS_WITH(w.append({{"kt", 0.0}, {"D_xyz", 0.0}}),
                    Catch::Matchers::Contains("quantity D_xyz has no row in solver/io/quantities.cpp"));
  CHECK_THROWS_WITH(w.set_markers({{"t_maximum", 1.0}}), Catch::Matchers::Contains("quantity t_maximum has no row"));
  CHECK(!fs::exists("never_written.h5.partial"));
}

TEST_CASE("the content hash covers units and descriptions", "[io][checksum]") {
  const auto dir = fresh_dir("hash");
  const std::string path = write_member(dir);
  REQUIRE_NOTHROW(read_member(path));
  {  // A stray edit changes a unit.
    const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    const hid_t set = H5Dopen2(f, "series/D_xy", H5P_DEFAULT);
    H5Adelete(set, "units");
    const hid_t t = H5Tcopy(H5T_C_S1);
    H5Tset_size(t, H5T_VARIABLE);
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t a = H5Acreate2(set, "units", t, space, H5P_DEFAULT, H5P_DEFAULT);
    const char* wrong = "a";
    H5Awrite(a, t, &wrong);
    H5Aclose(a);
    H5Sclose(space);
    H5Tclose(t);
    H5Dclose(set);
    H5Fclose(f);
  }
  CHECK_THROWS_WITH(read_member(path), Catch::Matchers::Contains("content hash does not match"));
  fs::remove_all(dir);
}

TEST_CASE("every shipped member file, written before the descriptions, still verifies", "[io][checksum]") {
  std::size_t read = 0, hashed = 0;
  for (const auto& e : fs::recursive_directory_iterator(fs::path(CAPSULE_SOURCE_DIR) / "results")) {
    if (e.path().filename() != "member.h5") continue;
    INFO(e.path().string());
    const auto m = read_member(e.path().string());  // throws when the content hash does not match
    ++read;
    hashed += m.attributes.contains(kContentHashAttribute) ? 1 : 0;
  }
  CHECK(read > 500);
  CHECK(hashed > 0);
}
