// write_report on a small synthetic campaign written with MemberWriter, and
// compare_campaigns on two such reports.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "analysis/compare/campaign_compare.hpp"
#include "analysis/dissertation/table2_compare.hpp"
#include "analysis/report/plot_script.hpp"
#include "analysis/report/report.hpp"
#include "tests/analysis/synthetic_campaign.hpp"

using namespace capsule::analysis;
using capsule::analysis::testing::SyntheticMember;
using capsule::analysis::testing::lines;
using capsule::analysis::testing::slurp;
using capsule::analysis::testing::TempDir;
using Catch::Matchers::Contains;
using Catch::Matchers::EndsWith;
using Catch::Matchers::StartsWith;
namespace fs = std::filesystem;

namespace {



// A (eta, V) grid of 6 complete members with k tau = a eta + b V + c exactly, one
// unstable member and one never run.
ReportRequest make_campaign(const fs::path& root, const std::string& name, double b_s, double b_r, bool figures) {
  ReportRequest req;
  req.campaign_name = name;
  req.campaign_file = name + ".json";
  req.out_dir = (root / name / "report").string();
  req.analysis = {{"fits", {"response", "recovery"}},
                  {"tables",
                   {{{"name", "times_vs_eta"}, {"x", "eta"}, {"columns", {"response.k_tau_s", "recovery.k_tau_r"}}},
                    {{"name", "normalised_vs_V"},
                     {"x", "V"},
                     {"columns", {"recovery.k_tau_r"}},
                     {"normalise", "tau_e"}}}},
                  {"bilinear", {{"targets", {"response.k_tau_s", "recovery.k_tau_r"}}, {"V_base", 0.2}}},
                  {"figures", figures}};
  unsigned seed = 1;
  for (double eta : {0.0, 2.0, 4.0})
    for (double V : {0.2, 1.0}) {
      SyntheticMember m;
      m.eta = eta;
      m.V = V;
      m.k_tau_s = 0.02 * eta + b_s * V + 0.4;
      m.k_tau_r = 0.05 * eta + b_r * V + 0.4;
      m.seed = seed++;
      const std::string slug = "eta" + std::to_string(static_cast<int>(eta)) + "_V" + std::to_string(V).substr(0, 3);
      const std::string path = (root / name / "members" / slug / "member.h5").string();
      capsule::analysis::testing::write_member(path, m);
      // Half the members pass their scene, half leave it to the member file.
      req.members.push_back({"id" + slug, slug, path, "sphere", eta == 2.0 ? nlohmann::json() : scene_of(m)});
    }
  SyntheticMember bad;
  bad.eta = 8.0;
  bad.status = "unstable at kt = 3.5: inverted triangle";
  const std::string bad_path = (root / name / "members" / "unstable" / "member.h5").string();
  capsule::analysis::testing::write_member(bad_path, bad);
  req.members.push_back({"id_unstable", "unstable", bad_path, "sphere", scene_of(bad)});
  req.members.push_back(
      {"id_missing", "missing", (root / name / "members" / "missing" / "member.h5").string(), "sphere", scene_of(bad)});
  return req;
}

}  // namespace

