#pragma once
// What every report section reads: the parsed analysis block and, per member, its
// status, scene parameters, fits and the series figures need (analysed once, here).
#include <filesystem>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/report/analysis_block.hpp"
#include "analysis/fit/member_fits.hpp"
#include "analysis/report/report.hpp"
#include "analysis/report/slices_table.hpp"

namespace capsule::analysis {

inline constexpr double k_nan = std::numeric_limits<double>::quiet_NaN();

struct MemberAnalysis {
  MemberRef ref;
  std::string status;   // the member file's status, or why there is none
  nlohmann::json scene; // the canonical scene (the request's, else the member file's; null if neither)
  std::map<std::string, double> parameters;        // found scene parameters
  std::map<std::string, std::string> missing;      // parameter -> why not found
  MemberFits fits;
  std::vector<double> kt, D;                       // for figures
  std::vector<double> D_extent;                    // D from the extents L, W (3D members; published curves)
  std::vector<double> gamma_min, gamma_max;        // 3D power-law members: surface shear rate range (Fig. 64)
  std::vector<double> theta;                       // inclination of the major axis, rad (Figs. 61, 63)
  std::vector<double> lambda;                      // stretch members: D_axial / D_transverse (Hochmuth's extension ratio)
  std::map<std::string, std::vector<double>> series;  // the series the experiments compare (compare[].series)
  std::map<std::string, double> markers;
  double wall_seconds = k_nan;                     // the member file's run time (attribute wall_seconds)
  long threads = 0;                                // threads it ran on (attribute threads); 0: not recorded
  MemberSlices slices;                             // 3D members with stored shapes (Figs. 41-53)
  std::string slices_note;                         // why a 3D member's shapes could not be sliced
};

struct ReportContext {
  const ReportRequest& request;
  AnalysisBlock block;
  std::vector<MemberAnalysis> members;  // in the request's order
};

// Reads and fits every member of the request; `wanted`: scene parameters to look up.
std::vector<MemberAnalysis> analyse_members(const ReportRequest& request, const AnalysisBlock& block,
                                            const std::set<std::string>& wanted);

// Records in every member's parameters the numeric scene values that differ among the members
// (dotted keys, e.g. "resolution.mesh_level", "power_law.n", "c0"), beside the wanted ones:
// fits.json then says what tells members apart, so study thesis can find a ladder's points and
// study compare can match members, whatever the campaign sweeps.
void record_varying_parameters(std::vector<MemberAnalysis>& members);

std::string case_label(const std::string& c);

// A slug made safe to name a file: [A-Za-z0-9_.-] kept, anything else becomes '_'.
std::string file_slug(const std::string& slug);

// A found scene parameter, NaN when not found.
double parameter(const MemberAnalysis& m, const std::string& name);

// Members ordered by case (first appearance), then by parameter `x` ("" for none), then by slug.
std::vector<const MemberAnalysis*> ordered(const std::vector<MemberAnalysis>& members, const std::string& x);

// Fit result keys of a member in a fixed, readable order.
std::vector<std::string> fit_keys(const MemberFits& fits);

// A parameter's value when every member of the group agrees, else NaN.
double common_value(const std::vector<const MemberAnalysis*>& group, const std::string& name);

// y(at) by linear interpolation in a series sorted by t; NaN outside [t.front(), t.back()].
double interpolate_series(const std::vector<double>& t, const std::vector<double>& y, double at);

// A number for fits.json: null when not finite (JSON has no NaN).
nlohmann::json json_number(double x);

// A member file listed under several cases (a shared base point) once, with every case.
struct DistinctMember {
  const MemberAnalysis* member = nullptr;
  std::vector<std::string> cases;  // in order of first appearance
};
std::vector<DistinctMember> distinct_members(const std::vector<MemberAnalysis>& members);

// The cases joined by "/" ("(all)" for none).
std::string cases_label(const std::vector<std::string>& cases);

// Every leaf of a scene as dotted key -> its JSON text ("resolution.a" -> "10.0").
std::map<std::string, std::string> scene_leaves(const nlohmann::json& scene);

// "Ca = 0.05, E_b = 0": the leaves (short names) whose values differ among `scenes`, as
// they are in scenes[i]; "" when none differs.
std::string differing_leaves(const std::vector<nlohmann::json>& scenes, std::size_t i);

// A scene value as a table cell: numbers by format_number, strings bare, others as JSON.
std::string value_text(const nlohmann::json& v);

// The member file's status as a reason: "member not complete: <status>" for a file that
// ended otherwise, the status itself when there is no readable file.
std::string incomplete_reason(const MemberAnalysis& m);

void write_text(const std::filesystem::path& path, const std::string& text, std::vector<std::string>& files);

}  // namespace capsule::analysis
