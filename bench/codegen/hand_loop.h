/* Hand-written reference implementation of the paper's filter (docs/maths.md (5)-(6)) for
 * bench_codegen: the plain C loop a flight-software engineer would write. */
#ifndef HINF_BENCH_HAND_LOOP_H
#define HINF_BENCH_HAND_LOOP_H

#ifdef __cplusplus
extern "C" {
#endif

void hand_step(double x[6], const double y[3], double z[6]);
void hand_step_f(float x[6], const float y[3], float z[6]);

#ifdef __cplusplus
}
#endif

#endif
