#pragma once
// Numbers the prose of THESIS.md quotes from shipped results (deviations.md's probes), written as
// placeholders and filled from the results at generation, so a quoted number cannot go stale:
//   {fit <campaign>/<slug>/<column>}          a fitted parameter of a member ("recovery.k_tau_r")
//   {r2 <campaign>/<slug>/<fit>}               R^2 of a member's fit ("recovery")
//   {intercept <campaign>/<column>/<x>/<slug>+<slug>...}, {slope ...}
//                                              the least-squares line of the column against
//                                              parameter x over those members (>= 2)
//   {exponent <campaign>/<column>/<x>/<slug>+<slug>...}
//                                              the same in log-log: column ~ x^exponent
//   {bilinear <campaign>/<target>/<coefficient>/<level>}
//                                              a coefficient (a, b, c, or b_over_a) of the campaign's
//                                              bilinear fit (95)-(96) of target ("response.k_tau_s")
//                                              at its finest level, or Richardson-extrapolated over
//                                              its ladder (level "finest" or "extrapolated")
//   {at <campaign>/<slug>/<series>/<kt>}      a series of the member file ("D_xy") at time kt,
//                                              linearly interpolated; kt "stop" is the marker t_stop
// Each number is printed at three significant digits (short_number).
#include <string>

#include "analysis/dissertation/results.hpp"

namespace capsule::analysis {

// The value of one placeholder's inside ("fit probe/slug/recovery.k_tau_r"). Throws
// std::runtime_error naming the placeholder and what is missing (campaign, member, fit).
double measured_number(const DissertationResults& results, const std::string& spec);

// `text` with every placeholder above filled; other braces are left alone. Throws as
// measured_number does when `strict`; otherwise a number without its source (results folder
// without the probe) is written "[not measured: why]".
std::string fill_measured_numbers(const std::string& text, const DissertationResults& results, bool strict = true);

}  // namespace capsule::analysis
