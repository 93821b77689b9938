/* Hand-written step of the paper's published filter (docs/maths.md (78)-(80)), typed
 * from that document, not from generated code: z = C_F x, then x = A_F x + B_F y. */
#include "hand_loop.h"

/* The coefficients, written once; R(v) makes each literal a double (R_DOUBLE) or, with the
 * suffix f, a float (R_FLOAT): the same decimal text either way. */
#define HAND_A(R)                                                           \
  {{R(-0.6126), R(-0.0053), R(-0.0046), R(0.1), R(-1.7e-6), R(-1.0e-6)},   \
   {R(-0.0052), R(-0.6083), R(-0.0035), R(-1.5e-6), R(0.1), R(-1.4e-6)},   \
   {R(-0.0046), R(-0.0035), R(-0.6066), R(-1.5e-6), R(-5.6e-7), R(0.1)},   \
   {R(-6.1302), R(-0.0390), R(-0.0337), R(0.9980), R(1.1e-4), R(8.2e-5)},  \
   {R(-0.0385), R(-6.0991), R(-0.0259), R(8.0e-5), R(0.9979), R(6.3e-5)},  \
   {R(-0.0337), R(-0.0259), R(-6.0864), R(8.3e-5), R(6.4e-5), R(0.9979)}}
#define HAND_B(R)                                                                          \
  {{R(-1.6126), R(-0.0053), R(-0.0046)}, {R(-0.0052), R(-1.6083), R(-0.0035)},           \
   {R(-0.0046), R(-0.0035), R(-1.6066)}, {R(-6.1300), R(-0.0390), R(-0.0337)},           \
   {R(-0.0385), R(-6.0989), R(-0.0259)}, {R(-0.0337), R(-0.0259), R(-6.0862)}}
#define HAND_C(R)                                                                                         \
  {{R(-1.0), R(0.0489e-6), R(0.0247e-6), R(6.3345e-6), R(-5.4934e-6), R(-4.3894e-6)},                  \
   {R(0.0386e-6), R(-1.0), R(0.0418e-6), R(-5.3662e-6), R(10.3349e-6), R(-2.9326e-6)},                 \
   {R(0.0420e-6), R(0.0148e-6), R(-1.0), R(-4.5742e-6), R(-2.9659e-6), R(11.3677e-6)},                 \
   {R(-0.3164e-6), R(0.3131e-6), R(0.1588e-6), R(-0.999960), R(-33.635e-6), R(-28.487e-6)},            \
   {R(0.2469e-6), R(-0.5593e-6), R(0.2630e-6), R(-33.612e-6), R(-0.999935), R(-19.564e-6)},            \
   {R(0.2712e-6), R(0.0939e-6), R(-0.5821e-6), R(-28.520e-6), R(-19.572e-6), R(-0.999927)}}
#define R_DOUBLE(v) v
#define R_FLOAT(v) v##f

/* One step, z = C_F x then x = A_F x + B_F y, in the arithmetic type REAL. */
#define HAND_STEP(NAME, REAL, R)                         \
  void NAME(REAL x[6], const REAL y[3], REAL z[6])       \
  {                                                      \
    static const REAL A[6][6] = HAND_A(R);               \
    static const REAL B[6][3] = HAND_B(R);               \
    static const REAL C[6][6] = HAND_C(R);               \
    REAL xn[6];                                          \
    int i, j;                                            \
    for (i = 0; i < 6; ++i) {                            \
      REAL s = R(0.0);                                   \
      for (j = 0; j < 6; ++j) s += C[i][j] * x[j];       \
      z[i] = s;                                          \
    }                                                    \
    for (i = 0; i < 6; ++i) {                            \
      REAL s = R(0.0);                                   \
      for (j = 0; j < 6; ++j) s += A[i][j] * x[j];       \
      for (j = 0; j < 3; ++j) s += B[i][j] * y[j];       \
      xn[i] = s;                                         \
    }                                                    \
    for (i = 0; i < 6; ++i) x[i] = xn[i];                \
  }

HAND_STEP(hand_step, double, R_DOUBLE)
HAND_STEP(hand_step_f, float, R_FLOAT)
