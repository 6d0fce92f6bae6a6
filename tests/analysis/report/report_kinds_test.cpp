// The report's resolution ladder, accuracy-against-cost and stability kinds on small
// synthetic campaigns written with MemberWriter, and their refusals.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "analysis/report/report.hpp"
#include "analysis/report/report_context.hpp"
#include "analysis/report/scene_parameter.hpp"
#include "analysis/report/table.hpp"
#include "tests/analysis/synthetic_campaign.hpp"

using namespace capsule::analysis;
using capsule::analysis::testing::lines;
using capsule::analysis::testing::slurp;
using capsule::analysis::testing::SyntheticMember;
using capsule::analysis::testing::TempDir;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;
namespace fs = std::filesystem;

namespace {

void add_member(ReportRequest& req, const fs::path& root, const std::string& case_name, const std::string& slug,
                const SyntheticMember& m) {
  const std::string path = (root / "members" / slug / "member.h5").string();
  capsule::analysis::testing::write_member(path, m);
  req.members.push_back({"id_" + slug, slug, path, case_name, capsule::analysis::testing::scene_of(m)});
}

// D_stop = D_max (the synthetic writer stops the shear at the largest D) on a first-order
// ladder: D(a) = 0.3 + 0.8 / a, so the limit is 0.3 and the observed order 1.
SyntheticMember ladder_member(double a, double Ca = 0.05) {
  SyntheticMember m;
  m.Ca = Ca;
  m.D_max = 0.3 + 0.8 / a;
  m.k_tau_s = 0.5 + 0.5 / a;
  m.sigma = 1e-6;
  m.resolution = {{"a", a}};
  m.wall_seconds = a * a * a / 100.0;
  m.threads = 2;
  return m;
}

// Every cell "nan" in any file under `dir` (tables, fits.json, figure data).
std::vector<std::string> files_with_nan(const fs::path& dir) {
  std::vector<std::string> bad;
  static const std::regex nan_word("\\bnan\\b", std::regex::icase);
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (!e.is_regular_file() || e.path().extension() == ".png") continue;
    if (std::regex_search(slurp(e.path()), nan_word)) bad.push_back(e.path().string());
  }
  return bad;
}

std::string row_starting(const std::vector<std::string>& rows, const std::string& start) {
  for (const auto& r : rows)
    if (r.rfind(start, 0) == 0) return r;
  return "";
}

}  // namespace

