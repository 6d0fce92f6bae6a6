#pragma once
// Five-point centred derivative on non-uniformly spaced abscissae (Sec. 2.4.1): the
// derivative at s[2] of the quartic through (s[k], f[k]), k = 0..4, written as weights,
// w_k = L_k'(s[2]) of the Lagrange basis. Fourth-order accurate on smooth f.
namespace capsule::membrane2d {

inline void five_point_weights(const double s[5], double w[5]) {
  const double x = s[2];
  w[2] = 0.0;
  for (int k = 0; k < 5; ++k)
    if (k != 2) w[2] += 1.0 / (x - s[k]);
  for (int j = 0; j < 5; ++j) {
    if (j == 2) continue;
    double num = 1.0, den = 1.0;
    for (int k = 0; k < 5; ++k) {
      if (k == j) continue;
      den *= s[j] - s[k];
      if (k != 2) num *= x - s[k];
    }
    w[j] = num / den;
  }
}

// Derivative at the centre from the five values.
inline double five_point_derivative(const double s[5], const double f[5]) {
  double w[5];
  five_point_weights(s, w);
  double d = 0;
  for (int k = 0; k < 5; ++k) d += w[k] * f[k];
  return d;
}

}  // namespace capsule::membrane2d
