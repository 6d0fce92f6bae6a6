#pragma once
// How results/THESIS.md points within itself and at the shipped files: stable anchor ids for
// a claim or a cause (written as <a id> tags, so they do not depend on how a viewer turns
// headings into ids), Markdown links, and the "a; b; c" lists of the embedded data files.
#include <cstddef>
#include <string>
#include <vector>

namespace capsule::analysis {

// "claim", "3.2 small Ca" -> "claim-3-2-small-ca": lower case, every run of other characters
// than letters and digits one '-', none at either end.
std::string anchor_id(const std::string& kind, const std::string& name);

// The anchor a claim's detail section carries, and the anchor and short label of the known
// cause numbered `number` (1 for the first of deviations.md): "cause-3", "C3".
std::string claim_anchor(const std::string& claim_key);
std::string cause_anchor(std::size_t number);
std::string cause_label(std::size_t number);

// "[label](target)"; `target` a path or "#" + an anchor id.
std::string markdown_link(const std::string& label, const std::string& target);

// "[label](#id)": a link to an anchor of the document.
std::string anchor_link(const std::string& label, const std::string& id);

// Claims' keys as links to their detail sections: "[3.2 small Ca](#claim-3-2-small-ca), ...".
std::string claim_links(const std::vector<std::string>& keys);

// Appends `item` to the comma-separated `list` ("a" -> "a, b").
void append_listed(std::string& list, const std::string& item);

// "a; b;c" -> {"a", "b", "c"}: split at ';', blanks around each item trimmed, empty items dropped.
std::vector<std::string> split_list(const std::string& text);

}  // namespace capsule::analysis
