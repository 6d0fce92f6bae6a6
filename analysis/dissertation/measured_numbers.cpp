#include "analysis/dissertation/measured_numbers.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "analysis/compare/bilinear_entries.hpp"
#include "analysis/dissertation/rules.hpp"
#include "analysis/report/report_context.hpp"

namespace capsule::analysis {

namespace {

std::vector<std::string> split(const std::string& s, char by) {
  std::vector<std::string> out;
  std::string part;
  std::istringstream in(s);
  while (std::getline(in, part, by)) out.push_back(part);
  return out;
}

const DissertationMember& member_of(const DissertationCampaign& c, const std::string& slug, const std::string& spec) {
  for (const auto& m : c.members)
    if (m.slug == slug) return m;
  throw std::runtime_error("{" + spec + "}: campaign " + c.name + " has no member " + slug);
}

const DissertationCampaign& campaign_of(const DissertationResults& results, const std::string& name, const std::string& spec) {
  const DissertationCampaign& c = results.campaign(name);
  if (!c.found) throw std::runtime_error("{" + spec + "}: " + c.missing);
  return c;
}

double fitted(const DissertationMember& m, const std::string& column, const std::string& spec) {
  const ColumnValue v = column_value(m.fits, column);
  if (!v.parameter) throw std::runtime_error("{" + spec + "}: " + m.slug + " has no " + column + " (" + v.reason + ")");
  return v.parameter->value;
}

// Least-squares slope and intercept of y against x (exact through two points).
std::pair<double, double> line(const std::vector<double>& x, const std::vector<double>& y) {
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < x.size(); ++i) mx += x[i], my += y[i];
  mx /= double(x.size()), my /= double(y.size());
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < x.size(); ++i) sxy += (x[i] - mx) * (y[i] - my), sxx += (x[i] - mx) * (x[i] - mx);
  const double slope = sxy / sxx;
  return {slope, my - slope * mx};
}

// {bilinear campaign/target/coefficient/level}: the first (finest) fit of the target, or its extrapolation.
double bilinear_coefficient(const DissertationCampaign& c, const std::vector<std::string>& parts, const std::string& spec) {
  const bool extrapolated = parts[3] == "extrapolated";
  if (!extrapolated && parts[3] != "finest") throw std::runtime_error("{" + spec + "}: level " + parts[3] + " is neither finest nor extrapolated");
  for (const BilinearEntry& e : read_bilinear_entries(c.name, c.fits)) {
    if (e.target != parts[1]) continue;
    const auto coefficient = [&](const std::string& name) {
      if (extrapolated) {
        const auto x = e.ladder_extrapolated.find(name);
        if (x == e.ladder_extrapolated.end() || !std::isfinite(x->second))
          throw std::runtime_error("{" + spec + "}: " + c.name + " has no extrapolation of " + name + " for " + parts[1]);
        return x->second;
      }
      if (!e.fit.ok) throw std::runtime_error("{" + spec + "}: the bilinear fit of " + parts[1] + " failed");
      for (const auto& p : e.fit.parameters)
        if (p.name == name) return p.value;
      throw std::runtime_error("{" + spec + "}: the bilinear fit has no coefficient " + name);
    };
    if (parts[2] == "b_over_a") return coefficient("b") / coefficient("a");
    return coefficient(parts[2]);
  }
  throw std::runtime_error("{" + spec + "}: " + c.name + " has no bilinear fit of " + parts[1]);
}

// {at campaign/slug/series/kt}: the member file's series at kt (or at its marker t_stop).
double series_at(const DissertationResults& results, const DissertationMember& m, const std::vector<std::string>& parts,
                 const std::string& spec) {
  std::string why;
  const auto data = results.member_data(m, why);
  if (!data) throw std::runtime_error("{" + spec + "}: " + why);
  const auto kt = data->series.find("kt"), y = data->series.find(parts[2]);
  if (kt == data->series.end() || y == data->series.end()) throw std::runtime_error("{" + spec + "}: " + m.slug + " records no " + parts[2]);
  double at = std::nan("");
  if (parts[3] == "stop") {
    const auto t = data->markers.find("t_stop");
    if (t != data->markers.end()) at = t->second;
  } else {
    at = std::stod(parts[3]);
  }
  if (!std::isfinite(at) || at < kt->second.front() || at > kt->second.back())
    throw std::runtime_error("{" + spec + "}: kt " + parts[3] + " is outside " + m.slug + "'s series");
  return interpolate_series(kt->second, y->second, at);
}

}  // namespace

