#pragma once
// The axes of the dissertation's figures (analysis/dissertation/figure_axes.md, embedded at build
// time): per figure of the text, the quantity on x, left y and right y, the members a report
// draws together on one figure as the text does, and where the toolkit's axes differ and why.
// Feeds `study report` (which figures of a report stand for which of the text's, and the
// figures drawn together) and the test that checks every linked figure's declaration.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace capsule::analysis {

struct MemberGroup {
  std::string label;                 // e.g. "power law, n 0.64"
  std::vector<std::string> members;  // member slugs
};

struct TextFigureAxes {
  std::string number;
  std::string x;
  std::vector<std::string> left, right;
  double right_scale = 0.0;           // the right axis's range over the left's ("(100 x left)"); 0 without one
  std::vector<MemberGroup> together;  // empty: not a figure of members drawn together
  std::string toolkit_otherwise;      // "x = kt; left y = a; b: why", or empty
  // The axes the toolkit draws: the text's, or those `toolkit_otherwise` names.
  std::string toolkit_x() const;
  std::vector<std::string> toolkit_left() const;
  std::vector<std::string> toolkit_right() const;
};

// The rows of a figure_axes.md text (six cells each). Throws std::runtime_error naming the line
// for a row with another number of cells, no figure number, no x or no left y, or a malformed
// `drawn together` or `the toolkit draws otherwise` cell.
std::vector<TextFigureAxes> parse_figure_axes(const std::string& markdown);

// The embedded figure_axes.md.
const std::vector<TextFigureAxes>& figure_axes();

// For `study report` of campaign `campaign`: ReportRequest::text_figures, every file of
// figures.md under `<campaign>/report/figures/` with its figure's number and what it shows,
// and for a figure drawn together, its groups, the series on its left axis ("left": D_xy or
// theta) and what the toolkit draws otherwise ("otherwise", the row's cell, when not empty).
nlohmann::json text_figures_of_campaign(const std::string& campaign);

}  // namespace capsule::analysis
