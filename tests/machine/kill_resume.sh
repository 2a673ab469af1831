#!/usr/bin/env bash
# kill -9 in the middle of a job, then --resume: every segment is cut exactly
# once across the two runs, and the second run re-pierces where the first
# one's torch went off.
#
#   kill_resume.sh KERF JOB WORKDIR
set -euo pipefail
kerf=$1 job=$2 dir=$3
mkdir -p "$dir"
journal=$dir/journal report1=$dir/report1.json report2=$dir/report2.json
rm -f "$journal" "$report1" "$report2"

# In real time, so that the kill lands mid-job.
"$kerf" sim --speed 1 --journal "$journal" --report "$report1" "$job" >/dev/null 2>&1 &
pid=$!
# Wait until at least 5 segments are journaled (a few seconds), then kill.
for _ in $(seq 1 400); do
  n=$(grep -c '^done ' "$journal" 2>/dev/null || true)
  ((${n:-0} >= 5)) && break
  sleep 0.05
done
kill -9 "$pid"
wait "$pid" 2>/dev/null || true
[[ ! -e "$report1" ]] || { echo "FAIL: the killed run wrote a report"; exit 1; }
done_before=$(grep -c '^done ' "$journal")
echo "killed after $done_before journaled segments"
((done_before >= 5)) || { echo "FAIL: the job never got going"; exit 1; }

"$kerf" sim --resume --journal "$journal" --report "$report2" "$job"
python3 - "$report2" "$done_before" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
before = int(sys.argv[2])
def check(ok, what):
    if not ok:
        print("FAIL:", what, json.dumps(r, indent=1)); sys.exit(1)
check(r["state"] == "done", "the resumed run finished")
check(r["segments_executed_total"] == r["segments_planned"], "every segment executed once in all")
check(r["duplicates"] == 0, "no duplicates")
check(r["runs"] == 2, "two runs in the journal")
check(r["resumed_from_segment"] >= before + 1, "resumed after the journaled segments")
check(r["segments_executed"] + r["resumed_from_segment"] - 1 == r["segments_planned"], "the rest, exactly")
print("ok: resumed from segment %d, %d of %d segments in all, 0 duplicates"
      % (r["resumed_from_segment"], r["segments_executed_total"], r["segments_planned"]))
PY
