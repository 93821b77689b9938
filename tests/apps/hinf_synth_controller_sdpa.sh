#!/usr/bin/env bash
# A controller config's `export-sdpa` solved by CSDP must agree with `solve`: γ (the
# exported LMI's optimum times the equilibration factor the file states) within RTOL.
#   hinf_synth_controller_sdpa.sh EXE CSDP CONFIG RTOL
set -u
exe=$1 csdp=$2 cfg=$3 rtol=$4
work=$(mktemp -d "${TMPDIR:-/tmp}/hinf-ctl-sdpa-XXXXXX")
trap 'rm -rf "$work"' EXIT
"$exe" export-sdpa "$cfg" -o "$work/lmi.dat-s" >/dev/null || { echo "FAIL: export-sdpa exit $?"; exit 1; }
"$exe" solve "$cfg" -o "$work/controller.yaml" >/dev/null || { echo "FAIL: solve exit $?"; exit 1; }
(cd "$work" && "$csdp" lmi.dat-s lmi.sol >csdp.out 2>&1)
crc=$?
[ $crc -eq 0 ] || { echo "FAIL: csdp exit $crc"; cat "$work/csdp.out"; exit 1; }
dual=$(awk -F: '/Dual objective value/{gsub(/ /,"",$2); print $2}' "$work/csdp.out")
factor=$(sed -n 's/.*gamma = it times \([0-9.eE+-]*\) .*/\1/p' "$work/lmi.dat-s" | head -1)
ours=$(awk '/^gamma:/{print $2}' "$work/controller.yaml")
[ -n "$dual" ] && [ -n "$factor" ] && [ -n "$ours" ] || { echo "FAIL: could not parse (csdp '$dual', factor '$factor', ours '$ours')"; exit 1; }
awk -v a="$ours" -v b="$dual" -v f="$factor" -v r="$rtol" 'BEGIN{
  b = b * f; d = (a - b) / b; if (d < 0) d = -d;
  printf "gamma: hinf-synth %.10g, csdp %.10g, rel diff %.2e (tol %s)\n", a, b, d, r;
  exit (d <= r) ? 0 : 1 }' || { echo "FAIL: gamma differs"; exit 1; }
echo PASS