TEST_CASE("Ladder report: extrapolation with the observed order, and refusals with reasons", "[analysis][ladder]") {
  TempDir tmp("ladder");
  ReportRequest req;
  req.campaign_name = "ladder";
  req.out_dir = (tmp.path / "report").string();
  req.analysis = {{"fits", {"response"}},
                  {"ladder", {{"key", "resolution.a"}, {"quantities", {"D_stop", "response.k_tau_s"}}}},
                  {"figures", false}};
  for (double a : {5.0, 7.0, 10.0}) add_member(req, tmp.path, "s", "ca005_a" + format_number(a), ladder_member(a));
  // Ca = 0.2: one resolution only.
  add_member(req, tmp.path, "s", "ca02_a10", ladder_member(10, 0.2));
  // Ca = 0.1: the finest member went unstable.
  for (double a : {5.0, 7.0, 10.0}) {
    SyntheticMember m = ladder_member(a, 0.1);
    if (a == 10.0) m.status = "unstable at kt = 2.5: non-finite populations";
    add_member(req, tmp.path, "s", "ca01_a" + format_number(a), m);
  }
  // Ca = 0.4: a middle level went unstable; the two others give a two-level estimate.
  for (double a : {5.0, 7.0, 10.0}) {
    SyntheticMember m = ladder_member(a, 0.4);
    if (a == 7.0) m.status = "unstable at kt = 1: inverted triangle";
    add_member(req, tmp.path, "s", "ca04_a" + format_number(a), m);
  }
  write_report(req);
  const fs::path out(req.out_dir);
  for (const char* ext : {".md", ".csv", ".tex"}) CHECK(fs::exists(out / "ladder" / (std::string("ladder_a") + ext)));
  const auto csv = lines(slurp(out / "ladder" / "ladder_a.csv"));
  REQUIRE(csv.size() == 1 + 4 * 2);  // 4 groups x 2 quantities
  // CSV keeps numbers numeric: a missing finest value is an empty cell, its reason beside it.
  CHECK_THAT(csv[0], StartsWith("group,quantity,a levels,finest a,finest value,finest value reason,extrapolated,"));

  const auto j = nlohmann::json::parse(slurp(out / "fits.json"));
  REQUIRE(j["ladders"].size() == 1);
  const auto& groups = j["ladders"][0]["groups"];
  auto find = [&](const std::string& ca, const std::string& q) {
    for (const auto& g : groups)
      if (g["group"].get<std::string>().find("Ca = " + ca) != std::string::npos && g["quantity"] == q) return g;
    return nlohmann::json();
  };
  // D_stop is the exact marker: the limit and order come back to round-off (values ~0.4,
  // differences ~0.03: 1e-12 leaves a wide margin over ~1e-14).
  const auto good = find("0.05", "D_stop");
  REQUIRE(good.is_object());
  CHECK(good["ok"] == true);
  CHECK(good["order"].get<double>() == Approx(1.0).margin(1e-10));
  CHECK(good["extrapolated"].get<double>() == Approx(0.3).margin(1e-12));
  CHECK(good["finest_value"].get<double>() == Approx(0.38).margin(1e-12));
  CHECK(good["error_estimate"].get<double>() == Approx(0.08).margin(1e-12));
  // The fitted time carries the fit's error (noise 1e-6 on D): the order within 5 %.
  const auto fitted = find("0.05", "response.k_tau_s");
  REQUIRE(fitted["ok"] == true);
  CHECK(fitted["order"].get<double>() == Approx(1.0).margin(0.05));

  const auto one = find("0.2", "D_stop");
  CHECK(one["ok"] == false);
  CHECK_THAT(one["note"].get<std::string>(), Contains("one level only (a = 10): no ladder"));
  const auto unstable = find("0.1", "D_stop");
  CHECK(unstable["ok"] == false);
  CHECK_THAT(unstable["note"].get<std::string>(),
             Contains("finest level a = 10 has no value: member not complete: unstable at kt = 2.5"));
  const auto two = find("0.4", "D_stop");
  CHECK(two["ok"] == true);
  CHECK(two["order_observed"] == false);
  CHECK_THAT(two["note"].get<std::string>(), Contains("order assumed p = 1") && Contains("excluded: a = 7"));
  // a = 5 and 10 at the assumed p = 1, exact for D = 0.3 + 0.8 / a: |D(10) - 0.3|.
  CHECK(two["error_estimate"].get<double>() == Approx(0.8 / 10).margin(1e-12));
  CHECK(files_with_nan(out) == std::vector<std::string>{});

  // fits.json records the ladder key, and every numeric scene value that differs among the
  // members, among each member's parameters (study thesis finds a ladder's points by them).
  for (const auto& m : j["members"]) {
    INFO(m["slug"]);
    CHECK(m["parameters"].contains("resolution.a"));
    CHECK(m["parameters"].contains("Ca"));
    CHECK_FALSE(m["parameters"].contains("Re"));  // the same for every member: not recorded
  }
}

