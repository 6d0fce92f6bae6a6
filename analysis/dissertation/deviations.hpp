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
  std::string affects;  // the campaigns / claims it moves
};

const std::vector<KnownDeviation>& known_deviations();

// The causes of a deviations.md text: each "## " heading a topic, the lines below it the text
// (joined by spaces), the line "Moves: ..." what it moves. Throws std::runtime_error naming the
// line when a cause has no Moves: line or text follows it.
std::vector<KnownDeviation> parse_known_deviations(const std::string& markdown);

// The list as a Markdown section body (one bullet per deviation).
std::string known_deviations_markdown();

}  // namespace capsule::analysis
