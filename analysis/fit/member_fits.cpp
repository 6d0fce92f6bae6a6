#include "analysis/fit/member_fits.hpp"

#include <cmath>
#include <limits>

#include "analysis/fit/exponential_fits.hpp"
#include "analysis/fit/extensional_recovery.hpp"

namespace capsule::analysis {

namespace {
std::vector<std::string> result_keys(const std::string& fit) {
  if (fit == "two_phase") return {"two_phase_R1", "two_phase_R2"};
  return {fit};
}
const char* model_of(const std::string& key) {
  if (key == "response") return "response (85)";
  if (key == "recovery") return "recovery (86)";
  if (key == "two_phase_R1") return "two-phase recovery, initial (87)";
  if (key == "two_phase_R2") return "two-phase recovery, late (88)";
  if (key == "double_exponential") return "double exponential (90)";
  if (key == "double_exponential_free") return "double exponential, free amplitudes";
  if (key == "extensional_recovery") return "extensional recovery (Hochmuth, Worthy and Evans 1979)";
  return "unknown";
}
// A released stretch member's recovery of lambda = D_axial / D_transverse after t_stop, towards
// the lambda of its first row: the cell at rest before the pull, the shape it recovers to.
FitResult extensional_recovery_of(const io::MemberData& member, double t_stop, double t_end) {
  const auto axial = member.series.find("D_axial"), transverse = member.series.find("D_transverse");
  if (axial == member.series.end() || transverse == member.series.end())
    return FitResult::failure(model_of("extensional_recovery"),
                              "member has no D_axial or D_transverse series (a stretch member's)");
  std::vector<double> lambda(axial->second.size());
  for (std::size_t i = 0; i < lambda.size(); ++i) lambda[i] = axial->second[i] / transverse->second[i];
  return fit_extensional_recovery(member.series.at("kt"), lambda, t_stop, t_end, lambda.front());
}

}  // namespace

MemberFits failed_member(const std::vector<std::string>& fits, const std::string& reason) {
  MemberFits out;
  for (const auto& f : fits)
    for (const auto& key : result_keys(f)) out[key] = FitResult::failure(model_of(key), reason);
  return out;
}

MemberFits fit_member(const io::MemberData& member, const std::vector<std::string>& fits) {
  if (!member.complete()) return failed_member(fits, "member not complete: " + member.status);
  const auto kt_it = member.series.find("kt");
  const auto d_it = member.series.find("D_xy");
  if (kt_it == member.series.end() || d_it == member.series.end())
    return failed_member(fits, "member has no kt or D_xy series");
  const auto& kt = kt_it->second;
  const auto& D = d_it->second;
  if (kt.empty()) return failed_member(fits, "member has no output rows");

  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto marker = [&](const char* name) {
    const auto it = member.markers.find(name);
    return it == member.markers.end() ? nan : it->second;
  };
  // The recovery runs to the marker t_end, or to the last output when it is not set.
  const double t_end = std::isfinite(marker("t_end")) ? marker("t_end") : kt.back();

  MemberFits out;
  for (const auto& f : fits) {
    if (f == "response") out[f] = fit_response(kt, D, marker("D_max"), marker("t_max"));
    if (f == "recovery") out[f] = fit_recovery(kt, D, marker("D_stop"), marker("t_stop"), t_end);
    if (f == "two_phase") {
      out["two_phase_R1"] = fit_two_phase_initial(kt, D, marker("D_stop"), marker("D_min"), marker("t_stop"),
                                                  marker("t_min"));
      out["two_phase_R2"] = fit_two_phase_late(kt, D, marker("D_min"), marker("D_inf"), marker("t_min"), t_end);
    }
    if (f == "double_exponential")
      out[f] = fit_double_exponential(kt, D, marker("D_stop"), marker("D_inf"), marker("t_stop"), t_end);
    if (f == "double_exponential_free")
      out[f] = fit_double_exponential_free(kt, D, marker("D_stop"), marker("D_inf"), marker("t_stop"), t_end);
    if (f == "extensional_recovery") out[f] = extensional_recovery_of(member, marker("t_stop"), t_end);
  }
  return out;
}

ColumnValue column_value(const MemberFits& fits, const std::string& column) {
  ColumnValue v;
  const auto dot = column.find('.');
  const std::string fit = column.substr(0, dot);
  const std::string time = dot == std::string::npos ? "" : column.substr(dot + 1);
  std::string key = fit;
  if (fit == "two_phase") key = time == "k_tau_R1" ? "two_phase_R1" : "two_phase_R2";
  const auto it = fits.find(key);
  if (it == fits.end()) {
    v.reason = "fit " + fit + " not made";
    return v;
  }
  v.fit = &it->second;
  if (!it->second.ok) {
    v.reason = it->second.reason;
    return v;
  }
  v.parameter = it->second.parameter(time);
  if (!v.parameter) v.reason = "fit " + fit + " has no " + time;
  return v;
}

}  // namespace capsule::analysis
