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
