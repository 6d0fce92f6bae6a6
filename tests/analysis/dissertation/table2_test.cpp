// THESIS.md's Table 2 section: synthetic fits.json files with known bilinear coefficients
// give the right differences, overlaps, ratios and "cannot tell" for a campaign not run.
#include <cmath>

#include <catch2/catch.hpp>

#include "analysis/fit/fit_statistics.hpp"
#include "analysis/dissertation/report.hpp"
#include "analysis/dissertation/table2.hpp"
#include "tests/analysis/synthetic_campaign.hpp"
#include "tests/analysis/dissertation_fixtures.hpp"

using namespace capsule::analysis;
using namespace capsule::analysis::testing;

TEST_CASE("Dissertation Table 2: known coefficients give the right differences and overlaps", "[analysis][dissertation]") {
  TempDir tmp("dissertation_table2");
  // Ca = 0.05, E_b = 0 (Table 2: a_s 0.0208 ± 0.0039, b_s 0.0590 ± 0.0149, c_s 0.4158 ± 0.0638).
  const FitResult s = known_fit("bilinear (95)-(96)", {{"a", {0.0408, 0.002}}, {"b", {0.0590, 0.01}}, {"c", {0.4158 + 0.1, 0.05}}}, 0.93, 15);
  // k tau_r (Table 2: a_r 0.0534 ± 0.0028, b_r 0.2711 ± 0.0109, c_r 0.3986 ± 0.0466).
  const FitResult r = known_fit("bilinear (95)-(96)", {{"a", {0.0534 + 0.006, 0.0022}}, {"b", {0.25, 0.02}}, {"c", {0.40, 0.01}}}, 0.998, 15);
  write_fits(tmp.path, "ch5_bilinear_ca005", nlohmann::json::array(),
             nlohmann::json::array({bilinear_json("response.k_tau_s", 0.05, 0.0, s), bilinear_json("recovery.k_tau_r", 0.05, 0.0, r)}));
  // The E_b = 0.025 campaign has a failed fit; Ca = 0.2 is not run at all.
  write_fits(tmp.path, "ch5_bilinear_ca005_eb", nlohmann::json::array(),
             nlohmann::json::array({bilinear_json("response.k_tau_s", 0.05, 0.025,
                                                  FitResult::failure("bilinear (95)-(96)", "too few members (3 < 5)"))}));

  const DissertationResults results(tmp.path.string());
  const auto rows = compare_table2_rows(results);
  REQUIRE(rows.size() == 6);

  const auto& rs = rows[0];  // k_tau_s, Ca 0.05, E_b 0
  REQUIRE(rs.found);
  REQUIRE(rs.coefficients.size() == 3);
  CHECK(rs.coefficients[0].difference == Approx(0.02));
  CHECK_FALSE(rs.coefficients[0].overlap);  // [0.0388, 0.0428] against [0.0169, 0.0247]
  CHECK(rs.coefficients[1].difference == Approx(0.0).margin(1e-12));
  CHECK(rs.coefficients[1].overlap);
  CHECK(rs.coefficients[2].difference == Approx(0.1));
  CHECK(rs.coefficients[2].overlap);        // [0.4658, 0.5658] against [0.352, 0.4796]: share [0.4658, 0.4796]
  // The coefficient extrapolated over a ladder against the text's: |x - 0.0208| <= 1.96 sigma,
  // sigma^2 = (0.0039/1.96)^2 + (0.002/1.96)^2 + e^2.
  Table2RowComparison laddered = rs;
  CHECK_FALSE(extrapolated_difference_test(laddered, laddered.coefficients[0]).has_value());  // no extrapolation
  laddered.entry.ladder_extrapolated["a"] = 0.03, laddered.entry.ladder_error["a"] = 0.005;
  laddered.entry.ladder_coarser["a"] = 0.045;  // 0.045 -> 0.0408: toward the text's 0.0208
  auto x = extrapolated_difference_test(laddered, laddered.coefficients[0]);
  REQUIRE(x.has_value());
  CHECK(x->difference == Approx(0.0092));
  CHECK(x->sigma == Approx(std::sqrt(std::pow(0.0039 / 1.96, 2) + std::pow(0.002 / 1.96, 2) + 0.005 * 0.005)));
  CHECK(x->passes);  // 0.0092 <= 1.96 x 0.00548
  CHECK(x->moves == 1);
  laddered.entry.ladder_error["a"] = 0.001, laddered.entry.ladder_coarser["a"] = 0.035;  // 0.035 -> 0.0408: away
  x = extrapolated_difference_test(laddered, laddered.coefficients[0]);
  CHECK_FALSE(x->passes);  // 0.0092 > 1.96 x 0.00245
  CHECK(x->moves == -1);

  const auto& rr = rows[1];  // k_tau_r, Ca 0.05, E_b 0
  REQUIRE(rr.found);
  CHECK(rr.coefficients[0].difference == Approx(0.006));
  CHECK_FALSE(rr.coefficients[0].overlap);  // [0.0572, 0.0616] against [0.0506, 0.0562]
  CHECK(rr.coefficients[1].difference == Approx(0.25 - 0.2711));
  CHECK(rr.coefficients[1].overlap);
  CHECK(rr.coefficients[2].overlap);

  // E_b = 0.025: the k tau_s fit failed (its reason), the k tau_r fit is absent from fits.json.
  REQUIRE(rows[2].found);
  CHECK_FALSE(rows[2].coefficients[0].measured);
  CHECK(rows[2].coefficients[0].reason == "too few members (3 < 5)");
  CHECK_FALSE(rows[3].found);
  CHECK(rows[3].why.find("no bilinear fit of k_tau_r") != std::string::npos);
  // Ca = 0.2: not run.
  CHECK_FALSE(rows[4].found);
  CHECK(rows[4].why.find("campaign ch5_bilinear_ca02 not run") != std::string::npos);

  const std::string md = dissertation_markdown(results, tmp.path.string());
  CHECK(md.find("cannot tell (campaign ch5_bilinear_ca02 not run") != std::string::npos);
  CHECK(md.find("| k_tau_s (Ca 0.05, E_b 0) | ch5_bilinear_ca005 | a | 0.0208 ± 0.0039 | 0.0408 ± 0.002 | 0.02 | NO | ~ 0.91 | 0.93 | 15 |") !=
        std::string::npos);
}

