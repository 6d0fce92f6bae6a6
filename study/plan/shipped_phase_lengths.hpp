#pragma once
// The phase lengths of the toolkit's own shipped members (results/), built into `study` from
// study/plan/shipped_phase_lengths.json, which scripts/update-phase-table writes from the
// shipped member files: a JSON array of {campaign, scene (the keys the distance reads),
// shear_kt, recover_kt}. A results folder with no finished neighbours still gets phase
// lengths from the nearest shipped physics (docs/guide/running.md "Time and memory estimates").
namespace capsule::study {

const char* shipped_phase_lengths_json();

}  // namespace capsule::study
