#pragma once
// The claims of the dissertation's Chapters 2-5, each a small rule with a stated numeric
// criterion, judged from the shipped campaigns' fitted times (and, where a claim is about
// a curve, their member files) as agrees / differs / cannot tell, with the numbers.
#include <string>
#include <vector>

#include "analysis/dissertation/results.hpp"
#include "analysis/dissertation/rules.hpp"

namespace capsule::analysis {

struct ClaimResult {
  std::string key;        // the claim in analysis/dissertation/claims.md; one claim may give several
                          // rows (the circle and the sphere, or two figures)
  std::string section;    // the dissertation's section, e.g. "3.2"
  std::string statement;  // what the text says
  std::string campaign;   // the campaign (and case) that tests it
  std::string criterion;  // the rule, in numbers
  Verdict verdict = Verdict::cannot_tell;
  std::string measured;   // what the toolkit measures, or why it cannot tell
};

// Every claim, in the order of the text. Never throws for missing campaigns or members
// (they give "cannot tell" naming what is missing).
std::vector<ClaimResult> evaluate_claims(const DissertationResults& results);

// One verdict per claim (key) from its rows, in the order of the text: agrees or differs when
// every row says so, cannot tell when no row is judged, in part otherwise (rows that disagree,
// or some rows judged and some not).
enum class ClaimVerdict { agrees, differs, in_part, cannot_tell };
std::vector<std::pair<std::string, ClaimVerdict>> claim_verdicts(const std::vector<ClaimResult>& rows);
const char* claim_verdict_text(ClaimVerdict v);  // "agrees", "differs", "in part", "cannot tell"

// The chapter of the text a claim row belongs to: the first number of its section ("3.2" -> "3").
std::string claim_chapter(const ClaimResult& row);

}  // namespace capsule::analysis
