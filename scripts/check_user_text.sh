#!/usr/bin/env bash
# Checks that the user-facing text says what is, not how it came to be: no
# development sessions ("session 45", "sessions 35-36", "this session"), no
# issue numbers ("issue #4", "Issue 28", "(#24)"), no "the issue's target",
# no development "wave" ("wave 2", "this wave"; a P wave is physics), no
# "until ... lands". Lists FILE:LINE: TEXT for each mention and
# exits 1 if there is any, 0 otherwise.
# Usage: scripts/check_user_text.sh [FILE...]
#   default: README.md, doc/, prm/ (the .prm files and the mesh scripts),
#   scripts/ (but this file, whose comments name the patterns),
#   tests/README* and the tests' sources, the program's sources (source/,
#   include/), and every README.md, results.md and script (.sh, .py) under
#   benchmarks/ outside the run folders.
# A name joined to a path by '/', '-' or '_' is data, not prose, and is
# not flagged.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

if (($#)); then
  files=("$@")
else
  cd "$root"
  files=(README.md)
  while IFS= read -r -d '' f; do files+=("$f"); done < <(
    find doc scripts tests benchmarks prm source include -type f \( \
         -path 'doc/*.md' \
      -o -path 'prm/*.prm' -o -path 'prm/meshes/*.py' \
      -o \( -path 'scripts/*' ! -name '*.pyc' ! -name check_user_text.sh \) \
      -o -path 'tests/README*' -o -path 'tests/*.cc' -o -path 'tests/*.h' \
      -o -path 'source/*' -o -path 'include/*' \
      -o \( -path 'benchmarks/*' ! -path '*/runs/*' \( -name README.md \
             -o -name results.md -o -name '*.sh' -o -name '*.py' \) \) \
    \) -print0 | sort -z)
fi

perl -ne '
  BEGIN { $found = 0 }
  # A history mention, case-insensitive:
  our $history = qr{
      (?<![\w/-])sessions?(?![\w/-])          # session, sessions, session 45
    | (?<![\w/-])session[ -]?\d+              # session 45, session-45 in prose
    | \bissues?\s*\#?\s*\d+                  # issue #4, Issue 28, issues #4 and #3
    | (?<![\w&/\#])\#\d{1,3}\b               # (#24), #28
    | \b(?:the|this|that)(?:\s+[a-z]+)?\s+issue(?:s|\x27s)?\b  # the issue, this issue
    | \bwave\s+\d+                           # wave 2
    | \b(?:this|next|last|previous|current)\s+wave\b  # this wave
    | \buntil\b.*\blands\b                   # until frictional contact lands
  }xi;
  if (/$history/) {
    chomp;
    print "$ARGV:$.: $_\n";
    $found = 1;
  }
  close ARGV if eof;   # restart $. for each file
  END { exit $found }
' "${files[@]}" && status=0 || status=$?

if ((status == 0)); then
  echo "check_user_text: no development history in ${#files[@]} files"
else
  echo "check_user_text: development history found (above); say what is instead" >&2
fi
exit "$status"
