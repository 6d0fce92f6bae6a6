#pragma once
// Whether a process of this host is alive. A zombie is dead: a killed capsule whose parent died
// too may stay one for good where PID 1 does not reap (containers), and kill(pid, 0) still
// succeeds on it.
namespace capsule::study {

bool process_alive(long pid);

}  // namespace capsule::study
