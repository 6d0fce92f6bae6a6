// The declarations of a report's figures (analysis/report/figure_declarations.hpp) on synthetic
// figure data: the text's two axes for the two-phase times, fractions in a panel of their own,
// only the series that sweep x, members drawn together, and the text's figure numbers.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include "analysis/report/figure_declarations.hpp"

using namespace capsule::analysis;
using json = nlohmann::json;

namespace {

json series(std::vector<double> x) {
  std::vector<double> y(x.size(), 1.0);
  return {{"x", x}, {"y", y}, {"lo", y}, {"hi", y}};
}

const json* find_file(const json& figures, const std::string& file) {
  for (const auto& d : figures)
    if (d["file"] == file) return &d;
  return nullptr;
}

}  // namespace

TEST_CASE("Figure declarations: tumbling times on the text's two axes, w_R1 in its own panel", "[analysis][figures]") {
  json data{{"tables", json::array()}};
  json cols_swept{{"double_exponential.k_tau_R1", series({0.2, 0.3, 0.4})},
                  {"double_exponential.k_tau_R2", series({0.2, 0.3, 0.4})},
                  {"double_exponential_free.w_R1", series({0.2, 0.3, 0.4})}};
  json cols_point{{"double_exponential.k_tau_R1", series({0.4})}, {"double_exponential.k_tau_R2", series({0.4})}};
  data["tables"].push_back({{"name", "tumble_times_vs_Ca"}, {"x", "Ca"}, {"normalise", "none"},
                            {"cases", {{"Ca", {{"columns", cols_swept}}}, {"V (V = 3)", {{"columns", cols_point}}}}}});
  declare_figures(data, json::array({{{"file", "tumble_times_vs_Ca.png"}, {"number", "33"}, {"shows", "times"}}}));
  const json* d = find_file(data["figures"], "tumble_times_vs_Ca.png");
  REQUIRE(d != nullptr);
  CHECK((*d)["kind"] == "times");
  CHECK((*d)["number"] == "33");
  CHECK((*d)["x"] == "Ca");
  CHECK((*d)["left"] == json::array({"k tau_R1"}));
  CHECK((*d)["right"] == json::array({"k tau_R2"}));
  CHECK((*d)["right_scale"] == 10);  // the tumbling (90): O(10^-1) against O(1), as Figs. 33-36
  REQUIRE((*d)["panels"].size() == 1);
  CHECK((*d)["panels"][0]["label"] == "fraction");
  CHECK((*d)["panels"][0]["left"] == json::array({"w_R1"}));
  CHECK((*d)["panels"][0]["right"].empty());
  // A free-amplitude fit of the text's times: a panel below, on the same two axes.
  json data2 = data;
  data2["tables"][0]["cases"]["Ca"]["columns"]["double_exponential_free.k_tau_R1"] = series({0.2, 0.3});
  data2["tables"][0]["cases"]["Ca"]["columns"]["double_exponential_free.k_tau_R2"] = series({0.2, 0.3});
  declare_figures(data2, json::array());
  const json& d2 = data2["figures"][0];
  CHECK(d2["left"] == json::array({"k tau_R1"}));
  REQUIRE(d2["panels"].size() == 2);
  CHECK(d2["panels"][0]["label"] == "free-amplitude fit");
  CHECK(d2["panels"][0]["left"] == json::array({"k tau_R1"}));
  CHECK(d2["panels"][0]["right"] == json::array({"k tau_R2"}));
  CHECK(d2["panels"][1]["left"] == json::array({"w_R1"}));
  // The V case's single point at Ca 0.4 is another sweep's base member: not a series here.
  REQUIRE((*d)["series"].size() == 1);
  CHECK((*d)["series"][0]["label"] == "Ca");
}

TEST_CASE("Figure declarations: with no series sweeping x every series is drawn, and normalised names", "[analysis][figures]") {
  json data{{"tables", json::array()}};
  json one{{"recovery.k_tau_r", series({0.5})}, {"response.k_tau_s", series({0.5})}};
  data["tables"].push_back({{"name", "by_case"}, {"x", "E_b"}, {"normalise", "tau_e"},
                            {"cases", {{"text", {{"columns", one}}}, {"size", {{"columns", one}}}}}});
  declare_figures(data, json::array());
  const json* d = find_file(data["figures"], "by_case.png");
  REQUIRE(d != nullptr);
  CHECK((*d)["series"].size() == 2);
  CHECK((*d)["left"] == json::array({"tau_r/tau_e", "tau_s/tau_e"}));
  CHECK((*d)["right"].empty());
  CHECK_FALSE(d->contains("number"));
  CHECK(column_quantity("two_phase.k_tau_R2", "none") == "k tau_R2");
  CHECK(column_quantity("recovery.k_tau_r", "tau_v") == "tau_r/tau_v");
  CHECK(column_quantity("double_exponential_free.w_R1", "none") == "w_R1");
}

