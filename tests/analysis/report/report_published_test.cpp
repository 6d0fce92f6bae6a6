// The report's "published" kind: members against the embedded published curves D(kt), on
// synthetic members whose D_xy is the curve itself shifted by a known offset.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include "analysis/report/published_curves.hpp"
#include "analysis/report/report.hpp"
#include "analysis/report/report_context.hpp"
#include "solver/io/member_file.hpp"
#include "tests/analysis/synthetic_campaign.hpp"

using namespace capsule::analysis;
using capsule::analysis::testing::slurp;
using capsule::analysis::testing::TempDir;
using Catch::Matchers::Contains;
namespace fs = std::filesystem;

namespace {

const std::string kCurve = "sphere_neohookean_V1_rp1998_ca0.05";

// A member at Ca whose D_xy is the curve + offset (D_extent the curve + 2 offset) on a fine
// grid, sheared until t_stop, then 1 kt of recovery at D = 0 (which must not be compared).
void add_curve_member(ReportRequest& req, const fs::path& root, const std::string& slug, double Ca, double offset,
                      double t_stop) {
  const PublishedCurve c = published_curve(kCurve);
  const std::string path = (root / slug / "member.h5").string();
  fs::create_directories(root / slug);
  const nlohmann::json scene{{"dim", 3}, {"Ca", Ca}, {"E_b", 0}, {"V", 1}, {"eta", 0}, {"Re", 0.05}};
  {
    capsule::io::MemberWriter w(path);
    w.set_scene(scene);
    for (double t = 0; t <= t_stop + 1.0 + 1e-9; t += 0.01) {
      const bool shear = t <= t_stop + 1e-9;
      double d = 0;
      if (shear) {  // the curve, linearly interpolated, flat past its ends
        if (t <= c.kt.front()) d = c.D.front();
        else if (t >= c.kt.back()) d = c.D.back();
        else
          for (std::size_t j = 1; j < c.kt.size(); ++j)
            if (t <= c.kt[j]) {
              d = c.D[j - 1] + (t - c.kt[j - 1]) / (c.kt[j] - c.kt[j - 1]) * (c.D[j] - c.D[j - 1]);
              break;
            }
      }
      w.append({{"kt", t}, {"D_xy", shear ? d + offset : 0.0}, {"D_extent", shear ? d + 2 * offset : 0.0},
                {"shear_on", shear ? 1.0 : 0.0}});
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    w.set_markers({{"t_stop", t_stop}, {"D_stop", nan}, {"t_max", nan}, {"D_max", nan}, {"t_end", t_stop + 1.0}});
    w.finish("complete");
  }
  req.members.push_back({"id_" + slug, slug, path, "", scene});
}

}  // namespace

TEST_CASE("Published curves: the embedded copies are the files in analysis/reference", "[analysis][published]") {
  const auto names = published_curve_names();
  REQUIRE(names.size() >= 4);
  for (const auto& name : names) {
    std::ifstream f(std::string(CAPSULE_SOURCE_DIR) + "/analysis/reference/" + name + ".csv");
    REQUIRE(f.good());
    std::stringstream text;
    text << f.rdbuf();
    PublishedCurve from_file;
    parse_curve_csv(text.str(), from_file);
    const PublishedCurve embedded = published_curve(name);
    CHECK(embedded.kt == from_file.kt);
    CHECK(embedded.D == from_file.D);
    for (std::size_t i = 1; i < embedded.kt.size(); ++i) CHECK(embedded.kt[i] >= embedded.kt[i - 1]);  // sorted
  }
  CHECK_THROWS_WITH(published_curve("no_such_curve"), Contains("known: "));
}

TEST_CASE("interpolate_series: exact on a straight line, the end points included, NaN outside", "[analysis][published]") {
  const std::vector<double> t{0.0, 0.5, 2.0}, y{1.0, 2.0, 5.0};  // y = 1 + 2 t
  for (const double at : {0.0, 0.25, 0.5, 1.3, 2.0}) CHECK(interpolate_series(t, y, at) == Approx(1.0 + 2.0 * at));
  CHECK(std::isnan(interpolate_series(t, y, -0.1)));
  CHECK(std::isnan(interpolate_series(t, y, 2.1)));
  CHECK(std::isnan(interpolate_series({}, {}, 0.0)));
}

TEST_CASE("Published report: differences at the curve's points during the shear, and refusals", "[analysis][published]") {
  TempDir tmp("published");
  ReportRequest req;
  req.campaign_name = "published";
  req.out_dir = (tmp.path / "report").string();
  req.analysis = {{"fits", {"response"}},
                  {"figures", false},
                  {"published",
                   {{{"curve", kCurve}, {"where", {{"Ca", 0.05}}}},
                    {{"curve", "sphere_neohookean_V1_rp1998_ca0.2"}, {"where", {{"Ca", 0.2}}}}}}};
  const double offset = 0.012;
  add_curve_member(req, tmp.path / "members", "close", 0.05, 0.002, 10.0);  // beyond the curve's end
  add_curve_member(req, tmp.path / "members", "far", 0.05, offset, 10.0);
  add_curve_member(req, tmp.path / "members", "short", 0.05, 0.0, 2.0);    // stops before the curve does
  add_curve_member(req, tmp.path / "members", "other_ca", 0.1, 0.0, 10.0);   // matches no curve
  write_report(req);
  const auto fits = nlohmann::json::parse(slurp(fs::path(req.out_dir) / "fits.json"));
  REQUIRE(fits.contains("published"));
  std::map<std::string, nlohmann::json> by_member;
  for (const auto& e : fits["published"])
    by_member[e.value("member", std::string("(none) ") + e["curve"].get<std::string>())] = e;
  REQUIRE(by_member.count("far"));
  const PublishedCurve c = published_curve(kCurve);
  const auto& far = by_member["far"];
  // Linear interpolation of a series that is the curve + offset gives offset at every point
  // (to the fine grid's interpolation error of the curve's own kinks: a small fraction of it).
  CHECK(far["points"].get<std::size_t>() == c.kt.size());
  CHECK(far["bias_D_xy"].get<double>() == Approx(offset).margin(5e-4));
  CHECK(far["max_abs_D_xy"].get<double>() == Approx(offset).margin(2e-3));
  CHECK(far["max_abs_D_extent"].get<double>() == Approx(2 * offset).margin(2e-3));
  CHECK(far["D_curve_last"].get<double>() == Approx(c.D.back()));
  CHECK(far["D_xy_last"].get<double>() == Approx(c.D.back() + offset).margin(1e-4));
  CHECK(far["within_digitising_error"] == "no");
  CHECK(by_member["close"]["within_digitising_error"] == "yes");
  // The short member: only the curve's points before its shear ended, and a note of the rest.
  const auto& shorter = by_member["short"];
  std::size_t before = 0;
  for (double t : c.kt) before += t <= 2.0;
  CHECK(shorter["points"].get<std::size_t>() == before);
  CHECK_THAT(shorter["note"].get<std::string>(), Contains("after the member's shear ended at kt = 2"));
  CHECK(by_member.count("other_ca") == 0);
  // A curve that no member matches says so.
  REQUIRE(by_member.count("(none) sphere_neohookean_V1_rp1998_ca0.2"));
  CHECK_THAT(by_member["(none) sphere_neohookean_V1_rp1998_ca0.2"]["reason"].get<std::string>(),
             Contains("no member with Ca = 0.2"));
  CHECK_THAT(slurp(fs::path(req.out_dir) / "published" / "published.md"), Contains("| far |"));
}

TEST_CASE("Published block: unknown curves and keys are refused with their path", "[analysis][published]") {
  ReportRequest req;
  req.campaign_name = "bad";
  req.out_dir = "/nonexistent";
  req.analysis = {{"published", {{{"curve", "rp_nothing"}}}}};
  CHECK_THROWS_WITH(write_report(req), Contains("/analysis/published/0/curve: unknown curve \"rp_nothing\""));
  req.analysis = {{"published", {{{"curve", kCurve}, {"where", {{"Ca", "0.05"}}}}}}};
  CHECK_THROWS_WITH(write_report(req), Contains("/analysis/published/0/where/Ca: expected a number"));
  req.analysis = {{"published", {{{"curve", kCurve}, {"shape", "sphere"}}}}};
  CHECK_THROWS_WITH(write_report(req), Contains("/analysis/published/0/shape: unknown key"));
  req.analysis = {{"published", nlohmann::json::array()}};
  CHECK_THROWS_WITH(write_report(req), Contains("/analysis/published: expected a non-empty array"));
}

#include "analysis/dissertation/report.hpp"
#include "analysis/dissertation/validation.hpp"

TEST_CASE("THESIS.md validation: the published rows of ch2_3d_ca, and cannot tell without them", "[analysis][published]") {
  TempDir tmp("dissertation_validation");
  {
    const DissertationResults none(tmp.path.string());
    const Table t = validation_table(none);
    REQUIRE(t.rows.size() == 1);
    CHECK(t.rows[0][10] == "cannot tell");
    CHECK_THAT(t.rows[0][11], Contains("not run"));
  }
  const auto dir = tmp.path / "ch2_3d_ca" / "report";
  fs::create_directories(dir);
  nlohmann::json fits{{"campaign", "ch2_3d_ca"}, {"members", nlohmann::json::array()}};
  fits["published"] = {{{"curve", kCurve}, {"member", "Ca0.05"}, {"points", 40}, {"bias_D_xy", 0.0148},
                        {"max_abs_D_xy", 0.0203}, {"max_abs_D_extent", 0.0201}, {"D_curve_last", 0.25},
                        {"D_xy_last", 0.27}, {"within_digitising_error", "no"}},
                       {{"curve", "sphere_neohookean_V1_rp1998_ca0.2"}, {"reason", "no member with Ca = 0.2"}}};
  std::ofstream(dir / "fits.json") << fits.dump(2);
  const DissertationResults results(tmp.path.string());
  const Table t = validation_table(results);
  REQUIRE(t.rows.size() == 2);
  CHECK(t.rows[0][2] == "Ca0.05");
  CHECK(t.rows[0][9] == "+8 %");  // 0.27 / 0.25 - 1
  CHECK(t.rows[0][10] == "no");
  CHECK(t.rows[1][10] == "cannot tell");
  CHECK(t.rows[1][11] == "no member with Ca = 0.2");
  CHECK_THAT(dissertation_markdown(results, "r"), Contains("## Validation against published curves"));
}
