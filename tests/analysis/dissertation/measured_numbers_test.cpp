// The measured numbers THESIS.md's prose quotes (deviations.md's probes): placeholders filled from
// the shipped results at generation, on a synthetic campaign and on the shipped one, and the
// committed THESIS.md checked against its sources.
#include <catch2/catch.hpp>

#include <filesystem>
#include <map>
#include <fstream>
#include <regex>
#include <sstream>

#include "analysis/dissertation/cause_grades.hpp"
#include "analysis/dissertation/deviations.hpp"
#include "analysis/dissertation/measured_numbers.hpp"
#include "analysis/dissertation/prose_lines.hpp"
#include "tests/analysis/dissertation_fixtures.hpp"
#include "tests/analysis/synthetic_campaign.hpp"

using namespace capsule::analysis;
using namespace capsule::analysis::testing;
namespace fs = std::filesystem;

namespace {

std::string file_text(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST_CASE("Measured numbers: placeholders filled from a campaign's fits", "[analysis][dissertation]") {
  TempDir tmp("dissertation_measured_numbers");
  nlohmann::json members = nlohmann::json::array();
  for (const double V : {0.2, 1.0})
    members.push_back(member_json("V" + short_number(V), "", {{"V", V}},
                                  {{"recovery", known_fit("recovery (86)", {{"k_tau_r", {0.5 + 0.25 * V, 0.01}}}, 0.97)}}));
  write_fits(tmp.path, "probe", members);
  const DissertationResults results(tmp.path.string());
  CHECK(measured_number(results, "fit probe/V0.2/recovery.k_tau_r") == Approx(0.55));
  CHECK(measured_number(results, "r2 probe/V1/recovery") == Approx(0.97));
  CHECK(measured_number(results, "intercept probe/recovery.k_tau_r/V/V0.2+V1") == Approx(0.5));
  CHECK(measured_number(results, "slope probe/recovery.k_tau_r/V/V0.2+V1") == Approx(0.25));
  CHECK(measured_number(results, "exponent probe/recovery.k_tau_r/V/V0.2+V1") ==
        Approx(std::log(0.75 / 0.55) / std::log(5.0)));
  CHECK(fill_measured_numbers("k tau_r {fit probe/V1/recovery.k_tau_r} ({case} left alone)", results) ==
        "k tau_r 0.75 ({case} left alone)");
  CHECK_THROWS_WITH(measured_number(results, "fit probe/V5/recovery.k_tau_r"), Catch::Contains("has no member V5"));
  CHECK_THROWS_WITH(measured_number(results, "fit probe/V1/response.k_tau_s"), Catch::Contains("has no response.k_tau_s"));
  CHECK_THROWS_WITH(measured_number(results, "fit other/V1/recovery.k_tau_r"), Catch::Contains("not run"));
  CHECK_THROWS_WITH(fill_measured_numbers("{slope probe/recovery.k_tau_r/V/V1}", results), Catch::Contains("two members"));
  // Results without the probe (an empty results folder) still give a document, saying what is missing.
  CHECK(fill_measured_numbers("k tau_r {fit probe/V5/recovery.k_tau_r}.", results, false) ==
        "k tau_r [not measured: campaign probe has no member V5].");
}

TEST_CASE("Measured numbers: a bilinear coefficient at the finest level or extrapolated and a member series at a time", "[analysis][dissertation]") {
  TempDir tmp("dissertation_measured_bilinear");
  SyntheticMember sm;  // D_xy rises as (85) to kt 6 (t_stop), then falls as (86)
  write_member((tmp.path / "probe/members/m/member.h5").string(), sm);
  const nlohmann::json members = nlohmann::json::array({member_json("m", "", {{"V", 1.0}}, {}, "members/m/member.h5")});
  const nlohmann::json bilinear = nlohmann::json::array(
      {bilinear_json("response.k_tau_s", 0.05, 0.0, known_fit("bilinear (95)-(96)", {{"a", {0.02, 0.001}}, {"b", {0.08, 0.002}}, {"c", {0.4, 0.01}}}, 0.9))});
  write_fits(tmp.path, "probe", members, bilinear);
  {  // the ladder's extrapolations, as the report writes them
    nlohmann::json fits;
    std::ifstream(tmp.path / "probe/report/fits.json") >> fits;
    fits["bilinear_ladder"] = nlohmann::json::array();
    for (const auto& [coefficient, x] : std::map<std::string, double>{{"a", 0.025}, {"b", 0.1}})
      fits["bilinear_ladder"].push_back({{"case", ""}, {"target", "response.k_tau_s"}, {"coefficient", coefficient}, {"ok", true},
                                         {"extrapolated", x}, {"error_estimate", 0.01}, {"levels", nlohmann::json::array()}});
    std::ofstream(tmp.path / "probe/report/fits.json") << fits.dump();
  }
  const DissertationResults results(tmp.path.string());
  CHECK(measured_number(results, "bilinear probe/response.k_tau_s/b/finest") == Approx(0.08));
  CHECK(measured_number(results, "bilinear probe/response.k_tau_s/b_over_a/finest") == Approx(4.0));
  CHECK(measured_number(results, "bilinear probe/response.k_tau_s/b_over_a/extrapolated") == Approx(4.0));
  CHECK(measured_number(results, "bilinear probe/response.k_tau_s/a/extrapolated") == Approx(0.025));
  CHECK_THROWS_WITH(measured_number(results, "bilinear probe/response.k_tau_s/c/extrapolated"), Catch::Contains("no extrapolation of c"));
  CHECK_THROWS_WITH(measured_number(results, "bilinear probe/recovery.k_tau_r/a/finest"), Catch::Contains("no bilinear fit of recovery.k_tau_r"));
  CHECK_THROWS_WITH(measured_number(results, "bilinear probe/response.k_tau_s/a/coarsest"), Catch::Contains("neither finest nor extrapolated"));
  // (85) at kt 1 and the value at the stop, D_max (1 - exp(-t_stop / k tau_s)); the series carries noise sigma 1e-4.
  CHECK(measured_number(results, "at probe/m/D_xy/1") == Approx(sm.D_max * (1 - std::exp(-1.0 / sm.k_tau_s))).margin(5e-4));
  CHECK(measured_number(results, "at probe/m/D_xy/stop") == Approx(sm.D_max * (1 - std::exp(-sm.t_max / sm.k_tau_s))).margin(5e-4));
  CHECK_THROWS_WITH(measured_number(results, "at probe/m/D_xy/99"), Catch::Contains("outside"));
  CHECK_THROWS_WITH(measured_number(results, "at probe/m/tension/1"), Catch::Contains("records no tension"));
  CHECK(fill_measured_numbers("D {at probe/m/D_xy/stop}", results).rfind("D 0.", 0) == 0);
}

TEST_CASE("Measured numbers: deviations.md's quoted probe numbers are their shipped sources, and THESIS.md quotes them", "[analysis][dissertation]") {
  const fs::path results_dir = fs::path(CAPSULE_SOURCE_DIR) / "results";
  const DissertationResults results(results_dir.string());
  // Each {fit ...} and {r2 ...} of deviations.md against fits.json read here, independently.
  const std::string whole = file_text(fs::path(CAPSULE_SOURCE_DIR) / "analysis/dissertation/deviations.md");
  const std::string md = whole.substr(whole.find("\n## "));  // the causes, not the introduction's example
  const std::regex placeholder(R"(\{(fit|r2) ([^/}]+)/([^/}]+)/([^}]+)\})");
  int checked = 0;
  for (std::sregex_iterator it(md.begin(), md.end(), placeholder), end; it != end; ++it) {
    const std::string kind = (*it)[1], campaign = (*it)[2], slug = (*it)[3], what = (*it)[4];
    INFO(it->str());
    nlohmann::json fits;
    std::ifstream(results_dir / campaign / "report/fits.json") >> fits;
    double source = std::nan("");
    for (const auto& m : fits["members"]) {
      if (m["slug"] != slug) continue;
      if (kind == "r2") {
        source = m["fits"][what]["r_squared"].get<double>();
      } else {
        const std::string fit = what.substr(0, what.find('.')), name = what.substr(what.find('.') + 1);
        for (const auto& p : m["fits"][fit]["parameters"])
          if (p["name"] == name) source = p["value"].get<double>();
      }
    }
    REQUIRE(std::isfinite(source));
    CHECK(measured_number(results, kind + " " + campaign + "/" + slug + "/" + what) == source);
    ++checked;
  }
  CHECK(checked >= 20);
  // The committed THESIS.md quotes the numbers the shipped results give now.
  const std::string filled = known_deviations_markdown(results, grade_causes(results));
  CHECK(filled.find("{fit ") == std::string::npos);
  CHECK(filled.find("[not measured") == std::string::npos);
  CHECK(file_text(results_dir / "THESIS.md").find(wrap_prose_lines(filled)) != std::string::npos);
}
