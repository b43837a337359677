#!/usr/bin/env bash
# Usage: expect_adaptive_resume.sh MPIEXEC EXECUTABLE SCENE.prm MESH.msh (in
# a scratch folder)
# A checkpoint holds an adapted mesh. Coarse notched
# tension (SCENE.prm = tests/sent_adaptive.prm on MESH.msh, h = 2 l_f,
# refined where s > 0.05 up to level 1), 9 steps; the mesh is refined in
# steps 4, 7 and 8. Passes when
#  1. the run on 1 rank, checkpointed every step and ended at step 5 (after
#     the first refinement), resumed on 2 ranks to the end, refines in the
#     same steps and gives the statistics of the uninterrupted 2-rank run
#     (every column but the timings and iteration counts, to 1e-6 of its
#     scale: compare_statistics.py), and
#  2. a resume may change the refinement entries (Phase-field threshold
#     0.05 -> 0.02: the resumed run names the change and refines more cells
#     in step 6 than the 100 the uninterrupted run has).
set -u
mpiexec=$1 exe=$2 prm=$3 mesh=$4
here=$(cd "$(dirname "$0")" && pwd)
source "$here/common.sh"

# scene NAME END_TIME CHECKPOINT_INTERVAL DIRECTORY [THRESHOLD]
scene() {
  { cat "$prm"; cat <<EOT
subsection Mesh
  subsection Gmsh
    set File name = $mesh
  end
  subsection Adaptive refinement
    set Phase-field threshold = ${5:-0.05}
  end
end
subsection Load stepping
  set End time = $2
end
subsection Output
  set Interval  = 1
  set Directory = $4
end
subsection Checkpoint
  set Interval = $3
end
EOT
  } > "$1.prm"
}
refined_steps() { # the steps of DIR/statistics whose refinements column is > 0
  awk 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "refinements") c = i; next }
       $c > 0 { printf "%d ", $1 }' "$1/statistics"
}
rm -rf full part deeper ./*.prm ./*.log

scene full 0.45 0 full
run 2 full.prm || fail "the uninterrupted run failed"
[[ $(refined_steps full) == "4 7 " ]] ||
  fail "refined in steps $(refined_steps full), expected 4 7"

# 1. Checkpointed on 1 rank up to step 5, resumed on 2 ranks.
scene part 0.25 1 part
run 1 part.prm || fail "the run up to step 5 failed"
[[ $(cat part/checkpoints/last) == step_000005 ]] || fail "no checkpoint of step 5"
scene part_resume 0.45 1 part
run 2 part_resume.prm --resume || fail "the resume (1 -> 2 ranks) failed"
grep -q "step_000005" part_resume.log || fail "the resume does not name its checkpoint"
[[ $(refined_steps part) == "4 7 " ]] ||
  fail "the resumed run refined in steps $(refined_steps part)"
python3 "$here/compare_statistics.py" full/statistics part/statistics ||
  fail "checkpointed on an adapted mesh, resumed 1 -> 2"

# 2. The refinement entries may change on a resume.
scene deeper 0.25 1 deeper
run 2 deeper.prm || fail "the run up to step 5 failed"
scene deeper_resume 0.3 1 deeper 0.02
run 1 deeper_resume.prm --resume || fail "the resume with another threshold was refused"
grep -q "Phase-field threshold: 0.05 -> 0.02" deeper_resume.log ||
  fail "the taken change is not named"
awk 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "cells") c = i; next }
     { n = $c } END { exit !(n > 100) }' deeper/statistics ||
  fail "the threshold 0.02 did not refine more than 0.05 (100 cells)"
echo PASS
