// compare_campaigns / compare_members: per-member fitted times matched across campaigns.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "analysis/compare/campaign_compare.hpp"
#include "analysis/fit/fit_result.hpp"
#include "analysis/compare/member_compare.hpp"
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


// Split a CSV line without quoted commas (the cells checked here have none, or are last).
std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, ',')) out.push_back(cell);
  return out;
}

// A Ca sweep of case "sphere": Ca = 0.02, 0.05, 0.1 complete, Ca = 0.2 unstable, plus `extra_Ca`
// when positive. The Ca = 0.05 member recovers with `k_tau_r_005`.
ReportRequest ca_sweep(const fs::path& root, const std::string& name, double k_tau_r_005, double extra_Ca) {
  ReportRequest req;
  req.campaign_name = name;
  req.campaign_file = name + ".json";
  req.out_dir = (root / name / "report").string();
  req.analysis = {{"fits", {"response", "recovery"}},
                  {"tables", {{{"name", "times_vs_Ca"}, {"x", "Ca"}, {"columns", {"response.k_tau_s", "recovery.k_tau_r"}}}}},
                  {"figures", false}};
  std::vector<double> cas{0.02, 0.05, 0.1, 0.2};
  if (extra_Ca > 0) cas.push_back(extra_Ca);
  unsigned seed = 11;
  for (double Ca : cas) {
    SyntheticMember m;
    m.Ca = Ca;
    m.k_tau_s = 0.5 + Ca;
    m.k_tau_r = Ca == 0.05 ? k_tau_r_005 : 0.6 + Ca;
    m.seed = seed++;  // the same noise in both campaigns: equal members fit to equal times
    if (Ca == 0.2) m.status = "unstable at kt = 2.5: inverted triangle";
    std::ostringstream slug;
    slug << "Ca" << Ca;
    const std::string path = (root / name / "members" / slug.str() / "member.h5").string();
    capsule::analysis::testing::write_member(path, m);
    req.members.push_back({"id_" + slug.str(), slug.str(), path, "sphere", capsule::analysis::testing::scene_of(m)});
  }
  return req;
}

const std::vector<std::string>* find_row(const std::vector<std::vector<std::string>>& rows, const std::string& member,
                                         const std::string& time) {
  for (const auto& r : rows)
    if (r.size() > 2 && r[1] == member && r[2] == time) return &r;
  return nullptr;
}

}  // namespace

TEST_CASE("compare_campaigns sets matched members' fitted times side by side", "[analysis]") {
  TempDir tmp("cmpmembers_sweep");
  // "fine" recovers the Ca = 0.05 member with k tau_r = 0.9 instead of 0.65, and has an extra Ca = 0.3.
  const ReportRequest coarse = ca_sweep(tmp.path, "coarse", 0.65, 0.0);
  const ReportRequest fine = ca_sweep(tmp.path, "fine", 0.9, 0.3);
  write_report(coarse);
  write_report(fine);
  std::ostringstream text;
  const fs::path out_dir = tmp.path / "cmp";
  const int rc = compare_campaigns({{"coarse", coarse.out_dir}, {"fine", fine.out_dir}}, text, out_dir.string());
  CHECK(rc == 1);
  for (const char* ext : {".md", ".csv", ".tex"}) {
    CHECK(fs::exists(out_dir / (std::string("compare_members") + ext)));
    CHECK(fs::exists(out_dir / (std::string("compare_members_unmatched") + ext)));
  }
  // Without bilinear blocks the bilinear part still says so, and the member table follows.
  CHECK_THAT(text.str(), Contains("No bilinear fits"));
  CHECK_THAT(text.str(), Contains("Members matched by case and Ca (") && Contains("| sphere | Ca = 0.05 | recovery.k_tau_r |"));
  CHECK_THAT(text.str(), Contains("6 pairs of 95 % intervals compared, 1 do not overlap"));
  CHECK_THAT(slurp(out_dir / "compare.md"), Contains("## Per-member fitted times"));
  CHECK_THAT(slurp(out_dir / "compare_members.tex"), Contains("\\begin{tabular}") && Contains("$\\pm$"));

  const auto csv = lines(slurp(out_dir / "compare_members.csv"));
  REQUIRE(!csv.empty());
  CHECK(csv[0] == "case,member,time,coarse,fine,difference fine - coarse,95% overlap fine");
  std::vector<std::vector<std::string>> rows;
  for (std::size_t i = 1; i < csv.size(); ++i) rows.push_back(cells(csv[i]));
  // 4 members in both campaigns x 2 times; the Ca = 0.3 member is not in the side-by-side table.
  CHECK(rows.size() == 4 * 2);

  // The shifted recovery does not overlap; the response of the same member does.
  const auto* rec = find_row(rows, "Ca = 0.05", "recovery.k_tau_r");
  REQUIRE(rec);
  REQUIRE(rec->size() == 7);
  CHECK((*rec)[6] == "NO");
  CHECK(std::stod((*rec)[5]) == Approx(0.25).margin(5e-3));
  CHECK_THAT((*rec)[3], Contains(" ± "));
  CHECK(std::stod((*rec)[3]) == Approx(0.65).epsilon(1e-3));
  CHECK(std::stod((*rec)[4]) == Approx(0.9).epsilon(1e-3));
  const auto* resp = find_row(rows, "Ca = 0.05", "response.k_tau_s");
  REQUIRE(resp);
  CHECK((*resp)[6] == "yes");
  for (const char* member : {"Ca = 0.02", "Ca = 0.1"})
    for (const char* time : {"response.k_tau_s", "recovery.k_tau_r"}) {
      INFO(member << " " << time);
      const auto* r = find_row(rows, member, time);
      REQUIRE(r);
      CHECK(r->back() == "yes");
    }

  // The unstable member shows its reason in both campaigns and no overlap verdict.
  const auto* bad = find_row(rows, "Ca = 0.2", "recovery.k_tau_r");
  REQUIRE(bad);
  CHECK_THAT((*bad)[3], StartsWith("n/a: member not complete: unstable at kt = 2.5"));
  CHECK_THAT((*bad)[4], StartsWith("n/a: member not complete: unstable at kt = 2.5"));
  for (const auto& l : csv)
    if (l.find("Ca = 0.2,") != std::string::npos) CHECK_THAT(l, EndsWith(",,"));  // no difference, no verdict

  // The member found only in "fine".
  const auto unmatched = lines(slurp(out_dir / "compare_members_unmatched.csv"));
  REQUIRE(unmatched.size() == 2);
  CHECK(unmatched[0] == "case,member,found,slug");
  CHECK(unmatched[1] == "sphere,Ca = 0.3,only in fine,fine: Ca0.3");
  CHECK_THAT(text.str(), Contains("| sphere | Ca = 0.3 | only in fine |"));

  // The same campaign twice: every interval overlaps, nothing unmatched.
  std::ostringstream again;
  CHECK(compare_campaigns({{"coarse", coarse.out_dir}, {"again", coarse.out_dir}}, again,
                          (tmp.path / "cmp2").string()) == 0);
  CHECK_THAT(again.str(), Contains("Every member appears in every campaign.") && !Contains("| NO |"));
}

