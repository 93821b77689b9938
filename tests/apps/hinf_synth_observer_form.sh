#!/usr/bin/env bash
# The observer form end to end (docs/maths.md §18), on the plants of tests/data/plants:
#   hinf_synth_observer_form.sh EXE PLANTS_DIR
# - the double integrator: solve exit 0, the gains file says form: observer and carries K,
#   verify exit 0; with one entry of A_F changed, verify exit 1 (the realisation is no longer
#   A − K C); codegen exit 0;
# - the triple integrator with a known input: solve exit 0 with G_F in the gains file,
#   verify exit 0; codegen exit 0 with G_F u in the C and a step that takes u;
# - kalman on the double integrator: a certified gains file whose H2 norm is below, and
#   gamma above, the H∞ filter's.
# - the filtered estimate x̂(k|k) of the double integrator (§18.6): solve exit 0 with
#   estimate: filtered, D_F and M in the gains file and a gamma below the predictor's; verify
#   exit 0, and exit 1 with D_F changed; codegen exit 0 with D_F y in the C; kalman gives
#   the Kalman filter x̂(k|k); compare exit 0.
set -u
exe=$1 plants=$2
work=$(mktemp -d "${TMPDIR:-/tmp}/hinf-observer-XXXXXX")
trap 'rm -rf "$work"' EXIT
fail=0
say() { echo "FAIL: $*"; fail=1; }
run() {  # expected_rc name args...
  local want=$1 name=$2
  shift 2
  "$exe" "$@" >"$work/$name.out" 2>"$work/$name.err"
  local rc=$?
  [ "$rc" -eq "$want" ] || { say "$name: exit $rc, expected $want"; cat "$work/$name.out" "$work/$name.err"; }
}

# tamper MATRIX IN OUT: OUT is the gains file IN with the first entry of filter.MATRIX + 1e-3
tamper() {
  python3 - "$1" "$2" "$3" <<'PY'
import sys
text = open(sys.argv[2]).read()
i = text.index("  " + sys.argv[1] + ":\n")
j = text.index("[", i) + 1
k = min(text.index(",", j), text.index("]", j))
open(sys.argv[3], "w").write(text[:j] + repr(float(text[j:k]) + 1e-3) + text[k:])
PY
}

dint=$plants/double-integrator.yaml
run 0 solve_dint solve "$dint" -o "$work/dint.yaml"
grep -q "^  form: observer$" "$work/dint.yaml" || say "gains file does not say form: observer"
grep -q "^  K:$" "$work/dint.yaml" || say "gains file has no filter.K"
grep -q "^bound: .*(A - K C) e" "$work/dint.yaml" || say "gains file does not state what gamma bounds"
grep -q "filter form: observer" "$work/solve_dint.out" || say "solve does not say which form it used"
run 0 verify_dint verify "$dint" "$work/dint.yaml"
grep -q "^verified" "$work/verify_dint.out" || say "verify did not verify"
# change the first entry of A_F's first row: no longer A − K C
tamper A_F "$work/dint.yaml" "$work/tampered.yaml"
run 1 verify_tampered verify "$dint" "$work/tampered.yaml"
grep -q "NOT A - K C" "$work/verify_tampered.out" || say "verify does not name the broken realisation"
mkdir "$work/c"
run 0 codegen_dint codegen "$work/dint.yaml" -o "$work/c" --prefix dint

# the Kalman predictor of the same plant: a certified gains file; its H2 below the H∞
# filter's, its gamma above (each filter wins in its own norm)
run 0 kalman_dint kalman "$dint" -o "$work/kalman.yaml"
grep -q "method: .Kalman one-step predictor" "$work/kalman.yaml" || say "kalman gains file does not say what it is"
run 0 verify_kalman verify "$dint" "$work/kalman.yaml"
h2() { sed -n 's/^  h2_norm_nominal: //p' "$1"; }
gam() { sed -n 's/^gamma: //p' "$1"; }
python3 -c "import sys; k2, h2, kg, hg = map(float, sys.argv[1:]); sys.exit(0 if k2 <= h2 * (1 + 1e-9) and kg >= hg * (1 - 1e-9) else 1)" \
  "$(h2 "$work/kalman.yaml")" "$(h2 "$work/dint.yaml")" "$(gam "$work/kalman.yaml")" "$(gam "$work/dint.yaml")" \
  || say "Kalman H2 $(h2 "$work/kalman.yaml") vs Hinf $(h2 "$work/dint.yaml"); gamma $(gam "$work/kalman.yaml") vs $(gam "$work/dint.yaml")"

dintf=$plants/double-integrator-filtered.yaml
run 0 solve_dintf solve "$dintf" -o "$work/dintf.yaml"
grep -q "^  estimate: filtered$" "$work/dintf.yaml" || say "gains file does not say estimate: filtered"
grep -q "^  D_F:$" "$work/dintf.yaml" || say "gains file has no filter.D_F"
grep -q "^  M:$" "$work/dintf.yaml" || say "gains file has no filter.M"
grep -q "filtered estimate" "$work/solve_dintf.out" || say "solve does not say it gives the filtered estimate"
python3 -c "import sys; f, p = map(float, sys.argv[1:]); sys.exit(0 if f < p else 1)" \
  "$(gam "$work/dintf.yaml")" "$(gam "$work/dint.yaml")" \
  || say "filtered gamma $(gam "$work/dintf.yaml") not below the predictor's $(gam "$work/dint.yaml")"
run 0 verify_dintf verify "$dintf" "$work/dintf.yaml"
grep -q "L - L M C, L M, G to" "$work/verify_dintf.out" || say "verify does not check the filtered realisation"
tamper D_F "$work/dintf.yaml" "$work/tamperedf.yaml"
run 1 verify_tamperedf verify "$dintf" "$work/tamperedf.yaml"
grep -q "NOT A - K C, K, L - L M C, L M, G" "$work/verify_tamperedf.out" || say "verify does not name the broken filtered realisation"
mkdir "$work/c3"
run 0 codegen_dintf codegen "$work/dintf.yaml" -o "$work/c3" --prefix dintf
grep -q "dintf_D_F\[i\]\[j\] \* y\[j\]" "$work/c3/dintf.c" || say "the generated C has no feedthrough D_F y"
run 0 kalman_dintf kalman "$dintf" -o "$work/kalmanf.yaml"
grep -q "method: .\?Kalman filter, estimate x_hat(k|k)" "$work/kalmanf.yaml" || say "kalman does not give the Kalman filter"
run 0 verify_kalmanf verify "$dintf" "$work/kalmanf.yaml"
run 0 compare_dintf compare "$dintf" "$work/dintf.yaml"

tint=$plants/triple-integrator-known-input.yaml
run 0 solve_tint solve "$tint" -o "$work/tint.yaml"
grep -q "^  G_F:$" "$work/tint.yaml" || say "gains file has no filter.G_F"
grep -q "r: 1" "$work/tint.yaml" || say "gains file dimensions lack r"
run 0 verify_tint verify "$tint" "$work/tint.yaml"
mkdir "$work/c2"
run 0 codegen_tint codegen "$work/tint.yaml" -o "$work/c2" --prefix tint
grep -q "tint_G_F\[i\]\[j\] \* u\[j\]" "$work/c2/tint.c" || say "the generated C has no known input G_F u"
grep -q "void tint_step(tint_state \*s, const double y\[TINT_NY\], const double u\[TINT_NU\], double z\[TINT_NZ\]);" \
  "$work/c2/tint.h" || say "the generated step does not take the known input u"
exit $fail