TEST_CASE("write_report writes all three table formats with the expected rows", "[analysis]") {
  TempDir tmp("report");
  const ReportRequest req = make_campaign(tmp.path, "demo", 0.06, 0.27, false);
  const ReportSummary summary = write_report(req);
  const fs::path out(req.out_dir);
  CHECK(summary.figures_skipped);  // figures off in this block
  for (const char* stem : {"member_fits", "tables/times_vs_eta", "tables/normalised_vs_V", "bilinear",
                           "artificial_viscosity"})
    for (const char* ext : {".md", ".csv", ".tex"}) {
      INFO(stem << ext);
      CHECK(fs::exists(out / (std::string(stem) + ext)));
    }
  CHECK(fs::exists(out / "fits.json"));

  // The eta table: header + 8 members (6 fitted, 1 unstable, 1 missing), sorted by eta.
  const auto csv = lines(slurp(out / "tables/times_vs_eta.csv"));
  REQUIRE(csv.size() == 9);
  CHECK_THAT(csv[0], Contains("case,eta,member,response.k_tau_s"));
  CHECK_THAT(csv[1], StartsWith("sphere,0,"));
  // Both at eta = 8, so ordered by slug: "missing" before "unstable".
  // The fitted time stays numeric: empty, with the reason in the column beside it.
  CHECK_THAT(csv[0], Contains(",response.k_tau_s,response.k_tau_s reason,"));
  CHECK_THAT(csv[7], StartsWith("sphere,8,missing,,member file missing"));
  CHECK_THAT(csv[8], StartsWith("sphere,8,unstable,,member not complete: unstable at kt = 3.5"));
  CHECK_THAT(slurp(out / "tables/times_vs_eta.md"), Contains("| n/a: member file missing"));
  const auto md = lines(slurp(out / "tables/times_vs_eta.md"));
  CHECK(md.size() == 1 + 2 + 8);  // title, header + rule, 8 rows
  const std::string tex = slurp(out / "tables/times_vs_eta.tex");
  CHECK_THAT(tex, Contains("\\begin{tabular}") && Contains("response.k\\_tau\\_s"));

  // fits.json: every member, the fitted times near the truth, failures with reasons.
  const auto j = nlohmann::json::parse(slurp(out / "fits.json"));
  REQUIRE(j["members"].size() == 8);
  for (const auto& m : j["members"]) {
    INFO(m["slug"]);
    // Member files under the campaign's results folder are named relative to it, so a
    // shipped fits.json reads the same from a clone in any folder.
    CHECK(m["path"] == "members/" + m["slug"].get<std::string>() + "/member.h5");
    const bool good = m["slug"] != "unstable" && m["slug"] != "missing";
    CHECK(m["fits"]["response"]["ok"] == good);
    CHECK(m["fits"]["recovery"]["ok"] == good);
    if (good) {
      const double eta = m["parameters"]["eta"], V = m["parameters"]["V"];
      // Noise 1e-4 on D ~ 0.3 over ~100 points: the times come out within 1e-3 relative.
      CHECK(m["fits"]["response"]["parameters"][0]["value"].get<double>() ==
            Approx(0.02 * eta + 0.06 * V + 0.4).epsilon(1e-3));
      CHECK(m["fits"]["recovery"]["parameters"][0]["value"].get<double>() ==
            Approx(0.05 * eta + 0.27 * V + 0.4).epsilon(1e-3));
    } else {
      CHECK_FALSE(m["fits"]["response"]["reason"].get<std::string>().empty());
    }
  }

  // Bilinear: the 6 fitted members recover a, b, c (the times carry ~1e-3 relative error).
  REQUIRE(j["bilinear"].size() == 2);
  for (const auto& b : j["bilinear"]) {
    INFO(b["target"]);
    REQUIRE(b["fit"]["ok"] == true);
    CHECK(b["fit"]["n_points"] == 6);
    CHECK(b["excluded"].size() == 2);
    CHECK(b["Ca"] == 0.05);
    const bool s = b["target"] == "response.k_tau_s";
    const auto& p = b["fit"]["parameters"];
    CHECK(p[0]["value"].get<double>() == Approx(s ? 0.02 : 0.05).margin(2e-3));
    CHECK(p[1]["value"].get<double>() == Approx(s ? 0.06 : 0.27).margin(5e-3));
    CHECK(p[2]["value"].get<double>() == Approx(0.4).margin(5e-3));
  }
  const auto bilinear_csv = lines(slurp(out / "bilinear.csv"));
  REQUIRE(bilinear_csv.size() == 3);
  CHECK_THAT(bilinear_csv[1], StartsWith("sphere,response.k_tau_s,0.05,0,"));
  // Artificial viscosity: 6 members x 2 targets; eta* (97) only for eta = 0 members.
  const auto av = lines(slurp(out / "artificial_viscosity.csv"));
  CHECK(av.size() == 1 + 12);

  // The member-fit table lists one row per parameter (or failure) per fit.
  CHECK(lines(slurp(out / "member_fits.csv")).size() == 1 + 8 * 2);
}

