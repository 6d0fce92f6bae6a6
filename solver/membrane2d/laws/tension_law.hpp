#pragma once
// What every 2D membrane law provides (Sec. 2.4): the elastic in-plane tension tau_e of a
// segment from its stretch lambda = l / l0 (29), the elastic part of tau = tau_e + tau_v (28).
// One law per file beside this one; solver/membrane2d/elastic_law.hpp picks one by name, once.
#include <concepts>

namespace capsule::membrane2d {

template <class Law>
concept TensionLaw = requires(const Law law, double lambda) {
  { law.tension(lambda) } -> std::same_as<double>;
};

}  // namespace capsule::membrane2d
