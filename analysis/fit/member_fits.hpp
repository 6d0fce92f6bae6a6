#pragma once
// The per-member fits of a campaign's "analysis" block, made on one member file's
// D_xy(kt) with the amplitudes and interval ends taken from its /markers.
#include <map>
#include <string>
#include <vector>

#include "analysis/fit/fit_result.hpp"
#include "solver/io/member_file.hpp"

namespace capsule::analysis {

// Keyed by fit name; "two_phase" gives two results, "two_phase_R1" (87) and "two_phase_R2" (88).
using MemberFits = std::map<std::string, FitResult>;

// `fits`: names from known_fits(). A member that is not complete (unstable, stopped,
// running) or lacks kt / D_xy gets every fit as a failure naming why.
MemberFits fit_member(const io::MemberData& member, const std::vector<std::string>& fits);

// Every requested fit failing for the same reason (e.g. the member file is missing).
MemberFits failed_member(const std::vector<std::string>& fits, const std::string& reason);

// The fit result and parameter behind a column "<fit>.<time>"; nullptr parameter when
// that fit failed (its reason is in the returned FitResult) or was not made.
struct ColumnValue {
  const FitResult* fit = nullptr;
  const FitParameter* parameter = nullptr;
  std::string reason;  // why there is no number
};
ColumnValue column_value(const MemberFits& fits, const std::string& column);

}  // namespace capsule::analysis