double measured_number(const DissertationResults& results, const std::string& spec) {
  const std::size_t blank = spec.find(' ');
  const std::string kind = spec.substr(0, blank);
  const auto parts = split(blank == std::string::npos ? "" : spec.substr(blank + 1), '/');
  if ((kind == "fit" || kind == "r2") && parts.size() == 3) {
    const DissertationMember& m = member_of(campaign_of(results, parts[0], spec), parts[1], spec);
    if (kind == "fit") return fitted(m, parts[2], spec);
    const auto f = m.fits.find(parts[2]);
    if (f == m.fits.end() || !f->second.ok) throw std::runtime_error("{" + spec + "}: " + m.slug + " has no fit " + parts[2]);
    return f->second.r_squared;
  }
  if ((kind == "intercept" || kind == "slope" || kind == "exponent") && parts.size() == 4) {
    const DissertationCampaign& c = campaign_of(results, parts[0], spec);
    std::vector<double> x, y;
    for (const auto& slug : split(parts[3], '+')) {
      const DissertationMember& m = member_of(c, slug, spec);
      const auto p = m.parameters.find(parts[2]);
      if (p == m.parameters.end()) throw std::runtime_error("{" + spec + "}: " + slug + " records no " + parts[2]);
      x.push_back(kind == "exponent" ? std::log(p->second) : p->second);
      const double v = fitted(m, parts[1], spec);
      y.push_back(kind == "exponent" ? std::log(v) : v);
    }
    if (x.size() < 2) throw std::runtime_error("{" + spec + "}: a line needs two members or more");
    const auto [slope, intercept] = line(x, y);
    return kind == "intercept" ? intercept : slope;
  }
  if (kind == "bilinear" && parts.size() == 4) return bilinear_coefficient(campaign_of(results, parts[0], spec), parts, spec);
  if (kind == "at" && parts.size() == 4)
    return series_at(results, member_of(campaign_of(results, parts[0], spec), parts[1], spec), parts, spec);
  throw std::runtime_error("{" + spec + "}: not a measured-number placeholder (fit, r2: campaign/slug/column; intercept, slope, "
                           "exponent: campaign/column/x/slug+slug; bilinear: campaign/target/coefficient/level; at: campaign/slug/series/kt)");
}

std::string fill_measured_numbers(const std::string& text, const DissertationResults& results, bool strict) {
  static const char* const kinds[] = {"fit ", "r2 ", "intercept ", "slope ", "exponent ", "bilinear ", "at "};
  std::string out;
  std::size_t at = 0;
  while (true) {
    const std::size_t open = text.find('{', at);
    if (open == std::string::npos) break;
    const std::size_t close = text.find('}', open);
    bool placeholder = false;
    for (const char* k : kinds) placeholder = placeholder || text.compare(open + 1, std::string(k).size(), k) == 0;
    if (!placeholder || close == std::string::npos) {
      out += text.substr(at, open + 1 - at);
      at = open + 1;
      continue;
    }
    const std::string spec = text.substr(open + 1, close - open - 1);
    std::string number;
    try {
      number = short_number(measured_number(results, spec));
    } catch (const std::runtime_error& e) {
      if (strict) throw;
      const std::string why = e.what();
      number = "[not measured: " + why.substr(why.find("}: ") == std::string::npos ? 0 : why.find("}: ") + 3) + "]";
    }
    out += text.substr(at, open - at) + number;
    at = close + 1;
  }
  return out + text.substr(at);
}

}  // namespace capsule::analysis
