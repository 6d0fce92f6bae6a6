#include "analysis/dissertation/deviations.hpp"

#include <sstream>
#include <stdexcept>

#include "analysis/dissertation/document_links.hpp"
#include "analysis/dissertation/measured_numbers.hpp"
#include "deviations_text.hpp"

namespace capsule::analysis {

std::vector<KnownDeviation> parse_known_deviations(const std::string& markdown) {
  std::vector<KnownDeviation> out;
  std::istringstream in(markdown);
  std::string line;
  KnownDeviation* d = nullptr;
  int line_number = 0;
  const auto where = [&] { return "analysis/dissertation/deviations.md line " + std::to_string(line_number) + ": "; };
  while (std::getline(in, line)) {
    ++line_number;
    if (line.rfind("## ", 0) == 0) {
      if (d && d->affects.empty()) throw std::runtime_error(where() + "the cause before has no Moves: line");
      if (d && d->claims.empty() && d->unlinked.empty()) throw std::runtime_error(where() + "the cause before has no Claims: line");
      out.push_back({line.substr(3), "", "", {}, ""});
      d = &out.back();
    } else if (!d || line.empty()) {
      continue;  // the title and introduction, and blank lines
    } else if (line.rfind("Moves: ", 0) == 0 && d->affects.empty()) {
      d->affects = line.substr(7);
    } else if (line.rfind("Claims: none", 0) == 0 && !d->affects.empty() && d->claims.empty() && d->unlinked.empty()) {
      const std::size_t open = line.find('('), close = line.rfind(')');
      if (open == std::string::npos || close == std::string::npos || close < open + 2)
        throw std::runtime_error(where() + "\"Claims: none\" of \"" + d->topic + "\" needs its reason in parentheses");
      d->unlinked = line.substr(open + 1, close - open - 1);
    } else if (line.rfind("Claims: ", 0) == 0 && !d->affects.empty() && d->claims.empty() && d->unlinked.empty()) {
      d->claims = split_list(line.substr(8));
    } else if (!d->affects.empty()) {
      throw std::runtime_error(where() + "text after the Moves: line of \"" + d->topic + "\"");
    } else {
      d->text += (d->text.empty() ? "" : " ") + line;
    }
  }
  if (d && d->affects.empty()) throw std::runtime_error(where() + "the last cause has no Moves: line");
  if (d && d->claims.empty() && d->unlinked.empty()) throw std::runtime_error(where() + "the last cause has no Claims: line");
  return out;
}

const std::vector<KnownDeviation>& known_deviations() {
  static const std::vector<KnownDeviation> d = parse_known_deviations(k_deviations_markdown);
  return d;
}

std::string known_deviations_markdown() {
  std::string s;
  const auto& all = known_deviations();
  for (std::size_t i = 0; i < all.size(); ++i)
    s += "- <a id=\"" + cause_anchor(i + 1) + "\"></a>**" + cause_label(i + 1) + " " + all[i].topic + ".** " + all[i].text +
         " *Moves:* " + all[i].affects + "." +
         (all[i].unlinked.empty() ? std::string() : " *Linked from no claim:* " + all[i].unlinked + ".") + "\n";
  return s;
}

std::string known_deviations_markdown(const DissertationResults& results) {
  return fill_measured_numbers(known_deviations_markdown(), results, false);
}

std::vector<std::size_t> causes_of_claim(const std::string& claim_key) {
  std::vector<std::size_t> out;
  const auto& all = known_deviations();
  for (std::size_t i = 0; i < all.size(); ++i)
    for (const auto& key : all[i].claims)
      if (key == claim_key) out.push_back(i + 1);
  return out;
}

}  // namespace capsule::analysis
