#!/usr/bin/env bash
# Usage: expect_dynamic_resume.sh MPIEXEC EXECUTABLE SCENE.prm MESH.msh (in a
# scratch folder)
# A dynamic run resumes where it stopped: the bar impact (SCENE.prm =
# prm/bar_impact.prm on MESH.msh, the 10-cell bars of the tests), 20 us
# steps to 3 ms. Passes when the run on 2 ranks, checkpointed every step and
# ended at 1.5 ms (in the middle of the contact), resumed on 3 ranks to the
# end, gives the statistics of the uninterrupted 2-rank run (every column
# but the timings and iteration counts, to 1e-6 of its scale:
# compare_statistics.py): the velocity, the acceleration and the inertial
# acceleration of the step travel with the checkpoint, and a run cannot
# resume with another Time integration. (The checkpointed run uses the
# uninterrupted run's 2 ranks: in the step in which the bars touch, at zero
# pressure, round-off decides which nodes count as active, and the contact
# area of that step differs between 1 and 2 ranks by 8 %.)
set -u
mpiexec=$1 exe=$2 prm=$3 mesh=$4
here=$(cd "$(dirname "$0")" && pwd)
source "$here/common.sh"

# scene NAME END_TIME CHECKPOINT_INTERVAL DIRECTORY [TIME_INTEGRATION]
scene() {
  { cat "$prm"; cat <<EOT
subsection Mesh
  subsection Gmsh
    set File name = $mesh
  end
end
subsection Load stepping
  set End time         = $2
  set Time step        = 2e-5
  set Time integration = ${5:-Bossak}
end
subsection Output
  set Interval  = 0
  set Directory = $4
end
subsection Checkpoint
  set Interval = $3
end
EOT
  } > "$1.prm"
}
rm -rf full part ./*.prm ./*.log

scene full 3e-3 0 full
run 2 full.prm || fail "the uninterrupted run failed"

scene part 1.5e-3 1 part
run 2 part.prm || fail "the run up to 1.5 ms failed"
[[ $(cat part/checkpoints/last) == step_000075 ]] || fail "no checkpoint of step 75"
scene quasi 3e-3 1 part quasi-static
run 1 quasi.prm --resume && fail "a resume with another Time integration was taken"
grep -q "Time integration" quasi.log || fail "the refused resume does not name the entry"
scene part_resume 3e-3 1 part
run 3 part_resume.prm --resume || fail "the resume (2 -> 3 ranks) failed"
grep -q "step_000075" part_resume.log || fail "the resume does not name its checkpoint"
python3 "$here/compare_statistics.py" full/statistics part/statistics ||
  fail "a dynamic run resumed 2 -> 3 ranks in the middle of a contact"
echo PASS
