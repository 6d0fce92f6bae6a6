#include "analysis/dissertation/cause_grades.hpp"

#include <cmath>
#include <stdexcept>

#include "analysis/dissertation/measured_numbers.hpp"
#include "analysis/dissertation/rules.hpp"

namespace capsule::analysis {

double gap_fraction(double toolkit, double with_cause, double text) {
  if (text == toolkit) return std::nan("");
  return (with_cause - toolkit) / (text - toolkit);
}

double gap_side_value(const DissertationResults& results, const std::string& side) {
  const auto inside = [&side](std::size_t open, std::size_t close) {
    if (open == std::string::npos || close == std::string::npos || side[open] != '{' || side[close] != '}')
      throw std::runtime_error("\"" + side + "\": a Gap: side is \"{placeholder}\" or \"{placeholder} / {placeholder}\"");
    return side.substr(open + 1, close - open - 1);
  };
  const std::size_t divide = side.find("} / {");
  if (divide == std::string::npos) return measured_number(results, inside(0, side.size() - 1));
  return measured_number(results, inside(0, divide)) / measured_number(results, inside(divide + 4, side.size() - 1));
}

std::vector<CauseGrade> grade_causes(const DissertationResults& results) {
  std::vector<CauseGrade> out;
  const auto& all = known_deviations();
  for (std::size_t i = 0; i < all.size(); ++i)
    for (const auto& gap : all[i].gaps) {
      CauseGrade g;
      g.cause = i + 1;
      g.gap = gap;
      try {
        g.toolkit = gap_side_value(results, gap.toolkit);
        g.with_cause = gap_side_value(results, gap.with_cause);
        g.fraction = gap_fraction(g.toolkit, g.with_cause, gap.text);
        g.measured = true;
      } catch (const std::runtime_error& e) {
        g.why = e.what();
      }
      out.push_back(g);
    }
  return out;
}

std::vector<const CauseGrade*> grades_of_claim(const std::vector<CauseGrade>& grades, const std::string& claim_key) {
  std::vector<const CauseGrade*> out;
  for (const auto& g : grades)
    if (g.gap.claim == claim_key) out.push_back(&g);
  return out;
}

bool explains(const CauseGrade& g) { return g.measured && std::isfinite(g.fraction) && g.fraction >= k_explains_share; }

namespace {
std::string percent(double fraction) { return short_number(std::round(100.0 * fraction)) + " %"; }
}  // namespace

std::string closes_percent(const CauseGrade& g) {
  if (!g.measured) return "not measured";
  if (!std::isfinite(g.fraction)) return "no gap";
  return percent(g.fraction);
}

std::string closes_text(const CauseGrade& g) {
  if (!g.measured) return "not measured";
  if (!std::isfinite(g.fraction)) return "no gap to close";
  if (g.fraction < 0.0) return "widens the gap (" + percent(g.fraction) + ")";
  if (g.fraction > 1.0) return "closes " + percent(g.fraction) + " of the gap (past the text)";
  if (g.fraction < k_explains_share) return "closes only " + percent(g.fraction) + " of the gap";
  return "closes " + percent(g.fraction) + " of the gap";
}

std::string grade_sentence(const CauseGrade& g) {
  std::string s = closes_text(g) + " in " + g.gap.quantity;
  if (g.measured)
    s += ": " + short_number(g.toolkit) + " -> " + short_number(g.with_cause) + " with the cause, the text " +
         short_number(g.gap.text) + " (" + g.gap.text_words + ")";
  else
    s += " (" + g.why + ")";
  return s + "; " + g.gap.source;
}

}  // namespace capsule::analysis
