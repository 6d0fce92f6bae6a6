#pragma once
// A campaign's bilinear fits (95)-(96), read back from the fits.json its report wrote: what
// `study compare` sets side by side, and what the dissertation comparison reads.
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/fit/fit_result.hpp"

namespace capsule::analysis {

struct BilinearEntry {
  std::string campaign, case_name, target;  // target: "response.k_tau_s", ...
  double Ca = 0.0, E_b = 0.0;               // NaN when the case's members disagree
  FitResult fit;
  std::string level_key;                    // bilinear.ladder: the resolution key ("" without)
  double level = 0.0;                       // its value for this fit
  // bilinear.ladder: per coefficient ("a", "b", "c") the discretisation-error estimate of this
  // (the finest) level's value from fits.json "bilinear_ladder", or why there is none.
  std::map<std::string, double> ladder_error;
  std::map<std::string, std::string> ladder_note;
  // The same coefficients Richardson-extrapolated to zero spacing, and at the next coarser level.
  std::map<std::string, double> ladder_extrapolated, ladder_coarser;
};

// The "bilinear" array of a parsed fits.json (write_report's layout). With a ladder the
// report lists a case's levels finest first, so the first entry of a case and target is
// its finest level; the ladder's error estimates are attached to that entry.
std::vector<BilinearEntry> read_bilinear_entries(const std::string& campaign, const nlohmann::json& fits);

bool intervals_overlap(double lo1, double hi1, double lo2, double hi2);

// "v ± hw" with the tables' number format.
std::string plus_minus(double value, double half_width);

}  // namespace capsule::analysis
