// The report's "experiments" kind: members against an experiment's means and spreads (Mills et
// al. 2004's optical tweezers), on synthetic stretch members whose diameters are the measured
// means shifted by known multiples of the spread.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include "analysis/report/experiment_data.hpp"
#include "analysis/report/report.hpp"
#include "solver/io/member_file.hpp"
#include "tests/analysis/synthetic_campaign.hpp"

using namespace capsule::analysis;
using capsule::analysis::testing::slurp;
using capsule::analysis::testing::TempDir;
using Catch::Matchers::Contains;
namespace fs = std::filesystem;

namespace {

const std::string kData = "mills2004_optical_tweezers";

nlohmann::json experiment_block() {
  return {{"fits", nlohmann::json::array()},
          {"figures", false},
          {"experiments",
           {{{"data", kData},
             {"x", "force_pN"},
             {"parameter", "protocol.stretch.force_pN"},
             {"group", "resolution.a"},
             {"compare",
              {{{"measured", "axial_diameter_um"}, {"spread", "axial_sd_um"}, {"series", "D_axial_um"}},
               {{"measured", "transverse_diameter_um"}, {"spread", "transverse_sd_um"}, {"series", "D_transverse_um"}}}}}}}};
}

// A stretch member at force F and resolution a whose diameters reach mean + z spread at t_stop = 5
// (approached linearly from the rest diameter) and then jump away, which must not be read.
void add_stretch_member(ReportRequest& req, const fs::path& root, std::size_t point, double a, double z,
                        const std::string& status = "complete") {
  const ExperimentData d = experiment_data(kData);
  const double F = d.column("force_pN")[point];
  const double axial = d.column("axial_diameter_um")[point] + z * d.column("axial_sd_um")[point];
  const double transverse = d.column("transverse_diameter_um")[point] + z * d.column("transverse_sd_um")[point];
  const std::string slug = "F" + std::to_string(point) + "-a" + std::to_string(static_cast<int>(a));
  const std::string path = (root / slug / "member.h5").string();
  fs::create_directories(root / slug);
  const nlohmann::json scene{{"dim", 3}, {"Ca", 0.69}, {"E_b", 0.01}, {"V", 1}, {"eta", 0},
                             {"resolution", {{"a", a}}}, {"protocol", {{"stretch", {{"force_pN", F}}}}}};
  capsule::io::MemberWriter w(path);
  w.set_scene(scene);
  const double t_stop = 5.0;
  for (double t = 0; t <= 6.0 + 1e-9; t += 0.5) {
    const double s = std::min(1.0, t / t_stop);
    const double after = t > t_stop + 1e-9 ? 10.0 : 0.0;
    w.append({{"kt", t}, {"D_xy", 0.1}, {"D_axial_um", 7.8 + s * (axial - 7.8) + after},
              {"D_transverse_um", 7.8 + s * (transverse - 7.8) + after}});
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  w.set_markers({{"t_stop", t_stop}, {"D_stop", nan}, {"t_max", nan}, {"D_max", nan}, {"t_end", 6.0}});
  w.finish(status);
  req.members.push_back({"id_" + slug, slug, path, "", scene});
}

}  // namespace

TEST_CASE("Experiment data: the embedded copies are the files in analysis/reference", "[analysis][experiments]") {
  for (const auto& name : experiment_data_names()) {
    const fs::path file = fs::path(CAPSULE_SOURCE_DIR) / "analysis" / "reference" / (name + ".csv");
    std::ifstream f(file);
    REQUIRE(f.good());
    std::stringstream text;
    text << f.rdbuf();
    ExperimentData from_file;
    parse_experiment_csv(text.str(), from_file);
    const ExperimentData embedded = experiment_data(name);
    CHECK(embedded.columns == from_file.columns);
    CHECK(embedded.rows == from_file.rows);
  }
  const ExperimentData mills = experiment_data(kData);
  REQUIRE(mills.rows.size() == 7);
  CHECK(mills.column("force_pN").back() == Approx(193.093));
  CHECK_THROWS_WITH(mills.column("width"), Contains("columns: force_pN, axial_diameter_um"));
  CHECK_THROWS_WITH(experiment_data("nothing"), Contains("known: mills2004_optical_tweezers"));
  ExperimentData bad;
  bad.name = "bad";
  CHECK_THROWS_WITH(parse_experiment_csv("x,y\n1,2\n3\n", bad), Contains("bad line 3: expected 2 numbers"));
}

TEST_CASE("Experiment report: values at t_stop, deviations in spreads, two resolutions and a missing member",
          "[analysis][experiments]") {
  TempDir tmp("experiments");
  ReportRequest req;
  req.campaign_name = "mills";
  req.out_dir = (tmp.path / "report").string();
  req.analysis = experiment_block();
  for (std::size_t i = 0; i < 7; ++i) add_stretch_member(req, tmp.path / "members", i, 5, 0.5);
  for (std::size_t i = 0; i < 6; ++i) add_stretch_member(req, tmp.path / "members", i, 7, i < 3 ? -2.0 : 0.25);
  write_report(req);

  const auto fits = nlohmann::json::parse(slurp(fs::path(req.out_dir) / "fits.json"));
  REQUIRE(fits["experiments"].size() == 1);
  const auto& e = fits["experiments"][0];
  CHECK(e["within_one_spread"]["resolution.a = 5"]["within"] == 14);
  CHECK(e["within_one_spread"]["resolution.a = 5"]["compared"] == 14);
  CHECK(e["within_one_spread"]["resolution.a = 7"]["within"] == 6);     // the three z = 0.25 points, two quantities
  CHECK(e["within_one_spread"]["resolution.a = 7"]["compared"] == 12);  // the 193 pN member is missing
  const ExperimentData d = experiment_data(kData);
  const auto& p1 = e["points"][1];  // axial, 20 pN
  CHECK(p1["quantity"] == "axial_diameter_um");
  CHECK(p1["toolkit"]["resolution.a = 5"].get<double>() == Approx(d.rows[1][1] + 0.5 * d.rows[1][2]));
  CHECK(p1["deviation_in_spreads"]["resolution.a = 5"].get<double>() == Approx(0.5));
  CHECK(p1["deviation_in_spreads"]["resolution.a = 7"].get<double>() == Approx(-2.0));
  CHECK(p1["group_difference"].get<double>() == Approx(-2.5 * d.rows[1][2]));
  const auto& transverse_last = e["points"][13];
  CHECK(transverse_last["quantity"] == "transverse_diameter_um");
  CHECK_THAT(transverse_last["toolkit"]["resolution.a = 7"].get<std::string>(),
             Contains("no member with protocol.stretch.force_pN = 193.093, resolution.a = 7"));
  const std::string md = slurp(fs::path(req.out_dir) / "experiments" / (kData + ".md"));
  CHECK_THAT(md, Contains("Within one spread: resolution.a = 5: 14 of 14; resolution.a = 7: 6 of 12"));
  CHECK_THAT(md, Contains("difference 7 - 5"));
}

TEST_CASE("Experiment report: an unfinished member is a reason, not a number", "[analysis][experiments]") {
  TempDir tmp("experiments_unstable");
  ReportRequest req;
  req.campaign_name = "mills";
  req.out_dir = (tmp.path / "report").string();
  req.analysis = experiment_block();
  add_stretch_member(req, tmp.path / "members", 2, 5, 0.0, "unstable at kt = 3");
  write_report(req);
  const auto fits = nlohmann::json::parse(slurp(fs::path(req.out_dir) / "fits.json"));
  const auto& p = fits["experiments"][0]["points"][2];
  CHECK_THAT(p["toolkit"]["resolution.a = 5"].get<std::string>(), Contains("unstable at kt = 3"));
  CHECK(fits["experiments"][0]["within_one_spread"]["resolution.a = 5"]["compared"] == 0);
}

TEST_CASE("Experiments block: unknown data, columns and keys are refused with their path", "[analysis][experiments]") {
  ReportRequest req;
  req.campaign_name = "bad";
  req.out_dir = "/nonexistent";
  auto block = experiment_block();
  block["experiments"][0]["data"] = "hochmuth";
  req.analysis = block;
  CHECK_THROWS_WITH(write_report(req), Contains("/analysis/experiments/0/data: unknown experiment data \"hochmuth\""));
  block = experiment_block();
  block["experiments"][0]["compare"][1]["spread"] = "width_sd";
  req.analysis = block;
  CHECK_THROWS_WITH(write_report(req), Contains("/analysis/experiments/0/compare/1/spread: experiment data "
                                                "mills2004_optical_tweezers has no column \"width_sd\""));
  block = experiment_block();
  block["experiments"][0].erase("parameter");
  req.analysis = block;
  CHECK_THROWS_WITH(write_report(req), Contains("/analysis/experiments/0/parameter: required key missing"));
  block = experiment_block();
  block["experiments"][0]["colour"] = "red";
  req.analysis = block;
  CHECK_THROWS_WITH(write_report(req), Contains("/analysis/experiments/0/colour: unknown key"));
}

TEST_CASE("Extensional recovery in a report: the fit per member, and the member drawn as its extension ratio",
          "[analysis][experiments]") {
  TempDir tmp("extensional_report");
  ReportRequest req;
  req.campaign_name = "hochmuth";
  req.out_dir = (tmp.path / "report").string();
  req.analysis = {{"fits", {"extensional_recovery"}}, {"figures", true}};
  // Pulled to lambda_0 = 1.4 until t_stop = 4, then Hochmuth's recovery with k t_c = 2.5 towards the
  // rest lambda 1: the figure's curve is lambda itself, from lambda_0 at the release.
  const double t_stop = 4.0, t_c = 2.5, lambda_0 = 1.4, A = (lambda_0 - 1.0) / (lambda_0 + 1.0);
  const fs::path dir = tmp.path / "members" / "released";
  fs::create_directories(dir);
  const nlohmann::json scene{{"dim", 3}, {"Ca", 0.61}, {"E_b", 0.004}, {"V", 1}, {"eta", 21}, {"protocol", {{"stretch", {{"force", 0.5}}}}}};
  {
    capsule::io::MemberWriter w((dir / "member.h5").string());
    w.set_scene(scene);
    for (int i = 0; i <= 160; ++i) {
      const double t = 0.1 * i;
      const double y = A * (t <= t_stop ? t / t_stop : std::exp(-(t - t_stop) / t_c));
      const double lambda = t <= t_stop ? 1.0 + (lambda_0 - 1.0) * t / t_stop : (1.0 + y) / (1.0 - y);
      w.append({{"kt", t}, {"D_xy", 0.1}, {"D_axial", 2.0 * lambda}, {"D_transverse", 2.0}});
    }
    w.set_markers({{"t_stop", t_stop}, {"t_end", 16.0}});
    w.finish("complete");
  }
  req.members.push_back({"id_released", "released", (dir / "member.h5").string(), "", scene});
  write_report(req);

  CHECK_THAT(slurp(fs::path(req.out_dir) / "member_fits.md"), Contains("| k_t_c | 2.5 |"));
  const auto fd = nlohmann::json::parse(slurp(fs::path(req.out_dir) / "figures" / "figure_data.json"));
  const auto& m = fd["members"][0];
  CHECK(m["y"]["name"] == "lambda");
  CHECK(m["y"]["values"][40].get<double>() == Approx(lambda_0));
  REQUIRE(m["curves"].size() == 1);
  CHECK(m["curves"][0]["D"][0].get<double>() == Approx(lambda_0).epsilon(1e-6));  // lambda, not the decaying ratio
}
