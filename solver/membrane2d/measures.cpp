#include "solver/membrane2d/measures.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace capsule::membrane2d {

double polygon_area(const std::vector<double>& xy) {
  const std::size_t n = xy.size() / 2;
  double a2 = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    a2 += xy[2 * i] * xy[2 * j + 1] - xy[2 * j] * xy[2 * i + 1];
  }
  return 0.5 * a2;
}

Point polygon_centroid(const std::vector<double>& xy) {
  const std::size_t n = xy.size() / 2;
  // shift by the first node for accuracy
  const double ox = xy[0], oy = xy[1];
  double a2 = 0, cx = 0, cy = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    const double xi = xy[2 * i] - ox, yi = xy[2 * i + 1] - oy, xj = xy[2 * j] - ox, yj = xy[2 * j + 1] - oy;
    const double cr = xi * yj - xj * yi;
    a2 += cr;
    cx += (xi + xj) * cr;
    cy += (yi + yj) * cr;
  }
  return {ox + cx / (3.0 * a2), oy + cy / (3.0 * a2)};
}

double major_axis_angle(const std::vector<double>& xy) {
  const std::size_t n = xy.size() / 2;
  const Point c = polygon_centroid(xy);
  double Sxx = 0, Syy = 0, Sxy = 0;  // 12 (24) times the area moments about the centroid
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    const double xi = xy[2 * i] - c.x, yi = xy[2 * i + 1] - c.y, xj = xy[2 * j] - c.x, yj = xy[2 * j + 1] - c.y;
    const double cr = xi * yj - xj * yi;
    Sxx += cr * (xi * xi + xi * xj + xj * xj);                      // 12 int x^2 dA
    Syy += cr * (yi * yi + yi * yj + yj * yj);                      // 12 int y^2 dA
    Sxy += 0.5 * cr * (xi * yj + 2 * xi * yi + 2 * xj * yj + xj * yi);  // 12 int x y dA
  }
  // direction maximising int (r . e)^2 dA
  return wrap_half_turn(0.5 * std::atan2(2.0 * Sxy, Sxx - Syy));
}

double chord_length(const std::vector<double>& xy, Point p, double angle) {
  const std::size_t n = xy.size() / 2;
  const double ex = std::cos(angle), ey = std::sin(angle);
  double tmin = std::numeric_limits<double>::infinity(), tmax = -tmin;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    const double ax = xy[2 * i] - p.x, ay = xy[2 * i + 1] - p.y;
    const double dx = xy[2 * j] - xy[2 * i], dy = xy[2 * j + 1] - xy[2 * i + 1];
    const double den = ex * dy - ey * dx;  // e x d
    if (den == 0.0) continue;               // segment parallel to the line
    const double u = (ax * ey - ay * ex) / den;  // position along the segment
    if (u < 0.0 || u >= 1.0) continue;
    const double t = (ax * dy - ay * dx) / den;  // position along the line
    tmin = std::min(tmin, t);
    tmax = std::max(tmax, t);
  }
  return tmax > tmin ? tmax - tmin : 0.0;
}

TaylorDeformation taylor_deformation(const std::vector<double>& xy) {
  TaylorDeformation td;
  td.centroid = polygon_centroid(xy);
  td.theta = major_axis_angle(xy);
  td.L = chord_length(xy, td.centroid, td.theta);
  td.W = chord_length(xy, td.centroid, td.theta + 0.5 * std::numbers::pi);
  td.D = (td.L - td.W) / (td.L + td.W);  // (37)
  return td;
}

double wrap_half_turn(double angle) {
  const double pi = std::numbers::pi;
  double a = std::fmod(angle, pi);  // (-pi, pi)
  if (a > 0.5 * pi) a -= pi;
  if (a <= -0.5 * pi) a += pi;
  return a;
}

void PhaseAngle::observe(double alpha, double theta) {
  const double pi = std::numbers::pi;
  if (!started_) {
    alpha_ = alpha;
    theta_ = theta;
    offset_ = alpha - theta;
    started_ = true;
  } else {
    // continue each angle along the branch nearest its previous value
    alpha_ += std::remainder(alpha - alpha_, 2.0 * pi);
    theta_ += std::remainder(theta - theta_, pi);
  }
  beta_ = alpha_ - theta_ - offset_;  // (89)
}

double PhaseAngle::value() const { return wrap_half_turn(beta_); }

}  // namespace capsule::membrane2d
