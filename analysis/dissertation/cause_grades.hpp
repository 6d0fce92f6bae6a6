#pragma once
// How much of each linked claim's gap between the toolkit and the text a known cause closes,
// measured on a shipped probe (deviations.md's Gap: lines): fraction = (with the cause - toolkit)
// / (text - toolkit), filled from the shipped results when THESIS.md is generated, never typed.
// A fraction of 1 closes the gap; 0 or below explains none of it (below 0 the cause widens it), and
// a share under k_explains_share leaves the claim unexplained too: the toolkit's reading of "part of
// the gap", so that a cause that barely moves a claim is not offered as its explanation.
#include <cstddef>
#include <string>
#include <vector>

#include "analysis/dissertation/deviations.hpp"
#include "analysis/dissertation/results.hpp"

namespace capsule::analysis {

inline constexpr double k_explains_share = 0.1;

struct CauseGrade {
  std::size_t cause = 0;  // 1 for the first cause of deviations.md (C1)
  CauseGap gap;
  bool measured = false;
  std::string why;        // not measured: what is missing
  double toolkit = 0.0, with_cause = 0.0;
  double fraction = 0.0;  // NaN where the toolkit's value is the text's (no gap)
};

// (with_cause - toolkit) / (text - toolkit); NaN when text == toolkit.
double gap_fraction(double toolkit, double with_cause, double text);

// The value of a Gap: line's side: one placeholder "{fit ...}" or two divided "{...} / {...}".
// Throws as measured_number does.
double gap_side_value(const DissertationResults& results, const std::string& side);

// Every Gap: line of deviations.md graded from `results`; one whose probe is missing is not measured.
std::vector<CauseGrade> grade_causes(const DissertationResults& results);

// The grades linked from one claim, in the order of deviations.md.
std::vector<const CauseGrade*> grades_of_claim(const std::vector<CauseGrade>& grades, const std::string& claim_key);

// The cause closes part of the claim's gap: measured, with a fraction of k_explains_share or more.
bool explains(const CauseGrade& g);

// "closes 35 % of the gap", "closes only 4 % of the gap", "widens the gap (-42 %)", "closes 150 % of
// the gap (past the text)", "no gap to close", "not measured".
std::string closes_text(const CauseGrade& g);
// The short form for a table cell: "35 %", "-42 %", "no gap", "not measured".
std::string closes_percent(const CauseGrade& g);
// closes_text with what it is measured on: "closes 35 % of the gap in <quantity>: 0.935 -> 0.954
// with the cause, the text 0.99 (<its words>); <source>".
std::string grade_sentence(const CauseGrade& g);

}  // namespace capsule::analysis
