#pragma once
// Shape measures of the 2D capsule written every output interval (docs/guide/member-files.md "2D series").
// xy: closed polygon, flat (x0, y0, x1, y1, ...), counter-clockwise.
#include <vector>

namespace capsule::membrane2d {

double polygon_area(const std::vector<double>& xy);  // shoelace, > 0 counter-clockwise

struct Point {
  double x = 0, y = 0;
};
Point polygon_centroid(const std::vector<double>& xy);

// Inclination of the major axis of the polygon's area moment of inertia, in (-pi/2, pi/2].
double major_axis_angle(const std::vector<double>& xy);

// Length of the chord through `through` along direction `angle`: the distance between the
// outermost crossings of that line with the polygon.
double chord_length(const std::vector<double>& xy, Point through, double angle);

// Taylor deformation (37) with L and W the chords through the centroid along the major axis
// and across it (the undeformed biconcave capsule: W is the dimple thickness, D = 0.812).
struct TaylorDeformation {
  double L = 0, W = 0, D = 0;
  double theta = 0;  // inclination of the major axis, (-pi/2, pi/2]
  Point centroid;
};
TaylorDeformation taylor_deformation(const std::vector<double>& xy);

// Phase angle (89) of a membrane element: beta = alpha - theta - [alpha(0) - theta(0)], alpha
// the polar angle of the element about the centroid, theta the major axis inclination.
// Both angles are followed continuously between calls (alpha mod 2 pi, theta mod pi);
// value() is beta wrapped into (-pi/2, pi/2]: the capsule is symmetric under a half turn,
// so an element and its homologous one (Sec. 4.1.1) share a phase. unwrapped() is not wrapped
// (a tank-treading membrane's turns accumulate).
class PhaseAngle {
 public:
  void observe(double alpha, double theta);
  double value() const;
  double unwrapped() const { return beta_; }

  // Restart points: {started, alpha, theta, offset, beta}.
  std::vector<double> state() const { return {started_ ? 1.0 : 0.0, alpha_, theta_, offset_, beta_}; }
  void restore(const std::vector<double>& s) {
    started_ = s.at(0) != 0.0, alpha_ = s.at(1), theta_ = s.at(2), offset_ = s.at(3), beta_ = s.at(4);
  }

 private:
  bool started_ = false;
  double alpha_ = 0, theta_ = 0, offset_ = 0, beta_ = 0;
};

// Wraps an angle into (-pi/2, pi/2] (a direction without sense).
double wrap_half_turn(double angle);

}  // namespace capsule::membrane2d
