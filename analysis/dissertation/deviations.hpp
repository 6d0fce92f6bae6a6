#pragma once
// "Known causes of disagreement": where the toolkit departs from the dissertation on
// purpose, or measures something the text does not control, with the claims each one
// moves. Written in analysis/dissertation/deviations.md (embedded at build time), in one place:
// THESIS.md prints it, docs/findings/dissertation_comparison.md points to it.
#include <string>
#include <vector>

namespace capsule::analysis {

// How much of a claim's gap between the toolkit and the text a cause closes, as deviations.md's
// line "Gap: <claim> | <quantity> | text <number> (<the text's words>) | <toolkit> -> <with the cause> | <source>"
// states it: <toolkit> and <with the cause> each one placeholder of measured_numbers.hpp, or two
// divided ("{fit ...} / {fit ...}"), read from a shipped probe; filled and graded by cause_grades.hpp.
struct CauseGap {
  std::string claim;       // the claims.md key
  std::string quantity;    // what is compared, in words
  double text = 0.0;       // the text's value of it
  std::string text_words;  // where the text's value comes from (its words, quoted)
  std::string toolkit, with_cause;  // the placeholders, braces included
  std::string source;      // the probe and member, in words
};

struct KnownDeviation {
  std::string topic;    // short name
  std::string text;     // what differs and why (Markdown)
  std::string affects;  // the campaigns / claims it moves, in words
  std::vector<std::string> claims;  // the keys of claims.md it is linked from: those of its Gap: lines
  std::vector<CauseGap> gaps;       // one per linked claim
  std::string unlinked;             // "Claims: none (why)": why no claim links it (nothing measured moves one)
};

const std::vector<KnownDeviation>& known_deviations();

// The causes of a deviations.md text: each "## " heading a topic, the lines below it the text
// (joined by spaces), the line "Moves: ..." what it moves, then either one "Gap: " line per claim
// it is linked from (CauseGap) or the line "Claims: none (why)" where no shipped probe measures how
// much of a claim's gap it closes (no claim links it; `unlinked` keeps why). Throws
// std::runtime_error naming the line when a cause has no Moves: line, neither Gap: lines nor
// "Claims: none (why)", a malformed Gap: line, a "Claims: a; b" list (a link needs its Gap: line),
// or text after them.
std::vector<KnownDeviation> parse_known_deviations(const std::string& markdown);

// The list as a Markdown section body: one bullet per deviation, headed by its label and anchor
// (cause_label, cause_anchor: C1 the first of deviations.md).
std::string known_deviations_markdown();
// The same with the measured numbers deviations.md quotes as placeholders filled from the shipped
// results (measured_numbers.hpp), one without its source there reading "[not measured: why]", and
// each cause's grades (cause_grades.hpp: how much of each linked claim's gap it closes).
class DissertationResults;
struct CauseGrade;
std::string known_deviations_markdown(const DissertationResults& results, const std::vector<CauseGrade>& grades);

// The numbers (1 for the first of deviations.md) of the causes whose Claims: line names
// `claim_key`, in the order of deviations.md.
std::vector<std::size_t> causes_of_claim(const std::string& claim_key);

}  // namespace capsule::analysis
