#pragma once
// Whether a process of this host is alive. A zombie is dead: a killed capsule whose parent died
// too may stay one for good where PID 1 does not reap (containers), and kill(pid, 0) still
// succeeds on it.
namespace capsule::study {

bool process_alive(long pid);

// When a process of this host started, in clock ticks since boot (field 22 of /proc/PID/stat):
// with the pid it names one process, since a pid is reused only by a process started later.
// -1 when unknown (no such process, no /proc).
long long process_start_ticks(long pid);

// Seconds since the process started (from /proc/uptime and its start ticks); < 0 when unknown.
double process_age_seconds(long pid);

}  // namespace capsule::study
