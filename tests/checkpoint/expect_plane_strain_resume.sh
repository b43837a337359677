#!/usr/bin/env bash
# Usage: expect_plane_strain_resume.sh MPIEXEC EXECUTABLE SCENE.prm
#        [END STEP2_END] (in a scratch folder)
# A plane-strain run (Dimension = 2) checkpointed on 2 ranks after step 2
# (the time STEP2_END, default 0.2) and resumed on 1 rank to END (default
# 0.5), through ductile-contact, which hands both to the plane-strain
# build. Passes when the resumed run gives the statistics of the
# uninterrupted 1-rank run (every column but the timings and iteration
# counts, to 1e-6 of its scale: compare_statistics.py). With
# tests/plane_strain/clamped_plate.prm (plasticity with gradient hardening,
# refined where alpha grows in steps 1, 2 and 3): the 2-D mesh, its
# refinements and the 3 x 3 plastic history travel with the checkpoint;
# with prm/block_on_strip_2d.prm (plasticity, the phase field, frictional
# line3 contact): the committed contact state too.
set -u
mpiexec=$1 exe=$2 prm=$3 end=${4:-0.5} step2=${5:-0.2}
here=$(cd "$(dirname "$0")" && pwd)
source "$here/common.sh"

# scene NAME END_TIME CHECKPOINT_INTERVAL DIRECTORY
scene() {
  { cat "$prm"; cat <<EOT
subsection Load stepping
  set End time = $2
end
subsection Output
  set Directory = $4
end
subsection Checkpoint
  set Interval = $3
end
EOT
  } > "$1.prm"
}
rm -rf full part ./*.prm ./*.log

scene full "$end" 0 full
run 1 full.prm || fail "the uninterrupted run failed"
scene part "$step2" 1 part
run 2 part.prm || fail "the run up to step 2 failed"
[[ $(cat part/checkpoints/last) == step_000002 ]] || fail "no checkpoint of step 2"
scene part_resume "$end" 1 part
run 1 part_resume.prm --resume || fail "the resume (2 -> 1 ranks) failed"
grep -q "step_000002" part_resume.log || fail "the resume does not name its checkpoint"
python3 "$here/compare_statistics.py" full/statistics part/statistics ||
  fail "checkpointed in plane strain, resumed 2 -> 1"
echo PASS
