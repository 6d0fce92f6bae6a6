#pragma once
// The 2D membrane's elastic law (the scene's `law` in 2D) and the one switch from it to the
// law's formulas (laws/hooke.hpp, a TensionLaw). A new law: its file in laws/, a value here, a
// case in visit_law.
#include <stdexcept>
#include <utility>

#include "solver/membrane2d/laws/hooke.hpp"

namespace capsule::membrane2d {

enum class ElasticLaw { hooke };

// Calls f with the law's formulas for the shear elasticity modulus E_s: the one switch over
// the laws (a loop over segments calls it once, outside the loop).
template <class F>
decltype(auto) visit_law(ElasticLaw law, double E_s, F&& f) {
  switch (law) {
    case ElasticLaw::hooke: return std::forward<F>(f)(Hooke{E_s});
  }
  throw std::logic_error("membrane2d: an elastic law without formulas");
}

}  // namespace capsule::membrane2d
