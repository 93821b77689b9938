#!/usr/bin/env bash
# Outputs that must be refused without touching anything (issue 13):
#   hinf_synth_hostile_outputs.sh HINF_SYNTH CONFIG GAINS
# 1. solve / export-sdpa with -o the config itself (by its path, and by another path to
#    the same file): exit 2 "is the input file", the config unchanged;
# 2. codegen writing over its own gains file (named like a generated file): exit 2;
# 3. solve under a 1 KiB file-size limit (ulimit -f 1): exit 2 naming "File too large",
#    no process killed by SIGXFSZ, no temporary left.
set -u
exe=$1 config=$2 gains=$3
work=$(mktemp -d "${TMPDIR:-/tmp}/hinf-hostile-XXXXXX")
trap 'rm -rf "$work"' EXIT
fail=0
say() { echo "FAIL: $*"; fail=1; }
expect() {  # expect RC REGEX CMD...
  local rc=$1 re=$2; shift 2
  "$@" >"$work/stdout" 2>"$work/stderr"
  local got=$?
  [ "$got" -eq "$rc" ] || say "exit $got, expected $rc: $*"
  grep -Eq -- "$re" "$work/stderr" || { say "stderr does not match /$re/: $*"; cat "$work/stderr"; }
}
mkdir "$work/a" "$work/b"
cp "$config" "$work/a/cfg.yaml"
cp "$work/a/cfg.yaml" "$work/orig.yaml"
ln "$work/a/cfg.yaml" "$work/b/hardlink.yaml"
expect 2 "is the input file" "$exe" solve "$work/a/cfg.yaml" -o "$work/a/cfg.yaml"
expect 2 "is the input file" "$exe" solve "$work/a/cfg.yaml" -o "$work/a/../a/cfg.yaml"
expect 2 "is the input file" "$exe" solve "$work/a/cfg.yaml" -o "$work/b/hardlink.yaml"
expect 2 "is the input file" "$exe" export-sdpa "$work/a/cfg.yaml" -o "$work/a/cfg.yaml"
cmp -s "$work/a/cfg.yaml" "$work/orig.yaml" || say "the config was changed"
[ "$(ls -A "$work/a")" = "cfg.yaml" ] || say "files left beside the config: $(ls -A "$work/a")"
mkdir "$work/gen"
cp "$gains" "$work/gen/nav.h"
cp "$gains" "$work/gains-orig.yaml"
expect 2 "is the input file" "$exe" codegen "$work/gen/nav.h" --prefix nav -o "$work/gen"
cmp -s "$work/gen/nav.h" "$work/gains-orig.yaml" || say "codegen replaced its input"
[ "$(ls -A "$work/gen")" = "nav.h" ] || say "files left by codegen: $(ls -A "$work/gen")"
mkdir "$work/limited"
bash -c 'ulimit -f 1 && exec "$@"' _ "$exe" solve "$work/orig.yaml" -o "$work/limited/gains.yaml" \
  >"$work/stdout" 2>"$work/stderr"
rc=$?
[ "$rc" -eq 2 ] || say "under ulimit -f 1: exit $rc, expected 2"
grep -q "File too large" "$work/stderr" || { say "under ulimit -f 1: no 'File too large'"; cat "$work/stderr"; }
[ -z "$(ls -A "$work/limited")" ] || say "under ulimit -f 1: left $(ls -A "$work/limited")"
exit $fail
