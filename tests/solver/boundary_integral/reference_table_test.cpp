// The shipped boundary-integral table (analysis/reference/boundary_integral_sphere_neohookean.csv,
// made by scripts/reference-bim-table): that it is steady, converges with the mesh, meets
// small-deformation theory in the limit, and is what this code computes.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "solver/boundary_integral/reference_run.hpp"

using namespace capsule::boundary_integral;

namespace {

using Row = std::map<std::string, std::string>;

std::vector<Row> read_csv(std::istream& in) {
  std::vector<Row> rows;
  std::string line;
  std::vector<std::string> header;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream s(line);
    for (std::string cell; std::getline(s, cell, ',');) cells.push_back(cell);
    if (header.empty()) {
      header = cells;
      continue;
    }
    REQUIRE(cells.size() == header.size());
    Row r;
    for (std::size_t i = 0; i < cells.size(); ++i) r[header[i]] = cells[i];
    rows.push_back(r);
  }
  return rows;
}

std::vector<Row> shipped() {
  std::ifstream in(std::string(CAPSULE_SOURCE_DIR) + "/analysis/reference/boundary_integral_sphere_neohookean.csv");
  REQUIRE(in);
  return read_csv(in);
}

double num(const Row& r, const std::string& key) { return std::stod(r.at(key)); }

}  // namespace

TEST_CASE("reference table: every capsule reached its steady shape and kept its volume", "[boundary_integral]") {
  const auto rows = shipped();
  REQUIRE(rows.size() >= 12);
  for (const auto& r : rows) {
    INFO("Ca " << r.at("Ca") << " level " << r.at("level") << ": range of D over the window " << r.at("D_range_window"));
    // Level 2 (162 vertices) tank-treads with a ripple of a few 1e-4 in D as the vertices pass
    // the poles; there the run ends at its last kt and the ripple must stay below 0.2 % of D.
    if (std::stoi(r.at("level")) >= 3 || r.at("steady") == "no")
      CHECK((r.at("steady") == "yes" || num(r, "D_range_window") < 2e-3 * num(r, "D_end")));
    if (std::stoi(r.at("level")) >= 3) CHECK(r.at("steady") == "yes");
    // The flux is removed from each velocity evaluation, so the volume drifts only at the time
    // step's order: at most 1.3e-5 (Ca 0.2, level 2, kt 10); 3e-5 allows that, a leak would not.
    CHECK(std::abs(num(r, "volume_change")) < 3e-5);
  }
}

TEST_CASE("reference table: D converges with the mesh level, and to (25/4) Ca at small Ca", "[boundary_integral]") {
  std::map<double, std::map<int, double>> D;  // Ca -> level -> steady D
  for (const auto& r : shipped()) D[num(r, "Ca")][std::stoi(r.at("level"))] = num(r, "D_end");
  int ladders = 0;
  for (const auto& [Ca, by_level] : D) {
    if (!by_level.count(2) || !by_level.count(3) || !by_level.count(4)) continue;
    ++ladders;
    const double d2 = by_level.at(2), d3 = by_level.at(3), d4 = by_level.at(4);
    INFO("Ca " << Ca << ": " << d2 << " / " << d3 << " / " << d4);
    // Monotone, and the level 3 -> 4 step at most 0.35 of the 2 -> 3 step: an observed order
    // of at least 1.5 where the discretisation is second order (the exact problems' 2.0-2.2).
    CHECK(d3 > d2);
    CHECK(d4 >= d3);
    CHECK(d4 - d3 < 0.35 * (d3 - d2));
  }
  CHECK(ladders >= 3);
  // Small-deformation limit: the second-order Richardson limit of the two finest levels at
  // Ca = 0.005 (the order of the exact problems; the ladders above show at least that). 1 %:
  // the O(Ca) correction between Ca 0.005 and 0.0125 is below 0.3 % here.
  REQUIRE(D.count(0.005));
  const auto& small = D.at(0.005);
  REQUIRE(small.size() >= 2);
  const auto finest = std::prev(small.end()), next = std::prev(finest);
  REQUIRE(finest->first == next->first + 1);
  const double limit = finest->second + (finest->second - next->second) / 3.0;
  INFO("D/Ca extrapolated: " << limit / 0.005);
  CHECK(std::abs(limit / 0.005 / 6.25 - 1.0) < 0.01);
}

TEST_CASE("reference table: its level-2 row is what this code computes", "[boundary_integral]") {
  const auto rows = shipped();
  const Row* row = nullptr;
  for (const auto& r : rows)
    if (r.at("Ca") == "0.05" && r.at("level") == "2") row = &r;
  REQUIRE(row != nullptr);
  // The options of scripts/reference-bim-table.
  ReferenceRunOptions o;
  o.capsule.Ca = 0.05;
  o.capsule.level = 2;
  o.kt_end = 12;
  o.steady_tolerance = 1e-4;
  o.steady_window_kt = 1;
  o.every = 0.05;
  std::ostringstream out;
  run_reference(o, out);
  std::istringstream in(out.str());
  const auto fresh = read_csv(in);
  REQUIRE(fresh.size() == 1);
  CHECK(fresh[0].at("steps") == row->at("steps"));
  CHECK(num(fresh[0], "D_end") == Approx(num(*row, "D_end")).epsilon(1e-5));  // the table's 6 digits
}
