#pragma once
// `capsule bench member3d`: milliseconds per step of the default 3D member, by part.
namespace capsule {
int bench_member3d(bool quick, int max_threads);
}