TEST_CASE("Accuracy report: errors against a ladder or given reference, Pareto set, cheapest within bounds",
          "[analysis][accuracy]") {
  TempDir tmp("accuracy");
  ReportRequest req;
  req.campaign_name = "accuracy";
  req.out_dir = (tmp.path / "report").string();
  req.analysis = {
      {"fits", {"response"}},
      {"ladder", {{"key", "resolution.a"}, {"quantities", {"D_stop"}}, {"cases", {"sphere"}}}},
      {"accuracy",
       {{"quantities", {"D_stop", "response.k_tau_s"}},
        {"reference", {{{"ladder", "ladder_a"}}, {{"case", "sphere"}, {"response.k_tau_s", 0.5}}}},
        {"bounds", {0.01, 0.15, 0.3}}}},
      {"figures", true}};
  for (double a : {5.0, 7.0, 10.0, 14.0}) add_member(req, tmp.path, "sphere", "a" + format_number(a), ladder_member(a));
  // A cheaper-than-a = 14 setting at a = 10 that is more accurate: D_stop = 0.34 (error 13.3 %), 30 core-s.
  SyntheticMember tau = ladder_member(10);
  tau.resolution = {{"a", 10.0}, {"tau", 0.8}};
  tau.D_max = 0.34;
  tau.wall_seconds = 15;
  add_member(req, tmp.path, "sphere", "a10_tau0.8", tau);
  // Another physical case with no reference, and a member with no run-time attributes.
  SyntheticMember other = ladder_member(10, 0.2);
  add_member(req, tmp.path, "other", "ca02", other);
  SyntheticMember uncosted = ladder_member(7, 0.2);
  uncosted.threads = 0;
  add_member(req, tmp.path, "other", "ca02_a7", uncosted);
  const ReportSummary summary = write_report(req);
  const fs::path out = fs::path(req.out_dir) / "accuracy";
  if (summary.figures_skipped) WARN("figures skipped: " << summary.figures_note);
  else CHECK(fs::exists(fs::path(req.out_dir) / "figures" / "accuracy_case_sphere_D_stop.png"));
  for (const char* stem : {"case_sphere", "case_other", "reference", "pareto", "cheapest"})
    CHECK(fs::exists(out / (std::string(stem) + ".csv")));

  // Two physical cases: each labelled by its cases and what sets it apart.
  // Errors of D_stop against the ladder's extrapolation 0.3 (from a = 7, 10, 14, exact).
  const auto sphere = lines(slurp(out / "case_sphere.csv"));
  REQUIRE(sphere.size() == 1 + 5);
  CHECK_THAT(row_starting(sphere, "\"a = 5, tau = (absent)\""), Contains(",a5,complete,1.25,2,2.5,"));  // cost = 1.25 s x 2 threads
  const auto ref = lines(slurp(out / "reference.csv"));
  CHECK_THAT(row_starting(ref, "sphere (Ca = 0.05),D_stop,0.3,"), Contains("ladder ladder_a: extrapolated from levels 14, 10, 7 (p = 1, observed)"));
  CHECK_THAT(row_starting(ref, "sphere (Ca = 0.05),response.k_tau_s,0.5,"), Contains("given in the block"));
  CHECK_THAT(row_starting(ref, "other (Ca = 0.2),D_stop,,not available,"), Contains("no group of this physical case"));

  // The non-dominated set for D_stop: a = 5, 7, 10 and the tau = 0.8 setting; a = 14 is dominated.
  const auto j = nlohmann::json::parse(slurp(fs::path(req.out_dir) / "fits.json"));
  const auto& cases = j["accuracy"]["cases"];
  REQUIRE(cases.size() == 2);
  CHECK(cases[0]["pareto"]["D_stop"] == nlohmann::json({"a5", "a7", "a10", "a10_tau0.8"}));
  const auto cheap = lines(slurp(out / "cheapest.csv"));
  CHECK_THAT(row_starting(cheap, "sphere (Ca = 0.05),D_stop,1,"), Contains("n/a: none within 1 %"));
  CHECK_THAT(row_starting(cheap, "sphere (Ca = 0.05),D_stop,15,"), Contains("a10_tau0.8,30,"));
  CHECK_THAT(row_starting(cheap, "sphere (Ca = 0.05),D_stop,30,"), Contains("a10,20,"));
  // No reference: reported per member with the reason, never a number.
  const auto other_rows = lines(slurp(out / "case_other.csv"));
  REQUIRE(other_rows.size() == 1 + 2);
  CHECK_THAT(other_rows[1], Contains(",0.38,,no reference: "));  // D_stop, its error empty, the reason
  CHECK_THAT(other_rows[2], Contains(",3.43,,not available,,no wall_seconds or threads in the member file,"));
  CHECK_THAT(slurp(out / "case_other.md"), Contains("n/a: no wall_seconds or threads in the member file"));
  CHECK_THAT(row_starting(lines(slurp(out / "pareto.csv")), "other (Ca = 0.2),D_stop,"),
             Contains("n/a: no member with both a cost and an error"));
  CHECK(files_with_nan(req.out_dir) == std::vector<std::string>{});
}

