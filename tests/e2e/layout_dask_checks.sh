#!/usr/bin/env bash
# layout_dask_checks.sh PROBEPROXY MODULE_DIR SCENE WORK [LAYOUT OPTIONS...]
# scripts/layout_dask.py lays SCENE out with its candidate tiles judged and its probes' final
# proxies built by a Dask LocalCluster of two worker processes on loopback, one of them ended
# (SIGKILL) once two tiles are done and one once two proxies are built: Dask runs those workers'
# tasks again, and every file is the bytes `probeproxy layout SCENE --tile-size 6` writes in
# one process (layout.json: the same figures, timings aside).
set -eu
probeproxy=$1 module=$2 scene=$3 work=$4
shift 4
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
"$probeproxy" layout "$scene" --out "$work/one_process" --tile-size 6 "$@" --json >/dev/null
/usr/bin/python3 "$here/../../scripts/layout_dask.py" "$scene" --out "$work/dask" \
  --local-workers 2 --tile-size 6 --module-dir "$module" --kill-a-worker-after 2 "$@" \
  >"$work/dask.log" 2>&1 || { cat "$work/dask.log" >&2; fail "layout_dask.py failed"; }
grep -q "in [0-9]* tiles on 2 workers (one ended after 2 tiles and one after 2 proxy builds)" \
  "$work/dask.log" || { cat "$work/dask.log" >&2; fail "no worker was ended in each stage"; }
grep -q "; [1-9][0-9]* proxy builds: [1-9][0-9]* bytes of tasks out, [1-9][0-9]* bytes of builds back" \
  "$work/dask.log" || { cat "$work/dask.log" >&2; fail "the proxies were not built on the workers"; }
[ "$(ls "$work/one_process")" = "$(ls "$work/dask")" ] || fail "other files"
for f in $(ls "$work/one_process"); do
  [ "$f" = layout.json ] && continue
  cmp -s "$work/one_process/$f" "$work/dask/$f" || fail "$f differs"
done
python3 - "$work/one_process/layout.json" "$work/dask/layout.json" <<'PY' || fail "layout.json"
import json, sys
def figures(d):
    if isinstance(d, dict):
        return {k: figures(v) for k, v in d.items() if not k.endswith(("seconds", "_ms"))}
    return [figures(x) for x in d] if isinstance(d, list) else d
one, dask = (figures(json.load(open(f))) for f in sys.argv[1:])
assert one["candidate_tiles"] > 2, one["candidate_tiles"]
assert one == dask, "figures differ"
PY
echo "layout dask checks passed"
