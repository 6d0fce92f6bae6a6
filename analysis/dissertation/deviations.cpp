#include "analysis/dissertation/deviations.hpp"

#include <sstream>
#include <stdexcept>

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
      out.push_back({line.substr(3), "", ""});
      d = &out.back();
    } else if (!d || line.empty()) {
      continue;  // the title and introduction, and blank lines
    } else if (line.rfind("Moves: ", 0) == 0) {
      d->affects = line.substr(7);
    } else if (!d->affects.empty()) {
      throw std::runtime_error(where() + "text after the Moves: line of \"" + d->topic + "\"");
    } else {
      d->text += (d->text.empty() ? "" : " ") + line;
    }
  }
  if (d && d->affects.empty()) throw std::runtime_error(where() + "the last cause has no Moves: line");
  return out;
}

const std::vector<KnownDeviation>& known_deviations() {
  static const std::vector<KnownDeviation> d = parse_known_deviations(k_deviations_markdown);
  return d;
}

std::string known_deviations_markdown() {
  std::string s;
  for (const auto& d : known_deviations())
    s += "- **" + d.topic + ".** " + d.text + " *Moves:* " + d.affects + ".\n";
  return s;
}

}  // namespace capsule::analysis
