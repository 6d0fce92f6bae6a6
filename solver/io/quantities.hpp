#pragma once
// What every quantity a member file holds means: one row per series, marker and shape dataset, with its
// units and a description (docs/guide/member-files.md "Units and descriptions"). The writer
// attaches them as the attributes `units` and `description`; the Python package
// (python/capsule_study/quantities.py) keeps the same table for files written before.
#include <string>
#include <vector>

namespace capsule::io {

struct Quantity {
  const char* name;
  const char* units;        // "1" for a pure number; "1/k" time, "a" length, "E_s", "lattice" ...
  const char* description;  // one sentence, with the dissertation's equation where there is one
};

// Every series under /series (2D and 3D, beta included).
const std::vector<Quantity>& series_quantities();
// Every marker under /markers.
const std::vector<Quantity>& marker_quantities();
// The datasets under /shapes: "positions" (each /shapes/NNNN) and "triangles".
const std::vector<Quantity>& shape_quantities();

// The row for `name` in a table; throws std::logic_error naming the quantity when it has none,
// so that no quantity is written without its units.
const Quantity& quantity(const std::vector<Quantity>& table, const std::string& name);

}  // namespace capsule::io
