#!/usr/bin/env bash
# Clusters for real: a one-node Slurm (munged, slurmctld, slurmd) and a local sshd, started by
# scripts/cluster/cluster-daemons, run small 2D campaigns through `study export --slurm` and
# `study run --hosts`, and check what a cluster user relies on: every member completes, bitwise
# as a local run; a stale resubmission reruns nothing; a task cancelled while it runs continues
# from its restart point when submitted again; an export of 1100 members is accepted by Slurm and
# its held tasks are queued for `study status`; a dead SSH host loses no member. Daemons are
# stopped by pid at the end, whatever happened. Needs root (CI is) and the build in build/.
# Prints "N passed, M failed" last; exits 1 when anything failed or the daemons would not start
# (never a silent pass).
set -uo pipefail
cd "$(dirname "$0")/../.."
top=$PWD
daemons=$top/scripts/cluster/cluster-daemons
study=$top/build/study/study
export CAPSULE_BIN=$top/build/solver/capsule
export STUDY_ALLOW_DIRTY=1  # as in the unit tests: a developer's tree may hold uncommitted changes
py=/usr/bin/python3         # Debian's, with h5py (scripts/install-deps)
state=$(mktemp -d /tmp/capsule-cluster-state.XXXXXX)
work=$(mktemp -d /tmp/capsule-cluster-work.XXXXXX)
passed=0
failed=0
check() {  # check WHAT COMMAND...: one test row
  local what=$1
  shift
  if "$@"; then
    passed=$((passed + 1))
    echo "ok: $what"
  else
    failed=$((failed + 1))
    echo "FAILED: $what"
  fi
}
finish() {
  "$daemons" down "$state" >/dev/null 2>&1 || true
  echo "cluster tests: $passed passed, $failed failed"
  echo "$passed passed, $failed failed"
  [ -n "${CLUSTER_KEEP_WORK:-}" ] && echo "work folder kept: $work" || rm -rf "$work"
  [ "$failed" -eq 0 ]
}
trap 'finish; exit $?' EXIT

[ -x "$study" ] && [ -x "$CAPSULE_BIN" ] || { echo "no build in $top/build: run scripts/test first"; failed=1; exit 1; }
started=$(date +%s)
if ! "$daemons" up "$state"; then
  echo "FAILED: the Slurm and sshd daemons did not start (see above)"
  failed=$((failed + 1))
  exit 1
fi
eval "$("$daemons" env "$state")"
echo "daemons up in $(($(date +%s) - started)) s"
cd "$work"
export CLUSTER_KEEP_WORK=${CLUSTER_KEEP_WORK:-}

campaign() {  # campaign FILE NAME SHEAR_KT RECOVER_KT CA...: tiny 2D members (a = 4, 32 segments)
  local file=$1 name=$2 kt=$3 recover=$4
  shift 4
  local list
  list=$(printf '%s,' "$@")
  cat >"$file" <<JSON
{"name": "$name", "description": "cluster test",
 "base": {"dim": 2, "shape": "circle", "Ca": 0.05, "E_b": 0.0, "V": 1.0, "eta": 0.0,
          "resolution": {"a": 4, "segments": 32},
          "protocol": {"shear": {"until": "time", "kt": $kt}, "recover": {"until": "time", "kt": $recover}},
          "output": {"interval_kt": 0.1}},
 "sweep": {"grid": {"Ca": [${list%,}]}}}
JSON
}
same_series() {  # same_series DIR_A DIR_B: every member's /series bitwise equal
  "$py" - "$1" "$2" <<'PY'
import sys, glob, os, h5py, numpy as np
a, b = sys.argv[1], sys.argv[2]
members = sorted(os.path.basename(d) for d in glob.glob(os.path.join(a, "members", "*")))
assert members, "no members in " + a
for m in members:
    with h5py.File(os.path.join(a, "members", m, "member.h5")) as fa, h5py.File(os.path.join(b, "members", m, "member.h5")) as fb:
        assert sorted(fa["series"]) == sorted(fb["series"]), m
        for k in fa["series"]:
            assert np.array_equal(fa["series"][k][:], fb["series"][k][:], equal_nan=True), (m, k)
PY
}
status_is() {  # status_is RESULTS CAMPAIGN EXIT: `study status` exits EXIT
  "$study" status "$2" --results "$1" >/dev/null
  [ $? -eq "$3" ]
}
wait_until() {  # wait_until SECONDS COMMAND...
  local end=$(($(date +%s) + $1))
  shift
  until "$@"; do
    [ "$(date +%s)" -lt "$end" ] || return 1
    sleep 0.5
  done
}
no_jobs() { [ -z "$(squeue --noheader --me --states=PENDING,RUNNING,CONFIGURING,COMPLETING,SUSPENDED 2>/dev/null)" ]; }
# sbatch --wait polls at 2, 10, 42 s: submitting and polling squeue is faster.
submit_and_wait() {  # submit_and_wait SECONDS COMMAND...: the command submits; wait until no job is left
  local seconds=$1
  shift
  "$@" >/dev/null && wait_until "$seconds" no_jobs
}