TEST_CASE("Stability report: statuses per member and parameter pair, limits, no NaN anywhere", "[analysis][stability]") {
  TempDir tmp("stability");
  ReportRequest req;
  req.campaign_name = "stability";
  req.out_dir = (tmp.path / "report").string();
  req.analysis = {{"fits", {"response", "recovery"}}, {"stability", {{"parameters", {"Ca", "E_b"}}}},
                  {"figures", true}};
  auto member = [](double Ca, double E_b, const std::string& status) {
    SyntheticMember m;
    m.Ca = Ca;
    m.E_b = E_b;
    m.status = status;
    m.t_max = 1.0;
    m.t_end = 2.0;
    m.k_tau_s = 0.2;
    m.k_tau_r = 0.2;
    return m;
  };
  add_member(req, tmp.path, "Ca", "Ca0.05", member(0.05, 0, "complete"));
  add_member(req, tmp.path, "Ca", "Ca0.5", member(0.5, 0, "complete"));
  add_member(req, tmp.path, "Ca", "Ca2", member(2, 0, "unstable at kt = 1.25: inverted triangle"));
  add_member(req, tmp.path, "E_b", "E_b0.1", member(0.05, 0.1, "complete"));
  add_member(req, tmp.path, "E_b", "E_b1", member(0.05, 1, "unstable at kt = 0.4: non-finite populations"));
  add_member(req, tmp.path, "E_b", "E_b0.5", member(0.05, 0.5, "stopped: killed by the user"));
  // The base point is shared by both cases: analysed once.
  req.members.push_back(req.members.front());
  req.members.back().case_name = "E_b";
  // Never run: its scene comes from the campaign.
  SyntheticMember missing = member(1, 0, "complete");
  req.members.push_back({"id_missing", "Ca1", (tmp.path / "members/Ca1/member.h5").string(), "Ca",
                         capsule::analysis::testing::scene_of(missing)});
  const ReportSummary summary = write_report(req);
  const fs::path out = fs::path(req.out_dir) / "stability";

  const auto members = lines(slurp(out / "members.csv"));
  REQUIRE(members.size() == 1 + 7);
  CHECK(members[0] == "case,member,Ca,E_b,status,kt of blow-up,reason");
  CHECK(row_starting(members, "Ca/E_b,Ca0.05,0.05,0,complete,") != "");
  CHECK(row_starting(members, "Ca,Ca2,2,0,unstable,1.25,inverted triangle") != "");
  CHECK(row_starting(members, "E_b,E_b1,0.05,1,unstable,0.4,non-finite populations") != "");
  CHECK(row_starting(members, "E_b,E_b0.5,0.05,0.5,stopped,,killed by the user") != "");
  CHECK_THAT(row_starting(members, "Ca,Ca1,1,0,no result,,"), Contains("member file missing"));

  const auto map = lines(slurp(out / "map_Ca_E_b.csv"));
  REQUIRE(map.size() == 1 + 4);  // Ca = 0.05, 0.5, 1, 2
  CHECK(map[0] == "Ca \\ E_b,0,0.1,0.5,1");
  CHECK(map[1] == "0.05,complete,complete,stopped: killed by the user,unstable at kt = 0.4: non-finite populations");
  CHECK(map[4] == "2,unstable at kt = 1.25: inverted triangle,-,-,-");

  const auto limits = lines(slurp(out / "limits.csv"));
  const std::string ca_line = row_starting(limits, "Ca,");
  CHECK_THAT(ca_line, Contains(",4,0.05,0.5,2,2,2 (kt = 1.25: inverted triangle),"));
  const std::string eb_line = row_starting(limits, "E_b,");
  CHECK_THAT(eb_line, Contains(",4,0,0.1,1,1,1 (kt = 0.4: non-finite populations),0.5: stopped: killed by the user"));

  const auto j = nlohmann::json::parse(slurp(fs::path(req.out_dir) / "fits.json"));
  // Each line's edge: the unstable members with the kt and the cause of their blow-up.
  bool ca_edge = false;
  for (const auto& l : j["stability"]["limits"])
    if (l["parameter"] == "Ca") {
      REQUIRE(l["unstable"].size() == 1);
      CHECK(l["unstable"][0]["value"] == 2.0);
      CHECK(l["unstable"][0]["kt"] == 1.25);
      CHECK(l["unstable"][0]["cause"] == "inverted triangle");
      ca_edge = true;
    }
  CHECK(ca_edge);
  CHECK(j["stability"]["counts"]["unstable"] == 2);
  CHECK(j["stability"]["counts"]["complete"] == 3);
  CHECK(files_with_nan(req.out_dir) == std::vector<std::string>{});
  if (summary.figures_skipped) WARN("figures skipped: " << summary.figures_note);
  else CHECK(fs::exists(fs::path(req.out_dir) / "figures" / "stability_Ca_E_b.png"));
}

