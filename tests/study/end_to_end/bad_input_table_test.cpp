// The bad-input table: every refusal of a scene, a campaign or a command
// line, run through the real binaries (`capsule check`, `capsule`, `study plan` / `run` /
// `export`), checking the exit status and that the message names the file, the key and
// what is allowed. One row per refusal; a new refusal gets a new row.
#include <catch2/catch.hpp>

#include <functional>
#include <nlohmann/json.hpp>

#include "study/campaign/campaign.hpp"
#include "study/run/shell_quote.hpp"
#include "tests/study/support/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

json scene_2d() {
  return json::parse(R"({"dim": 2, "shape": "circle", "Ca": 0.05, "E_b": 0, "V": 1, "eta": 0,
    "resolution": {"a": 4, "segments": 32},
    "protocol": {"shear": {"until": "time", "kt": 1}, "recover": {"until": "time", "kt": 1}}})");
}

json scene_3d() {
  json j = scene_2d();
  j["dim"] = 3;
  j["shape"] = "sphere";
  j["resolution"] = {{"a", 4}, {"mesh_level", 2}};
  return j;
}

std::string scene_with(const std::function<void(json&)>& edit, json j = scene_2d()) {
  edit(j);
  return j.dump(2);
}

json campaign(const std::string& name = "bad") {
  return {{"name", name}, {"base", scene_2d()}, {"sweep", {{"grid", {{"Ca", {0.02, 0.05}}}}}}};
}

std::string campaign_with(const std::function<void(json&)>& edit) {
  json j = campaign();
  edit(j);
  return j.dump(2);
}

// A campaign text with the base's "Ca" replaced by raw text (for what JSON cannot hold).
std::string campaign_raw_ca(const std::string& raw) {
  std::string text = campaign().dump();
  const std::string from = "\"Ca\":0.05";
  text.replace(text.find(from), from.size(), "\"Ca\":" + raw);
  return text;
}

std::string scene_raw(const std::string& key, const std::string& raw) {
  std::string text = scene_2d().dump();
  const std::string from = "\"" + key + "\":";
  const auto at = text.find(from) + from.size();
  const auto end = text.find_first_of(",}", at);
  text.replace(at, end - at, raw);
  return text;
}

// A campaign whose grid has `axes` keys of `values` values each (keys named k0, k1, ... unless
// given): a member count that overflows, or is absurd, before any scene is made.
std::string campaign_with_grid(int axes, int values, const std::vector<std::string>& keys = {}) {
  json j = campaign();
  j["sweep"]["grid"] = json::object();
  for (int a = 0; a < axes; ++a) {
    json list = json::array();
    for (int v = 1; v <= values; ++v) list.push_back(0.001 * v);
    std::string key = "k";  // append(): GCC 12 -O3 false -Wrestrict on "literal" + string
    key.append(std::to_string(a));
    j["sweep"]["grid"][a < static_cast<int>(keys.size()) ? keys[a] : key] = list;
  }
  return j.dump();
}

struct Row {
  std::string what;
  std::string program;              // "capsule" or "study"
  std::vector<std::string> args;    // FILE stands for the written file's path
  std::string file_name;            // written with `text` into the scratch folder ("" = none)
  std::string text;
  int exit_code;
  std::vector<std::string> message_has;  // "FILE" (the file's path), the key, and what is allowed
};

}  // namespace

