#pragma once
// Initial membrane shapes of the 2D capsule (Sec. 2.4): node positions as a flat
// array (x0, y0, x1, y1, ...), counter-clockwise (so the outward normal is the tangent
// turned clockwise and a circle has curvature +1/a), equal segment lengths, node 0 at
// the end of the capsule (the element whose phase angle (89) is tracked).
#include <vector>

namespace capsule::membrane2d {

// Circle of radius a centred at (cx, cy); node 0 at polar angle start_angle.
std::vector<double> circle(int segments, double a, double cx, double cy, double start_angle);

// Biconcave capsule (24)-(25) with alpha = 1.39, scaled to equivalent radius a (the area
// of the circle of radius a), major axis inclined by `inclination` to the x-axis, centred
// at (cx, cy). Node 0 sits at the end of the major axis (chi = pi/2 before rotation).
std::vector<double> biconcave(int segments, double a, double cx, double cy, double inclination);

// (24)-(25) with a = 1 enclose an area pi s^2 with s = biconcave_equivalent_radius();
// the shape is therefore drawn with a / s in place of a. Measured from a polyline of
// 20000 points (relative area error ~ 1e-8).
double biconcave_equivalent_radius();

inline constexpr double biconcave_alpha = 1.39;  // cell radius ratio of (24)-(25)

}  // namespace capsule::membrane2d
