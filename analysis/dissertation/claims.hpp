#pragma once
// The claims of the dissertation's Chapters 2-5, each a small rule with a stated numeric
// criterion, judged from the shipped campaigns' fitted times (and, where a claim is about
// a curve, their member files) as agrees / differs / cannot tell, with the numbers.
#include <string>
#include <vector>

#include "analysis/dissertation/results.hpp"
#include "analysis/dissertation/rules.hpp"

namespace capsule::analysis {

// Whether the text's own numbers (its Table 2, the numbers in its sentences) pass the claim's rule:
// the same rule run on them as on the toolkit's. A rule they fail is not the text's claim.
enum class TextPasses { yes, no, no_numbers };
const char* text_passes_text(TextPasses t);  // "yes", "no", "no numbers"

// Whether a verdict holds at the two finest levels of the resolution ladders of the campaigns it
// reads: one_level where none of them ships a point at two levels; not_judged where the finest level
// cannot tell already.
enum class Levels { one_level, converged, not_converged, not_judged };
const char* levels_text(Levels l);  // "one level", "converged", "not converged", ""

struct ClaimResult {
  std::string key;        // the claim in analysis/dissertation/claims.md; one claim may give several
                          // rows (the circle and the sphere, or two figures)
  std::string section;    // the dissertation's section, e.g. "3.2"
  std::string statement;  // what the text says
  std::string campaign;   // the campaign (and case) that tests it
  std::string criterion;  // the rule, in numbers
  std::string reread;     // claims.md's "Re-read:": the sentence the rule was re-read from, what changed
  Verdict verdict = Verdict::cannot_tell;
  std::string measured;   // what the toolkit measures, or why it cannot tell
  bool several_levels = false;  // a campaign it reads ships some point (or bilinear fit) at two levels or more
  Levels levels = Levels::one_level;
  std::string coarse_measured;   // the next coarser level's verdict and numbers, where judged there
  TextPasses text_passes = TextPasses::no_numbers;
  std::string text_numbers;  // the text's numbers the rule ran on, and what it gave ("" without numbers)
};

// Every claim, in the order of the text. Never throws for missing campaigns or members
// (they give "cannot tell" naming what is missing).
std::vector<ClaimResult> evaluate_claims(const DissertationResults& results);

// THESIS.md's convergence policy: every claim judged at the finest level (evaluate_claims of
// `finest`) and at the next coarser level (the same results folder read at level 1), combined by
// combine_levels.
std::vector<ClaimResult> evaluate_claims_at_two_levels(const DissertationResults& finest);

// Row by row (the two lists in the same order, from evaluate_claims): a row that reads no ladder
// keeps its verdict (one level); one the finest level judges keeps it where the next coarser level
// gives the same (converged) and otherwise cannot tell (not converged), with both levels' numbers.
// Throws std::logic_error when the lists do not match.
std::vector<ClaimResult> combine_levels(std::vector<ClaimResult> fine, const std::vector<ClaimResult>& coarse);

// One verdict per claim (key) from its rows, in the order of the text: agrees or differs when
// every row says so, cannot tell when no row is judged, in part otherwise (rows that disagree,
// or some rows judged and some not).
enum class ClaimVerdict { agrees, differs, in_part, cannot_tell };
std::vector<std::pair<std::string, ClaimVerdict>> claim_verdicts(const std::vector<ClaimResult>& rows);
const char* claim_verdict_text(ClaimVerdict v);  // "agrees", "differs", "in part", "cannot tell"

// One answer per claim (key) from its rows' text_passes: no when any row's numbers fail the rule,
// yes when every row with numbers passes it, no numbers when no row has any.
std::vector<std::pair<std::string, TextPasses>> claim_text_passes(const std::vector<ClaimResult>& rows);

// The chapter of the text a claim row belongs to: the first number of its section ("3.2" -> "3").
std::string claim_chapter(const ClaimResult& row);

}  // namespace capsule::analysis
