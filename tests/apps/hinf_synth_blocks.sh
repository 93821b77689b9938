#!/usr/bin/env bash
# Block-diagonal uncertainty end to end (docs/maths.md §23): solve, then verify and analyze
# the gains without the solver's help, each naming the per-block multipliers:
#   hinf_synth_blocks.sh EXE CONFIG
set -u
exe=$1 config=$2
work=$(mktemp -d "${TMPDIR:-/tmp}/hinf-blocks-XXXXXX")
trap 'rm -rf "$work"' EXIT
fail=0
"$exe" solve "$config" -o "$work/g.yaml" > "$work/out" 2>&1 || { echo "FAIL: solve"; cat "$work/out"; exit 1; }
grep -q "F = diag(F_1, F_2)" "$work/out" || { echo "FAIL: solve does not say F is block-diagonal"; cat "$work/out"; fail=1; }
grep -q "robust_block_multipliers: \[" "$work/g.yaml" || { echo "FAIL: no robust_block_multipliers in the gains"; fail=1; }
"$exe" verify "$config" "$work/g.yaml" > "$work/out" 2>&1
rc=$?
[ "$rc" -eq 0 ] || { echo "FAIL: verify exit $rc"; cat "$work/out"; fail=1; }
grep -q "S-procedure multipliers \[.*\] (one per block of F)" "$work/out" ||
  { echo "FAIL: verify does not name the blocks' multipliers"; cat "$work/out"; fail=1; }
"$exe" analyze "$config" "$work/g.yaml" > "$work/out" 2>&1 || { echo "FAIL: analyze"; cat "$work/out"; fail=1; }
grep -q "^worst case found" "$work/out" || { echo "FAIL: analyze without the worst case found"; cat "$work/out"; fail=1; }
exit $fail
