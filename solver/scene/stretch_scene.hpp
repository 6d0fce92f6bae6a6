#pragma once
// A scene's stretch protocol (protocol.stretch, docs/guide/scenes.md "Stretching"): reading it,
// with its refusals, and writing it into the canonical scene.
#include <nlohmann/json.hpp>
#include <string>

#include "solver/scene/scene.hpp"

namespace capsule {

// Reads protocol.stretch of `scene` (its dim, law and physical block already read): the load,
// and into `phase` the rule that ends the loading (until time or steady D_axial). Throws
// SceneError naming `source`, the key and the allowed range.
StretchLoad read_stretch(const nlohmann::json& stretch, const std::string& source, const Scene& scene,
                         PhaseSpec& phase);

// The canonical protocol.stretch object: the load as given and the loading phase's rule.
nlohmann::json stretch_json(const StretchLoad& load, const PhaseSpec& phase);

// F / (E_s a) of a force in pN on the scene's physical cell (E_s of (34), a its radius).
double dimensionless_force(const Scene& scene, double force_pN);

}  // namespace capsule