# --- Slurm: a campaign runs to completion, bitwise as a local run -------------------------------
campaign tiny.json tiny 1 1 0.01 0.02 0.03
"$study" run tiny.json --results local >/dev/null
"$study" export tiny.json --slurm --results slurm >/dev/null
cp slurm/tiny/slurm/capsule.sbatch old.sbatch
check "the exported array is accepted and runs to the end" submit_and_wait 180 sh slurm/tiny/slurm/submit.sh
check "every member complete after the Slurm run" status_is slurm tiny.json 0
check "Slurm's members are bitwise the local run's" same_series local/tiny slurm/tiny
check "every Slurm task appended a record to runs.jsonl" test "$(grep -c '"engine":"slurm"' slurm/tiny/runs.jsonl)" -eq 3
check "each task wrote its own output file, naming its member" test "$(ls slurm/tiny/slurm/task-*_*.out | wc -l)" -eq 3

# --- A stale resubmission reruns nothing ---------------------------------------------------------
before=$(md5sum slurm/tiny/members/*/member.h5)
check "the old script, submitted again, is accepted" submit_and_wait 180 sbatch "$work/old.sbatch"
check "it rewrote no member file" test "$before" = "$(md5sum slurm/tiny/members/*/member.h5)"
check "its tasks said the members were complete" test "$(cat slurm/tiny/slurm/task-*.out | grep -c 'is complete: nothing run')" -eq 3

# --- A task cancelled while it runs continues from its restart point -----------------------------
campaign long.json long 1 300 0.05  # about 30 s, most of it recovering
"$study" export long.json --slurm --results slurm >/dev/null
job=$(sbatch --parsable slurm/long/slurm/capsule.sbatch)
member=$(ls -d slurm/long/members/*)
check "the long member starts running" wait_until 60 test -f "$member/member.h5.progress"
sleep 1
scancel "$job"
check "the cancelled job leaves the queue" wait_until 60 no_jobs
check "the cancelled member wrote a restart point" test -f "$member/member.h5.restart"
check "the cancelled member is interrupted, not failed" test ! -f "$member/exit_status"
"$study" export long.json --slurm --results slurm >/dev/null
check "resubmitted, it runs to the end" submit_and_wait 300 sh slurm/long/slurm/submit.sh
check "it continued from its restart point" grep -q "continuing from the restart point" "$member/capsule.log"
check "and is complete" status_is slurm long.json 0

# --- 1100 members: split below MaxArraySize, accepted, and held tasks are queued ------------------
cas=$("$py" -c 'print(" ".join("%.5f" % (0.06 + 1e-5 * i) for i in range(1100)))')  # shares no member with the others
# shellcheck disable=SC2086
campaign big.json big 1 1 $cas
"$study" export big.json --slurm --results slurm >/dev/null
check "an 1100-member export is accepted by sbatch (held)" sh slurm/big/slurm/submit.sh --hold
all_queued() { "$study" status big.json --results slurm >big-status.out 2>&1; grep -q 'queued: 1100' big-status.out; }
check "study status sees 1100 queued members" wait_until 30 all_queued
grep -q 'queued: 1100' big-status.out || head -20 big-status.out
check "a new export leaves the queued members out" sh -c "'$study' export big.json --slurm --results slurm | grep -q '0 of 1100 members to run'"
scancel --me
check "the held jobs are cancelled" wait_until 60 no_jobs

# --- GNU Parallel over SSH, one host dead ---------------------------------------------------------
check "over SSH with a dead host every member completes" "$study" run tiny.json --results ssh --hosts "$CLUSTER_HOSTS_ONE_DEAD" --ssh "$CLUSTER_SSH"
check "SSH's members are bitwise the local run's" same_series local/tiny ssh/tiny
printf '1/127.0.0.2\n' >dead-only
"$study" run tiny.json --results dead --hosts dead-only --ssh "$CLUSTER_SSH" >dead.out 2>&1
code=$?
check "with only a dead host the run exits 1" test "$code" -eq 1
check "and names the host and its members" grep -q "host 127.0.0.2 could not be reached (exit 255) for 3 members" dead.out
echo "cluster tests took $(($(date +%s) - started)) s"
