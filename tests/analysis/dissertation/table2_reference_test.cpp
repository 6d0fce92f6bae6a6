// The dissertation's Table 2, shipped as CSV and embedded in the library: the two must agree.
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>

#include "analysis/dissertation/table2_reference.hpp"

using namespace capsule::analysis;

TEST_CASE("Table 2 reference: the build embeds analysis/reference/table2_dissertation.csv as it is", "[analysis]") {
  std::ifstream f(std::string(CAPSULE_SOURCE_DIR) + "/analysis/reference/table2_dissertation.csv");
  REQUIRE(f);
  std::stringstream s;
  s << f.rdbuf();
  CHECK(s.str() == table2_csv_text());
}

TEST_CASE("Table 2 reference: rows as printed in the dissertation", "[analysis]") {
  const auto& rows = table2_dissertation();
  REQUIRE(rows.size() == 6);
  // Spot checks against the text (Sec. 5.1.1, Table 2), first and last rows.
  CHECK(rows[0].target == "k_tau_s");
  CHECK(rows[0].Ca == 0.05);
  CHECK(rows[0].E_b == 0.0);
  CHECK(rows[0].a == 0.0208);
  CHECK(rows[0].a_half_width == 0.0039);
  CHECK(rows[5].target == "k_tau_r");
  CHECK(rows[5].Ca == 0.2);
  CHECK(rows[5].b == 1.0120);
  CHECK(rows[5].c_half_width == 0.162);
  // The text's ratios (Sec. 5.1.1): b_s/a_s ~ 2.8 and b_r/a_r ~ 5 for Ca = 0.05, E_b = 0;
  // "~" read as the text's one or two significant digits (+-0.1 and +-0.2).
  CHECK(rows[0].b / rows[0].a == Approx(2.8).margin(0.1));
  CHECK(rows[1].b / rows[1].a == Approx(5.0).margin(0.2));
  CHECK_THROWS_AS(parse_table2_csv("header\nk_tau_s,0.05,0,x,1,2,3,4,5\n"), std::runtime_error);
  CHECK_THROWS_AS(parse_table2_csv("header\nk_tau_s,0.05\n"), std::runtime_error);
}
