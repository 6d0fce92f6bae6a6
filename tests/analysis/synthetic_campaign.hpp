#pragma once
// Test helper: member files of a synthetic campaign written with capsule::io::MemberWriter.
// Response (85) and recovery (86) with known times k tau_s, k tau_r and small noise.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>
#include <limits>
#include <random>
#include <string>

#include <nlohmann/json.hpp>
#include <unistd.h>

#include "solver/io/member_file.hpp"

namespace capsule::analysis::testing {

// A scratch folder under the system temp dir, unique per process and tag, removed when done.
struct TempDir {
  std::filesystem::path path;
  explicit TempDir(const std::string& tag)
      : path(std::filesystem::temp_directory_path() / ("capsule_analysis_" + tag + "_" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~TempDir() { std::filesystem::remove_all(path); }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
};

struct SyntheticMember {
  double Ca = 0.05, E_b = 0.0, V = 1.0, eta = 0.0;
  double k_tau_s = 0.5, k_tau_r = 0.6;
  double D_max = 0.3;
  double t_max = 6.0, t_end = 12.0;  // shear stops at t_max (t_stop = t_max)
  double sigma = 1e-4;               // noise on D_xy
  unsigned seed = 1;
  std::string status = "complete";
  nlohmann::json resolution;         // written into the scene when not null (ladders, accuracy)
  double wall_seconds = std::numeric_limits<double>::quiet_NaN();  // run-time attributes when set
  long threads = 0;
};

inline nlohmann::json scene_of(const SyntheticMember& m) {
  nlohmann::json scene{{"dim", 3}, {"Ca", m.Ca}, {"E_b", m.E_b}, {"V", m.V}, {"eta", m.eta}, {"Re", 0.05}};
  if (!m.resolution.is_null()) scene["resolution"] = m.resolution;
  return scene;
}

inline void write_member(const std::string& path, const SyntheticMember& m) {
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  capsule::io::MemberWriter w(path);
  w.set_scene(scene_of(m));
  w.set_attribute("dim", 3L);
  if (std::isfinite(m.wall_seconds)) w.set_attribute("wall_seconds", m.wall_seconds);
  if (m.threads > 0) w.set_attribute("threads", m.threads);
  std::mt19937 rng(m.seed);
  std::normal_distribution<double> noise(0.0, m.sigma);
  const double dt = 0.05;
  const int n = static_cast<int>(std::lround(m.t_end / dt));
  for (int i = 0; i <= n; ++i) {
    const double t = i * dt;
    const bool shear = t <= m.t_max + 1e-12;
    const double D = shear ? m.D_max * (1 - std::exp(-t / m.k_tau_s))                // (85)
                           : m.D_max * std::exp(-(t - m.t_max) / m.k_tau_r);         // (86), D_stop = D_max
    w.append({{"kt", t}, {"D_xy", D + (i == 0 ? 0.0 : noise(rng))}, {"theta", 0.4}, {"shear_on", shear ? 1.0 : 0.0}});
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  w.set_markers({{"t_max", m.t_max}, {"D_max", m.D_max}, {"t_stop", m.t_max}, {"D_stop", m.D_max},
                 {"t_min", nan}, {"D_min", nan}, {"t_end", m.t_end}, {"D_inf", nan}});
  w.finish(m.status);
}

// A whole file as text, and its non-empty lines (for checking written tables).
inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream f(p);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

inline std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);)
    if (!l.empty()) out.push_back(l);
  return out;
}

}  // namespace capsule::analysis::testing
