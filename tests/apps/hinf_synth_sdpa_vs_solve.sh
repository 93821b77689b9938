#!/usr/bin/env bash
# `export-sdpa` solved by CSDP must agree with `solve`: γ² within RTOL (relative).
#   hinf_synth_sdpa_vs_solve.sh EXE CSDP CONFIG RTOL
set -u
exe=$1 csdp=$2 cfg=$3 rtol=$4
work=$(mktemp -d "${TMPDIR:-/tmp}/hinf-sdpa-XXXXXX")
trap 'rm -rf "$work"' EXIT
"$exe" export-sdpa "$cfg" -o "$work/lmi.dat-s" >/dev/null || { echo "FAIL: export-sdpa exit $?"; exit 1; }
"$exe" solve "$cfg" -o "$work/gains.yaml" >/dev/null || { echo "FAIL: solve exit $?"; exit 1; }
(cd "$work" && "$csdp" lmi.dat-s lmi.sol >csdp.out 2>&1)
crc=$?
[ $crc -eq 0 ] || { echo "FAIL: csdp exit $crc"; cat "$work/csdp.out"; exit 1; }
dual=$(awk -F: '/Dual objective value/{gsub(/ /,"",$2); print $2}' "$work/csdp.out")
ours=$(awk '/^gamma_squared:/{print $2}' "$work/gains.yaml")
[ -n "$dual" ] && [ -n "$ours" ] || { echo "FAIL: could not parse (csdp '$dual', ours '$ours')"; exit 1; }
awk -v a="$ours" -v b="$dual" -v r="$rtol" 'BEGIN{
  d = (a - b) / b; if (d < 0) d = -d;
  printf "gamma^2: hinf-synth %.10g, csdp %.10g, rel diff %.2e (tol %s)\n", a, b, d, r;
  exit (d <= r) ? 0 : 1 }' || { echo "FAIL: gamma^2 differ"; exit 1; }
