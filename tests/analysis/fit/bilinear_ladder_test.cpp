// The bilinear model (95)-(96) over a resolution ladder (bilinear.ladder): one fit per level,
// each coefficient extrapolated over the levels, and Table 2's reader taking the finest level
// with its error estimate.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include <algorithm>

#include "analysis/report/analysis_block.hpp"
#include "analysis/fit/fit_result.hpp"
#include "analysis/report/report.hpp"
#include "analysis/dissertation/table2_compare.hpp"
#include "tests/analysis/synthetic_campaign.hpp"

using namespace capsule::analysis;
using capsule::analysis::testing::SyntheticMember;
using capsule::analysis::testing::lines;
using capsule::analysis::testing::slurp;
using capsule::analysis::testing::TempDir;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;
namespace fs = std::filesystem;

namespace {

// k tau_r = a(h) eta + b(h) V + c(h) with every coefficient first order in h = 1/a:
// a = 0.05 + 0.1 h, b = 0.27 + 0.5 h, c = 0.4 + 1.0 h; k tau_s = 0.02 eta + 0.06 V + 0.4 at
// every level. The limits are the h -> 0 values.
ReportRequest ladder_campaign(const fs::path& root, const std::vector<int>& levels, bool stray_member) {
  ReportRequest req;
  req.campaign_name = "ladder";
  req.campaign_file = "ladder.json";
  req.out_dir = (root / "report").string();
  req.analysis = {{"fits", {"response", "recovery"}},
                  {"bilinear", {{"targets", {"response.k_tau_s", "recovery.k_tau_r"}}, {"ladder", "resolution.a"}}},
                  {"figures", false}};
  unsigned seed = 1;
  for (int a : levels)
    for (double eta : {0.0, 2.0, 4.0})
      for (double V : {0.2, 1.0, 2.0}) {
        const double h = 1.0 / a;
        SyntheticMember m;
        m.eta = eta;
        m.V = V;
        m.k_tau_s = 0.02 * eta + 0.06 * V + 0.4;
        m.k_tau_r = (0.05 + 0.1 * h) * eta + (0.27 + 0.5 * h) * V + (0.4 + 1.0 * h);
        m.sigma = 1e-7;  // the fitted times then carry ~1e-6 relative error: far below the ladder's differences
        m.t_end = m.t_max + 12.0 * m.k_tau_r;
        m.seed = seed++;
        m.resolution = {{"a", a}};
        const std::string slug = "a" + std::to_string(a) + "_eta" + std::to_string(static_cast<int>(eta)) + "_V" +
                                 std::to_string(V).substr(0, 3);
        const std::string path = (root / "members" / slug / "member.h5").string();
        capsule::analysis::testing::write_member(path, m);
        req.members.push_back({"id" + slug, slug, path, "sphere", scene_of(m)});
      }
  if (stray_member) {  // a member whose scene names no resolution.a is on no level
    SyntheticMember m;
    const std::string path = (root / "members" / "stray" / "member.h5").string();
    capsule::analysis::testing::write_member(path, m);
    req.members.push_back({"idstray", "stray", path, "sphere", scene_of(m)});
  }
  return req;
}

const nlohmann::json* ladder_entry(const nlohmann::json& fits, const std::string& target, const std::string& coef) {
  for (const auto& l : fits["bilinear_ladder"])
    if (l["target"] == target && l["coefficient"] == coef) return &l;
  return nullptr;
}

}  // namespace

