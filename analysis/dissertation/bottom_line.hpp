#pragma once
// THESIS.md's bottom line, the first thing a reader sees: how many of the dissertation's claims
// the shipped results reproduce, contradict, reproduce in part or cannot judge, by chapter, which
// ones cannot be told, Table 2's coefficients, and the known causes behind most of the
// differences. Every number is counted from the verdicts; nothing is typed in.
#include <string>
#include <vector>

#include "analysis/dissertation/cause_grades.hpp"
#include "analysis/dissertation/claims.hpp"

namespace capsule::analysis {

struct DissertationSummary;

// The claims' counts come from claim_verdicts(rows); Table 2's from `summary`.
// The causes named are those that close part of the gap of the most claims (grades).
std::string bottom_line_markdown(const std::vector<ClaimResult>& rows, const DissertationSummary& summary,
                                 const std::vector<CauseGrade>& grades = {});

}  // namespace capsule::analysis
