#!/usr/bin/env bash
# Two `solve` runs of the same config must give byte-identical gains files apart from
# the `timing:` section (docs/maths.md [D13]), and leave nothing but the two files behind.
#   hinf_synth_determinism.sh EXE CONFIG
set -u
exe=$1 cfg=$2
work=$(mktemp -d "${TMPDIR:-/tmp}/hinf-det-XXXXXX")
trap 'rm -rf "$work"' EXIT
"$exe" solve "$cfg" -o "$work/a.yaml" >/dev/null || { echo "FAIL: first solve exit $?"; exit 1; }
"$exe" solve "$cfg" -o "$work/b.yaml" >/dev/null || { echo "FAIL: second solve exit $?"; exit 1; }
# drop the top-level `timing:` mapping (the key line and its indented lines)
strip() { awk '/^timing:/{skip=1; next} skip && /^[ \t]/{next} {skip=0; print}' "$1"; }
grep -q '^timing:' "$work/a.yaml" || { echo "FAIL: no timing section (format changed?)"; exit 1; }
grep -q '^gamma:' "$work/a.yaml" || { echo "FAIL: no gamma in the gains file"; exit 1; }
if ! cmp -s <(strip "$work/a.yaml") <(strip "$work/b.yaml"); then
  echo "FAIL: outputs differ outside timing:"
  diff <(strip "$work/a.yaml") <(strip "$work/b.yaml") | head -40
  exit 1
fi
n=$(ls -A "$work" | wc -l)
[ "$n" -eq 2 ] || { echo "FAIL: unexpected files: $(ls -A "$work")"; exit 1; }
echo "identical apart from timing: $(grep '^gamma:' "$work/a.yaml")"
