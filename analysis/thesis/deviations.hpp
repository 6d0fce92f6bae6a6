#pragma once
// "Known causes of disagreement": where the toolkit departs from the dissertation on
// purpose, or measures something the text does not control, with the claims each one
// moves. Maintained here, in one place: THESIS.md prints it, docs/findings/dissertation_comparison.md points to it.
#include <string>
#include <vector>

namespace capsule::analysis {

struct KnownDeviation {
  std::string topic;    // short name
  std::string text;     // what differs and why (Markdown)
  std::string affects;  // the campaigns / claims it moves
};

const std::vector<KnownDeviation>& known_deviations();

// The list as a Markdown section body (one bullet per deviation).
std::string known_deviations_markdown();

}  // namespace capsule::analysis
