#pragma once
// THESIS.md's detail section of each claim, the target of the chapter tables' links: the
// claim's verdict, then for each of its rows what the text says, the campaign that tests it,
// the full criterion, the row's verdict and everything the toolkit measures (the numbers and
// the members), then the text's figures that show it (linked to the toolkit's) and the known
// causes linked from it with how much of its gap each closes, or "unexplained" where it differs
// and none closes part of it.
#include <string>
#include <vector>

#include "analysis/dissertation/cause_grades.hpp"
#include "analysis/dissertation/claims.hpp"

namespace capsule::analysis {

// `results_dir` and `link_base` as for figure_links (figure_index.hpp).
std::string claim_details_markdown(const std::vector<ClaimResult>& rows, const std::string& results_dir,
                                   const std::string& link_base, const std::vector<CauseGrade>& grades);

}  // namespace capsule::analysis
