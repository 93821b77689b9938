#!/usr/bin/env bash
# scripts/convergence-profile on a synthetic trajectory with known settle times:
# T = 0.1 s, 0..100 s; the filter's x error is 5 m until 20 s, then 0.2 m, with a single
# 3 m outlier at 60 s. Expected by hand: error < 1 m from 60.1 s (the sample after the
# outlier); the 10 s (100-sample) RMS is < 1 m once at most 3 of the 5 m samples are in
# the window (25k + 0.04(100 − k) < 100 ⇔ k ≤ 3): the last window with 4 ends at 29.5 s,
# so from 29.6 s (the outlier's window has RMS √(12.96/100) = 0.36 m); after 30 s, 1 of
# 700 samples is ≥ 1 m.
#   convergence_profile_test.sh SCRIPT
set -eu
script=$1
work=$(mktemp -d "${TMPDIR:-/tmp}/hinf-conv-XXXXXX")
trap 'rm -rf "$work"' EXIT
python3 - "$work/trajectory.csv" <<'PY'
import sys
with open(sys.argv[1], "w") as f:
    f.write("t,true_x,true_y,true_z,hinf_x,hinf_y,hinf_z\n")
    for k in range(1001):
        t = 0.1 * k
        e = 5.0 if t < 20.0 - 1e-9 else 0.2
        if k == 600:
            e = 3.0
        f.write(f"{t:.1f},0,0,0,{e},0,0\n")
PY
out=$("$script" "$work/trajectory.csv" --thresholds 1 --window 10 --after 30)
echo "$out"
echo "$out" | grep -q "error < 1 m from 60.1 s" || { echo "FAIL: pointwise settle time"; exit 1; }
echo "$out" | grep -q "10 s RMS < 1 m from 29.6 s" || { echo "FAIL: windowed settle time"; exit 1; }
echo "$out" | grep -q "after 30 s: 1 of 700 samples" || { echo "FAIL: exceedance count"; exit 1; }
echo "ok"
