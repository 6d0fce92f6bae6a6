// The capsule command line: output paths checked before the first step (one line naming
// the path), `check` refusing what `run` refuses, and the documented exit status 2 for
// command-line errors (CLI11 returns 104-109 by default).
#include <catch2/catch.hpp>

#include "capsule_process.hpp"

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

namespace fs = std::filesystem;
using capsule_test::quote;
using capsule_test::Result;
using capsule_test::run_capsule;

namespace {


std::size_t lines(const std::string& text) {
  std::size_t n = 0;
  for (char c : text) n += c == '\n';
  return n;
}

fs::path scratch() {
  const fs::path d = fs::temp_directory_path() / ("capsule_cli_test_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

const std::string scene = quote(std::string(CAPSULE_SOURCE_DIR) + "/tests/data/scenes/circle_quick_2d.json");

// Nothing but finished files beside `file`: no temporary of an atomic write (<name>.tmp.<pid>).
bool no_temporary_beside(const fs::path& file) {
  for (const auto& e : fs::directory_iterator(file.parent_path()))
    if (e.path().filename().string().rfind(file.filename().string() + ".tmp.", 0) == 0) return false;
  return true;
}

}  // namespace

TEST_CASE("capsule -o naming a folder fails before the first step, in one line", "[capsule2d]") {
  const fs::path dir = scratch();
  const Result r = run_capsule(scene + " -o " + quote(dir.string()) + " --quiet");
  INFO(r.output);
  CHECK(r.exit_code == 2);
  CHECK(lines(r.output) == 1);
  CHECK(r.output.find(dir.string() + ": is a folder") != std::string::npos);
  CHECK_FALSE(fs::exists(dir.string() + ".partial"));
  fs::remove_all(dir);
}

TEST_CASE("capsule -o in a missing folder prints one line naming it, no HDF5 stack", "[capsule2d]") {
  const fs::path dir = scratch();
  const fs::path out = dir / "no" / "such" / "m.h5";
  const Result r = run_capsule(scene + " -o " + quote(out.string()) + " --quiet");
  INFO(r.output);
  CHECK(r.exit_code == 2);
  CHECK(lines(r.output) == 1);
  CHECK(r.output.find("the folder " + (dir / "no" / "such").string() + " does not exist") != std::string::npos);
  CHECK(r.output.find("HDF5") == std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("capsule check refuses a 2D power-law scene, as the run does", "[capsule2d]") {
  const fs::path dir = scratch();
  std::ifstream in(std::string(CAPSULE_SOURCE_DIR) + "/tests/data/scenes/circle_quick_2d.json");
  nlohmann::json j = nlohmann::json::parse(in);
  j["power_law"] = {{"K", 0.1}, {"n", 0.64}};
  std::ofstream(dir / "p.json") << j.dump();
  const Result check = run_capsule("check " + quote((dir / "p.json").string()));
  INFO(check.output);
  CHECK(check.exit_code == 2);
  CHECK(check.output.find((dir / "p.json").string() + ": power_law.K: ") != std::string::npos);
  const Result run = run_capsule(quote((dir / "p.json").string()) + " -o " + quote((dir / "p.h5").string()) + " --quiet");
  CHECK(run.exit_code == 2);
  CHECK_FALSE(fs::exists(dir / "p.h5"));
  fs::remove_all(dir);
}

TEST_CASE("capsule command-line errors exit 2, and --help documents the exit status", "[capsule2d]") {
  const fs::path dir = scratch();
  const std::string out = " -o " + quote((dir / "m.h5").string());
  for (const std::string& args : {scene + out + " --threads -1", scene + out + " --threads two", scene + out + " --frob",
                                 scene, std::string("check"), std::string("bench gpu"),
                                 std::string("/nonexistent/scene.json") + out}) {
    INFO("capsule " << args);
    const Result r = run_capsule(args);
    INFO(r.output);
    CHECK(r.exit_code == 2);
  }
  CHECK(run_capsule(scene + out + " --threads -1").output.find("must be a whole number from 0") != std::string::npos);
  const Result help = run_capsule("--help");
  CHECK(help.exit_code == 0);
  CHECK(help.output.find("Exit status: 0 complete") != std::string::npos);
  CHECK(help.output.find("3 the member ended unstable") != std::string::npos);
  CHECK(run_capsule("check --help").output.find("Exit status:") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("capsule reference-bim writes a summary row and a series - bad options exit 2", "[capsule3d]") {
  const fs::path dir = scratch();
  const fs::path series = dir / "series.csv";
  const Result r = run_capsule("reference-bim --ca 0.1 --level 1 --kt 0.2 --every 0.1 -o " + quote(series.string()));
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(r.output.rfind("level,vertices,Ca,law,", 0) == 0);
  CHECK(r.output.find("\n1,42,0.1,neo-hookean,") != std::string::npos);
  CHECK(run_capsule("reference-bim --ca 0.1 --level 1 --kt 5 --steady 0.5 --steady-window 0.2").output.find(",yes,") != std::string::npos);
  std::ifstream in(series);
  std::string header;
  std::getline(in, header);
  CHECK(header == "kt,D,theta,L,W,extent_D,volume_change,area_change");
  CHECK(no_temporary_beside(series));
  for (const std::string& args : {std::string("reference-bim"), std::string("reference-bim --ca -1"),
                                  std::string("reference-bim --ca 0.1 --law hooke"),
                                  std::string("reference-bim --ca 0.1 --level 9")}) {
    INFO("capsule " << args);
    CHECK(run_capsule(args).exit_code == 2);
  }
  fs::remove_all(dir);
}

TEST_CASE("capsule rigid-sphere writes a summary row and a series - bad options exit 2", "[capsule3d]") {
  const fs::path dir = scratch();
  const fs::path series = dir / "series.csv";
  const Result r = run_capsule("rigid-sphere --a 2 --level 1 --domain 5 5 5 --kt 0.1 --every 0.05 -o " + quote(series.string()));
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(r.output.rfind("a,marker_radius,level,nx,ny,nz,spin,kernel,precision,refine_margin,kt,torque,", 0) == 0);
  CHECK(r.output.find("\n2,2,1,10,10,10,0,peskin4,double,") != std::string::npos);
  std::ifstream in(series);
  std::string header;
  std::getline(in, header);
  CHECK(header == "kt,torque,stresslet,leakage,lag,slip,slip_rms");
  CHECK(no_temporary_beside(series));
  for (const std::string& args : {std::string("rigid-sphere --a 1"), std::string("rigid-sphere --gain 0"),
                                  std::string("rigid-sphere --kernel gauss"), std::string("rigid-sphere --domain 10 10")}) {
    INFO("capsule " << args);
    CHECK(run_capsule(args).exit_code == 2);
  }
  fs::remove_all(dir);
}

TEST_CASE("capsule rigid-circle writes a summary row and a series - bad options exit 2", "[capsule2d]") {
  const fs::path dir = scratch();
  const fs::path series = dir / "series.csv";
  const Result r = run_capsule("rigid-circle --a 3 --segments 32 --domain 5 5 --kt 0.1 --every 0.05 -o " + quote(series.string()));
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(r.output.rfind("a,marker_radius,segments,nx,ny,spin,kernel,precision,refine_margin,kt,torque,", 0) == 0);
  CHECK(r.output.find("\n3,3,32,15,15,0,peskin4,double,0,") != std::string::npos);
  std::ifstream in(series);
  std::string header;
  std::getline(in, header);
  CHECK(header == "kt,torque,stresslet,leakage,lag,slip,slip_rms");
  CHECK(no_temporary_beside(series));
  for (const std::string& args : {std::string("rigid-circle --a 1"), std::string("rigid-circle --segments 8"),
                                  std::string("rigid-circle --kernel gauss"), std::string("rigid-circle --domain 10 10 8"),
                                  std::string("rigid-circle --refine-margin 21")}) {
    INFO("capsule " << args);
    CHECK(run_capsule(args).exit_code == 2);
  }
  fs::remove_all(dir);
}

TEST_CASE("capsule names a misspelt key with the key it is near, before any missing one", "[capsule2d]") {
  const fs::path dir = scratch();
  std::ifstream in(std::string(CAPSULE_SOURCE_DIR) + "/tests/data/scenes/circle_quick_2d.json");
  nlohmann::json j = nlohmann::json::parse(in);
  j["Eb"] = j["E_b"];
  j.erase("E_b");
  std::ofstream(dir / "eb.json") << j.dump();
  const Result r = run_capsule("check " + quote((dir / "eb.json").string()));
  INFO(r.output);
  CHECK(r.exit_code == 2);
  CHECK(r.output.find("eb.json: Eb: unknown key, did you mean E_b?") != std::string::npos);
  CHECK(r.output.find("missing required key") == std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("capsule says why a scene cannot be opened, and that a campaign is not a scene", "[capsule2d]") {
  const fs::path dir = scratch();
  const Result missing = run_capsule("check " + quote((dir / "none.json").string()));
  INFO(missing.output);
  CHECK(missing.exit_code == 2);
  CHECK(missing.output.find("cannot open the scene file: No such file or directory") != std::string::npos);
  // A name without .json: the file meant.
  std::ifstream in(std::string(CAPSULE_SOURCE_DIR) + "/tests/data/scenes/circle_quick_2d.json");
  std::ofstream(dir / "quick.json") << in.rdbuf();
  const Result bare = run_capsule("check " + quote((dir / "quick").string()));
  INFO(bare.output);
  CHECK(bare.output.find("did you mean " + (dir / "quick.json").string() + "?") != std::string::npos);
  const Result campaign = run_capsule("check " + quote(std::string(CAPSULE_SOURCE_DIR) + "/campaigns/demo.json"));
  INFO(campaign.output);
  CHECK(campaign.exit_code == 2);
  CHECK(campaign.output.find("this is a campaign file, not a scene") != std::string::npos);
  CHECK(campaign.output.find("unknown key") == std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("capsule --version, examples in --help, and the subcommands through CLI11", "[capsule2d]") {
  const Result version = run_capsule("--version");
  INFO(version.output);
  CHECK(version.exit_code == 0);
  CHECK(version.output.rfind("capsule ", 0) == 0);
  CHECK(version.output.find("(physics version ") != std::string::npos);
  const Result help = run_capsule("--help");
  CHECK(help.output.find("Examples:") != std::string::npos);
  CHECK(help.output.find("capsule check tests/data/scenes/circle_quick_2d.json") != std::string::npos);
  // Every subcommand is listed by CLI11 and has its own --help with an example or its exit status.
  for (const char* name : {"check", "version", "units", "bench", "reference-bim", "rigid-sphere", "rigid-circle"}) {
    const std::string sub = name;
    INFO(sub);
    CHECK(help.output.find("  " + sub) != std::string::npos);
    const Result sub_help = run_capsule(sub + " --help");
    CHECK(sub_help.exit_code == 0);
    CHECK(sub_help.output.find("Exit status:") != std::string::npos);
  }
  // A subcommand's options belong to it: the run's -o is not taken by check.
  CHECK(run_capsule("check " + scene + " --frob").exit_code == 2);
  // `capsule version` stays JSON, as study run-member reads it.
  const Result json = run_capsule("version");
  CHECK(nlohmann::json::parse(json.output).contains("physics_version"));
}
