#pragma once
// Exponential models of the Taylor deformation D_xy(kt): response (85), recovery (86),
// two-phase recovery (87)-(88) of tank-treading capsules, and the double exponential
// (90) of tumbling capsules. Only the characteristic times k tau are fitted; the
// amplitudes (D_max, D_stop, D_min, D_inf) are the member's markers, as in the text
// ("Since D_max and D_stop are factored out ...", Sec. 3.1).
#include <cstddef>
#include <vector>

#include "analysis/fit/fit_result.hpp"

namespace capsule::analysis {

// Fewer points than this give no fit: with 1-2 parameters, 5 points leave >= 3 degrees
// of freedom (t_975 <= 3.18); fewer make the interval meaningless and cannot tell an
// exponential from any other monotone curve.
inline constexpr std::size_t k_min_fit_points = 5;

// Lower bound of every k tau: a relaxation time is positive; 1e-9 (in 1/k) is far
// below any output interval, so a fit that reaches it is reported as undetermined.
inline constexpr double k_tau_floor = 1e-9;

// A fit whose model explains less than half of the variance of its data (R^2 < 0.5) does
// not describe them: it is reported as a failure naming its R^2, never as a number. The
// text's poorest accepted fits are R^2 ~ 0.91-0.92 (Sec. 3.1, 5.1.1); a response (85)
// fitted to a biconcave capsule, which starts at D = 0.812 rather than 0, gave R^2 = -80.
inline constexpr double k_min_r_squared = 0.5;

// (85) D = D_max (1 - exp(-t / k tau_s)) on [0, t_max]; t = kt.
FitResult fit_response(const std::vector<double>& kt, const std::vector<double>& D, double D_max, double t_max);

// (86) D = D_stop exp(-t / k tau_r) on [t_stop, t_end], t = kt - t_stop.
FitResult fit_recovery(const std::vector<double>& kt, const std::vector<double>& D, double D_stop, double t_stop,
                       double t_end);

// (87) D = D_min + (D_stop - D_min) exp(-t / k tau_R1) on [t_stop, t_min], t = kt - t_stop.
FitResult fit_two_phase_initial(const std::vector<double>& kt, const std::vector<double>& D, double D_stop,
                                double D_min, double t_stop, double t_min);

// (88) D = D_inf + (D_min - D_inf) exp(-t / k tau_R2) on [t_min, t_end], t = kt - t_min.
FitResult fit_two_phase_late(const std::vector<double>& kt, const std::vector<double>& D, double D_min,
                             double D_inf, double t_min, double t_end);

// (90) D = D_inf + (D_stop - D_inf)(exp(-t / k tau_R1) + exp(-t / k tau_R2)) / 2 on
// [t_stop, t_end], t = kt - t_stop; reported with k tau_R1 <= k tau_R2.
FitResult fit_double_exponential(const std::vector<double>& kt, const std::vector<double>& D, double D_stop,
                                 double D_inf, double t_stop, double t_end);

// (90) with free amplitudes: D = D_inf + (D_stop - D_inf)(w exp(-t / k tau_R1) +
// (1 - w) exp(-t / k tau_R2)) on [t_stop, t_end], w in (0, 1) fitted (parameter "w_R1"),
// k tau_R1 <= k tau_R2. (90) fixes w = 1/2; a recovery whose fast phase carries a quarter
// of the change (Fig. 38's capsule) needs w free.
FitResult fit_double_exponential_free(const std::vector<double>& kt, const std::vector<double>& D, double D_stop,
                                      double D_inf, double t_stop, double t_end);

// Evaluate a successful fit's curve at the member's time kt (for figures and tests).
double evaluate_fit(const FitResult& fit, double kt);

}  // namespace capsule::analysis
