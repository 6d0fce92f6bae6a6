// The figures results/THESIS.md links, checked against the dissertation's figures they stand for:
// each linked PNG's declaration in its report's figures/figure_data.json (what plot_report.py
// drew) has the x, left-y and right-y quantities of the text's figure (figure_axes.md), keeps
// fractions off time axes, scales k tau_R2's right axis as the text does, joins no two members at one
// x in a line, and is titled with the text's figure number.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "analysis/dissertation/figure_axes.hpp"
#include "analysis/dissertation/figure_index.hpp"

using namespace capsule::analysis;
namespace fs = std::filesystem;

namespace {

const fs::path k_results = fs::path(CAPSULE_SOURCE_DIR) / "results";

std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The quantities of an axis, in sorted order (an axis's legend order is not its content).
std::vector<std::string> strings(const nlohmann::json& a) {
  std::vector<std::string> out;
  for (const auto& v : a) out.push_back(v.get<std::string>());
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::string> sorted(std::vector<std::string> v) {
  std::sort(v.begin(), v.end());
  return v;
}

}  // namespace

TEST_CASE("Figures: every figure THESIS.md links has the axes of the text's figure it stands for", "[analysis][dissertation][figures]") {
  REQUIRE(figure_axes().size() == parse_figure_axes(read_text(fs::path(CAPSULE_SOURCE_DIR) / "analysis/dissertation/figure_axes.md")).size());
  std::map<std::string, std::string> number_of;  // linked file -> the text's figure
  for (const auto& f : figure_index())
    for (const auto& file : f.files) number_of[file] = f.number;
  const std::string thesis = read_text(k_results / "THESIS.md");
  const std::regex link(R"(\]\(([^()\s]+/report/figures/[^()\s]+\.png)\))");
  std::set<std::string> linked;
  for (auto it = std::sregex_iterator(thesis.begin(), thesis.end(), link); it != std::sregex_iterator(); ++it)
    linked.insert((*it)[1].str());
  REQUIRE(linked.size() >= 40);
  std::map<fs::path, nlohmann::json> data;
  for (const auto& file : linked) {
    INFO(file);
    REQUIRE(number_of.count(file) == 1);  // every linked figure stands for a figure of the text
    const std::string number = number_of.at(file);
    const fs::path png(file);
    const fs::path data_file = k_results / png.parent_path() / "figure_data.json";
    REQUIRE(fs::is_regular_file(data_file));
    if (!data.count(data_file)) data[data_file] = nlohmann::json::parse(read_text(data_file));
    const nlohmann::json* decl = nullptr;
    for (const auto& d : data[data_file]["figures"])
      if (d["file"] == png.filename().string()) decl = &d;
    REQUIRE(decl != nullptr);
    CHECK((*decl)["number"] == number);  // titled "Fig. N: ..."
    const auto left = strings((*decl)["left"]), right = strings((*decl)["right"]);
    bool matched = false;
    for (const auto& a : figure_axes())
      if (a.number == number && a.toolkit_x() == (*decl)["x"] && sorted(a.toolkit_left()) == left && sorted(a.toolkit_right()) == right &&
          (right.empty() || (*decl)["right_scale"] == a.right_scale))
        matched = true;
    INFO("declared: x " << (*decl)["x"] << ", left " << (*decl)["left"] << ", right " << (*decl)["right"]);
    CHECK(matched);
    for (const auto& q : left) CHECK(q.rfind("w_", 0) != 0);  // fractions never on a time axis
    for (const auto& q : right) CHECK(q.rfind("w_", 0) != 0);
    if ((*decl)["kind"] == "times") {
      // A line joins members at different x only: ladder levels and other cases are series of their own.
      const auto& table = [&]() -> const nlohmann::json& {
        for (const auto& t : data[data_file]["tables"])
          if (t["name"] == (*decl)["source"]) return t;
        FAIL("no table " << (*decl)["source"]);
        return data[data_file];
      }();
      CHECK_FALSE((*decl)["series"].empty());
      for (const auto& s : (*decl)["series"])
        for (const auto& c : s["columns"]) {
          const auto xs = table["cases"][s["label"].get<std::string>()]["columns"][c["column"].get<std::string>()]["x"];
          CHECK(std::set<double>(xs.begin(), xs.end()).size() == xs.size());
          if ((*decl)["series"].size() > 1) CHECK(xs.size() > 1);  // the text's cases: those that sweep x
        }
    }
    if ((*decl)["kind"] == "together") {
      for (const auto& a : figure_axes())
        if (a.number == number) REQUIRE((*decl)["source"].size() == a.together.size());
      // Every member drawn carries the declared series (D_xy, theta) beside its kt.
      const std::string q = (*decl)["left"][0].get<std::string>();
      std::map<std::string, const nlohmann::json*> member;
      for (const auto& m : data[data_file]["members"]) member[m["slug"].get<std::string>()] = &m;
      for (const auto& g : (*decl)["source"]) {
        CHECK_FALSE(g["members"].empty());
        for (const auto& slug : g["members"]) {
          INFO("member " << slug << ", series " << q);
          REQUIRE(member.count(slug.get<std::string>()) == 1);
          const auto& m = *member.at(slug.get<std::string>());
          REQUIRE(m.contains(q));
          CHECK(m[q].size() == m["kt"].size());
        }
      }
    }
  }
}

TEST_CASE("Figures: every figure figures.md links has a row of axes, and the rows parse", "[analysis][dissertation][figures]") {
  std::set<std::string> with_axes;
  for (const auto& a : figure_axes()) with_axes.insert(a.number);
  for (const auto& f : figure_index())
    if (!f.files.empty()) {
      INFO("Fig. " << f.number);
      CHECK(with_axes.count(f.number) == 1);
    }
  const auto rows = parse_figure_axes(
      "| Fig. | x | left | right | together | otherwise |\n|---|---|---|---|---|---|\n"
      "| 25 | Ca | k tau_R1 | k tau_R2 (100 x left) | | |\n"
      "| 62 | kt | D_xy | | power law: K-K20-a7, K-K50-a7 / Kelvin-Voigt: kv-eta20-a7 | |\n"
      "| 67 | u(H) | gamma_max | | | x = kt; left y = gamma_max; gamma_min: no u(H) series |\n");
  REQUIRE(rows.size() == 3);
  CHECK(rows[0].right == std::vector<std::string>{"k tau_R2"});
  CHECK(rows[0].right_scale == 100);
  CHECK(rows[1].right_scale == 0);
  CHECK(rows[0].toolkit_x() == "Ca");
  REQUIRE(rows[1].together.size() == 2);
  CHECK(rows[1].together[0].label == "power law");
  CHECK(rows[1].together[0].members == std::vector<std::string>{"K-K20-a7", "K-K50-a7"});
  CHECK(rows[1].together[1].members == std::vector<std::string>{"kv-eta20-a7"});
  CHECK(rows[2].x == "u(H)");
  CHECK(rows[2].toolkit_x() == "kt");
  CHECK(rows[2].toolkit_left() == std::vector<std::string>{"gamma_max", "gamma_min"});
  CHECK(rows[2].toolkit_right().empty());
  CHECK_THROWS_WITH(parse_figure_axes("| a |\n|---|\n| 1 | kt | D |\n"), Catch::Contains("line 3") && Catch::Contains("6 cells"));
  CHECK_THROWS_WITH(parse_figure_axes("| a |\n|---|\n| 1 | kt | D | | K-K20 | |\n"), Catch::Contains("label: members"));
  CHECK_THROWS_WITH(parse_figure_axes("| a |\n|---|\n| 1 | kt | D | | | x = kt |\n"), Catch::Contains("why"));
}

TEST_CASE("Figures: a campaign's report is told which of its figures stand for which of the text's", "[analysis][dissertation][figures]") {
  const auto tf = text_figures_of_campaign("ch5_powerlaw");
  bool fig62 = false;
  for (const auto& t : tf) {
    CHECK(t["file"].get<std::string>().find('/') == std::string::npos);
    if (t["number"] == "62") {
      fig62 = true;
      CHECK(t["file"] == "fig62.png");
      REQUIRE(t["together"].size() == 2);
      CHECK(t["together"][1]["label"].get<std::string>().find("Kelvin-Voigt") == 0);
    }
  }
  CHECK(fig62);
  // Fig. 63 draws the same members' inclination: the entry names the series.
  bool fig63 = false;
  for (const auto& t : tf)
    if (t["number"] == "63") {
      fig63 = true;
      CHECK(t["file"] == "fig63.png");
      CHECK(t["left"] == nlohmann::json::array({"theta"}));
      CHECK(t["together"].size() == 2);
    }
  CHECK(fig63);
  // The levels of a resolution ladder are groups of their own, and what the text draws otherwise is passed on.
  for (const auto& t : text_figures_of_campaign("ch4_3d_cases"))
    if (t["number"] == "40") {
      REQUIRE(t["together"].size() == 2);
      CHECK(t["together"][0]["label"] == "a = 7");
      CHECK(t["together"][1]["label"] == "a = 5");
      CHECK(t["left"] == nlohmann::json::array({"D_xy"}));
      CHECK(t["otherwise"].get<std::string>().rfind("with ", 0) == 0);
    }
  CHECK(text_figures_of_campaign("no_such_campaign").empty());
}
