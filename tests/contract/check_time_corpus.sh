#!/usr/bin/env bash
# kerf-sim check's time estimate within 2 % of kerf-sim sim --speed 0's
# simulated time, for every G-code file of the corpus (tests/data/gcode), on
# check_time.toml's coarse machine. A file the sim refuses must be refused by
# check too (exit 2). Prints one line per file: sim, check, difference.
#
#   check_time_corpus.sh KERF_SIM CONFIG CORPUS_DIR WORKDIR [NAME...]
# (NAME...: only these files of the corpus)
set -euo pipefail
kerf=$1 config=$2 corpus=$3 dir=$4
shift 4
files=("$corpus"/*.gcode "$corpus"/*.ngc "$corpus"/*.nc)
if (($# > 0)); then files=(); for n in "$@"; do files+=("$corpus/$n"); done; fi
mkdir -p "$dir"
fail=0
for f in "${files[@]}"; do
  [[ -e $f ]] || continue
  name=$(basename "$f")
  rc_sim=0
  "$kerf" sim --config "$config" --speed 0 --report "$dir/$name.json" "$f" >"$dir/$name.sim" 2>&1 || rc_sim=$?
  rc_check=0
  "$kerf" check --config "$config" "$f" >"$dir/$name.check" 2>&1 || rc_check=$?
  if ((rc_sim == 2)); then
    if ((rc_check != 2)); then echo "FAIL: $name: sim refuses it (exit 2), check exits $rc_check"; fail=1; fi
    echo "$name: refused by both"
    continue
  fi
  if ((rc_sim != 0 || rc_check != 0)); then
    echo "FAIL: $name: sim exit $rc_sim, check exit $rc_check"; cat "$dir/$name.sim" "$dir/$name.check"; fail=1; continue
  fi
  python3 - "$name" "$dir/$name.json" "$dir/$name.check" <<'PY' || fail=1
import json, re, sys
name, report, check = sys.argv[1:4]
sim = json.load(open(report))["duration_s"]
m = re.search(r"time ([0-9.]+) s", open(check).read())
if not m:
    print("FAIL:", name, ": no time in kerf-sim check's output"); sys.exit(1)
est = float(m.group(1))
diff = (est - sim) / sim * 100
print(f"{name}: sim {sim:.3f} s, check {est:.3f} s, {diff:+.3f} %")
if abs(diff) > 2:
    print("FAIL:", name, ": the estimate is more than 2 % off"); sys.exit(1)
PY
done
exit $fail
