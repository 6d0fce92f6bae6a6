#include "analysis/fit/exponential_fits.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>

#include "analysis/fit/ceres_least_squares.hpp"

namespace capsule::analysis {

namespace {

// D(t) = base + amplitude * sum_i w_i exp(-t / k tau_i), written once for all five models:
//   (85): base = D_max, amplitude = -D_max, one term
//   (86): base = 0, amplitude = D_stop;  (87): base = D_min, amplitude = D_stop - D_min
//   (88): base = D_inf, amplitude = D_min - D_inf;  (90): two terms of weight 1/2.
struct OneExponential {
  double t, y, base, amplitude;
  template <class T>
  bool operator()(const T* p, T* r) const {
    r[0] = T(base) + T(amplitude) * exp(-T(t) / p[0]) - T(y);
    return true;
  }
};
struct TwoExponentials {
  double t, y, base, amplitude;
  template <class T>
  bool operator()(const T* p, T* r) const {
    r[0] = T(base) + T(0.5 * amplitude) * (exp(-T(t) / p[0]) + exp(-T(t) / p[1])) - T(y);
    return true;
  }
};

struct WeightedExponentials {
  double t, y, base, amplitude;
  template <class T>
  bool operator()(const T* p, T* r) const {
    r[0] = T(base) + T(amplitude) * (p[2] * exp(-T(t) / p[0]) + (T(1.0) - p[2]) * exp(-T(t) / p[1])) - T(y);
    return true;
  }
};

// k_min_r_squared: a fit that explains less than half its data's variance is no fit.
FitResult refuse_poor(FitResult fit) {
  if (!fit.ok || fit.r_squared >= k_min_r_squared) return fit;
  FitResult f = FitResult::failure(fit.model, "the model does not describe the data: R^2 = " + std::to_string(fit.r_squared) +
                                                  " < " + std::to_string(k_min_r_squared));
  f.r_squared = fit.r_squared;
  f.n_points = fit.n_points;
  f.t_begin = fit.t_begin;
  f.t_end = fit.t_end;
  return f;
}

// A time shorter than a fifth of the output spacing is not resolved: the model's first
// sample after the start has then moved e^-5 = 99.3 % of the way, so the data carry
// almost no information on it (and Ceres stops on a vanishing gradient, not at the truth).
FitResult refuse_unresolved(FitResult fit, const std::vector<double>& t) {
  if (!fit.ok || t.size() < 2) return fit;
  const double dt = t[1] - t[0];
  for (const auto& p : fit.parameters)
    if (p.value < 0.2 * dt)
      return FitResult::failure(fit.model, p.name + " = " + std::to_string(p.value) +
                                               " is below a fifth of the output spacing " + std::to_string(dt) +
                                               ": not resolved by the data");
  return fit;
}

std::string fmt(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

// The points of the interval [t0, t1] (t reset to t - t_reset), or a reason.
struct Window {
  std::vector<double> t, y;
  std::string reason;
};

Window select(const std::vector<double>& kt, const std::vector<double>& D, double t0, double t1, double t_reset,
              const std::vector<std::pair<std::string, double>>& markers) {
  Window w;
  for (const auto& [name, value] : markers)
    if (!std::isfinite(value)) {
      w.reason = "marker " + name + " not reached (NaN)";
      return w;
    }
  if (kt.size() != D.size()) {
    w.reason = "kt and D_xy differ in length";
    return w;
  }
  if (!(t1 > t0)) {
    w.reason = "empty interval [" + fmt(t0) + ", " + fmt(t1) + "]";
    return w;
  }
  // Markers are output times; 1e-9 relative absorbs their round trip through text/HDF5.
  const double eps = 1e-9 * std::max(1.0, std::abs(t1));
  for (std::size_t i = 0; i < kt.size(); ++i) {
    if (!(kt[i] >= t0 - eps && kt[i] <= t1 + eps)) continue;
    if (!std::isfinite(D[i])) {
      w.reason = "non-finite D_xy at kt = " + fmt(kt[i]);
      return w;
    }
    w.t.push_back(kt[i] - t_reset);
    w.y.push_back(D[i]);
  }
  if (w.t.size() < k_min_fit_points) {
    w.reason = "too few points (" + std::to_string(w.t.size()) + " < " + std::to_string(k_min_fit_points) +
               ") in [" + fmt(t0) + ", " + fmt(t1) + "]";
    return w;
  }
  const auto [lo, hi] = std::minmax_element(w.y.begin(), w.y.end());
  // Relative 1e-12: a series that varies less than this is constant to round-off.
  if (*hi - *lo <= 1e-12 * std::max(1.0, std::abs(*hi))) w.reason = "D_xy is constant on [" + fmt(t0) + ", " + fmt(t1) + "]";
  return w;
}

// First-guess time: where the normalised progress g = (y - end) / (start - end) first
// falls to 1/e; the span / 3 when it never does.
double initial_tau(const Window& w, double start, double end) {
  const double span = w.t.back() - w.t.front();
  for (std::size_t i = 0; i < w.t.size(); ++i) {
    const double g = (w.y[i] - end) / (start - end);
    if (g <= std::exp(-1.0) && w.t[i] > 0.0) return w.t[i];
  }
  return std::max(span / 3.0, 10.0 * k_tau_floor);
}

FitResult one_exponential(const std::string& model, const std::string& name, const Window& w, double base,
                          double amplitude, double start, double end, double t_begin, double t_end) {
  if (!w.reason.empty()) return FitResult::failure(model, w.reason);
  if (!(std::abs(amplitude) > 0.0)) return FitResult::failure(model, "zero amplitude: nothing decays or grows");
  std::vector<OneExponential> points;
  for (std::size_t i = 0; i < w.t.size(); ++i) points.push_back({w.t[i], w.y[i], base, amplitude});
  detail::ParameterSpec<1> spec{{name}, {initial_tau(w, start, end)}, {k_tau_floor}, {detail::k_unbounded}};
  return refuse_poor(refuse_unresolved(detail::solve_least_squares<1>(model, points, w.y, spec, t_begin, t_end), w.t));
}

}  // namespace

FitResult fit_response(const std::vector<double>& kt, const std::vector<double>& D, double D_max, double t_max) {
  const std::string model = "response (85)";
  const Window w = select(kt, D, 0.0, t_max, 0.0, {{"D_max", D_max}, {"t_max", t_max}});
  // Growth from D = 0 (start) to D_max (end).
  FitResult fit = one_exponential(model, "k_tau_s", w, D_max, -D_max, 0.0, D_max, 0.0, t_max);
  fit.fixed = {{"form", "response"}, {"D_max", D_max}, {"t0", 0.0}};
  return fit;
}

FitResult fit_recovery(const std::vector<double>& kt, const std::vector<double>& D, double D_stop, double t_stop,
                       double t_end) {
  const Window w = select(kt, D, t_stop, t_end, t_stop, {{"D_stop", D_stop}, {"t_stop", t_stop}, {"t_end", t_end}});
  FitResult fit = one_exponential("recovery (86)", "k_tau_r", w, 0.0, D_stop, D_stop, 0.0, t_stop, t_end);
  fit.fixed = {{"form", "recovery"}, {"D_stop", D_stop}, {"t0", t_stop}};
  return fit;
}

FitResult fit_two_phase_initial(const std::vector<double>& kt, const std::vector<double>& D, double D_stop,
                                double D_min, double t_stop, double t_min) {
  const Window w =
      select(kt, D, t_stop, t_min, t_stop, {{"D_stop", D_stop}, {"D_min", D_min}, {"t_stop", t_stop}, {"t_min", t_min}});
  FitResult fit = one_exponential("two-phase recovery, initial (87)", "k_tau_R1", w, D_min, D_stop - D_min, D_stop,
                                  D_min, t_stop, t_min);
  fit.fixed = {{"form", "two_phase_initial"}, {"D_stop", D_stop}, {"D_min", D_min}, {"t0", t_stop}};
  return fit;
}

FitResult fit_two_phase_late(const std::vector<double>& kt, const std::vector<double>& D, double D_min, double D_inf,
                             double t_min, double t_end) {
  const Window w =
      select(kt, D, t_min, t_end, t_min, {{"D_min", D_min}, {"D_inf", D_inf}, {"t_min", t_min}, {"t_end", t_end}});
  FitResult fit = one_exponential("two-phase recovery, late (88)", "k_tau_R2", w, D_inf, D_min - D_inf, D_min, D_inf,
                                  t_min, t_end);
  fit.fixed = {{"form", "two_phase_late"}, {"D_min", D_min}, {"D_inf", D_inf}, {"t0", t_min}};
  return fit;
}

FitResult fit_double_exponential(const std::vector<double>& kt, const std::vector<double>& D, double D_stop,
                                 double D_inf, double t_stop, double t_end) {
  const std::string model = "double exponential (90)";
  const Window w =
      select(kt, D, t_stop, t_end, t_stop, {{"D_stop", D_stop}, {"D_inf", D_inf}, {"t_stop", t_stop}, {"t_end", t_end}});
  if (!w.reason.empty()) return FitResult::failure(model, w.reason);
  const double amplitude = D_stop - D_inf;
  if (!(std::abs(amplitude) > 0.0)) return FitResult::failure(model, "zero amplitude: D_stop = D_inf");
  std::vector<TwoExponentials> points;
  for (std::size_t i = 0; i < w.t.size(); ++i) points.push_back({w.t[i], w.y[i], D_inf, amplitude});
  // Start the two times a decade apart around the single-exponential guess (the text
  // finds them an order of magnitude apart, Sec. 4.1.2), so they can separate.
  const double tau0 = initial_tau(w, D_stop, D_inf);
  detail::ParameterSpec<2> spec{{"k_tau_R1", "k_tau_R2"},
                                {tau0 / 3.0, tau0 * 3.0},
                                {k_tau_floor, k_tau_floor},
                                {detail::k_unbounded, detail::k_unbounded}};
  FitResult fit = refuse_poor(refuse_unresolved(detail::solve_least_squares<2>(model, points, w.y, spec, t_stop, t_end), w.t));
  if (fit.ok && fit.parameters[0].value > fit.parameters[1].value) {
    // The model is symmetric in the two times: report the shorter one as R1.
    std::swap(fit.parameters[0].value, fit.parameters[1].value);
    std::swap(fit.parameters[0].std_error, fit.parameters[1].std_error);
    std::swap(fit.parameters[0].ci_low, fit.parameters[1].ci_low);
    std::swap(fit.parameters[0].ci_high, fit.parameters[1].ci_high);
    std::swap(fit.covariance[0][0], fit.covariance[1][1]);
  }
  fit.fixed = {{"form", "double_exponential"}, {"D_stop", D_stop}, {"D_inf", D_inf}, {"t0", t_stop}};
  return fit;
}

FitResult fit_double_exponential_free(const std::vector<double>& kt, const std::vector<double>& D, double D_stop,
                                      double D_inf, double t_stop, double t_end) {
  const std::string model = "double exponential, free amplitudes";
  const Window w =
      select(kt, D, t_stop, t_end, t_stop, {{"D_stop", D_stop}, {"D_inf", D_inf}, {"t_stop", t_stop}, {"t_end", t_end}});
  if (!w.reason.empty()) return FitResult::failure(model, w.reason);
  if (w.t.size() < k_min_fit_points + 1) return FitResult::failure(model, "too few points for three parameters");
  const double amplitude = D_stop - D_inf;
  if (!(std::abs(amplitude) > 0.0)) return FitResult::failure(model, "zero amplitude: D_stop = D_inf");
  std::vector<WeightedExponentials> points;
  for (std::size_t i = 0; i < w.t.size(); ++i) points.push_back({w.t[i], w.y[i], D_inf, amplitude});
  // Three parameters have more than one basin: from the single-exponential guess alone, the
  // fast time of a recovery whose fast phase is short and small (Fig. 38's capsule: 0.18 kt
  // carrying 18 % of the change) runs onto its floor. So start from fast times of a few
  // output spacings up to a third of the guess, and keep the best usable fit (lowest cost).
  // w is bounded to [0, 1]; on a bound the data show one phase only.
  const double tau0 = initial_tau(w, D_stop, D_inf);
  const double dt = w.t.size() > 1 ? w.t[1] - w.t[0] : tau0;
  FitResult fit;
  for (const double fast : {4.0 * dt, 0.1 * tau0, tau0 / 3.0}) {
    for (const double share : {0.25, 0.5}) {
      detail::ParameterSpec<3> spec{{"k_tau_R1", "k_tau_R2", "w_R1"},
                                    {std::max(fast, 10.0 * k_tau_floor), tau0 * 3.0, share},
                                    {k_tau_floor, k_tau_floor, 0.0},
                                    {detail::k_unbounded, detail::k_unbounded, 1.0}};
      FitResult trial =
          refuse_poor(refuse_unresolved(detail::solve_least_squares<3>(model, points, w.y, spec, t_stop, t_end), w.t));
      const bool first = fit.model.empty();
      if (first || (trial.ok && (!fit.ok || trial.reduced_chi_square < fit.reduced_chi_square))) fit = trial;
    }
  }
  if (fit.ok && fit.parameters[0].value > fit.parameters[1].value) {
    // (tau1, tau2, w) and (tau2, tau1, 1 - w) are the same curve: report the shorter time as R1.
    std::swap(fit.parameters[0].value, fit.parameters[1].value);
    std::swap(fit.parameters[0].std_error, fit.parameters[1].std_error);
    std::swap(fit.parameters[0].ci_low, fit.parameters[1].ci_low);
    std::swap(fit.parameters[0].ci_high, fit.parameters[1].ci_high);
    auto& wp = fit.parameters[2];
    wp.value = 1.0 - wp.value;
    const double lo = 1.0 - wp.ci_high, hi = 1.0 - wp.ci_low;
    wp.ci_low = lo;
    wp.ci_high = hi;
    // Permute the covariance: swap indices 0 and 1, and negate the w row/column.
    auto c = fit.covariance;
    const int perm[3] = {1, 0, 2};
    const double sign[3] = {1.0, 1.0, -1.0};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) fit.covariance[i][j] = sign[i] * sign[j] * c[perm[i]][perm[j]];
  }
  fit.fixed = {{"form", "double_exponential_free"}, {"D_stop", D_stop}, {"D_inf", D_inf}, {"t0", t_stop}};
  return fit;
}

double evaluate_fit(const FitResult& fit, double kt) {
  if (!fit.ok) return std::nan("");
  const std::string form = fit.fixed.value("form", "");
  const double t = kt - fit.fixed.value("t0", 0.0);
  const double tau = fit.parameters.at(0).value;
  auto get = [&](const char* key) { return fit.fixed.at(key).get<double>(); };
  if (form == "response") return get("D_max") * (1.0 - std::exp(-t / tau));
  if (form == "recovery") return get("D_stop") * std::exp(-t / tau);
  if (form == "two_phase_initial") return get("D_min") + (get("D_stop") - get("D_min")) * std::exp(-t / tau);
  if (form == "two_phase_late") return get("D_inf") + (get("D_min") - get("D_inf")) * std::exp(-t / tau);
  if (form == "double_exponential")
    return get("D_inf") + 0.5 * (get("D_stop") - get("D_inf")) *
                              (std::exp(-t / tau) + std::exp(-t / fit.parameters.at(1).value));
  if (form == "double_exponential_free") {
    const double w1 = fit.parameters.at(2).value;
    return get("D_inf") + (get("D_stop") - get("D_inf")) *
                              (w1 * std::exp(-t / tau) + (1.0 - w1) * std::exp(-t / fit.parameters.at(1).value));
  }
  return std::nan("");
}

}  // namespace capsule::analysis
