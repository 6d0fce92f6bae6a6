#include "analysis/fit/pareto.hpp"

#include <algorithm>
#include <cmath>

namespace capsule::analysis {

namespace {
bool usable(const CostError& p) { return std::isfinite(p.cost) && std::isfinite(p.error); }
bool dominates(const CostError& a, const CostError& b) {
  return a.cost <= b.cost && a.error <= b.error && (a.cost < b.cost || a.error < b.error);
}
}  // namespace

std::vector<std::size_t> pareto_front(const std::vector<CostError>& points) {
  std::vector<std::size_t> front;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!usable(points[i])) continue;
    bool dominated = false;
    for (std::size_t j = 0; j < points.size() && !dominated; ++j)
      dominated = j != i && usable(points[j]) && dominates(points[j], points[i]);
    if (!dominated) front.push_back(i);
  }
  std::stable_sort(front.begin(), front.end(), [&](std::size_t a, std::size_t b) {
    if (points[a].cost != points[b].cost) return points[a].cost < points[b].cost;
    return points[a].error < points[b].error;
  });
  return front;
}

std::optional<std::size_t> cheapest_within(const std::vector<CostError>& points, double bound) {
  std::optional<std::size_t> best;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const CostError& p = points[i];
    if (!usable(p) || p.error > bound) continue;
    if (!best || p.cost < points[*best].cost || (p.cost == points[*best].cost && p.error < points[*best].error))
      best = i;
  }
  return best;
}

}  // namespace capsule::analysis
