#!/usr/bin/env bash
# Runs one libFuzzer harness for SECONDS on a fresh corpus seeded from SEED_DIR...; exits
# non-zero on any finding (crash, sanitizer report, leak, timeout of one input, memory
# beyond the limit) and prints the executions done.
#   run_harness.sh HARNESS SECONDS SEED_DIR...
# With HINF_FUZZ_RUNS=N in the environment it stops after N executions instead (SECONDS
# is then only a ceiling), as docs/benchmarks.md "Fuzzing" measures.
set -u
harness=$1 seconds=$2
shift 2
work=$(mktemp -d "${TMPDIR:-/tmp}/hinf-fuzz-XXXXXX")
trap 'rm -rf "$work"' EXIT
mkdir "$work/corpus" "$work/artifacts"
runs=()
[ -n "${HINF_FUZZ_RUNS:-}" ] && runs=(-runs="$HINF_FUZZ_RUNS")
"$harness" "$work/corpus" "$@" "${runs[@]}" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
  -max_len=8192 -print_final_stats=1 -artifact_prefix="$work/artifacts/" > "$work/log" 2>&1
rc=$?
grep -E "^stat::number_of_executed_units|^stat::peak_rss_mb" "$work/log"
if [ $rc -ne 0 ] || [ -n "$(ls -A "$work/artifacts")" ]; then
  echo "FINDING (exit $rc):"
  tail -60 "$work/log"
  for f in "$work"/artifacts/*; do [ -e "$f" ] && { echo "--- input $f:"; head -c 2000 "$f" | od -c | head -40; }; done
  exit 1
fi
echo "no finding in $seconds s"
