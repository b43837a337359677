# Sourced by memory/run.sh and speed/run.sh (after scripts/env.sh and
# require_build): the first 3 steps of prm/two_bodies.prm for each case and
# solver.
#
# run_two_bodies_cases DIR MODE CASE...: for every entry of the array
# `cases` ("name:ranks:extra entries", the entries separated by '|') whose
# name is among CASE... (all when none is given), each solver of the array
# `solvers` on each of the entry's ranks (or those of $NP), into
# DIR/runs/NAME-SOLVER-npN. MODE 'again' redoes every run; 'keep' skips the
# finished ones (run_finished).
run_two_bodies_cases() {
  local dir=$1 mode=$2
  shift 2
  local selected=("$@") entry name ranks extra np solver out e
  for entry in "${cases[@]}"; do
    IFS=: read -r name ranks extra <<< "$entry"
    if ((${#selected[@]})) && [[ ! " ${selected[*]} " == *" $name "* ]]; then
      continue
    fi
    for np in ${NP:-$ranks}; do
      for solver in "${solvers[@]}"; do
        out=$dir/runs/$name-$solver-np$np
        if [[ $mode == keep ]] && run_finished "$out"; then
          echo "== $name $solver on $np rank(s) (done)"
          continue
        fi
        rm -rf "$out"
        mkdir -p "$out"
        local args=(--set "Load stepping/End time = 3"
                    --set "Linear solver/Type = $solver"
                    --set "Output/Directory = $out" --set "Output/Interval = 0")
        local entries=()
        IFS='|' read -ra entries <<< "$extra"
        for e in "${entries[@]}"; do args+=(--set "$e"); done
        echo "== $name $solver on $np rank(s)"
        (cd "$project_root" && mpirun -np "$np" "$exe" "${args[@]}" \
           "$project_root/prm/two_bodies.prm") > "$out/screen.txt" 2>&1 ||
          echo "   (failed: see $out/screen.txt)"
      done
    done
  done
}
