#pragma once
// Hooke's law, the 2D membrane's elastic tension (Sec. 2.4) of a segment of stretch
// lambda = l / l0 (29):
//   tau_e = E_s (lambda - 1)                                          (30)
#include "solver/membrane2d/laws/tension_law.hpp"

namespace capsule::membrane2d {

struct Hooke {
  double E_s = 0;  // shear elasticity modulus (30)

  double tension(double lambda) const { return E_s * (lambda - 1.0); }
};
static_assert(TensionLaw<Hooke>);

}  // namespace capsule::membrane2d
