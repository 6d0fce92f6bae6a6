#pragma once
// What each of a report's figures shows: one declaration per PNG in figure_data.json's
// "figures" (file, the quantity on x, on the left and right y axes and in extra panels, the
// series drawn, and the dissertation's figure number when the figure stands for one).
// analysis/report/plot_report.py draws from these declarations, so a declaration is what the
// PNG shows; study thesis's figure test compares them with the text's axes
// (analysis/dissertation/figure_axes.md).
#include <map>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace capsule::analysis {

// The quantity a time-table column holds, as the dissertation writes it: "two_phase.k_tau_R1"
// -> "k tau_R1", "recovery.k_tau_r" normalised by tau_e -> "tau_r/tau_e", "*.w_R1" -> "w_R1".
std::string column_quantity(const std::string& column, const std::string& normalise);

// The member series a figure of members drawn together may plot against kt, as the members block
// of figure_data.json names them: "D_xy" (Figs. 59-62) and "theta", the inclination (Figs. 61, 63).
const std::vector<std::string>& together_quantities();

// Per member slug, the series other than D_xy that the figures drawn together in `text_figures`
// plot (the members block carries them for those members only).
std::map<std::string, std::set<std::string>> together_series(const nlohmann::json& text_figures);

// figure_data["figures"] from the blocks the sections wrote (members, tables, slices, accuracy,
// stability, published) and `text_figures` (the request's: file -> the text's figure it stands
// for, and members drawn together on one figure of the text: the group members that this report has
// and whose block carries the series drawn; throws std::invalid_argument naming the file for a
// series not in together_quantities()). A time table draws only the
// series that vary its x (every series when none does), k tau_R2 on a right axis at 100 times the
// left for the tank-treading phases and 10 times for the tumbling ones, as the text's Figs. 25-36; a free-amplitude fit of the text's times in a panel below (same
// axes), and the fast phase's weight w_R1 in a panel of its own.
void declare_figures(nlohmann::json& figure_data, const nlohmann::json& text_figures);

}  // namespace capsule::analysis
