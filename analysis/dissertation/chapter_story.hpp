#pragma once
// THESIS.md's first screen, per chapter of the text: one or two generated sentences saying how many
// of its claims the shipped results reproduce, how many they contradict, and of those how many have
// a measured cause that closes part of the gap (the largest share named), and which are unexplained.
// Counted from the verdicts and the causes' grades (cause_grades.hpp); nothing is typed in.
#include <string>
#include <vector>

#include "analysis/dissertation/cause_grades.hpp"
#include "analysis/dissertation/claims.hpp"
#include "analysis/dissertation/prose_lines.hpp"

namespace capsule::analysis {

// One bullet per chapter (2-5) with claims, each line at most k_prose_line_characters long.
std::string chapter_story_markdown(const std::vector<ClaimResult>& rows, const std::vector<CauseGrade>& grades);

}  // namespace capsule::analysis
