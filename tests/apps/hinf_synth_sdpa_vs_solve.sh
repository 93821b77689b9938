#!/usr/bin/env bash
# `export-sdpa` solved by CSDP must agree with `solve` within RTOL (relative): for a filter
# config, γ² (the exported LMI's objective); for a controller config (docs/maths.md §26),
# γ = the exported LMI's optimum times the equilibration factor its comment states.
#   hinf_synth_sdpa_vs_solve.sh EXE CSDP CONFIG RTOL
set -u
exe=$1 csdp=$2 cfg=$3 rtol=$4
work=$(mktemp -d "${TMPDIR:-/tmp}/hinf-sdpa-XXXXXX")
trap 'rm -rf "$work"' EXIT
"$exe" export-sdpa "$cfg" -o "$work/lmi.dat-s" >/dev/null || { echo "FAIL: export-sdpa exit $?"; exit 1; }
"$exe" solve "$cfg" -o "$work/out.yaml" >/dev/null || { echo "FAIL: solve exit $?"; exit 1; }
(cd "$work" && "$csdp" lmi.dat-s lmi.sol >csdp.out 2>&1)
crc=$?
[ $crc -eq 0 ] || { echo "FAIL: csdp exit $crc"; cat "$work/csdp.out"; exit 1; }
dual=$(awk -F: '/Dual objective value/{gsub(/ /,"",$2); print $2}' "$work/csdp.out")
if grep -q '^format: hinf-controller/1' "$work/out.yaml"; then
  what=gamma
  factor=$(sed -n 's/.*gamma = it times \([0-9.eE+-]*\) .*/\1/p' "$work/lmi.dat-s" | head -1)
  ours=$(awk '/^gamma:/{print $2}' "$work/out.yaml")
else
  what=gamma^2
  factor=1
  ours=$(awk '/^gamma_squared:/{print $2}' "$work/out.yaml")
fi
[ -n "$dual" ] && [ -n "$factor" ] && [ -n "$ours" ] || { echo "FAIL: could not parse (csdp '$dual', factor '$factor', ours '$ours')"; exit 1; }
awk -v a="$ours" -v b="$dual" -v f="$factor" -v r="$rtol" -v w="$what" 'BEGIN{
  b = b * f; d = (a - b) / b; if (d < 0) d = -d;
  printf "%s: hinf-synth %.10g, csdp %.10g, rel diff %.2e (tol %s)\n", w, a, b, d, r;
  exit (d <= r) ? 0 : 1 }' || { echo "FAIL: $what differs"; exit 1; }