TEST_CASE("Figure declarations: members drawn together keep the groups, a shared member draws once", "[analysis][figures]") {
  json m{{"kt", {0.0, 1.0}}, {"D_xy", {0.0, 0.1}}, {"curves", json::array()}, {"markers", json::object()}};
  json data{{"members", json::array()}};
  for (const std::string slug : {"K-K20-a7", "kv-eta20-a7", "K-K20-a7"}) {
    json mm = m;
    mm["slug"] = slug;
    data["members"].push_back(mm);
  }
  const json text = json::array(
      {{{"file", "fig62.png"}, {"number", "62"}, {"shows", "pairs"},
        {"together", {{{"label", "power law"}, {"members", {"K-K20-a7", "K-K50-a7"}}},
                      {{"label", "Kelvin-Voigt"}, {"members", {"kv-eta20-a7"}}}}}},
       {{"file", "member_K-K20-a7.png"}, {"number", "14"}, {"shows", "one"}}});
  declare_figures(data, text);
  int member_figures = 0;
  for (const auto& d : data["figures"]) member_figures += d["kind"] == "member";
  CHECK(member_figures == 2);
  const json* d = find_file(data["figures"], "fig62.png");
  REQUIRE(d != nullptr);
  CHECK((*d)["kind"] == "together");
  CHECK((*d)["number"] == "62");
  REQUIRE((*d)["source"].size() == 2);
  CHECK((*d)["source"][0]["members"] == json::array({"K-K20-a7"}));  // K-K50-a7 is not in this report
  CHECK((*d)["source"][1]["label"] == "Kelvin-Voigt");
  CHECK((*find_file(data["figures"], "member_K-K20-a7.png"))["number"] == "14");
  CHECK((*find_file(data["figures"], "member_K-K20-a7.png"))["left"] == json::array({"D_xy"}));
}

TEST_CASE("Figure declarations: members drawn together plot the series the text draws: theta for the inclination", "[analysis][figures]") {
  json data{{"members", json::array()}};
  for (const std::string slug : {"n-n1-a7", "n-n0.64-a7"}) {
    json m{{"slug", slug}, {"kt", {0.0, 1.0}}, {"D_xy", {0.0, 0.1}}, {"curves", json::array()}, {"markers", json::object()}};
    if (slug == "n-n1-a7") m["theta"] = {0.8, 0.5};  // n-n0.64-a7's block carries no theta
    data["members"].push_back(m);
  }
  json text = json::array({{{"file", "fig61.png"}, {"number", "61"}, {"shows", "theta"}, {"left", {"theta"}},
                            {"together", {{{"label", "power law"}, {"members", {"n-n1-a7", "n-n0.64-a7"}}}}},
                            {"otherwise", "without X: why"}},
                           {{"file", "fig60.png"}, {"number", "60"}, {"shows", "D"},
                            {"together", {{{"label", "power law"}, {"members", {"n-n1-a7", "n-n0.64-a7"}}}}}}});
  // The members block carries theta only for the members a theta figure draws.
  const auto wanted = together_series(text);
  REQUIRE(wanted.size() == 2);
  CHECK(wanted.at("n-n1-a7") == std::set<std::string>{"theta"});
  declare_figures(data, text);
  const json* theta = find_file(data["figures"], "fig61.png");
  REQUIRE(theta != nullptr);
  CHECK((*theta)["left"] == json::array({"theta"}));
  CHECK((*theta)["x"] == "kt");
  CHECK((*theta)["source"][0]["members"] == json::array({"n-n1-a7"}));  // the member without theta is left out
  CHECK((*theta)["otherwise"] == "without X: why");
  const json* d = find_file(data["figures"], "fig60.png");
  REQUIRE(d != nullptr);
  CHECK((*d)["left"] == json::array({"D_xy"}));  // no "left": D_xy, as Figs. 59-62
  CHECK((*d)["series"].size() == 2);
  CHECK_FALSE(d->contains("otherwise"));
  // A series the members block does not carry is refused, naming the figure.
  text[0]["left"] = {"beta"};
  CHECK_THROWS_WITH(declare_figures(data, text), Catch::Contains("fig61.png") && Catch::Contains("D_xy, theta"));
}
