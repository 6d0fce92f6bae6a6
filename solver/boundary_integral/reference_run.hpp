#pragma once
// `capsule reference-bim`: one boundary-integral capsule sheared from rest, its shape series
// written as CSV and a one-row summary (the steady or peak deformation) printed.
#include <iosfwd>
#include <string>

#include "solver/boundary_integral/sheared_capsule.hpp"

namespace capsule::boundary_integral {

struct ReferenceRunOptions {
  ShearedCapsuleParameters capsule;
  double kt_end = 6;         // shear until this kt (with a steady tolerance: at most this kt)
  double steady_tolerance = 0;  // > 0: stop once the range of D over the last steady_window_kt is below this
  double steady_window_kt = 1;
  double every = 0.05;       // series interval in kt
  std::string series_path;   // empty: no series file
};

// The summary's CSV header and row (no trailing newline).
std::string reference_summary_header();

// Runs the capsule; writes the series to options.series_path (under a temporary name,
// renamed when complete) and the summary header and row to `summary`. Throws on bad options
// (the message names the option and its allowed range) and on a blow-up.
void run_reference(const ReferenceRunOptions& options, std::ostream& summary);

}  // namespace capsule::boundary_integral