TEST_CASE("write_report rejects a bad analysis block with its JSON path", "[analysis]") {
  TempDir tmp("badblock");
  ReportRequest req;
  req.campaign_name = "bad";
  req.campaign_file = "campaigns/bad.json";
  req.out_dir = (tmp.path / "report").string();
  req.analysis = {{"fits", {"response"}}, {"tabels", nlohmann::json::array()}};
  CHECK_THROWS_WITH(write_report(req), Contains("campaigns/bad.json: /analysis/tabels: unknown key"));
  req.analysis = {{"fits", {"response"}},
                  {"tables", {{{"name", "t"}, {"x", "Ca"}, {"columns", {"recovery.k_tau_r"}}}}}};
  CHECK_THROWS_WITH(write_report(req), Contains("/analysis/tables/0/columns/0: the fit \"recovery\" is not listed"));
  CHECK_THROWS_AS(validate_analysis_block({{"figures", "yes"}}, "x"), std::invalid_argument);
  CHECK_THROWS_WITH(validate_analysis_block({{"bilinear", {{"targets", {"response.k_tau_x"}}}}}, "c.json"),
                    Contains("c.json: /analysis/bilinear/targets/0: expected \"<fit>.<time>\""));
  CHECK_THROWS_WITH(validate_analysis_block({{"fits", {"response", "response"}}}, "c.json"),
                    Contains("/analysis/fits/1: \"response\" listed twice"));
  CHECK_NOTHROW(validate_analysis_block(nlohmann::json(), "c.json"));
  CHECK_NOTHROW(validate_analysis_block({{"fits", {"two_phase", "double_exponential"}},
                                         {"parameters", {{"Ca", "/physics/Ca"}}},
                                         {"tables",
                                          {{{"name", "tt"},
                                            {"x", "Ca"},
                                            {"columns", {"two_phase.k_tau_R1", "double_exponential.k_tau_R2"}},
                                            {"normalise", "tau_v"}}}}},
                                        "c.json"));
}

TEST_CASE("compare_campaigns flags non-overlapping intervals", "[analysis]") {
  TempDir tmp("compare");
  // Same a and c, b of the recovery time 0.27 against 0.40: far outside each other's intervals.
  const ReportRequest r1 = make_campaign(tmp.path, "one", 0.06, 0.27, false);
  const ReportRequest r2 = make_campaign(tmp.path, "two", 0.06, 0.40, false);
  write_report(r1);
  write_report(r2);
  std::ostringstream text;
  const int rc = compare_campaigns({{"one", r1.out_dir}, {"two", r2.out_dir}}, text,
                                   (tmp.path / "cmp").string());
  CHECK(rc == 1);
  CHECK_THAT(text.str(), Contains("NO"));
  CHECK(fs::exists(tmp.path / "cmp" / "compare.md"));
  const auto csv = lines(slurp(tmp.path / "cmp" / "compare.csv"));
  REQUIRE(csv.size() == 1 + 2 * 3);  // header + 2 targets x 3 coefficients
  // The b row of the recovery target differs; a and c overlap.
  for (const auto& l : csv) {
    if (l.rfind("recovery.k_tau_r,b,", 0) == 0) CHECK_THAT(l, EndsWith(",NO"));
    if (l.rfind("recovery.k_tau_r,a,", 0) == 0) CHECK_THAT(l, EndsWith(",yes"));
  }
  // A campaign against itself: every interval overlaps.
  std::ostringstream same;
  CHECK(compare_campaigns({{"one", r1.out_dir}, {"again", r1.out_dir}}, same, (tmp.path / "cmp2").string()) ==
        0);
  // Against Table 2: Ca = 0.05, E_b = 0 rows exist; the synthetic coefficients differ from them.
  std::ostringstream t2;
  compare_campaigns({{"one", r1.out_dir}}, t2, (tmp.path / "cmp3").string(), table2_comparison);
  CHECK_THAT(t2.str(), Contains("0.2711 ± 0.0109"));
  CHECK(fs::exists(tmp.path / "cmp3" / "compare_table2.csv"));
  CHECK(lines(slurp(tmp.path / "cmp3" / "compare_table2.csv")).size() == 1 + 2 * 3);
  // A missing report is an error naming the file.
  CHECK_THROWS_WITH(compare_campaigns({{"none", (tmp.path / "nowhere").string()}}, same,
                                      (tmp.path / "cmp4").string()),
                    Contains("fits.json"));
}

