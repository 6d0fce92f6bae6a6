#pragma once
// What each claim of the dissertation comparison says, which campaign tests it and the rule that
// judges it, in words: written in analysis/dissertation/claims.md (embedded at build time), so
// the prose lives in one Markdown file and the rules in code (claims/chapter*.cpp).
#include <map>
#include <string>
#include <vector>

namespace capsule::analysis {

struct ClaimText {
  std::string key;        // the "## " heading, e.g. "3.3 falls"
  std::string section;    // the dissertation's section
  std::string statement;  // what the text says
  std::string tested_by;  // the campaign (and case) that tests it, the campaign first
  std::string criterion;  // the rule, in numbers
  std::string reread;     // optional: the sentence a rule was re-read from, and what changed
};

// The claims of a claims.md text: each "## " heading a key, followed by the lines "Section: ",
// "Statement: ", "Tested by: " and "Criterion: " in that order, then optionally one "Re-read: " line. Throws std::runtime_error naming
// the line when a line is missing, out of order or unknown, or a key is given twice.
std::vector<ClaimText> parse_claim_texts(const std::string& markdown);

// The claims of the embedded claims.md, in the order of the file (the order of the text).
const std::vector<ClaimText>& claim_texts();

// The claim `key` of the embedded claims.md. Throws std::logic_error for an unknown key.
const ClaimText& claim_text(const std::string& key);

// `text` with every {name} replaced by values[name] (a value the text does not use is
// ignored: one set of values serves all four texts). Throws std::logic_error naming the claim
// and the placeholder when a value is missing.
std::string fill_placeholders(const std::string& text, const std::map<std::string, std::string>& values,
                              const std::string& key);

}  // namespace capsule::analysis
