// Malformed campaign files are refused with a message naming the file, the place and the problem.
#include <catch2/catch.hpp>

#include "study/campaign/campaign.hpp"
#include "study/campaign/campaign_error.hpp"
#include "study/campaign/expansion.hpp"

using namespace capsule::study;

namespace {
const std::string scene = R"({"dim": 2, "shape": "circle", "Ca": 0.05, "E_b": 0, "V": 1, "eta": 0,
  "protocol": {"shear": {"until": "time", "kt": 1}, "recover": {"until": "time", "kt": 1}}})";
std::string with(const std::string& rest) { return R"({"name": "bad", "base": )" + scene + rest + "}"; }
}  // namespace

TEST_CASE("malformed campaigns are refused, each with a message naming its problem", "[study]") {
  struct Case {
    std::string what, text, expected_in_message;
  };
  const std::vector<Case> table{
      {"bad JSON", R"({"name": "bad", "base": {)", "not valid JSON"},
      {"not an object", R"([1, 2])", "a JSON object"},
      {"unknown top-level key", with(R"(, "sweeps": {})"), "sweeps: unknown key"},
      {"missing name", R"({"base": )" + scene + "}", "name: missing required key"},
      {"missing base", R"({"name": "x"})", "base: missing required key"},
      {"name of wrong type", R"({"name": 7, "base": )" + scene + "}", "name: is a number"},
      {"unsafe name (slash)", R"({"name": "../etc", "base": )" + scene + "}", "not a safe name"},
      {"unsafe name (dot first)", R"({"name": ".hidden", "base": )" + scene + "}", "not a safe name"},
      {"base of wrong type", R"({"name": "x", "base": [1]})", "base: is a array"},
      {"sweep values not a list", with(R"(, "sweep": {"grid": {"Ca": 0.1}})"), "sweep.grid.Ca: is a number"},
      {"empty sweep list", with(R"(, "sweep": {"grid": {"Ca": []}})"), "sweep.grid.Ca: empty sweep"},
      {"empty sweep object", with(R"(, "sweep": {})"), "sweep: empty sweep"},
      {"unknown sweep kind", with(R"(, "sweep": {"product": {"Ca": [1]}})"), "sweep.product: unknown key"},
      {"zip lists of unequal length", with(R"(, "sweep": {"zip": {"Ca": [0.1, 0.2], "V": [1, 2, 3]}})"),
       "unequal length"},
      {"key swept twice", with(R"(, "sweep": {"grid": {"Ca": [0.1]}, "zip": {"Ca": [0.2]}})"), "swept twice"},
      {"bad key path", with(R"(, "sweep": {"grid": {"resolution..a": [4]}})"), "not a key path"},
      {"cases not a list", with(R"(, "cases": {"name": "a"})"), "cases: is a object"},
      {"case without name", with(R"(, "cases": [{"set": {"Ca": 0.1}}])"), "cases[0].name: missing required key"},
      {"duplicate case", with(R"(, "cases": [{"name": "a"}, {"name": "a"}])"), "appears twice"},
      {"unknown case key", with(R"(, "cases": [{"name": "a", "override": {}}])"), "cases[0].override: unknown key"},
      {"unknown scene key in a sweep", with(R"(, "sweep": {"grid": {"Capillary": [0.1]}})"), "Capillary: unknown key"},
      {"scene value out of range", with(R"(, "sweep": {"grid": {"Ca": [0.1, -1]}})"), "Ca"},
      {"wrong type in a case", with(R"(, "cases": [{"name": "a", "set": {"V": "five"}}])"), "V"},
      {"override into a number", with(R"(, "cases": [{"name": "a", "set": {"Ca.x": 1}}])"), "not an object"},
      {"case sets a swept key", with(R"(, "sweep": {"grid": {"resolution.a": [4, 5]}},
                                      "cases": [{"name": "a", "set": {"resolution": {"a": 6}}}])"),
       "which its sweep also varies"},
      {"bad analysis block", with(R"(, "analysis": {"fitz": []})"), "fitz"},
  };
  for (const auto& c : table) {
    INFO(c.what);
    bool refused = false;
    try {
      expand_campaign(parse_campaign(c.text, "campaigns/bad.json"));
    } catch (const CampaignError& e) {
      refused = true;
      const std::string message = e.what();
      INFO(message);
      CHECK(message.find("campaigns/bad.json") != std::string::npos);
      CHECK(message.find(c.expected_in_message) != std::string::npos);
    }
    CHECK(refused);
  }
}

TEST_CASE("a well-formed campaign with every feature is accepted", "[study]") {
  // The control for the table above: the same base, valid sweeps, cases and analysis.
  const auto members = expand_campaign(parse_campaign(
      with(R"(, "description": "ok", "sweep": {"grid": {"Ca": [0.1, 0.2]}, "zip": {"V": [1, 2], "eta": [0, 1]}},
              "cases": [{"name": "a", "description": "first", "set": {"E_b": 0.01}}],
              "analysis": {"fits": ["response", "recovery"]})"),
      "campaigns/good.json"));
  CHECK(members.size() == 4);
}

TEST_CASE("a missing campaign file is reported by name", "[study]") {
  CHECK_THROWS_WITH(load_campaign("/nonexistent/c.json"), Catch::Contains("/nonexistent/c.json: (top level): cannot open"));
}
