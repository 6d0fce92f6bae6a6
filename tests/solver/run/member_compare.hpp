#pragma once
// Helpers for the restart tests (2D and 3D): run the real `capsule` binary, and compare two
// member files bit for bit (series, tracked angles, markers, shapes; NaN equal to NaN).
#include <catch2/catch.hpp>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "solver/io/member_file.hpp"

namespace capsule::testing {

inline bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

// Everything a fit or a figure reads is bitwise equal.
inline void require_bitwise_equal(const io::MemberData& a, const io::MemberData& b) {
  REQUIRE(a.status == b.status);
  REQUIRE(a.series.size() == b.series.size());
  for (const auto& [name, values] : a.series) {
    INFO("series " << name);
    REQUIRE(b.series.count(name) == 1);
    REQUIRE(same_bits(values, b.series.at(name)));
  }
  REQUIRE(a.beta.size() == b.beta.size());
  for (std::size_t r = 0; r < a.beta.size(); ++r) REQUIRE(same_bits(a.beta[r], b.beta[r]));
  REQUIRE(a.markers.size() == b.markers.size());
  for (const auto& [name, v] : a.markers) {
    INFO("marker " << name);
    REQUIRE(same_bits({v}, {b.markers.at(name)}));
  }
  REQUIRE(a.shapes.size() == b.shapes.size());
  for (std::size_t i = 0; i < a.shapes.size(); ++i) {
    REQUIRE(same_bits({a.shapes[i].kt}, {b.shapes[i].kt}));
    REQUIRE(same_bits(a.shapes[i].xyz, b.shapes[i].xyz));
  }
  REQUIRE(a.triangles == b.triangles);
  REQUIRE(a.attributes.at("steps") == b.attributes.at("steps"));
}

struct CapsuleRun {
  int exit_code;
  std::string output;
};

inline std::filesystem::path scratch(const std::string& name) {
  const auto d = std::filesystem::temp_directory_path() / ("capsule_restart_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

// 'text' for a shell (test paths hold no quote); built by appending, which GCC 12's -Wrestrict
// does not misread as it does "'" + std::string.
inline std::string quoted(const std::string& text) {
  std::string q;
  q += '\'';
  q += text;
  q += '\'';
  return q;
}

// `capsule SCENE -o OUT --threads 1 EXTRA` (paths from scratch(): no user string).
inline CapsuleRun run_capsule(const std::filesystem::path& scene, const std::filesystem::path& out,
                              const std::string& extra = "") {
  const std::filesystem::path log = out.string() + ".log";
  const std::string cmd = std::string(CAPSULE_BINARY_DIR) + "/solver/capsule " + quoted(scene.string()) + " -o " +
                          quoted(out.string()) + " --threads 1 " + extra + " > " + quoted(log.string()) + " 2>&1";
  const int rc = std::system(cmd.c_str());
  std::ifstream in(log);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return {WIFEXITED(rc) ? WEXITSTATUS(rc) : -1, text};
}

inline std::filesystem::path write_scene(const std::filesystem::path& dir, const std::string& name,
                                         const nlohmann::json& scene) {
  const auto p = dir / (name + ".json");
  std::ofstream(p) << scene.dump(2);
  return p;
}

// Steps per output row of a finished member.
inline long steps_per_output(const io::MemberData& m) {
  const double k = m.attributes.at("shear_rate").get<double>();
  const double interval = m.attributes.at("scene").at("output").at("interval_kt").get<double>();
  return std::max(1L, std::lround(interval / k));
}

// Runs the member uninterrupted, then again with a restart point at `at_step` and a simulated
// kill at `stop_step`, then resumes it with the plain command; both files must agree bitwise.
inline void require_restart_is_bitwise(const std::filesystem::path& dir, const std::filesystem::path& scene,
                                       long at_step, long stop_step) {
  const auto whole = dir / "whole.h5", cut = dir / "cut.h5";
  const auto a = run_capsule(scene, whole, "--quiet");
  INFO(a.output);
  REQUIRE(a.exit_code == 0);
  const auto killed = run_capsule(scene, cut, "--checkpoint-at-step " + std::to_string(at_step) +
                                                  " --stop-after-step " + std::to_string(stop_step));
  INFO(killed.output);
  REQUIRE(killed.exit_code == 1);
  REQUIRE(std::filesystem::exists(cut.string() + ".restart"));
  REQUIRE(std::filesystem::exists(cut.string() + ".partial"));
  REQUIRE(!std::filesystem::exists(cut));
  const auto resumed = run_capsule(scene, cut);
  INFO(resumed.output);
  REQUIRE(resumed.exit_code == 0);
  REQUIRE(resumed.output.find("continuing from the restart point at step " + std::to_string(at_step)) !=
          std::string::npos);
  REQUIRE(!std::filesystem::exists(cut.string() + ".restart"));  // removed when the member ended
  REQUIRE(!std::filesystem::exists(cut.string() + ".progress"));
  const auto m_whole = io::read_member(whole.string()), m_cut = io::read_member(cut.string());
  require_bitwise_equal(m_whole, m_cut);
  CHECK(m_cut.attributes.at("restarts") == 1);
  CHECK(m_whole.attributes.at("restarts") == 0);
}

}  // namespace capsule::testing