TEST_CASE("Dissertation ratios b/a: delta method from half-widths and from the covariance", "[analysis][dissertation]") {
  const RatioInterval h = ratio_from_half_widths(2.0, 0.2, 4.0, 0.4);
  REQUIRE(h.ok);
  CHECK(h.value == Approx(2.0));
  CHECK(h.half_width == Approx(2.0 * std::sqrt(0.01 + 0.01)));

  // The text's own numbers: b_s/a_s = 0.0590/0.0208 = 2.84 (it says ~ 2.8), b_r/a_r = 5.08 (~ 5).
  const auto& t2 = table2_dissertation();
  CHECK(ratio_from_half_widths(t2[0].a, t2[0].a_half_width, t2[0].b, t2[0].b_half_width).value == Approx(2.8365).epsilon(1e-3));
  CHECK(ratio_from_half_widths(t2[1].a, t2[1].a_half_width, t2[1].b, t2[1].b_half_width).value == Approx(5.0768).epsilon(1e-3));

  FitResult f = known_fit("bilinear (95)-(96)", {{"a", {2.0, 0.2}}, {"b", {4.0, 0.4}}, {"c", {1.0, 0.1}}}, 0.99, 8);
  f.covariance = {{0.01, 0.0, 0.0}, {0.0, 0.04, 0.0}, {0.0, 0.0, 1.0}};
  const RatioInterval c = ratio_b_over_a_interval(f);
  REQUIRE(c.ok);
  CHECK(c.value == Approx(2.0));
  // se = (b/a) sqrt(var a / a^2 + var b / b^2) = 2 sqrt(0.0025 + 0.0025); 95 %: t(8 - 3) se.
  CHECK(c.half_width == Approx(student_t_975(5) * 2.0 * std::sqrt(0.005)));
  CHECK(c.method.find("covariance") != std::string::npos);

  f.covariance.clear();  // a fits.json without covariance: the half-width rule
  const RatioInterval d = ratio_b_over_a_interval(f);
  CHECK(d.half_width == Approx(h.half_width));
  CHECK(d.method.find("half-widths") != std::string::npos);
}

TEST_CASE("Dissertation Table 2: while a ladder's finest level is too small to fit, the finest fitted level stands in", "[analysis][dissertation]") {
  TempDir tmp("dissertation_table2_level");
  const FitResult coarse = known_fit("bilinear (95)-(96)", {{"a", {0.05, 0.01}}, {"b", {0.07, 0.03}}, {"c", {0.8, 0.1}}}, 0.88, 15);
  nlohmann::json fine = bilinear_json("response.k_tau_s", 0.2, 0.0, FitResult::failure("bilinear (95)-(96)", "too few members (2 < 5)"));
  fine["level"] = {{"key", "resolution.a"}, {"value", 7.0}};
  nlohmann::json five = bilinear_json("response.k_tau_s", 0.2, 0.0, coarse);
  five["level"] = {{"key", "resolution.a"}, {"value", 5.0}};
  write_fits(tmp.path, "ch5_bilinear_ca02", nlohmann::json::array(), nlohmann::json::array({fine, five}));
  const DissertationResults results(tmp.path.string());
  const auto rows = compare_table2_rows(results);
  REQUIRE(rows.size() == 6);
  const auto& r = rows[4];  // k_tau_s, Ca 0.2, E_b 0
  REQUIRE(r.found);
  CHECK(r.entry.level == 5.0);
  REQUIRE(r.coefficients.size() == 3);
  CHECK(r.coefficients[0].measured);
  CHECK(r.coefficients[0].difference == Approx(0.05 - 0.0417));
  CHECK(r.entry.ladder_note.at("a") == "the finest level, resolution.a = 7, not fitted yet (too few members (2 < 5))");
  // With no level fitted at all, the finest one is shown with its reason.
  write_fits(tmp.path, "ch5_bilinear_ca02", nlohmann::json::array(), nlohmann::json::array({fine}));
  const DissertationResults none(tmp.path.string());
  const auto rows2 = compare_table2_rows(none);
  REQUIRE(rows2[4].found);
  CHECK(rows2[4].entry.level == 7.0);
  CHECK_FALSE(rows2[4].coefficients[0].measured);
}
