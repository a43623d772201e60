#!/usr/bin/env bash
# The pile of issue 16 against Bullet, in the same run: N boxes dropped with
# restitution 0.5 and friction 0.5 (pile_bench.cpp, bullet_pile.cpp). Each
# round runs, for each N, this project on every core, on one thread, and
# Bullet, each in its own process (so peak memory is each one's own), and
# rbsim itself on the same scene as a world config for 2 s (the whole
# process: config, URDFs, output; its rest columns are '-'). The table gives
# medians over the rounds, and the ratios to Bullet's time. Bullet at its
# defaults bounces lower than the restitution it is given (bullet_bounce),
# so each round also runs this project on every core at the median
# restitution Bullet's boxes actually bounce with (row rbs-2t@eB).
# Usage: bench/pile.sh [rounds] [N ...]   (default: 3 rounds, N = 1000)
# Needs libbullet-dev for the Bullet column (apt install libbullet-dev).
set -euo pipefail
source "$(dirname "$0")/../scripts/common.sh"
ROUNDS=${1:-3}
shift || true
SIZES=("${@:-1000}")
[ ${#SIZES[@]} -eq 0 ] && SIZES=(1000)
rbs_install_packages
RBS_BUILD_TYPE=Release rbs_build >/dev/null
BIN="$RBS_WS/devel/lib/rigid_body_sim"
OUT=$(mktemp)
WORLD=$(mktemp -d)
trap 'rm -rf "$OUT" "$WORLD"' EXIT
E_BULLET=
if [ -x "$BIN/bullet_bounce" ]; then
  E_BULLET=$("$BIN/bullet_bounce" | sed -n 's/^engine bullet .* e_median \([0-9.]*\) .*/\1/p')
  echo "Bullet's boxes bounce with e = $E_BULLET (median of bullet_bounce's drops; given 0.5)"
fi
for round in $(seq "$ROUNDS"); do
  for n in "${SIZES[@]}"; do
    "$BIN/pile_bench" "$n" | sed 's/^engine rbs/engine rbs-2t/' >>"$OUT"
    RBS_THREADS=1 "$BIN/pile_bench" "$n" | sed 's/^engine rbs/engine rbs-1t/' >>"$OUT"
    if [ -x "$BIN/bullet_pile" ]; then "$BIN/bullet_pile" "$n" >>"$OUT"; fi
    if [ -n "$E_BULLET" ]; then "$BIN/pile_bench" "$n" 1 "$E_BULLET" | sed 's/^engine rbs/engine rbs-2t@eB/' >>"$OUT"; fi
    "$BIN/pile_bench" --yaml "$n" "$RBS_ROOT/urdf/box.urdf" >"$WORLD/pile.yaml"
    /usr/bin/time -f %M -o "$WORLD/rss" "$BIN/rbsim" --config "$WORLD/pile.yaml" --duration 2 --quiet >"$WORLD/out.json"
    /usr/bin/python3 -c 'import json, sys
j = json.load(open(sys.argv[1])); n = int(sys.argv[2])
print("engine rbsim N", n, "ns_per_body_step", j["ns_per_step"] / n, "rest2_sleep - rest2_peers - rest3_sleep -",
      "rest3_peers - deepest_mm", 1e3 * j["max_penetration"], "peak_rss_kb", open(sys.argv[3]).read().split()[-1])' \
      "$WORLD/out.json" "$n" "$WORLD/rss" >>"$OUT"
  done
  echo "round $round of $ROUNDS done" >&2
done
/usr/bin/python3 - "$OUT" <<'PY'
import collections, statistics, sys
rows = collections.defaultdict(list)
for line in open(sys.argv[1]):
    f = line.split()
    d = dict(zip(f[0::2], f[1::2]))
    rows[(int(d["N"]), d["engine"])].append(d)
def med(runs, key):
    vals = [float(r[key]) for r in runs if r[key] != "-"]
    return statistics.median(vals) if vals else None
fmt = lambda x, spec: "-" if x is None else format(x, spec)
print(f"{'N':>6} {'engine':>9} {'ns/body-step':>13} {'vs Bullet':>9} {'rest 2 s (sleep | peers)':>25} "
      f"{'rest 3 s (sleep | peers)':>25} {'deepest mm':>10} {'peak RSS KB/body':>16}")
for n in sorted({k[0] for k in rows}):
    bullet = med(rows.get((n, "bullet"), []), "ns_per_body_step") if (n, "bullet") in rows else None
    for engine in ("rbs-2t", "rbs-1t", "bullet", "rbs-2t@eB", "rbsim"):
        runs = rows.get((n, engine))
        if not runs:
            continue
        ns = med(runs, "ns_per_body_step")
        ratio = ns / bullet if bullet else None
        print(f"{n:>6} {engine:>9} {ns:>13.1f} {fmt(ratio, '.3f'):>9} "
              f"{fmt(med(runs, 'rest2_sleep'), '.1f'):>11} % | {fmt(med(runs, 'rest2_peers'), '.1f'):>6} % "
              f"{fmt(med(runs, 'rest3_sleep'), '.1f'):>11} % | {fmt(med(runs, 'rest3_peers'), '.1f'):>6} % "
              f"{med(runs, 'deepest_mm'):>10.3f} {med(runs, 'peak_rss_kb') / n:>16.2f}")
print(f"({len(next(iter(rows.values())))} rounds; medians)")
PY
