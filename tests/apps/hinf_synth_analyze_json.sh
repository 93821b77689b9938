#!/usr/bin/env bash
# `analyze --json` escapes the gains path: run on a copy of GAINS whose name holds a double
# quote and a backslash, the output must be one line of valid JSON (no NaN/Infinity) whose
# "gains" is that path, with the keys in the documented order.
#   hinf_synth_analyze_json.sh EXE PYTHON3 CONFIG GAINS
set -u
exe=$1 python=$2 config=$3 gains=$4
work=$(mktemp -d "${TMPDIR:-/tmp}/hinf-cli-json-XXXXXX")
trap 'rm -rf "$work"' EXIT
odd="$work/odd \"name\" \\ gains.yaml"
cp "$gains" "$odd"
"$exe" analyze "$config" "$odd" --json --delta-points 3 >"$work/stdout" 2>"$work/stderr"
rc=$?
if [ "$rc" -ne 0 ]; then
  echo "FAIL: analyze --json exited $rc"
  cat "$work/stderr"
  exit 1
fi
"$python" - "$odd" "$work/stdout" <<'PY' || { echo "--- stdout"; cat "$work/stdout"; exit 1; }
import json, sys

path, out = sys.argv[1], sys.argv[2]
text = open(out, encoding="utf-8").read()

def refuse(name):
    raise ValueError("non-finite number " + name)

assert text.endswith("\n") and text.count("\n") == 1, "not one line"
d = json.loads(text, parse_constant=refuse)
assert d["gains"] == path, "gains %r != %r" % (d["gains"], path)
assert d["schema"] == "hinf-synth.analyze/1" and d["kind"] == "filter", d["schema"]
want = ["schema", "kind", "config", "gains", "claimed_gamma", "spectral_radius_nominal", "hinf_norm_nominal",
        "hinf_norm_peak_frequency", "sample_time_s", "hinf_norm_peak_frequency_hz",
        "spectral_radius_sampled_max", "robust_bound", "worst_F_gain", "worst_F", "worst_F_evaluations",
        "worst_delta", "worst_delta_hinf_norm", "delta_grid"]
assert list(d) == want, list(d)
# the hill config states T = 0.1 s: the peak in Hz is θ/(2πT)
import math
assert d["sample_time_s"] == 0.1, d["sample_time_s"]
assert abs(d["hinf_norm_peak_frequency_hz"] - d["hinf_norm_peak_frequency"] / (2 * math.pi * 0.1)) <= 1e-9 * 5, d
assert len(d["delta_grid"]) == 3, d["delta_grid"]
for p in d["delta_grid"]:
    assert list(p) == ["delta", "spectral_radius", "hinf_norm"], list(p)
for k in want[5:13] + ["worst_F_evaluations", "worst_delta", "worst_delta_hinf_norm"]:
    assert isinstance(d[k], (int, float)), k
# the worst case found over F (docs/maths.md (140)) lies between the nominal norm and the bound
assert d["hinf_norm_nominal"] <= d["worst_F_gain"] * (1 + 1e-8) and d["worst_F_gain"] <= d["robust_bound"] * (1 + 1e-8), d
assert len(d["worst_F"]) == 6 and all(len(r) == 6 for r in d["worst_F"]), d["worst_F"]
print("ok: gains = %r" % d["gains"])
PY
