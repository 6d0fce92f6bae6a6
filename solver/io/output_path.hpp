#pragma once
// Checks `capsule -o PATH` before the first step: a folder, a missing folder, or one that
// cannot be written would otherwise fail only when the member file is first written (or,
// for a folder, after the whole run).
#include <string>

namespace capsule::io {

// "" when PATH can be written as a member file (and PATH.partial beside it); else one
// line naming the path and the problem.
std::string output_path_problem(const std::string& path);

}  // namespace capsule::io
