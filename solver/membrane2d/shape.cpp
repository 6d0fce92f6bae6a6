#include "solver/membrane2d/shape.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace capsule::membrane2d {
namespace {

constexpr int kDense = 20000;  // polyline points to measure area and arc length

// (24)-(25) with a = 1, traversed counter-clockwise starting at the right end:
// chi runs from pi/2 down to pi/2 - 2 pi ((24)-(25) with increasing chi is clockwise).
void biconcave_unit(double chi, double& x, double& y) {
  const double s = std::sin(chi), s2 = s * s;
  x = biconcave_alpha * s;                                                          // (24)
  y = 0.5 * biconcave_alpha * (0.207 + 2.003 * s2 - 1.123 * s2 * s2) * std::cos(chi);  // (25)
}

double chi_at(int k) { return 0.5 * std::numbers::pi - 2.0 * std::numbers::pi * k / kDense; }

}  // namespace

std::vector<double> circle(int segments, double a, double cx, double cy, double start_angle) {
  if (segments < 8) throw std::invalid_argument("circle: need at least 8 segments");
  std::vector<double> xy(2 * segments);
  for (int i = 0; i < segments; ++i) {
    const double phi = start_angle + 2.0 * std::numbers::pi * i / segments;
    xy[2 * i] = cx + a * std::cos(phi);
    xy[2 * i + 1] = cy + a * std::sin(phi);
  }
  return xy;
}

double biconcave_equivalent_radius() {
  double area2 = 0;  // twice the shoelace area
  double x0, y0, x1, y1;
  biconcave_unit(chi_at(0), x0, y0);
  for (int k = 1; k <= kDense; ++k) {
    biconcave_unit(chi_at(k), x1, y1);
    area2 += x0 * y1 - x1 * y0;
    x0 = x1;
    y0 = y1;
  }
  return std::sqrt(0.5 * area2 / std::numbers::pi);
}

std::vector<double> biconcave(int segments, double a, double cx, double cy, double inclination) {
  if (segments < 8) throw std::invalid_argument("biconcave: need at least 8 segments");
  const double scale = a / biconcave_equivalent_radius();
  // Dense polyline and its cumulative arc length.
  std::vector<double> px(kDense + 1), py(kDense + 1), s(kDense + 1, 0.0);
  for (int k = 0; k <= kDense; ++k) biconcave_unit(chi_at(k), px[k], py[k]);
  for (int k = 1; k <= kDense; ++k) s[k] = s[k - 1] + std::hypot(px[k] - px[k - 1], py[k] - py[k - 1]);
  // Nodes at equal arc length (equal segments, Sec. 2.4), linear along the dense polyline.
  const double c = std::cos(inclination), sn = std::sin(inclination);
  std::vector<double> xy(2 * segments);
  int k = 0;
  for (int i = 0; i < segments; ++i) {
    const double target = s[kDense] * i / segments;
    while (s[k + 1] < target) ++k;
    const double f = (target - s[k]) / (s[k + 1] - s[k]);
    const double x = scale * (px[k] + f * (px[k + 1] - px[k]));
    const double y = scale * (py[k] + f * (py[k + 1] - py[k]));
    xy[2 * i] = cx + c * x - sn * y;
    xy[2 * i + 1] = cy + sn * x + c * y;
  }
  return xy;
}

}  // namespace capsule::membrane2d
