#pragma once
// "Known causes of disagreement": where the toolkit departs from the dissertation on
// purpose, or measures something the text does not control, with the claims each one
// moves. Written in analysis/dissertation/deviations.md (embedded at build time), in one place:
// THESIS.md prints it, docs/findings/dissertation_comparison.md points to it.
#include <string>
#include <vector>

namespace capsule::analysis {

struct KnownDeviation {
  std::string topic;    // short name
  std::string text;     // what differs and why (Markdown)
  std::string affects;  // the campaigns / claims it moves, in words
  std::vector<std::string> claims;  // the keys of claims.md it moves (its "Claims: " line)
  std::string unlinked;             // "Claims: none (why)": why no claim links it (nothing measured moves one)
};

const std::vector<KnownDeviation>& known_deviations();

// The causes of a deviations.md text: each "## " heading a topic, the lines below it the text
// (joined by spaces), the line "Moves: ..." what it moves, then the line "Claims: a; b" the claim
// keys it moves, or "Claims: none (why)" where no shipped probe measures how much of a claim's gap
// it closes (no claim links it; `unlinked` keeps why). Throws std::runtime_error naming the line when a cause has no Moves: or Claims:
// line, or text follows them.
std::vector<KnownDeviation> parse_known_deviations(const std::string& markdown);

// The list as a Markdown section body: one bullet per deviation, headed by its label and anchor
// (cause_label, cause_anchor: C1 the first of deviations.md).
std::string known_deviations_markdown();
// The same with the measured numbers deviations.md quotes as placeholders filled from the shipped
// results (measured_numbers.hpp); one without its source there reads "[not measured: why]".
class DissertationResults;
std::string known_deviations_markdown(const DissertationResults& results);

// The numbers (1 for the first of deviations.md) of the causes whose Claims: line names
// `claim_key`, in the order of deviations.md.
std::vector<std::size_t> causes_of_claim(const std::string& claim_key);

}  // namespace capsule::analysis
