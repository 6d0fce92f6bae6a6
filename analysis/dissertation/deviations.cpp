#include "analysis/dissertation/deviations.hpp"

#include <sstream>
#include <stdexcept>

#include "analysis/dissertation/cause_grades.hpp"
#include "analysis/dissertation/document_links.hpp"
#include "analysis/dissertation/measured_numbers.hpp"
#include "deviations_text.hpp"

namespace capsule::analysis {

namespace {

std::string trimmed(const std::string& s) {
  const std::size_t b = s.find_first_not_of(' '), e = s.find_last_not_of(' ');
  return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

// "Gap: <claim> | <quantity> | text <number> (<words>) | <toolkit> -> <with the cause> | <source>".
CauseGap parse_gap(const std::string& line, const std::string& where) {
  std::vector<std::string> f;
  std::size_t at = 5;  // after "Gap: "
  for (std::size_t bar; (bar = line.find(" | ", at)) != std::string::npos; at = bar + 3) f.push_back(trimmed(line.substr(at, bar - at)));
  f.push_back(trimmed(line.substr(at)));
  const std::string form = "\"Gap: <claim> | <quantity> | text <number> (<the text's words>) | <toolkit> -> <with the cause> | <source>\"";
  if (f.size() != 5 || f[0].empty() || f[1].empty() || f[4].empty()) throw std::runtime_error(where + "a Gap: line has the form " + form);
  CauseGap g;
  g.claim = f[0], g.quantity = f[1], g.source = f[4];
  std::size_t used = 0;
  try {
    if (f[2].rfind("text ", 0) != 0) throw std::invalid_argument("no text");
    g.text = std::stod(f[2].substr(5), &used);
  } catch (const std::exception&) {
    throw std::runtime_error(where + "the third field of a Gap: line is \"text <number> (<the text's words>)\", not \"" + f[2] + "\"");
  }
  g.text_words = trimmed(f[2].substr(5 + used));
  if (g.text_words.size() < 3 || g.text_words.front() != '(' || g.text_words.back() != ')')
    throw std::runtime_error(where + "the text's value in a Gap: line needs the text's words in parentheses: \"" + f[2] + "\"");
  g.text_words = g.text_words.substr(1, g.text_words.size() - 2);
  const std::size_t arrow = f[3].find(" -> ");
  if (arrow == std::string::npos || f[3].front() != '{' || f[3].back() != '}')
    throw std::runtime_error(where + "the fourth field of a Gap: line is \"{toolkit} -> {with the cause}\", not \"" + f[3] + "\"");
  g.toolkit = trimmed(f[3].substr(0, arrow)), g.with_cause = trimmed(f[3].substr(arrow + 4));
  return g;
}

}  // namespace

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
      if (d && d->claims.empty() && d->unlinked.empty()) throw std::runtime_error(where() + "the cause before has no Gap: lines nor \"Claims: none (why)\"");
      out.push_back({line.substr(3), "", "", {}, {}, ""});
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
      throw std::runtime_error(where() + "\"" + d->topic + "\" links claims without a Gap: line each (how much of the claim's gap a shipped probe finds the cause closes)");
    } else if (line.rfind("Gap: ", 0) == 0 && !d->affects.empty() && d->unlinked.empty()) {
      d->gaps.push_back(parse_gap(line, where()));
      for (const auto& key : d->claims)
        if (key == d->gaps.back().claim) throw std::runtime_error(where() + "a second Gap: line for " + key);
      d->claims.push_back(d->gaps.back().claim);
    } else if (!d->affects.empty()) {
      throw std::runtime_error(where() + "text after the Moves: line of \"" + d->topic + "\"");
    } else {
      d->text += (d->text.empty() ? "" : " ") + line;
    }
  }
  if (d && d->affects.empty()) throw std::runtime_error(where() + "the last cause has no Moves: line");
  if (d && d->claims.empty() && d->unlinked.empty()) throw std::runtime_error(where() + "the last cause has no Gap: lines nor \"Claims: none (why)\"");
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

std::string known_deviations_markdown(const DissertationResults& results, const std::vector<CauseGrade>& grades) {
  std::string s;
  const auto& all = known_deviations();
  for (std::size_t i = 0; i < all.size(); ++i) {
    std::string closes;
    for (const auto& g : grades)
      if (g.cause == i + 1) closes += std::string(closes.empty() ? "" : "; ") + anchor_link(g.gap.claim, claim_anchor(g.gap.claim)) + ": " + grade_sentence(g);
    s += "- <a id=\"" + cause_anchor(i + 1) + "\"></a>**" + cause_label(i + 1) + " " + all[i].topic + ".** " + all[i].text +
         " *Moves:* " + all[i].affects + "." +
         (all[i].unlinked.empty() ? std::string() : " *Linked from no claim:* " + all[i].unlinked + ".") +
         (closes.empty() ? std::string() : " *Measured on the claims it is linked from:* " + closes + ".") + "\n";
  }
  return fill_measured_numbers(s, results, false);
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
