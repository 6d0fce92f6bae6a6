#pragma once
// `capsule bench member3d`: milliseconds per step of the default 3D member, by part.
namespace capsule {
// a, mesh_level: the member's resolution (the default member: a = 10, level 4); a finer
// member shows what a step costs there (docs/findings/performance.md "Finer members").
int bench_member3d(bool quick, int max_threads, int a = 10, int mesh_level = 4, bool refined_only = false);
}
