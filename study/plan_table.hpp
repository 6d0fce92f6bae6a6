#pragma once
// `study plan`: one line per member (index, state, directory, swept parameters, cost)
// and the totals. Changes nothing. Members are expanded, inspected and printed one at a
// time (for_each_member), so a 10^6-member grid plans in bounded memory.
#include <ostream>

#include "study/campaign.hpp"
#include "study/results_layout.hpp"

namespace capsule::study {

void print_plan(const Campaign& campaign, const ResultsLayout& layout, std::ostream& out);

}  // namespace capsule::study
