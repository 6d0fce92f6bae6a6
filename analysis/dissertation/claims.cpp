#include "analysis/dissertation/claims.hpp"

#include <map>
#include <stdexcept>

#include "analysis/dissertation/claim_texts.hpp"
#include "analysis/dissertation/claims/registry.hpp"

namespace capsule::analysis {

using namespace claims;

namespace {

// The registry and claims.md agree (every rule has words, every worded claim a rule), or a
// std::logic_error says where they do not.
void check_registry() {
  std::vector<std::string> registered, worded;
  for (const auto& c : claim_registry()) registered.push_back(c.key);
  for (const auto& t : claim_texts()) worded.push_back(t.key);
  std::string problems;
  for (const auto& m : registry_mismatches(registered, worded)) problems += (problems.empty() ? "" : "; ") + m;
  if (!problems.empty()) throw std::logic_error("the claim registry and claims.md disagree: " + problems);
}

}  // namespace

std::vector<ClaimResult> evaluate_claims(const DissertationResults& res) {
  check_registry();
  std::map<std::string, const RegisteredClaim*> rules;
  for (const auto& c : claim_registry()) rules[c.key] = &c;
  std::vector<ClaimResult> out;
  res.take_campaigns_read();
  for (const ClaimText& text : claim_texts()) {
    for (const RowRule& rule : rules.at(text.key)->rows) {
      ClaimResult r = rule(res);
      if (r.key != text.key)
        throw std::logic_error("the rule registered as claim '" + text.key + "' judged the claim '" + r.key + "'");
      // Whether a campaign the row's rule read ships some point at two levels.
      for (const std::string& name : res.take_campaigns_read()) r.several_levels = r.several_levels || res.campaign(name).several_levels;
      res.take_campaigns_read();
      out.push_back(std::move(r));
    }
  }
  return out;
}

std::vector<ClaimResult> combine_levels(std::vector<ClaimResult> fine, const std::vector<ClaimResult>& coarse) {
  if (fine.size() != coarse.size()) throw std::logic_error("combine_levels: the two levels give different numbers of rows");
  for (std::size_t i = 0; i < fine.size(); ++i) {
    ClaimResult& f = fine[i];
    const ClaimResult& c = coarse[i];
    if (f.key != c.key) throw std::logic_error("combine_levels: row " + std::to_string(i) + " is " + f.key + " and " + c.key);
    if (!f.several_levels) {
      f.levels = Levels::one_level;
      continue;
    }
    f.coarse_measured = std::string(verdict_text(c.verdict)) + ": " + c.measured;
    if (f.verdict == Verdict::cannot_tell) {
      f.levels = Levels::not_judged;
    } else if (c.verdict == f.verdict) {
      f.levels = Levels::converged;
    } else {
      f.levels = Levels::not_converged;
      f.measured = "cannot tell: not converged (finest level " + std::string(verdict_text(f.verdict)) + ", next coarser level " +
                   verdict_text(c.verdict) + "); finest: " + f.measured + "; next coarser: " + c.measured;
      f.verdict = Verdict::cannot_tell;
    }
  }
  return fine;
}

std::vector<ClaimResult> evaluate_claims_at_two_levels(const DissertationResults& finest) {
  return combine_levels(evaluate_claims(finest), evaluate_claims(DissertationResults(finest.results_dir(), 1)));
}

const char* levels_text(Levels l) {
  switch (l) {
    case Levels::one_level: return "one level";
    case Levels::converged: return "converged";
    case Levels::not_converged: return "not converged";
    case Levels::not_judged: return "";
  }
  return "";
}

std::vector<std::pair<std::string, ClaimVerdict>> claim_verdicts(const std::vector<ClaimResult>& rows) {
  std::vector<std::pair<std::string, ClaimVerdict>> out;
  for (std::size_t i = 0; i < rows.size();) {
    std::size_t agree = 0, differ = 0, open = 0, j = i;
    for (; j < rows.size() && rows[j].key == rows[i].key; ++j)
      ++(rows[j].verdict == Verdict::agrees ? agree : rows[j].verdict == Verdict::differs ? differ : open);
    const std::size_t n = j - i;
    out.emplace_back(rows[i].key, agree == n    ? ClaimVerdict::agrees
                                  : differ == n ? ClaimVerdict::differs
                                  : open == n   ? ClaimVerdict::cannot_tell
                                                : ClaimVerdict::in_part);
    i = j;
  }
  return out;
}

const char* claim_verdict_text(ClaimVerdict v) {
  switch (v) {
    case ClaimVerdict::agrees: return "agrees";
    case ClaimVerdict::differs: return "differs";
    case ClaimVerdict::in_part: return "in part";
    case ClaimVerdict::cannot_tell: return "cannot tell";
  }
  return "cannot tell";
}

const char* text_passes_text(TextPasses t) {
  switch (t) {
    case TextPasses::yes: return "yes";
    case TextPasses::no: return "no";
    case TextPasses::no_numbers: return "no numbers";
  }
  return "no numbers";
}

std::vector<std::pair<std::string, TextPasses>> claim_text_passes(const std::vector<ClaimResult>& rows) {
  std::vector<std::pair<std::string, TextPasses>> out;
  for (std::size_t i = 0; i < rows.size();) {
    TextPasses t = TextPasses::no_numbers;
    std::size_t j = i;
    for (; j < rows.size() && rows[j].key == rows[i].key; ++j) {
      if (rows[j].text_passes == TextPasses::no) t = TextPasses::no;
      else if (rows[j].text_passes == TextPasses::yes && t == TextPasses::no_numbers) t = TextPasses::yes;
    }
    out.emplace_back(rows[i].key, t);
    i = j;
  }
  return out;
}

std::string claim_chapter(const ClaimResult& row) { return row.section.substr(0, row.section.find('.')); }

}  // namespace capsule::analysis