namespace {

nlohmann::json fit_json(const std::string& model, const std::string& time, double value, double hw) {
  FitResult f;
  f.model = model;
  f.ok = true;
  f.parameters.push_back({time, value, hw / 2, value - hw, value + hw});
  f.n_points = 50;
  return to_json(f);
}

nlohmann::json member_json(const std::string& slug, const std::string& case_name, nlohmann::json parameters,
                           double k_tau_r) {
  nlohmann::json fits = nlohmann::json::object();
  fits["recovery"] = fit_json("recovery (86)", "k_tau_r", k_tau_r, 0.01);
  fits["two_phase_R1"] = to_json(FitResult::failure("two-phase recovery, initial (87)", "marker t_min is NaN"));
  return {{"id", slug}, {"slug", slug}, {"case", case_name}, {"parameters", parameters}, {"fits", fits}};
}

}  // namespace

TEST_CASE("compare_members matches by the parameters that identify a member within its campaign", "[analysis]") {
  // "before" and "after" differ in V (constant within each) and sweep Ca in two cases; "before" also
  // holds two repeated runs of one point, told apart by slug.
  nlohmann::json before{{"members", nlohmann::json::array()}}, after{{"members", nlohmann::json::array()}};
  for (const char* c : {"sphere", "biconcave"})
    for (double Ca : {0.05, 0.1}) {
      const std::string slug = std::string(c) + "_" + std::to_string(Ca).substr(0, 4);
      before["members"].push_back(member_json(slug, c, {{"Ca", Ca}, {"V", 1.0}, {"E_b", 0.0}}, 0.6));
      after["members"].push_back(
          member_json(slug, c, {{"Ca", Ca}, {"V", 0.5}, {"E_b", 0.0}}, c == std::string("sphere") ? 0.605 : 0.7));
    }
  before["members"].push_back(member_json("rep_a", "repeat", {{"Ca", 0.05}, {"V", 1.0}}, 0.6));
  before["members"].push_back(member_json("rep_b", "repeat", {{"Ca", 0.05}, {"V", 1.0}}, 0.6));
  after["members"].push_back(member_json("rep_a", "repeat", {{"Ca", 0.05}, {"V", 0.5}}, 0.6));

  const MemberComparison mc = compare_members({{"before", before}, {"after", after}});
  CHECK(mc.match_parameters == std::vector<std::string>{"Ca"});
  CHECK(mc.differing_parameters == std::vector<std::string>{"V"});
  // 5 members in both x (recovery, two_phase.k_tau_R1) -- two_phase_R2 was not made.
  REQUIRE(mc.times.rows.size() == 5 * 2);
  CHECK(mc.compared == 5);
  CHECK(mc.non_overlapping == 2);  // biconcave at both Ca: 0.7 +- 0.01 against 0.6 +- 0.01
  const auto* r = find_row(mc.times.rows, "Ca = 0.1", "recovery.k_tau_r");
  REQUIRE(r);
  CHECK((*r)[0] == "sphere");
  CHECK(r->back() == "yes");  // 0.605 +- 0.01 against 0.6 +- 0.01
  const auto* tp = find_row(mc.times.rows, "Ca = 0.1", "two_phase.k_tau_R1");
  REQUIRE(tp);
  CHECK((*tp)[3] == "n/a: marker t_min is NaN");
  CHECK(tp->back().empty());
  // Rows: sphere first (first appearance), Ca ascending.
  CHECK(mc.times.rows.front()[0] == "sphere");
  CHECK(mc.times.rows.front()[1] == "Ca = 0.05");
  // The repeated run: rep_a matched by slug, rep_b only in "before".
  CHECK(find_row(mc.times.rows, "Ca = 0.05 [rep_a]", "recovery.k_tau_r"));
  REQUIRE(mc.unmatched.rows.size() == 1);
  CHECK(mc.unmatched.rows[0] ==
        std::vector<std::string>{"repeat", "Ca = 0.05 [rep_b]", "only in before", "before: rep_b"});
}
