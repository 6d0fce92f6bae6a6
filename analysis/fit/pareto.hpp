#pragma once
// Accuracy against cost: the non-dominated (Pareto) settings and the cheapest setting
// whose error stays within a bound.
#include <cstddef>
#include <optional>
#include <vector>

namespace capsule::analysis {

struct CostError {
  double cost = 0.0;   // core-seconds
  double error = 0.0;  // relative error against the reference, >= 0
};

// Indices of the points no other point dominates (cost <= and error <= with one of them
// strictly smaller), ordered by cost then error. Points with a non-finite cost or error
// take no part. Two identical points are both kept.
std::vector<std::size_t> pareto_front(const std::vector<CostError>& points);

// The cheapest point with error <= bound (ties: the smaller error, then the first), if any.
std::optional<std::size_t> cheapest_within(const std::vector<CostError>& points, double bound);

}  // namespace capsule::analysis