TEST_CASE("the bad-input table: every refusal exits with its code and names the file, key and range", "[study]") {
  const fs::path dir = testing::scratch_dir("bad_inputs");
  const std::vector<std::string> check{"check", "FILE"};
  const std::vector<std::string> plan{"plan", "FILE"};
  const std::string long_name(300, 'x');
  const std::vector<Row> table{
      // Scenes (`capsule check`; the run refuses the same, see the last rows).
      {"negative Ca", "capsule", check, "s.json", scene_with([](json& j) { j["Ca"] = -0.1; }), 2, {"FILE", "Ca: value -0.1 out of range", "(allowed: (0, 10])"}},
      {"V = 0", "capsule", check, "s.json", scene_with([](json& j) { j["V"] = 0; }), 2, {"FILE", "V: value 0 out of range", "(allowed: (0, 100])"}},
      {"a = 1", "capsule", check, "s.json", scene_with([](json& j) { j["resolution"]["a"] = 1; }), 2, {"FILE", "resolution.a: value 1 out of range", "(allowed: [2, 200])"}},
      {"mesh level 9", "capsule", check, "s.json", scene_with([](json& j) { j["resolution"]["mesh_level"] = 9; }, scene_3d()), 2,
       {"FILE", "resolution.mesh_level: value 9 out of range", "(allowed: integer in [0, 6])"}},
      {"wrong type (string for a number)", "capsule", check, "s.json", scene_with([](json& j) { j["E_b"] = "0.1"; }), 2,
       {"FILE", "E_b: expected a number, got \"0.1\"", "(allowed: [0, 10])"}},
      {"wrong type (number for a string)", "capsule", check, "s.json", scene_with([](json& j) { j["shape"] = 3; }), 2,
       {"FILE", "shape: expected a string, got 3", "(allowed: circle | biconcave)"}},
      {"wrong type (fractional integer)", "capsule", check, "s.json", scene_with([](json& j) { j["resolution"]["segments"] = 32.5; }), 2,
       {"FILE", "resolution.segments: expected an integer", "(allowed: integer in [16, 100000])"}},
      {"unknown key", "capsule", check, "s.json", scene_with([](json& j) { j["Capillary"] = 0.1; }), 2, {"FILE", "Capillary: unknown key", "(allowed: dim, physics_version, numerics, shape, law, C"}},
      {"unknown nested key", "capsule", check, "s.json", scene_with([](json& j) { j["protocol"]["shear"]["kt_max"] = 3; }), 2,
       {"FILE", "protocol.shear.kt_max: unknown key", "(allowed: until, kt, value"}},
      {"missing key", "capsule", check, "s.json", scene_with([](json& j) { j.erase("Ca"); }), 2, {"FILE", "Ca: missing required key", "(allowed: (0, 10])"}},
      {"missing nested key", "capsule", check, "s.json", scene_with([](json& j) { j["protocol"]["recover"].erase("kt"); }), 2,
       {"FILE", "protocol.recover.kt: missing required key", "(allowed: [0, 10000])"}},
      {"NaN", "capsule", check, "s.json", scene_raw("Ca", "NaN"), 2, {"FILE", "Ca: not valid JSON", "NaN and Infinity are not JSON"}},
      {"Infinity", "capsule", check, "s.json", scene_raw("V", "Infinity"), 2, {"FILE", "V: not valid JSON", "NaN and Infinity are not JSON"}},
      {"number overflow", "capsule", check, "s.json", scene_raw("Ca", "1e400"), 2, {"FILE", "Ca: not valid JSON", "1e400", "(allowed: numbers of magnitude below 1.8e308)"}},
      {"duplicate key", "capsule", check, "s.json", R"({"dim": 2, "Ca": 0.05, "Ca": 0.1})", 2, {"FILE", "Ca: key given twice", "(allowed: each key once per object)"}},
      {"2D power law", "capsule", check, "s.json", scene_with([](json& j) { j["power_law"] = {{"K", 0.1}}; }), 2, {"FILE", "power_law.K: ", "3D model", "(allowed: 0 in 2D)"}},
      {"3D-only kernel in 2D", "capsule", check, "s.json", scene_with([](json& j) { j["resolution"]["kernel"] = "roma3"; }), 2,
       {"FILE", "resolution.kernel: kernel \"roma3\" is 3D only", "(allowed: \"peskin4\" or \"cosine\" in 2D)"}},
      {"unstable tau", "capsule", check, "s.json", scene_with([](json& j) { j["resolution"]["tau"] = 0.5; }), 2,
       {"FILE", "resolution.tau: ", "(allowed: 0 (chosen by the solver) or [0.505, 10])"}},
      {"not an object", "capsule", check, "s.json", "[1, 2]", 2, {"FILE", "(top level): expected a JSON object", "(allowed: an object {...})"}},
      {"run refuses what check refuses", "capsule", {"FILE", "-o", "out.h5"}, "s.json",
       scene_with([](json& j) { j["power_law"] = {{"K", 0.1}}; }), 2, {"FILE", "power_law.K: ", "(allowed: 0 in 2D)"}},
      {"run refuses a folder as -o", "capsule", {"FILE", "-o", "."}, "s.json", scene_2d().dump(), 2, {": is a folder", "-o names the member file"}},

      // Campaigns (`study plan`).
      {"unsafe campaign name", "study", plan, "c.json", campaign("../etc").dump(), 2,
       {"FILE", "name: \"../etc\" is not a safe name", "(expected: letters, digits, '_', '-', '.'"}},
      {"hidden campaign name", "study", plan, "c.json", campaign(".hidden").dump(), 2, {"FILE", "name: \".hidden\" is not a safe name", "not starting with '.'"}},
      {"300-character campaign name", "study", plan, "c.json", campaign(long_name).dump(), 2,
       {"FILE", "name: a name of 300 characters is too long", "(expected: at most 100 characters)"}},
      {"unequal zip lists", "study", plan, "c.json", campaign_with([](json& j) { j["sweep"] = {{"zip", {{"Ca", {0.1, 0.2}}, {"V", {1, 2, 3}}}}}; }), 2,
       {"FILE", "sweep.zip.V: zip lists of unequal length", "(expected: every zip list of the same length)"}},
      {"empty sweep list", "study", plan, "c.json", campaign_with([](json& j) { j["sweep"]["grid"]["Ca"] = json::array(); }), 2,
       {"FILE", "sweep.grid.Ca: empty sweep", "(expected: a list of at least one value)"}},
      {"empty sweep", "study", plan, "c.json", campaign_with([](json& j) { j["sweep"] = json::object(); }), 2, {"FILE", "sweep: empty sweep", "(expected: \"grid\" and/or \"zip\")"}},
      {"duplicate members", "study", plan, "c.json", campaign_with([](json& j) { j["sweep"]["grid"]["Ca"] = {0.1, 1e-1}; }), 2,
       {"FILE", "sweep: Ca = 0.1 gives the same scene as Ca = 0.1", "(expected: every member of a case a different scene)"}},
      {"unknown campaign key", "study", plan, "c.json", campaign_with([](json& j) { j["sweeps"] = json::object(); }), 2,
       {"FILE", "sweeps: unknown key", "(expected: one of analysis, base, cases"}},
      {"missing base", "study", plan, "c.json", campaign_with([](json& j) { j.erase("base"); }), 2, {"FILE", "base: missing required key", "(expected: a scene object)"}},
      {"wrong type of name", "study", plan, "c.json", campaign_with([](json& j) { j["name"] = 7; }), 2, {"FILE", "name: is a number", "(expected: a string)"}},
      {"member scene out of range", "study", plan, "c.json", campaign_with([](json& j) { j["sweep"]["grid"]["Ca"] = {0.05, -1}; }), 2,
       {"FILE", "Ca = -1", "Ca: value -1 out of range", "(allowed: (0, 10])"}},
      {"member scene 2D power law", "study", plan, "c.json", campaign_with([](json& j) { j["base"]["power_law"] = {{"K", 1}}; }), 2,
       {"FILE", "power_law.K: ", "(allowed: 0 in 2D)"}},
      {"campaign duplicate key", "study", plan, "c.json", R"({"name": "a", "name": "b", "base": {}})", 2, {"FILE", "name: key given twice", "(allowed: each key once per object)"}},
      {"campaign number overflow", "study", plan, "c.json", campaign_raw_ca("1e400"), 2, {"FILE", "base.Ca: not valid JSON", "(allowed: numbers of magnitude below 1.8e308)"}},
      {"campaign NaN", "study", plan, "c.json", campaign_raw_ca("NaN"), 2, {"FILE", "base.Ca: not valid JSON", "NaN and Infinity are not JSON"}},

      // Bounded input: nesting depth, and values quoted in messages escaped and cut.
      {"scene nested 100 000 deep", "capsule", check, "s.json",
       "{\"dim\": 2, \"x\": " + std::string(100000, '[') + std::string(100000, ']') + "}", 2,
       {"FILE", "x[0][0]", "nested deeper than 64 levels", "(allowed: at most 64 nested objects or arrays)"}},
      {"campaign nested 100 000 deep", "study", plan, "c.json",
       "{\"name\": \"deep\", \"base\": " + std::string(100000, '[') + std::string(100000, ']') + "}", 2,
       {"FILE", "base[0][0]", "nested deeper than 64 levels"}},
      {"a 1 MB string with an ESC", "capsule", check, "s.json",
       scene_with([](json& j) { j["shape"] = "\x1b[31m" + std::string(1000000, 'A'); }), 2,
       {"FILE", "shape: unknown value \"\\u001b[31mAAAA", "... (1000005 characters)", "(allowed: circle | biconcave)"}},
      {"a 1 MB key", "capsule", check, "s.json", scene_with([](json& j) { j[std::string(1000000, 'k')] = 1; }), 2,
       {"FILE", "kkkk... (1000000 characters): unknown key"}},

      // Command lines.
      {"-j 0", "study", {"run", "FILE", "-j", "0"}, "c.json", campaign().dump(), 2, {"--jobs", "must be a whole number from 1 to 1000000, got \"0\""}},
      {"--threads -1", "study", {"run", "FILE", "--threads", "-1"}, "c.json", campaign().dump(), 2, {"--threads", "must be a whole number from 1 to 1000000"}},
      {"capsule --threads -1", "capsule", {"FILE", "-o", "out.h5", "--threads", "-1"}, "s.json", scene_2d().dump(), 2,
       {"--threads", "must be a whole number from 0 to 1000000"}},
      {"export --mem in words", "study", {"export", "FILE", "--slurm", "--mem", "lots"}, "c.json", campaign().dump(), 2,
       {"--mem", "(allowed: megabytes, or a number with K, M, G or T"}},
      {"export --time of 20 digits", "study", {"export", "FILE", "--slurm", "--time", "99999999999999999999"}, "c.json",
       campaign().dump(), 2, {"--time", "\"99999999999999999999\" is not in Slurm's form", "at most 8 digits a number)"}},
      {"export --mem of 20 digits", "study", {"export", "FILE", "--slurm", "--mem", "99999999999999999999T"}, "c.json",
       campaign().dump(), 2, {"--mem", "at most 12 digits)"}},
      {"--checkpoint-seconds nan", "study", {"run", "FILE", "--checkpoint-seconds", "nan"}, "c.json", campaign().dump(), 2,
       {"--checkpoint-seconds", "must be a number in (0, 10000000], got \"nan\""}},
      {"--checkpoint-seconds inf", "study", {"run", "FILE", "--checkpoint-seconds", "inf"}, "c.json", campaign().dump(), 2,
       {"--checkpoint-seconds", "must be a number in (0, 10000000], got \"inf\""}},
      {"export --checkpoint-seconds 1e300", "study", {"export", "FILE", "--slurm", "--checkpoint-seconds", "1e300"}, "c.json",
       campaign().dump(), 2, {"--checkpoint-seconds", "must be a number in (0, 10000000], got \"1e300\""}},
      {"run-member --checkpoint-seconds -inf", "study", {"run-member", "--capsule", "x", "--checkpoint-seconds", "-inf", "--", ".", "1"},
       "", "", 2, {"--checkpoint-seconds", "must be a number in (0, 10000000]"}},
      {"capsule --progress-seconds nan", "capsule", {"FILE", "-o", "out.h5", "--progress-seconds", "nan"}, "s.json", scene_2d().dump(), 2,
       {"--progress-seconds", "must be a number in (0, 10000000], got \"nan\""}},
      {"capsule --checkpoint-seconds 1e400", "capsule", {"FILE", "-o", "out.h5", "--checkpoint-seconds", "1e400"}, "s.json",
       scene_2d().dump(), 2, {"--checkpoint-seconds", "must be a number in [0, 10000000], got \"1e400\""}},
      {"control characters in a campaign's description, printed by plan", "study", plan, "c.json",
       campaign_with([](json& j) { j["description"] = "\x1b]0;retitled\x07\x1b[31mred\rover"; }), 0,
       {"\\u001b]0;retitled\\u0007\\u001b[31mred\\u000dover"}},

      // Sweep sizes: the product of the lengths is bounded before it can overflow.
      {"grid of 20 keys x 10 values (10^20 members, over 2^64)", "study", plan, "c.json", campaign_with_grid(20, 10), 2,
       {"FILE", "sweep: k0 (10 values) x k1 (10 values)", "makes more than 10000000 members", "(expected: at most 10000000 members in a campaign"}},
      {"grid of 4 scene keys x 100 values (10^8 members)", "study", plan, "c.json",
       campaign_with_grid(4, 100, {"Ca", "E_b", "eta", "c0"}), 2,
       {"FILE", "Ca (100 values) x E_b (100 values) x c0 (100 values) x eta (100 values) makes more than 10000000 members"}},

      // Values inside their ranges that no one means.
      {"E_b = -0.0 reads as 0.0 (the member id does not see the sign of a zero)", "capsule", check, "s.json",
       scene_raw("E_b", "-0.0"), 0, {"\"E_b\": 0.0"}},
      {"E_b 0.0 and -0.0 in one grid make one member", "study", plan, "c.json",
       campaign_with([](json& j) { j["sweep"]["grid"] = {{"E_b", {0.0, -0.0}}}; }), 2,
       {"FILE", "E_b = -0.0 gives the same scene as E_b = 0.0"}},
      {"Re = 1e-300: a run of 1e305 time steps", "capsule", check, "s.json", scene_with([](json& j) { j["Re"] = 1e-300; }), 2,
       {"FILE", "Re: the run takes up to", "(allowed: at most 1e+10 time steps: Re >= "}},
      {"output every 1e-300 kt", "capsule", check, "s.json",
       scene_with([](json& j) { j["output"] = {{"interval_kt", 1e-300}}; }), 2,
       {"FILE", "output.interval_kt: 1e-300 kt over a run of up to 2 kt makes 2e+300 rows", "(allowed: [2e-06, 10]"}},
      {"V = 0.001 leaves the inside at tau = 0.5", "capsule", check, "s.json", scene_with([](json& j) { j["V"] = 0.001; }), 2,
       {"FILE", "V: the capsule's inside relaxes at tau = 0.5 + V (tau - 0.5) = 0.50", "cannot be run stably",
        "(allowed: V >= "}},
      {"a campaign member with V = 0.001 refused at plan", "study", plan, "c.json",
       campaign_with([](json& j) { j["sweep"]["grid"] = {{"V", {1, 0.001}}}; }), 2, {"FILE", "V = 0.001", "V: the capsule's inside relaxes"}},

      // Messages: the range with every refusal, the right reason.
      {"-Infinity", "capsule", check, "s.json", scene_raw("V", "-Infinity"), 2, {"FILE", "V: not valid JSON", "NaN and Infinity are not JSON"}},
      {"tau given as a string", "capsule", check, "s.json", scene_with([](json& j) { j["resolution"]["tau"] = "0.6"; }), 2,
       {"FILE", "resolution.tau: expected a number, got \"0.6\"", "(allowed: 0 (chosen by the solver) or [0.505, 10])"}},

      // Numbers of capsule's other commands.
      {"capsule rigid-sphere --re nan", "capsule", {"rigid-sphere", "--re", "nan"}, "", "", 2, {"--re", "must be a number in [0.0001, 1], got \"nan\""}},
      {"capsule rigid-circle --tau inf", "capsule", {"rigid-circle", "--tau", "inf"}, "", "", 2, {"--tau", "must be a number in [0.51, 5], got \"inf\""}},
      {"capsule reference-bim --ca nan", "capsule", {"reference-bim", "--ca", "nan"}, "", "", 2, {"--ca", "must be a number in [0.00001, 10], got \"nan\""}},
      {"capsule reference-bim --C nan", "capsule", {"reference-bim", "--ca", "0.1", "--C", "nan"}, "", "", 2, {"--C", "must be a number in (0, 1000], got \"nan\""}},

      // Plan: what the report or the machine would refuse later.
      {"an analysis table naming a key the scene lacks", "study", plan, "c.json",
       campaign_with([](json& j) { j["analysis"] = {{"tables", {{{"name", "t"}, {"x", "Cb"}, {"columns", {"response.k_tau_s"}}}}}}; }), 2,
       {"FILE", "analysis.tables[0] (\"t\").x: \"Cb\" is not a key of the member scenes", "(expected: a scene key such as Ca"}},
      {"a member that needs more memory than this machine has", "study", plan, "c.json",
       campaign_with([](json& j) {
         j["base"] = scene_3d();
         j["base"]["resolution"]["a"] = 200;
       }), 0, {"needs about", "more than this machine's", "capsule check refuses it here"}},

      // Control characters in campaign text (and the command line) reach the terminal escaped.
      {"an ESC in a swept key", "study", plan, "c.json", campaign_with([](json& j) { j["sweep"]["grid"] = {{"\x1b[31mCa", {0.1}}}; }), 2,
       {"FILE", "\\u001b[31mCa = 0.1", "\\u001b[31mCa: unknown key"}},
      {"an ESC in a zip key", "study", plan, "c.json",
       campaign_with([](json& j) { j["sweep"] = {{"zip", {{"Ca", {0.1, 0.2}}, {"\x1b[31mV", {1}}}}}; }), 2,
       {"FILE", "\\u001b[31mV\" has 1"}},
      {"an OSC title sequence in analysis stability parameters", "study", plan, "c.json",
       campaign_with([](json& j) { j["analysis"] = {{"stability", {{"parameters", {"\x1b]0;t\x07", "\x1b]0;t\x07"}}}}}; }), 2,
       {"FILE", "\\u001b]0;t\\u0007\" listed twice"}},
      {"an ESC in --case", "study", {"plan", "FILE", "--case", "\x1b[31mx"}, "c.json", campaign().dump(), 2,
       {"--case \"\\u001b[31mx\" names no"}},

      {"results path with a line break", "study", {"export", "FILE", "--slurm", "--results", "r\nx"}, "c.json", campaign().dump(), 2,
       {"the results folder contains a control character", "refused in a generated script"}},
  };
  for (const auto& row : table) {
    INFO(row.what);
    const fs::path file = dir / row.file_name;
    if (!row.file_name.empty()) testing::write_text(file, row.text);
    std::vector<std::string> args;
    for (const auto& a : row.args) args.push_back(a == "FILE" ? file.string() : a);
    testing::CommandResult r;
    if (row.program == "study") {
      r = testing::run_study(args, dir);
    } else {
      std::string line = "cd ";  // append(): GCC 12 -O3 false -Wrestrict on "literal" + string
      line.append(shell_quote(dir.string())).append(" && ").append(shell_quote(testing::capsule_binary().string()));
      for (const auto& a : args) line.append(" ").append(shell_quote(a));
      r = testing::run_shell(line.append(" </dev/null"));
    }
    INFO(r.output.substr(0, 2000));
    CHECK(r.exit_code == row.exit_code);
    CHECK(r.output.size() < 2000);  // no message echoes a value in full
    CHECK(r.output.find('\x1b') == std::string::npos);
    for (const auto& part : row.message_has)  // "FILE": the message names the file
      CHECK(r.output.find(part == "FILE" ? file.string() : part) != std::string::npos);
  }
  CHECK_FALSE(fs::exists(dir / "out.h5"));
  CHECK_FALSE(fs::exists(dir / "results"));  // no refusal wrote anything
  fs::remove_all(dir);
}
