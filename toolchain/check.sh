#!/usr/bin/env bash
# The full check: install packages, then run every workflow preset (configure,
# build, test), print each preset's wall time and the total, and end with one
# line "N passed, N failed" (ctest's counts summed over the presets). Exits
# non-zero if anything failed. The cross presets run only the tests labelled
# target, tsan only those labelled threads (under ThreadSanitizer); quick
# (unit and component tests of the host build) is not in the default list,
# since host runs them all.
#
#   bash toolchain/check.sh                 # all presets
#   bash toolchain/check.sh host armhf      # just these
#   KERF_FRESH=0 bash toolchain/check.sh    # keep the existing CMake caches
#
# By default each preset is configured with --fresh (the cache is rebuilt from
# the preset and toolchain file, so edits to those always take effect; Ninja
# still rebuilds only what changed).
#
# A preset whose configure or build fails (so ctest never reports) counts as
# one failure. Logs: build/check-logs/<preset>.log
set -uo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
check_start=$SECONDS
mmss() { printf '%d:%02d' $(($1 / 60)) $(($1 % 60)); }

if ! bash toolchain/setup.sh; then
  echo "check.sh: toolchain/setup.sh failed" >&2
  echo "0 passed, 1 failed"
  exit 1
fi

presets=("$@")
((${#presets[@]})) || presets=(host debug-asan tsan aarch64 armhf cortex-m4 cortex-m0 fuzz)
fresh=()
[[ "${KERF_FRESH:-1}" == 0 ]] || fresh=(--fresh)

logdir=build/check-logs
mkdir -p "$logdir"
total_pass=0 total_fail=0 status=0
report=()
for p in "${presets[@]}"; do
  log="$logdir/$p.log"
  echo "=== $p: cmake --workflow --preset $p ${fresh[*]}"
  start=$SECONDS
  cmake --workflow --preset "$p" "${fresh[@]}" 2>&1 | tee "$log"
  rc=${PIPESTATUS[0]}
  secs=$((SECONDS - start))

  # ctest: "97% tests passed, 1 tests failed out of 34"
  summary=$(grep -E '^[0-9]+% tests passed, [0-9]+ tests? failed out of [0-9]+' "$log" | tail -n 1)
  pass=0 fail=0
  if [[ "$summary" =~ ([0-9]+)\ tests?\ failed\ out\ of\ ([0-9]+) ]]; then
    fail=${BASH_REMATCH[1]}
    pass=$((BASH_REMATCH[2] - fail))
  fi
  note=""
  if ((rc != 0)); then
    status=1
    if ((fail == 0)); then
      fail=1
      note=" (workflow failed before tests reported: see $log)"
    fi
  fi
  total_pass=$((total_pass + pass))
  total_fail=$((total_fail + fail))
  report+=("$(printf '%-11s rc=%-3s %4ss (%5s)  %s passed, %s failed%s' "$p" "$rc" "$secs" "$(mmss "$secs")" "$pass" "$fail" "$note")")
done

echo
echo "=== summary"
printf '%s\n' "${report[@]}"
((total_fail == 0)) || status=1
total=$((SECONDS - check_start))
printf '%-11s        %4ss (%5s)  wall time, setup.sh included\n' total "$total" "$(mmss "$total")"
echo "$total_pass passed, $total_fail failed"
exit "$status"
