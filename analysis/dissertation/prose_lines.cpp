#include "analysis/dissertation/prose_lines.hpp"

#include <sstream>

namespace capsule::analysis {

std::string wrap_prose_lines(const std::string& markdown, std::size_t limit) {
  std::istringstream in(markdown);
  std::string line, out;
  while (std::getline(in, line)) {
    if (line.size() <= limit || line.rfind("|", 0) == 0 || line.rfind("#", 0) == 0) {
      out += line + "\n";
      continue;
    }
    // A list item's continuation lines are indented to its text ("- " -> two blanks).
    std::size_t lead = line.find_first_not_of(' ');
    if (lead == std::string::npos) lead = 0;
    const bool item = line.compare(lead, 2, "- ") == 0;
    const std::string indent(lead + (item ? 2 : 0), ' ');
    std::string rest = line;
    bool first = true;
    while (true) {
      const std::string prefix = first ? "" : indent;
      if (prefix.size() + rest.size() <= limit) {
        out += prefix + rest + "\n";
        break;
      }
      const std::size_t room = limit - prefix.size();
      std::size_t cut = rest.rfind(' ', room);
      if (cut == std::string::npos || cut <= lead + 2) cut = rest.find(' ', room);  // a word longer than the room
      if (cut == std::string::npos) {
        out += prefix + rest + "\n";
        break;
      }
      out += prefix + rest.substr(0, cut) + "\n";
      rest = rest.substr(rest.find_first_not_of(' ', cut) == std::string::npos ? rest.size() : rest.find_first_not_of(' ', cut));
      first = false;
      if (rest.empty()) break;
    }
  }
  if (!markdown.empty() && markdown.back() != '\n' && !out.empty()) out.pop_back();
  return out;
}

}  // namespace capsule::analysis
