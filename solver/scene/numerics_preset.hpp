#pragma once
// The scene key `numerics`: "toolkit" (the default: this solver's numerics, measured in
// docs/findings) or "dissertation", which makes a scene run as the dissertation ran (Sec. 2.1-2.6:
// its delta, rates, markers, Reynolds number, lattice and the printed readings of its groups).
// The preset sets defaults only: a key the scene gives itself wins, so one item at a time can be
// switched back to the toolkit's choice (docs/guide/dissertation_numerics.md). Every item, and
// every part of the text that is not emulated with the choice made and why, is listed here once;
// the reader (scene.cpp), the member file (run_member.cpp) and the guide use this list.
#include <string>
#include <vector>

#include "solver/common/name_table.hpp"
#include "solver/scene/choices.hpp"

namespace capsule {

enum class Numerics { toolkit, dissertation };
inline constexpr NameTable<Numerics, 2> numerics_names{
    {{Numerics::toolkit, "toolkit"}, {Numerics::dissertation, "dissertation"}}};
constexpr const auto& name_table(Numerics) { return numerics_names; }

// One item of the preset: the scene key, the value the preset gives it in this dimension, and
// where in the text that value comes from.
struct NumericsItem {
  std::string key;
  std::string value;
  std::string source;
};

// The items the preset sets for a scene of this dimension and shape (a 2D biconcave capsule
// has one more: the size of (24)-(25)).
std::vector<NumericsItem> dissertation_numerics_items(int dim, Shape shape);

// What the text ran that the preset does not reproduce: the part, the choice made, and why.
struct NumericsGap {
  std::string part;
  std::string choice;
  std::string why;
};
std::vector<NumericsGap> dissertation_numerics_gaps(int dim);

// The defaults a scene of this dimension gets under the preset: the version-6 defaults with the
// text's delta, rates, precision, power-law model and marker inset.
SceneDefaults dissertation_scene_defaults(int dim, Shape shape);

// The text's capsule radius in its units: 0.5 for the 2D biconcave capsule (Sec. 2.4, printed),
// 1 for the sphere (Sec. 2.6, printed) and the 2D circle (not printed: the only reading under
// which the text's cosine delta (18) gives back its own 2D validation, probe_cosine_lattice_2d;
// docs/guide/dissertation_numerics.md "The 2D lattice").
double dissertation_radius(int dim, Shape shape);

// The lattice radius a = radius / h (Sec. 2: h = 0.05 in 2D, 0.1 in 3D): 2D circle 20, 2D
// biconcave 10, 3D 10.
double dissertation_lattice_a(int dim, Shape shape);

// The text's Reynolds number rho k a / mu_a = 0.05 (Sec. 2) in the toolkit's k a^2 / nu: the
// text's lengths are in its own units, so k a^2 / nu = 0.05 times its radius: 0.025 for the 2D
// biconcave capsule, 0.05 for the circle and in 3D.
double dissertation_Re(int dim, Shape shape);

// The items and gaps as lines "key = value: source" / "part: choice (why)", for the member file.
std::vector<std::string> numerics_item_lines(int dim, Shape shape);
std::vector<std::string> numerics_gap_lines(int dim);

}  // namespace capsule
