#include "solver/boundary_integral/reference_run.hpp"

#include "solver/common/atomic_write.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <ostream>
#include <stdexcept>
#include <vector>

namespace capsule::boundary_integral {

std::string reference_summary_header() {
  return "level,vertices,Ca,law,E_b,dt,steps,kt,steady,D_end,D_peak,kt_peak,theta_end_over_pi,D_range_window,"
         "extent_D_end,volume_change,area_change,wall_s";
}

void run_reference(const ReferenceRunOptions& o, std::ostream& summary) {
  if (!(o.kt_end > 0)) throw std::invalid_argument("reference-bim: --kt must be > 0");
  if (!(o.every > 0)) throw std::invalid_argument("reference-bim: --every must be > 0");
  if (!(o.steady_window_kt > 0)) throw std::invalid_argument("reference-bim: --steady-window must be > 0");
  const auto t0 = std::chrono::steady_clock::now();
  ShearedCapsule capsule(o.capsule);
  std::vector<CapsuleShape> series{capsule.shape()};
  const long total = std::lround(std::ceil(o.kt_end / capsule.dt() - 1e-9));
  const long stride = std::max(1L, std::lround(o.every / capsule.dt()));
  // Range of D over the written points of the last steady_window_kt (once that much has run).
  auto window_range = [&]() {
    const double from = series.back().kt - o.steady_window_kt;
    if (from < -1e-9) return std::numeric_limits<double>::infinity();
    double lo = series.back().D, hi = lo;
    for (auto s = series.rbegin(); s != series.rend() && s->kt >= from - 1e-9; ++s) {
      lo = std::min(lo, s->D);
      hi = std::max(hi, s->D);
    }
    return hi - lo;
  };
  bool steady = false;
  for (long n = 1; n <= total; ++n) {
    capsule.step();
    if (n % stride == 0 || n == total) {
      series.push_back(capsule.shape());
      if (o.steady_tolerance > 0 && window_range() < o.steady_tolerance) {
        steady = true;
        break;
      }
    }
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  if (!o.series_path.empty()) {
    replace_atomically(o.series_path, [&](const std::string& tmp) {
      std::ofstream out(tmp);
      if (!out) throw std::runtime_error("reference-bim: cannot write " + tmp);
      out << "kt,D,theta,L,W,extent_D,volume_change,area_change\n";
      char line[256];
      for (const auto& s : series) {
        std::snprintf(line, sizeof line, "%.6g,%.8g,%.8g,%.8g,%.8g,%.8g,%.4e,%.4e\n", s.kt, s.D, s.theta, s.L, s.W,
                      s.extent_D, s.volume_change, s.area_change);
        out << line;
      }
      if (!out) throw std::runtime_error("reference-bim: writing " + tmp + " failed");
    });
  }

  const CapsuleShape& end = series.back();
  CapsuleShape peak = series.front();
  for (const auto& s : series)
    if (s.D > peak.D) peak = s;
  char row[512];
  std::snprintf(row, sizeof row, "%d,%d,%.6g,%s,%.6g,%.6g,%ld,%.6g,%s,%.6f,%.6f,%.4g,%.5f,%.3e,%.6f,%.3e,%.3e,%.1f",
                o.capsule.level, capsule.mesh().vertex_count(), o.capsule.Ca, choice_name(o.capsule.law).c_str(), o.capsule.E_b,
                capsule.dt(), capsule.steps(), end.kt, steady ? "yes" : "no", end.D, peak.D, peak.kt,
                end.theta / std::numbers::pi, window_range(), end.extent_D, end.volume_change, end.area_change, wall);
  summary << reference_summary_header() << '\n' << row << '\n';
}

}  // namespace capsule::boundary_integral
