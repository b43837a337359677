#!/usr/bin/env bash
# Usage: expect_resume.sh MPIEXEC EXECUTABLE SCENE.prm (in a scratch folder)
# Checkpoint and resume on the coarse copy of the paper's scene (SCENE.prm:
# gradient plasticity, the phase field and frictional contact in one run),
# 16 steps of 0.6 mm (the plate yields from step 9, s grows, the block
# slides). Passes when every run below gives the statistics of
# the uninterrupted run on 2 ranks (every column but the timings and the
# solver's iteration counts, to 1e-6 of its scale; contact pressures to
# 1e-5, since two identical 2-rank runs repeat them only to ~3e-7:
# compare_statistics.py):
#  1. killed (SIGKILL, rank 0) on 1 rank while writing the checkpoint of
#     step 12 (checkpoints every 2 steps, End time 48): the checkpoint of
#     step 10 stays the newest complete one; resumed from it on 2 ranks
#     with End time 64, a change the resumed run names;
#  2. sent SIGTERM (to its ranks, as a scheduler does) on 2 ranks: it stops
#     after the step it is in with exit code 3, a checkpoint and its
#     output, and resumed on 1 rank;
#  3. a resume with a changed mesh is refused with exit code 1 and a
#     message naming the entry, and so is a resume without a checkpoint.
set -u
mpiexec=$1 exe=$2 scene=$3
here=$(cd "$(dirname "$0")" && pwd)
source "$here/common.sh"
compare() { python3 "$here/compare_statistics.py" "$1" "$2" || fail "$3"; }

# scene NAME END_TIME CHECKPOINT_INTERVAL DIRECTORY [extra lines]
scene() {
  { cat "$scene"; cat <<EOT
subsection Mesh
  subsection Two bodies
    set Plate subdivisions = 8, 5, ${5:-1}
    set Block subdivisions = 2, 2, 2
  end
end
subsection Load stepping
  set Time step = 4
  set End time  = $2
end
subsection Output
  set Interval  = 2
  set Directory = $4
end
subsection Checkpoint
  set Interval = $3
end
EOT
  } > "$1.prm"
}
rm -rf full killed signalled nothing_here ./*.prm ./*.log

scene full 64 0 full
run 2 full.prm || fail "the uninterrupted run failed"
python3 - full/statistics <<'EOT' || fail "the scene does not yield, crack and slide"
import sys
rows = [l.split() for l in open(sys.argv[1]) if l.strip()]
end = dict(zip(rows[0], map(float, rows[-1])))
sys.exit(not (end["plastic_work"] > 1e-3 and end["max_s"] > 1e-3 and
              end["contact1_dissipation"] > 1e-6))
EOT

# 1. Killed while writing the checkpoint of step 12, resumed 1 -> 2 ranks.
scene killed 48 2 killed
DUCTILE_CONTACT_TEST_KILL_IN_CHECKPOINT=12 run 1 killed.prm &&
  fail "the run was not killed"
[[ $(cat killed/checkpoints/last) == step_000010 ]] ||
  fail "the marker does not name the last complete checkpoint (step 10)"
[[ -d killed/checkpoints/.writing ]] || fail "the kill came too late"
scene killed_resume 64 2 killed
run 2 killed_resume.prm --resume || fail "the resume (1 -> 2 ranks) failed"
grep -q "step_000010" killed_resume.log || fail "the resume does not name its checkpoint"
grep -q "End time: 48 -> 64" killed_resume.log || fail "the taken change is not named"
compare full/statistics killed/statistics "killed while checkpointing, resumed 1 -> 2"
ls killed/checkpoints | grep -q step_000010 && fail "Checkpoint/Keep = 2 left step 10"
grep -q solution_00016 killed/solution.pvd && grep -q solution_00002 killed/solution.pvd ||
  fail "the output series is broken"

# 2. SIGTERM to the ranks of a running job, resumed 2 -> 1 ranks.
scene signalled 64 100 signalled
run 2 signalled.prm &
job=$!
# Signal once 8 steps are in (at most 10 min: a loaded machine is slow).
for _ in $(seq 6000); do
  [[ -f signalled/statistics && $(wc -l < signalled/statistics) -ge 9 ]] && break
  sleep 0.1
done
pkill -TERM -f "^$exe signalled.prm"
wait $job
code=$?
[[ $code -eq 3 ]] || fail "exit code $code after SIGTERM, expected 3"
grep -q "Stopped by a signal after step" signalled.log || fail "no stop message"
last=$(tail -n 1 signalled/statistics | awk '{print $1}')
[[ $(cat signalled/checkpoints/last) == step_$(printf %06d "$last") ]] ||
  fail "no checkpoint of the last step ($last)"
grep -q "solution_$(printf %05d "$last")" signalled/solution.pvd ||
  fail "no output of the last step ($last)"
run 1 signalled.prm --resume || fail "the resume after SIGTERM failed"
compare full/statistics signalled/statistics "stopped by SIGTERM, resumed 2 -> 1"

# 3. Refused resumes.
scene changed 64 2 killed 2
run 1 changed.prm --resume && fail "a resume with a changed mesh ran"
grep -q "Mesh/Two bodies/Plate subdivisions" changed.log ||
  fail "the refusal does not name the entry"
scene empty 64 2 nothing_here
run 1 empty.prm --resume && fail "a resume without a checkpoint ran"
grep -q "Output/Directory" empty.log || fail "no message naming Output/Directory"
echo PASS