TEST_CASE("write_report draws figures or says why it skipped them", "[analysis]") {
  TempDir tmp("figures");
  ReportRequest req = make_campaign(tmp.path, "fig", 0.06, 0.27, true);
  req.members.resize(2);  // two members keep matplotlib's run short
  req.analysis.erase("bilinear");
  const ReportSummary summary = write_report(req);
  const fs::path fig = fs::path(req.out_dir) / "figures";
  CHECK_FALSE(fs::exists(fig / "plot_report.py"));  // the toolkit's script draws; no copy is kept
  CHECK_FALSE(fs::exists(fig / ".plot_report.py.tmp"));
  CHECK(fs::exists(fig / "figure_data.json"));
  if (summary.figures_skipped) {
    WARN("figures skipped: " << summary.figures_note);
    CHECK_THAT(summary.figures_note, Contains("skipped"));
  } else {
    CHECK(fs::exists(fig / "times_vs_eta.png"));
    CHECK(fs::exists(fig / "member_eta0_V0.2.png"));
  }
}

TEST_CASE("Plotting without an interpreter or matplotlib says figures were skipped", "[analysis]") {
  TempDir tmp("noplot");
  const std::string script = (tmp.path / "plot_report.py").string();
  std::ofstream(script) << plot_script_text();
  CHECK_THAT(run_plot_script(script, "data.json", tmp.path.string(), "/nonexistent/python3"),
             Contains("figures skipped") && Contains("not found"));
  // /bin/false exists but cannot import matplotlib.
  CHECK_THAT(run_plot_script(script, "data.json", tmp.path.string(), "/bin/false"),
             Contains("figures skipped") && Contains("no matplotlib"));
}

TEST_CASE("write_report on a campaign with no member files says so instead of failing", "[analysis]") {
  TempDir tmp("empty");
  ReportRequest req;
  req.campaign_name = "empty";
  req.out_dir = (tmp.path / "report").string();
  req.analysis = {{"bilinear", {{"targets", {"recovery.k_tau_r"}}}}, {"figures", false}};
  write_report(req);
  const auto csv = lines(slurp(tmp.path / "report" / "bilinear.csv"));
  REQUIRE(csv.size() == 2);
  CHECK_THAT(csv[1], EndsWith("no members to fit"));
  CHECK(nlohmann::json::parse(slurp(tmp.path / "report" / "fits.json"))["members"].empty());
}

TEST_CASE("a time table in seconds divides k tau by the physical cell's shear rate - a member without one says why", "[analysis]") {
  TempDir tmp("seconds");
  ReportRequest req;
  req.campaign_name = "cells";
  req.campaign_file = "cells.json";
  req.out_dir = (tmp.path / "cells" / "report").string();
  req.analysis = {{"fits", {"recovery"}},
                  {"tables", {{{"name", "recovery_s"}, {"x", "Ca"}, {"columns", {"recovery.k_tau_r"}}, {"normalise", "seconds"}}}},
                  {"figures", false}};
  for (double Ca : {0.05, 0.1}) {
    SyntheticMember m;
    m.Ca = Ca;
    m.k_tau_r = 0.6;
    const std::string slug = Ca == 0.05 ? "physical" : "plain";
    const std::string path = (tmp.path / "cells" / "members" / slug / "member.h5").string();
    capsule::analysis::testing::write_member(path, m);
    nlohmann::json scene = scene_of(m);
    if (Ca == 0.05) scene["physical"] = {{"shear_rate_per_s", 200.0}, {"radius_um", 2.82}};
    req.members.push_back({"id" + slug, slug, path, "cell", scene});
  }
  write_report(req);
  const fs::path out(req.out_dir);
  const auto csv = lines(slurp(out / "tables/recovery_s.csv"));
  REQUIRE(csv.size() == 3);
  CHECK_THAT(slurp(out / "tables/recovery_s.md"), Contains("tau in seconds = k tau / k"));
  // k tau_r = 0.6 (fitted within 1e-3) at k = 200 1/s: 3 ms.
  const std::string physical_row = csv[1];
  INFO(physical_row);
  REQUIRE_THAT(physical_row, StartsWith("cell,0.05,physical,"));
  const double seconds = std::stod(physical_row.substr(std::string("cell,0.05,physical,").size()));
  CHECK(seconds == Approx(0.6 / 200).epsilon(2e-3));
  CHECK_THAT(csv[2], StartsWith("cell,0.1,plain,,no time in seconds: the scene gives no cell in physical units"));
  CHECK_THROWS_WITH(validate_analysis_block({{"fits", {"recovery"}},
                                             {"tables", {{{"name", "t"}, {"x", "Ca"}, {"columns", {"recovery.k_tau_r"}}, {"normalise", "s"}}}}},
                                            "c.json"),
                    Contains("expected \"none\", \"tau_e\", \"tau_v\" or \"seconds\""));
}
