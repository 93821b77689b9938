#!/usr/bin/env bash
# One end-to-end case of the hinf-synth executable.
#   hinf_synth_case.sh EXE EXPECTED_RC STDERR_REGEX [ARG...]
# In ARGs, @OUTDIR@ is a fresh empty directory, @OUT@ = @OUTDIR@/gains.yaml and
# @WORK@ its parent. Passes iff: the exit code is EXPECTED_RC (and < 128: no crash),
# stderr matches the extended regex, and — for a failing run — @OUTDIR@ is still empty
# (no output file, no temporary file left behind); for a successful run it holds at
# most gains.yaml. STDERR_REGEX "-" skips the message check.
set -u
exe=$1 expected=$2 pattern=$3
shift 3
work=$(mktemp -d "${TMPDIR:-/tmp}/hinf-cli-XXXXXX")
trap 'rm -rf "$work"' EXIT
outdir=$work/out
mkdir "$outdir"
args=()
for a in "$@"; do
  a=${a//@OUTDIR@/$outdir}
  a=${a//@OUT@/$outdir/gains.yaml}
  a=${a//@WORK@/$work}
  args+=("$a")
done
"$exe" "${args[@]}" >"$work/stdout" 2>"$work/stderr"
rc=$?
fail=0
say() { echo "FAIL: $*"; fail=1; }
[ "$rc" -lt 128 ] || say "crashed (exit $rc)"
[ "$rc" -eq "$expected" ] || say "exit code $rc, expected $expected"
if [ "$pattern" != "-" ]; then
  grep -Eq -- "$pattern" "$work/stderr" || say "stderr does not match /$pattern/"
fi
left=$(ls -A "$outdir")
if [ "$expected" -ne 0 ]; then
  [ -z "$left" ] || say "files left in the output directory: $left"
elif [ -n "$left" ] && [ "$left" != "gains.yaml" ]; then
  say "unexpected files in the output directory: $left"
fi
if [ $fail -ne 0 ]; then
  echo "command: $exe ${args[*]}"
  echo "--- stdout"; cat "$work/stdout"
  echo "--- stderr"; cat "$work/stderr"
fi
exit $fail
