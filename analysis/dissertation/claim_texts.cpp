#include "analysis/dissertation/claim_texts.hpp"

#include <set>
#include <sstream>
#include <stdexcept>

#include "claim_texts_md.hpp"

namespace capsule::analysis {

std::vector<ClaimText> parse_claim_texts(const std::string& markdown) {
  static const char* const fields[] = {"Section: ", "Statement: ", "Tested by: ", "Criterion: "};
  static const char* const k_reread = "Re-read: ";  // optional, after the criterion
  std::vector<ClaimText> out;
  std::set<std::string> keys;
  std::istringstream in(markdown);
  std::string line;
  int line_number = 0, next_field = 4;  // 4: no claim open, or its last field read
  const auto where = [&] { return "analysis/dissertation/claims.md line " + std::to_string(line_number) + ": "; };
  while (std::getline(in, line)) {
    ++line_number;
    if (line.rfind("## ", 0) == 0) {
      if (next_field != 4) throw std::runtime_error(where() + "the claim before lacks its " + fields[next_field] + "line");
      if (!keys.insert(line.substr(3)).second) throw std::runtime_error(where() + "the key '" + line.substr(3) + "' is given twice");
      out.push_back({line.substr(3), "", "", "", "", ""});
      next_field = 0;
    } else if (out.empty() || line.empty()) {
      continue;  // the title and introduction, and blank lines
    } else if (next_field < 4 && line.rfind(fields[next_field], 0) == 0) {
      std::string* slots[] = {&out.back().section, &out.back().statement, &out.back().tested_by, &out.back().criterion};
      *slots[next_field] = line.substr(std::string(fields[next_field]).size());
      ++next_field;
    } else if (next_field == 4 && line.rfind(k_reread, 0) == 0 && out.back().reread.empty()) {
      out.back().reread = line.substr(std::string(k_reread).size());
    } else {
      throw std::runtime_error(where() + "expected " + (next_field < 4 ? std::string("the ") + fields[next_field] + "line" : "a blank line, one 'Re-read: ' line or a '## ' heading") +
                               " of '" + out.back().key + "'");
    }
  }
  if (next_field != 4) throw std::runtime_error(where() + "the last claim lacks its " + fields[next_field] + "line");
  return out;
}

const std::vector<ClaimText>& claim_texts() {
  static const std::vector<ClaimText> texts = parse_claim_texts(k_claims_markdown);
  return texts;
}

const ClaimText& claim_text(const std::string& key) {
  for (const auto& t : claim_texts())
    if (t.key == key) return t;
  throw std::logic_error("analysis/dissertation/claims.md has no claim '" + key + "'");
}

std::string fill_placeholders(const std::string& text, const std::map<std::string, std::string>& values,
                              const std::string& key) {
  std::string out;
  std::set<std::string> used;
  std::size_t at = 0;
  while (true) {
    const std::size_t open = text.find('{', at);
    if (open == std::string::npos) break;
    const std::size_t close = text.find('}', open);
    if (close == std::string::npos) throw std::logic_error("claims.md '" + key + "': an unclosed { in: " + text);
    const std::string name = text.substr(open + 1, close - open - 1);
    const auto it = values.find(name);
    if (it == values.end()) throw std::logic_error("claims.md '" + key + "': no value for {" + name + "}");
    out += text.substr(at, open - at) + it->second;
    used.insert(name);
    at = close + 1;
  }
  return out + text.substr(at);
}

}  // namespace capsule::analysis