TEST_CASE("bilinear over a resolution ladder: one fit per level, finest first, coefficients extrapolated", "[analysis]") {
  TempDir tmp("bilinear_ladder");
  write_report(ladder_campaign(tmp.path, {5, 7, 10}, true));
  const fs::path out = tmp.path / "report";
  const nlohmann::json fits = nlohmann::json::parse(slurp(out / "fits.json"));

  // Two targets x three levels, the finest level first within each target's run of levels.
  REQUIRE(fits["bilinear"].size() == 6);
  CHECK(fits["bilinear"][0]["level"]["value"] == 10.0);
  CHECK(fits["bilinear"][0]["target"] == "response.k_tau_s");
  CHECK(fits["bilinear"][1]["target"] == "recovery.k_tau_r");
  CHECK(fits["bilinear"][1]["level"]["value"] == 10.0);
  CHECK(fits["bilinear"][5]["level"]["value"] == 5.0);
  const auto csv = lines(slurp(out / "bilinear.csv"));
  REQUIRE(csv.size() == 1 + 6 + 1);  // header, six fits, the stray member's row
  CHECK_THAT(csv[1], StartsWith("sphere,a = 10,response.k_tau_s,"));
  CHECK_THAT(csv[7], Contains("no level") && Contains("not fitted: stray"));
  CHECK(fits["bilinear_unplaced"].size() == 1);

  // Each level's fit recovers that level's coefficients (exact model, tiny noise).
  const FitResult a5 = fit_result_from_json(fits["bilinear"][5]["fit"]);
  REQUIRE(a5.ok);
  CHECK(a5.parameter("c")->value == Approx(0.4 + 1.0 / 5).epsilon(1e-3));

  // Three levels: observed order 1 and the h -> 0 limits; the error estimate is what the
  // finest level carries (0.1 h at a = 10 for a_r, 0.5 h for b_r, 1.0 h for c_r).
  const struct { const char* coef; double limit, slope; } expected[] = {{"a", 0.05, 0.1}, {"b", 0.27, 0.5}, {"c", 0.4, 1.0}};
  for (const auto& e : expected) {
    INFO("coefficient " << e.coef);
    const nlohmann::json* l = ladder_entry(fits, "recovery.k_tau_r", e.coef);
    REQUIRE(l);
    REQUIRE((*l)["ok"] == true);
    CHECK((*l)["order_observed"] == true);
    CHECK((*l)["order"].get<double>() == Approx(1.0).margin(0.05));
    CHECK((*l)["extrapolated"].get<double>() == Approx(e.limit).margin(0.02 * e.slope / 10));
    CHECK((*l)["error_estimate"].get<double>() == Approx(e.slope / 10).epsilon(0.05));
    CHECK((*l)["levels"].size() == 3);
  }
  // k tau_s does not depend on the level: the differences vanish and the ladder says so
  // (no order can be observed from differences that are only noise) rather than inventing one.
  const nlohmann::json* s = ladder_entry(fits, "response.k_tau_s", "c");
  REQUIRE(s);
  if ((*s)["ok"] == true) CHECK((*s)["error_estimate"].get<double>() < 1e-3);
  else CHECK_FALSE((*s)["note"].get<std::string>().empty());
  const auto ladder_md = slurp(out / "bilinear_ladder.md");
  CHECK_THAT(ladder_md, Contains("resolution.a") && Contains("(observed)"));

  // Table 2's reader: the first entry of a target is its finest level, with the ladder's errors.
  const auto entries = read_bilinear_entries("ladder", fits);
  const auto r = std::find_if(entries.begin(), entries.end(), [](const BilinearEntry& b) {
    return b.target == "recovery.k_tau_r";
  });
  REQUIRE(r != entries.end());
  CHECK(r->level_key == "resolution.a");
  CHECK(r->level == 10.0);
  REQUIRE(r->ladder_error.count("c") == 1);
  CHECK(r->ladder_error.at("c") == Approx(0.1).epsilon(0.05));
}

TEST_CASE("bilinear ladder of two levels assumes the order and says so - one level refuses", "[analysis]") {
  TempDir tmp("bilinear_ladder2");
  write_report(ladder_campaign(tmp.path, {7, 10}, false));
  const nlohmann::json fits = nlohmann::json::parse(slurp(tmp.path / "report" / "fits.json"));
  const nlohmann::json* l = ladder_entry(fits, "recovery.k_tau_r", "c");
  REQUIRE(l);
  REQUIRE((*l)["ok"] == true);
  CHECK((*l)["order_observed"] == false);
  CHECK((*l)["order"] == 1.0);
  // order 1 through h = 1/7 and 1/10 is exact for this model: the limit 0.4
  CHECK((*l)["extrapolated"].get<double>() == Approx(0.4).margin(1e-3));
  CHECK_THAT((*l)["note"].get<std::string>(), Contains("assumed"));

  TempDir one("bilinear_ladder1");
  write_report(ladder_campaign(one.path, {10}, false));
  const nlohmann::json f1 = nlohmann::json::parse(slurp(one.path / "report" / "fits.json"));
  const nlohmann::json* l1 = ladder_entry(f1, "recovery.k_tau_r", "a");
  REQUIRE(l1);
  CHECK((*l1)["ok"] == false);
  CHECK_FALSE((*l1)["note"].get<std::string>().empty());
  CHECK_THAT(slurp(one.path / "report" / "bilinear_ladder.md"), Contains("n/a"));
}

TEST_CASE("bilinear ladder keys are validated with the file and key named", "[analysis]") {
  CHECK_THROWS_WITH(
      validate_analysis_block({{"bilinear", {{"targets", {"recovery.k_tau_r"}}, {"spacing", "1/x"}}}}, "c.json"),
      Contains("c.json: /analysis/bilinear/spacing: only with /bilinear/ladder"));
  CHECK_THROWS_WITH(
      validate_analysis_block({{"bilinear", {{"targets", {"recovery.k_tau_r"}}, {"ladder", "resolution.tau"}}}}, "c.json"),
      Contains("c.json: /analysis/bilinear/spacing: required for key \"resolution.tau\""));
  CHECK_THROWS_WITH(validate_analysis_block({{"bilinear",
                                              {{"targets", {"recovery.k_tau_r"}},
                                               {"ladder", "resolution.a"},
                                               {"assumed_order", 0}}}},
                                            "c.json"),
                    Contains("c.json: /analysis/bilinear/assumed_order: expected an order in (0, 8]"));
  CHECK_NOTHROW(validate_analysis_block(
      {{"bilinear", {{"targets", {"recovery.k_tau_r"}}, {"ladder", "resolution.mesh_level"}}}}, "c.json"));
}
