#!/usr/bin/env bash
# One line per fuzz target (executions, seconds, libFuzzer's exit code) and a
# total, from the files run_fuzz.sh wrote. Fails when a target did not run or
# did not pass.
#
#   fuzz_summary.sh STATS_DIR TARGET...
set -uo pipefail
dir=$1
shift
status=0 total=0 line=()
for t in "$@"; do
  if [[ ! -f "$dir/$t.txt" ]]; then
    echo "fuzz summary: $t did not run"
    status=1
    continue
  fi
  read -r name execs secs rc <"$dir/$t.txt"
  printf 'fuzz summary: %-11s %10s executions %4ss  exit %s\n' "$name" "$execs" "$secs" "$rc"
  total=$((total + execs))
  line+=("$name=$execs")
  ((rc == 0)) || status=1
done
echo "fuzz executions: ${line[*]} total=$total"
exit "$status"
