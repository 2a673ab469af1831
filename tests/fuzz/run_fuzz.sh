#!/usr/bin/env bash
# Runs one libFuzzer target for a bounded time on its seed corpus.
#
#   run_fuzz.sh BINARY SEED_DIR BUILD_DIR SECONDS [RANDOM_SEED]
#
# RANDOM_SEED is libFuzzer's -seed (default 1; 0 picks a new one each run).
# With a fixed one the inputs tried are the same sequence on every machine.
# New inputs go to BUILD_DIR/fuzz-corpus/<target> (the seeds in the repo are
# only read). It starts empty on every run, since libFuzzer replays the whole
# corpus before -max_total_time counts and a growing one would stretch the
# test step without bound; KERF_FUZZ_KEEP_CORPUS=1 keeps it (longer hunts). A crash, hang (-timeout), leak or out-of-memory fails the run:
# the exit code is libFuzzer's, and the reproducer (crash-*, timeout-*,
# leak-*, oom-*) stays in BUILD_DIR/fuzz-artifacts/<target>/, whose path is
# printed with the command that replays it. The executions go to
# BUILD_DIR/fuzz-stats/<target>.txt for fuzz_summary.sh.
set -uo pipefail
bin=$1 seeds=$2 build=$3 secs=$4 seed=${5:-1}
name=$(basename "$bin")
name=${name#fuzz_}
corpus=$build/fuzz-corpus/$name
artifacts=$build/fuzz-artifacts/$name
stats=$build/fuzz-stats/$name.txt
log=$build/fuzz-logs/$name.log
[[ "${KERF_FUZZ_KEEP_CORPUS:-0}" == 1 ]] || rm -rf "$corpus"
mkdir -p "$corpus" "$artifacts" "$(dirname "$stats")" "$(dirname "$log")"
rm -f "$stats"

start=$SECONDS
stamp=$build/fuzz-logs/$name.start
touch "$stamp"
"$bin" -seed="$seed" -max_total_time="$secs" -timeout=10 -rss_limit_mb=1024 -malloc_limit_mb=1024 \
  -detect_leaks=1 -print_final_stats=1 -artifact_prefix="$artifacts/" \
  "$corpus" "$seeds" >"$log" 2>&1
rc=$?
wall=$((SECONDS - start))

execs=$(grep -Eo 'stat::number_of_executed_units: *[0-9]+' "$log" | grep -Eo '[0-9]+$' | tail -n 1)
execs=${execs:-0}
echo "$name $execs $wall $rc" >"$stats"
if ((rc != 0)); then
  echo "fuzz $name: FAILED (libFuzzer exit $rc, -seed=$seed) after $execs executions in ${wall}s; log $log"
  grep -E '^(==[0-9]+==ERROR|SUMMARY|.*fuzz check failed|.*runtime error|.*contract violated)' "$log" | head -n 20
  for a in $(find "$artifacts" -type f -newer "$stamp"); do  # this run's, not older ones
    echo "fuzz $name: reproducer kept: $a"
    echo "fuzz $name: replay: $bin $a"
  done
  exit "$rc"
fi
echo "fuzz $name: ok, $execs executions in ${wall}s (-seed=$seed), corpus $(ls "$corpus" | wc -l) inputs"