TEST_CASE("The new analysis kinds reject bad blocks with the key's path", "[analysis]") {
  CHECK_THROWS_WITH(validate_analysis_block({{"ladder", {{"key", "resolution.tau"}}}}, "c.json"),
                    Contains("c.json: /analysis/ladder/spacing: required for key \"resolution.tau\""));
  CHECK_THROWS_WITH(validate_analysis_block({{"ladder", {{"spacing", "1/x"}}}}, "c.json"),
                    Contains("/analysis/ladder/key: required key missing"));
  CHECK_THROWS_WITH(validate_analysis_block({{"ladder", {{"key", "resolution.a"}, {"quantities", {"D_end"}}}}}, "c.json"),
                    Contains("/analysis/ladder/quantities/0: expected a marker (D_stop, D_max, D_inf)"));
  CHECK_THROWS_WITH(
      validate_analysis_block({{"ladder", {{{"key", "resolution.a"}}, {{"key", "resolution.a"}}}}}, "c.json"),
      Contains("/analysis/ladder/1/name: ladder name \"ladder_a\" used twice"));
  CHECK_THROWS_WITH(validate_analysis_block({{"accuracy", {{"bounds", {0.01}}}}}, "c.json"),
                    Contains("/analysis/accuracy/reference: required key missing"));
  CHECK_THROWS_WITH(validate_analysis_block({{"accuracy", {{"reference", {{{"ladder", "ladder_a"}}}}}}}, "c.json"),
                    Contains("/analysis/accuracy/reference/0/ladder: no ladder named \"ladder_a\""));
  CHECK_THROWS_WITH(
      validate_analysis_block({{"accuracy", {{"reference", {{{"case", "x"}, {"D_stop", 0.3}}}}, {"bounds", {5}}}}},
                              "c.json"),
      Contains("/analysis/accuracy/bounds/0: expected a relative error in (0, 1)"));
  CHECK_THROWS_WITH(validate_analysis_block({{"stability", {{"parameters", {"Ca", "Ca"}}}}}, "c.json"),
                    Contains("/analysis/stability/parameters/1: \"Ca\" listed twice"));
  CHECK_NOTHROW(validate_analysis_block(
      {{"ladder", {{{"key", "resolution.a"}}, {{"key", "resolution.mesh_level"}, {"assumed_order", 2}}}},
       {"accuracy", {{"reference", {{{"ladder", "ladder_mesh_level"}}, {{"case", "c"}, {"D_stop", 0.3}}}}}},
       {"stability", {{"parameters", {"Ca", "resolution.tau"}}}}},
      "c.json"));
}

TEST_CASE("A key the canonical scene leaves out at its default reads as that default", "[analysis]") {
  // resolution.membrane_update is written only when not "euler", resolution.precision in 2D
  // only when "single": the accuracy and ladder tables must not print "(absent)" for them.
  const nlohmann::json s3{{"dim", 3}, {"resolution", {{"a", 7.0}, {"precision", "single"}}}};
  const nlohmann::json s2{{"dim", 2}, {"resolution", {{"a", 10.0}}}};
  REQUIRE(scene_value_at(s3, "resolution.membrane_update"));
  CHECK(*scene_value_at(s3, "resolution.membrane_update") == "euler");
  CHECK(*scene_value_at(s3, "resolution.precision") == "single");
  REQUIRE(scene_value_at(s2, "resolution.precision"));
  CHECK(*scene_value_at(s2, "resolution.precision") == "double");
  CHECK(scene_value_at(s2, "resolution.kernel") == nullptr);  // not a left-out key: absent stays absent
  // A fragment that is not a canonical scene gets no defaults.
  CHECK(scene_value_at(nlohmann::json{{"resolution", {{"a", 5.0}}}}, "resolution.membrane_update") == nullptr);
  const auto leaves = scene_leaves(s3);
  REQUIRE(leaves.count("resolution.membrane_update"));
  CHECK(leaves.at("resolution.membrane_update") == "\"euler\"");
  CHECK(leaves.count("resolution.precision"));
  // Told apart from an explicit other value.
  nlohmann::json ab2 = s3;
  ab2["resolution"]["membrane_update"] = "adams_bashforth2";
  CHECK(differing_leaves({s3, ab2}, 0) == "membrane_update = euler");
}

TEST_CASE("fits.json records the numeric scene values that tell members apart", "[analysis]") {
  TempDir tmp("varying_parameters");
  ReportRequest req;
  req.campaign_name = "varying";
  req.out_dir = (tmp.path / "report").string();
  req.analysis = {{"fits", {"response"}}, {"figures", false}};
  for (int level : {3, 4}) {
    SyntheticMember m = ladder_member(5.0);
    m.resolution = {{"a", 5.0}, {"mesh_level", level}};
    add_member(req, tmp.path, "mesh", "level" + std::to_string(level), m);
  }
  write_report(req);
  const auto j = nlohmann::json::parse(slurp(fs::path(req.out_dir) / "fits.json"));
  REQUIRE(j["members"].size() == 2);
  for (const auto& m : j["members"]) {
    INFO(m["slug"]);
    REQUIRE(m["parameters"].contains("resolution.mesh_level"));
    CHECK(m["parameters"]["resolution.mesh_level"].get<double>() ==
          (m["slug"] == "level3" ? 3.0 : 4.0));
    CHECK_FALSE(m["parameters"].contains("resolution.a"));  // the same for both
    CHECK(m["parameters"].contains("Ca"));                   // always recorded
  }
}
