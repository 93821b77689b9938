// PwmModulator and PwpfModulator (hinf/runtime/pulse_modulator.hpp). Expected values come
// from hand calculation (PWM pulse patterns) and from the closed-form static characteristics
// of the PWPF modulator (below, derived from the continuous loop, not from the header),
// never from the code under test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "hinf/runtime/pulse_modulator.hpp"

using hinf::runtime::PwmModulator;
using hinf::runtime::PwmSettings;
using hinf::runtime::PwpfModulator;
using hinf::runtime::PwpfSettings;

namespace {

const double kPi = std::acos(-1.0);

// ---------------------------------------------------------------------------------------
// PWM helpers.

// Whether `what` (an exception message) names `setting` as the offending one.
void expect_names(const std::string& what, const std::string& cls, const std::string& setting,
                  const std::string& value) {
  EXPECT_NE(what.find("hinf::runtime::" + cls + ": " + setting + " must"), std::string::npos) << what;
  EXPECT_NE(what.find("got " + value), std::string::npos) << what;
}

struct PwmRun {
  std::vector<PwmModulator::Pulse> pulses;  // one per period
  double max_abs_error = 0.0;               // max over period ends of |int U dt - int force dt| (N s)
  double final_error = 0.0;
  long shortest_firing = std::numeric_limits<long>::max();  // ticks, over contiguous firings
  long firings = 0;
  bool outputs_in_range = true;   // every tick output in {-1, 0, +1}
  double max_error_vs_carry = 0.0;  // |error - carry()| at period ends (should be round-off)
};

// Simulates `periods` periods on the resolution grid: at each period start the command is
// sampled (zero-order hold over the period, which is what the modulator is asked to realise),
// and the force F u is integrated tick by tick.
PwmRun run_pwm(PwmModulator& pwm, long periods, const std::function<double(double)>& command) {
  const PwmSettings& s = pwm.settings();
  const long N = pwm.ticks_per_period();
  PwmRun run;
  // Delivered impulse = F delta (signed count of firing ticks), counted exactly in integers.
  double commanded = 0.0;
  long delivered_ticks = 0;
  int prev = 0;
  long run_len = 0;
  auto close_firing = [&] {
    if (run_len > 0) {
      run.shortest_firing = std::min(run.shortest_firing, run_len);
      ++run.firings;
    }
    run_len = 0;
  };
  for (long k = 0; k < periods; ++k) {
    const double U = command(static_cast<double>(k) * s.period);
    const PwmModulator::Pulse p = pwm.begin_period(U);
    run.pulses.push_back(p);
    commanded += U * s.period;
    for (long i = 0; i < N; ++i) {
      const int u = p.output_at_tick(i);
      if (u != -1 && u != 0 && u != 1) run.outputs_in_range = false;
      delivered_ticks += u;
      if (u != prev) close_firing();
      if (u != 0) ++run_len;
      prev = u;
    }
    const double err = commanded - s.thruster.force * s.resolution * static_cast<double>(delivered_ticks);
    run.max_abs_error = std::max(run.max_abs_error, std::abs(err));
    run.max_error_vs_carry = std::max(run.max_error_vs_carry, std::abs(err - pwm.carry()));
    run.final_error = err;
  }
  close_firing();
  return run;
}

void expect_pulse_consistent(const PwmModulator& pwm, const PwmModulator::Pulse& p) {
  const PwmSettings& s = pwm.settings();
  EXPECT_TRUE(p.sign == -1 || p.sign == 0 || p.sign == 1) << p.sign;
  if (p.sign == 0) {
    EXPECT_EQ(p.on_ticks, 0);
    EXPECT_EQ(p.on_time, 0.0);
  } else {
    EXPECT_GE(p.on_time, s.thruster.min_on_time - 1e-12);
    EXPECT_LE(p.on_time, s.period + 1e-12);
    EXPECT_NEAR(p.on_time, static_cast<double>(p.on_ticks) * s.resolution, 1e-12);
  }
}

// ---------------------------------------------------------------------------------------
// PWPF: the closed-form static characteristics for a constant normalised input E > 0,
// from the continuous loop tau df/dt = K_m (E - u) - f with the relay u_on / u_off.
// Off phase (u = 0): f rises from u_off towards K_m E and reaches u_on after T_off;
// on phase (u = 1): f falls from u_on towards K_m (E - 1) and reaches u_off after T_on.
struct PwpfClosedForm {
  double Km, tau, u_on, u_off;
  explicit PwpfClosedForm(const PwpfSettings& s) : Km(s.Km), tau(s.tau), u_on(s.u_on), u_off(s.u_off) {}
  double h() const { return u_on - u_off; }
  double T_on(double E) const { return -tau * std::log(1.0 - h() / (u_on + Km * (1.0 - E))); }
  double T_off(double E) const { return -tau * std::log(1.0 - h() / (Km * E - u_off)); }
  double min_pulse() const { return -tau * std::log(1.0 - h() / Km); }  // T_on(E_d)
  double dead_zone() const { return u_on / Km; }                        // E_d
  double saturation() const { return 1.0 + u_off / Km; }                // E_s
  double duty(double E) const { return T_on(E) / (T_on(E) + T_off(E)); }
};

// u[k] is the output applied over [k dt, (k+1) dt): output() before step k.
std::vector<int> run_pwpf(PwpfModulator& m, double E, double dt, long steps) {
  const double F = m.settings().thruster.force;
  std::vector<int> u;
  u.reserve(static_cast<std::size_t>(steps));
  for (long k = 0; k < steps; ++k) {
    u.push_back(m.output());
    m.step(E * F, dt);
  }
  return u;
}

struct Firing {
  int sign;
  long start;   // index of the first step with this output
  long length;  // steps
};

// Maximal runs of a constant non-zero output (a direct reversal gives two firings). The last
// run is dropped if it reaches the end of the trace (it may be incomplete).
std::vector<Firing> firings(const std::vector<int>& u) {
  std::vector<Firing> out;
  const long n = static_cast<long>(u.size());
  long k = 0;
  while (k < n) {
    const int v = u[static_cast<std::size_t>(k)];
    if (v == 0) {
      ++k;
      continue;
    }
    long j = k;
    while (j < n && u[static_cast<std::size_t>(j)] == v) ++j;
    if (j < n) out.push_back({v, k, j - k});
    k = j;
  }
  return out;
}

struct Measured {
  double worst_on_error = 0.0;   // s
  double worst_off_error = 0.0;  // s
  int on_samples = 0, off_samples = 0;
};

// Steady pulses only: the first firing and the gap before it (transient from f = 0) are skipped.
Measured measure(const std::vector<Firing>& fs, double dt, double T_on, double T_off, int sign) {
  Measured m;
  for (std::size_t i = 1; i < fs.size(); ++i) {
    EXPECT_EQ(fs[i].sign, sign);
    m.worst_on_error = std::max(m.worst_on_error, std::abs(static_cast<double>(fs[i].length) * dt - T_on));
    ++m.on_samples;
    if (i + 1 < fs.size()) {
      const long gap = fs[i + 1].start - (fs[i].start + fs[i].length);
      m.worst_off_error = std::max(m.worst_off_error, std::abs(static_cast<double>(gap) * dt - T_off));
      ++m.off_samples;
    }
  }
  return m;
}

}  // namespace

// =======================================================================================
// PWM

TEST(PwmModulator, ConstantCommandsGiveHandComputedPulses) {
  // F = 5 N, T_m = 1 s, delta = 1 ms: one tick carries F delta = 0.005 N s.
  {
    PwmModulator pwm;  // 0.3 N: I = 0.3 N s -> 0.06 s = 60 ticks every period, carry 0
    for (int k = 0; k < 20; ++k) {
      const auto p = pwm.begin_period(0.3);
      EXPECT_EQ(p.sign, 1);
      EXPECT_EQ(p.on_ticks, 60) << "period " << k;
      EXPECT_NEAR(p.on_time, 0.060, 1e-12);
      EXPECT_NEAR(pwm.carry(), 0.0, 1e-12);
    }
  }
  {
    PwmModulator pwm;  // 1.83 N: 1.83 / 5 = 0.366 s
    for (int k = 0; k < 20; ++k) {
      const auto p = pwm.begin_period(1.83);
      EXPECT_EQ(p.sign, 1);
      EXPECT_EQ(p.on_ticks, 366) << "period " << k;
    }
  }
  {
    // 0.3013 N: 60.26 ticks wanted. Rounding to nearest with carry (by hand):
    // I = .3013 -> 60 (c +.0013); .3026 -> 61 (c -.0024); .2989 -> 60 (c -.0011);
    // .3002 -> 60 (c +.0002); .3015 -> 60 (c +.0015); .3028 -> 61 (c -.0022).
    PwmModulator pwm;
    const long expected[] = {60, 61, 60, 60, 60, 61};
    const double expected_carry[] = {0.0013, -0.0024, -0.0011, 0.0002, 0.0015, -0.0022};
    for (int k = 0; k < 6; ++k) {
      const auto p = pwm.begin_period(0.3013);
      EXPECT_EQ(p.on_ticks, expected[k]) << "period " << k;
      EXPECT_NEAR(pwm.carry(), expected_carry[k], 1e-12) << "period " << k;
    }
  }
}

TEST(PwmModulator, ImpulseMatchesCommandWithinCarryBound) {
  const PwmSettings s;
  const double F = s.thruster.force, delta = s.resolution;
  const double bound = s.carry_limit + F * delta / 2.0;  // 0.2025 N s
  // Sharper, below saturation: without a pulse |I_req| < F delta (40 - 1/2) (else it would
  // round to >= 40 ticks), with a pulse |carry| <= F delta / 2, so |error| < 0.1975 N s.
  const double sharp = F * (s.thruster.min_on_time - delta / 2.0);
  struct Case {
    const char* name;
    std::function<double(double)> U;
  };
  const std::vector<Case> cases = {
      {"0.3 N", [](double) { return 0.3; }},
      {"1.83 N", [](double) { return 1.83; }},
      {"-0.05 N", [](double) { return -0.05; }},
      {"0.3013 N", [](double) { return 0.3013; }},
      {"-2.0017 N", [](double) { return -2.0017; }},
      {"sinusoid", [](double t) { return 0.2 + 1.5 * std::sin(2.0 * kPi * t / 137.0); }},
      {"slow small sinusoid", [](double t) { return 0.12 * std::sin(2.0 * kPi * t / 400.0 + 0.3); }},
  };
  for (const Case& c : cases) {
    PwmModulator pwm(s);
    const PwmRun run = run_pwm(pwm, 800, c.U);
    EXPECT_LE(run.max_abs_error, bound) << c.name;
    EXPECT_LT(run.max_abs_error, sharp) << c.name;
    EXPECT_TRUE(run.outputs_in_range) << c.name;
    EXPECT_GT(run.firings, 0) << c.name;
    EXPECT_GE(run.shortest_firing, 40) << c.name;  // no firing shorter than t_min = 40 ms
    // No clamping below saturation: the error is exactly the carry (up to round-off).
    EXPECT_LE(run.max_error_vs_carry, 1e-9) << c.name;
    for (const auto& p : run.pulses) expect_pulse_consistent(pwm, p);
    std::printf("[ measured ] PWM %-20s max |impulse error| = %.6f N s (bounds %.4f, %.4f)\n", c.name,
                run.max_abs_error, bound, sharp);
  }
}

TEST(PwmModulator, SmallCommandFiresMinimumImpulseEveryFourPeriods) {
  // 0.05 N: 0.05 N s per period; 4 periods make 0.2 N s = F t_min -> one 40 ms pulse.
  for (double U : {0.05, -0.05}) {
    PwmModulator pwm;
    for (int k = 0; k < 40; ++k) {
      const auto p = pwm.begin_period(U);
      if (k % 4 == 3) {
        EXPECT_EQ(p.sign, U > 0 ? 1 : -1) << "period " << k;
        EXPECT_EQ(p.on_ticks, 40) << "period " << k;
        EXPECT_NEAR(pwm.carry(), 0.0, 1e-12);
      } else {
        EXPECT_EQ(p.sign, 0) << "period " << k;
        EXPECT_NEAR(pwm.carry(), U * (k % 4 + 1), 1e-12) << "period " << k;
      }
    }
  }
  // T_m = 0.1 s, 0.3 N: 0.03 N s per period; the 7th period holds 0.21 N s -> 42 ms
  // (the 6th, 0.18 N s = 36 ms, is below t_min).
  PwmSettings s;
  s.period = 0.1;
  PwmModulator pwm(s);
  EXPECT_EQ(pwm.ticks_per_period(), 100);
  for (int k = 0; k < 35; ++k) {
    const auto p = pwm.begin_period(0.3);
    EXPECT_EQ(p.on_ticks, k % 7 == 6 ? 42 : 0) << "period " << k;
  }
}

TEST(PwmModulator, SaturationFiresWholePeriodAndCarriesAtMostTheLimit) {
  for (double sgn : {1.0, -1.0}) {
    PwmModulator pwm;
    const auto p = pwm.begin_period(sgn * 7.0);  // 7 N > F: t_on = T_m, carry 2 N s clamped to 0.2
    EXPECT_EQ(p.sign, static_cast<int>(sgn));
    EXPECT_EQ(p.on_ticks, 1000);
    EXPECT_DOUBLE_EQ(p.on_time, 1.0);
    EXPECT_DOUBLE_EQ(pwm.carry(), sgn * 0.2);
    const auto q = pwm.begin_period(0.0);  // the carried 0.2 N s: one 40 ms pulse
    EXPECT_EQ(q.sign, static_cast<int>(sgn));
    EXPECT_EQ(q.on_ticks, 40);
    EXPECT_NEAR(pwm.carry(), 0.0, 1e-12);
    EXPECT_EQ(pwm.begin_period(0.0).sign, 0);
  }
  PwmModulator pwm;
  EXPECT_EQ(pwm.begin_period(4.9).on_ticks, 980);  // just below F: not saturated
  EXPECT_EQ(pwm.begin_period(5.0).on_ticks, 1000);
  EXPECT_NEAR(pwm.carry(), 0.0, 1e-12);
}

TEST(PwmModulator, WithoutCarrySmallCommandsAreDropped) {
  PwmSettings s;
  s.carry_remainder = false;
  PwmModulator pwm(s);
  for (int k = 0; k < 100; ++k) {
    EXPECT_EQ(pwm.begin_period(0.15).sign, 0);  // 0.15 N s = 30 ms < t_min, every period
    EXPECT_EQ(pwm.carry(), 0.0);
  }
  for (int k = 0; k < 10; ++k) EXPECT_EQ(pwm.begin_period(0.3013).on_ticks, 60);  // 60.26 -> 60, no carry
  const PwmRun run = run_pwm(pwm, 100, [](double) { return 0.15; });
  EXPECT_EQ(run.firings, 0);
  EXPECT_NEAR(run.final_error, 15.0, 1e-9);  // everything commanded was dropped
}

TEST(PwmModulator, OutputOnTheTickGrid) {
  PwmModulator pwm;
  const auto p = pwm.begin_period(-0.2);  // 40 ticks of -1
  ASSERT_EQ(p.on_ticks, 40);
  EXPECT_EQ(p.output_at_tick(-1), 0);
  EXPECT_EQ(p.output_at_tick(0), -1);
  EXPECT_EQ(p.output_at_tick(39), -1);
  EXPECT_EQ(p.output_at_tick(40), 0);
  EXPECT_EQ(p.output_at_tick(999), 0);
  for (long k = 0; k <= 1000; ++k)
    EXPECT_EQ(pwm.output_at_time(p, static_cast<double>(k) * 1e-3), p.output_at_tick(k)) << k;
  double t = 0.0;  // time accumulated by repeated addition, as a simulator would
  for (long k = 0; k <= 100; ++k, t += 1e-3) EXPECT_EQ(pwm.output_at_time(p, t), p.output_at_tick(k)) << k;
  EXPECT_EQ(pwm.output_at_time(p, 0.0395), -1);
  EXPECT_EQ(pwm.output_at_time(p, 0.0405), 0);
  EXPECT_EQ(pwm.output_at_time(p, -1e-3), 0);
  EXPECT_EQ(pwm.output_at_time(p, std::numeric_limits<double>::quiet_NaN()), 0);
}

TEST(PwmModulator, NonFiniteCommandFiresNothingAndKeepsCarry) {
  PwmModulator pwm;
  pwm.begin_period(0.15);
  ASSERT_NEAR(pwm.carry(), 0.15, 1e-12);
  for (double U : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                   -std::numeric_limits<double>::infinity()}) {
    const auto p = pwm.begin_period(U);
    EXPECT_EQ(p.sign, 0);
    EXPECT_EQ(p.on_ticks, 0);
    EXPECT_NEAR(pwm.carry(), 0.15, 1e-12);
  }
  const auto p = pwm.begin_period(1e308);  // finite but U T_m huge: saturated, carry clamped
  EXPECT_EQ(p.on_ticks, 1000);
  EXPECT_DOUBLE_EQ(pwm.carry(), 0.2);
  pwm.reset();
  EXPECT_EQ(pwm.carry(), 0.0);
}

TEST(PwmModulator, SettingsValidationNamesTheSetting) {
  struct Bad {
    std::function<void(PwmSettings&)> set;
    const char* setting;
    const char* value;
  };
  const std::vector<Bad> bad = {
      {[](PwmSettings& s) { s.period = -1.0; }, "period", "-1"},
      {[](PwmSettings& s) { s.period = std::numeric_limits<double>::infinity(); }, "period", "inf"},
      {[](PwmSettings& s) { s.resolution = 0.0; }, "resolution", "0"},
      {[](PwmSettings& s) { s.resolution = 2.0; }, "resolution", "2"},
      {[](PwmSettings& s) { s.resolution = 3e-4; }, "period / resolution", "3333.33"},
      {[](PwmSettings& s) { s.carry_limit = -0.1; }, "carry_limit", "-0.1"},
      {[](PwmSettings& s) { s.thruster.force = 0.0; }, "thruster.force", "0"},
      {[](PwmSettings& s) { s.thruster.force = std::numeric_limits<double>::quiet_NaN(); }, "thruster.force", "nan"},
      {[](PwmSettings& s) { s.thruster.min_on_time = -0.01; }, "thruster.min_on_time", "-0.01"},
      {[](PwmSettings& s) { s.thruster.min_on_time = 1.5; }, "thruster.min_on_time", "1.5"},
  };
  for (const Bad& b : bad) {
    PwmSettings s;
    b.set(s);
    try {
      PwmModulator pwm(s);
      ADD_FAILURE() << "no exception for " << b.setting;
    } catch (const std::invalid_argument& e) {
      expect_names(e.what(), "PwmModulator", b.setting, b.value);
    }
  }
  PwmSettings ok;
  ok.thruster.min_on_time = 0.0;  // allowed: every non-zero tick count fires
  ok.carry_limit = 0.0;
  PwmModulator pwm(ok);
  EXPECT_EQ(pwm.begin_period(0.003).on_ticks, 1);  // 0.6 ticks -> 1
  EXPECT_EQ(pwm.begin_period(0.002).on_ticks, 0);  // 0.4 ticks -> 0: no pulse
}

// =======================================================================================
// PWPF

TEST(PwpfModulator, ExactDiscretisationOfTheFilter) {
  // Below the dead zone the output stays 0 and f(t) = K_m E (1 - e^{-t/tau}) exactly, for
  // any step sizes (the step uses the exact solution, not an integration scheme).
  const PwpfSettings s;
  const double E = 0.099;
  PwpfModulator a(s), b(s);
  for (int k = 0; k < 2000; ++k) EXPECT_EQ(a.step(E * s.thruster.force, 1e-3), 0);
  EXPECT_NEAR(a.filter_state(), s.Km * E * (1.0 - std::exp(-2.0 / s.tau)), 1e-12);
  std::mt19937 g(7);
  std::uniform_real_distribution<double> udt(1e-4, 2e-2);
  double t = 0.0;
  for (int k = 0; k < 300; ++k) {
    const double dt = udt(g);
    b.step(E * s.thruster.force, dt);
    t += dt;
    ASSERT_NEAR(b.filter_state(), s.Km * E * (1.0 - std::exp(-t / s.tau)), 1e-12) << "t = " << t;
  }
}

TEST(PwpfModulator, ReturnedOutputAppliesToTheNextInterval) {
  // From f = 0 with E = 0.5: f(t) = K_m E (1 - e^{-t/tau}) reaches u_on at
  // t_c = -tau ln(1 - u_on / (K_m E)) = 0.12942 s. With dt = 1 ms the step over
  // [0.129, 0.130) is the first to end with f >= u_on; it returns +1, the output for
  // [0.130, 0.131): u[130] is the first non-zero entry of the trace.
  const PwpfSettings s;
  const double E = 0.5, dt = 1e-3;
  const double t_c = -s.tau * std::log(1.0 - s.u_on / (s.Km * E));
  ASSERT_NEAR(t_c, 0.12942, 1e-5);
  PwpfModulator m(s);
  const std::vector<int> u = run_pwpf(m, E, dt, 200);
  const long first = static_cast<long>(std::find(u.begin(), u.end(), 1) - u.begin());
  EXPECT_EQ(first, static_cast<long>(std::ceil(t_c / dt)));
  EXPECT_EQ(first, 130);
  PwpfModulator m2(s);
  for (int k = 0; k < 129; ++k) EXPECT_EQ(m2.step(E * s.thruster.force, dt), 0);
  EXPECT_LT(m2.filter_state(), s.u_on);
  EXPECT_EQ(m2.step(E * s.thruster.force, dt), 1);
  EXPECT_EQ(m2.output(), 1);
  EXPECT_NEAR(m2.filter_state(), s.Km * E * (1.0 - std::exp(-0.130 / s.tau)), 1e-12);
}

TEST(PwpfModulator, SteadyOnAndOffTimesMatchClosedForms) {
  const PwpfSettings s;
  const PwpfClosedForm cf(s);
  const double dt = 1e-4;
  double worst_on = 0.0, worst_off = 0.0;
  for (double E : {0.15, 0.3, 0.5, 0.8, 1.0}) {
    const double T_on = cf.T_on(E), T_off = cf.T_off(E);
    const double duration = 2.0 + 8.0 * (T_on + T_off);  // transient plus about 8 cycles
    PwpfModulator m(s);
    const std::vector<Firing> fs = firings(run_pwpf(m, E, dt, std::lround(duration / dt)));
    const Measured r = measure(fs, dt, T_on, T_off, 1);
    EXPECT_GE(r.on_samples, 5) << "E = " << E;
    EXPECT_GE(r.off_samples, 4) << "E = " << E;
    EXPECT_LE(r.worst_on_error, 1e-3) << "E = " << E << ", T_on = " << T_on;
    EXPECT_LE(r.worst_off_error, 1e-3) << "E = " << E << ", T_off = " << T_off;
    worst_on = std::max(worst_on, r.worst_on_error);
    worst_off = std::max(worst_off, r.worst_off_error);
    std::printf("[ measured ] PWPF E = %.2f: T_on %.2f ms (error %.3f ms), T_off %.2f ms (error %.3f ms)\n", E,
                1e3 * T_on, 1e3 * r.worst_on_error, 1e3 * T_off, 1e3 * r.worst_off_error);
  }
  std::printf("[ measured ] PWPF worst T_on error %.3f ms, worst T_off error %.3f ms (dt = 0.1 ms)\n",
              1e3 * worst_on, 1e3 * worst_off);
}

TEST(PwpfModulator, MinimumPulseAtTheDeadZoneEdge) {
  const PwpfSettings s;
  const PwpfClosedForm cf(s);
  EXPECT_NEAR(cf.min_pulse(), 0.040, 1e-4);    // -0.58 ln(1 - 0.3/4.5) = 40.02 ms
  EXPECT_NEAR(cf.dead_zone(), 0.1, 1e-15);
  const double E = 0.1001;  // just above the dead zone: T_on -> minimum pulse
  EXPECT_NEAR(cf.T_on(E), cf.min_pulse(), 1e-4);
  const double dt = 1e-4;
  PwpfModulator m(s);
  // From f = 0 the first switch-on takes about 4.0 s, then T_off = 3.77 s between pulses.
  const std::vector<Firing> fs = firings(run_pwpf(m, E, dt, 170000));
  ASSERT_GE(fs.size(), 3u);
  const Measured r = measure(fs, dt, cf.T_on(E), cf.T_off(E), 1);
  EXPECT_LE(r.worst_on_error, 1e-3);
  std::printf("[ measured ] PWPF E = 0.1001: on-time error %.3f ms vs T_on = %.3f ms (Delta = %.3f ms)\n",
              1e3 * r.worst_on_error, 1e3 * cf.T_on(E), 1e3 * cf.min_pulse());
}

TEST(PwpfModulator, DeadZoneNeverFires) {
  const PwpfSettings s;
  for (double E : {0.099, -0.099, 0.05, 0.0}) {
    PwpfModulator m(s);
    const std::vector<int> u = run_pwpf(m, E, 1e-3, 60000);  // 60 s: f settles at K_m E < u_on
    EXPECT_EQ(std::count(u.begin(), u.end(), 0), static_cast<long>(u.size())) << "E = " << E;
  }
}

TEST(PwpfModulator, SaturationStaysOnAfterFirstSwitchOn) {
  const PwpfSettings s;
  const PwpfClosedForm cf(s);
  const double dt = 1e-4;
  // At E = E_s the on-phase asymptote K_m (E - 1) is u_off itself, approached but not
  // reached (f - u_off = h e^{-t/tau} ~ 1e-8 after 10 s, far above round-off).
  for (double E : {cf.saturation(), 1.1, 2.0, 50.0}) {
    PwpfModulator m(s);
    const std::vector<int> u = run_pwpf(m, E, dt, 100000);
    const auto on = std::find(u.begin(), u.end(), 1);
    ASSERT_NE(on, u.end()) << "E = " << E;
    EXPECT_EQ(std::count(on, u.end(), 1), u.end() - on) << "E = " << E;
  }
  // Just below E_s the pulse does end, after T_on(E) (1.18 s at E = E_s - 0.01).
  const double E = cf.saturation() - 0.01;
  PwpfModulator m(s);
  const std::vector<Firing> fs = firings(run_pwpf(m, E, dt, 100000));
  ASSERT_GE(fs.size(), 2u);
  EXPECT_NEAR(static_cast<double>(fs[1].length) * dt, cf.T_on(E), 1e-3);
}

TEST(PwpfModulator, DutyCycleMatchesClosedForms) {
  const PwpfSettings s;
  const PwpfClosedForm cf(s);
  const double E = 0.37, dt = 1e-4;
  PwpfModulator m(s);
  const std::vector<Firing> fs = firings(run_pwpf(m, E, dt, 200000));  // 20 s, about 100 cycles
  ASSERT_GE(fs.size(), 50u);
  // Whole cycles from the start of the second firing to the start of the last one.
  long on = 0;
  for (std::size_t i = 1; i + 1 < fs.size(); ++i) on += fs[i].length;
  const long span = fs.back().start - fs[1].start;
  const double duty = static_cast<double>(on) / static_cast<double>(span);
  const double P = cf.T_on(E) + cf.T_off(E);
  // A 1 ms error in T_on or T_off moves the duty by at most 1 ms / P.
  EXPECT_NEAR(duty, cf.duty(E), 1e-3 / P);
  std::printf("[ measured ] PWPF E = 0.37: duty %.5f, closed form %.5f (T_on %.2f ms, T_off %.2f ms)\n", duty,
              cf.duty(E), 1e3 * cf.T_on(E), 1e3 * cf.T_off(E));
}

TEST(PwpfModulator, MinimumOnTimeIsEnforced) {
  // u_off close to u_on and a small tau: the natural pulse at E = 0.3 is
  // T_on = -0.2 ln(1 - 0.05 / (0.45 + 4.5 * 0.7)) = 2.8 ms, far below t_min = 40 ms.
  PwpfSettings s;
  s.tau = 0.2;
  s.u_off = 0.40;
  const PwpfClosedForm cf(s);
  const double E = 0.3, dt = 1e-4;
  ASSERT_LT(cf.T_on(E), 0.005);

  PwpfSettings free = s;
  free.thruster.min_on_time = 0.0;
  PwpfModulator natural(free);
  const std::vector<Firing> fn = firings(run_pwpf(natural, E, dt, 50000));
  ASSERT_GE(fn.size(), 3u);
  for (std::size_t i = 1; i < fn.size(); ++i)
    EXPECT_NEAR(static_cast<double>(fn[i].length) * dt, cf.T_on(E), 1e-3) << i;

  PwpfModulator held(s);
  const std::vector<Firing> fh = firings(run_pwpf(held, E, dt, 50000));
  ASSERT_GE(fh.size(), 3u);
  for (const Firing& f : fh) {
    EXPECT_EQ(f.sign, 1);
    EXPECT_EQ(f.length, 400);  // exactly t_min = 40 ms = 400 steps of 0.1 ms
  }
  // The same at dt = 1 ms (the simulation step): 40 steps.
  PwpfModulator held_ms(s);
  for (const Firing& f : firings(run_pwpf(held_ms, E, 1e-3, 5000))) EXPECT_EQ(f.length, 40);
}

TEST(PwpfModulator, HeldPulsePastOppositeThresholdReversesDirectly) {
  // tau = 0.1: during the 40 ms hold f falls from about u_on to
  // K_m (E - 1) + (u_on - K_m (E - 1)) e^{-0.4} = -3.15 + 3.6 * 0.670 = -0.737 <= -u_on,
  // so the +1 pulse is followed at once by a -1 pulse (documented relay behaviour).
  PwpfSettings s;
  s.tau = 0.1;
  s.u_off = 0.40;
  const double E = 0.3, dt = 1e-4;
  ASSERT_LE(s.Km * (E - 1.0) + (s.u_on - s.Km * (E - 1.0)) * std::exp(-0.04 / s.tau), -s.u_on);
  PwpfModulator m(s);
  const std::vector<Firing> fs = firings(run_pwpf(m, E, dt, 20000));
  ASSERT_GE(fs.size(), 2u);
  EXPECT_EQ(fs[0].sign, 1);
  EXPECT_EQ(fs[0].length, 400);
  EXPECT_EQ(fs[1].sign, -1);
  EXPECT_EQ(fs[1].start, fs[0].start + fs[0].length);  // no gap
  EXPECT_GE(fs[1].length, 400);
}

TEST(PwpfModulator, NegativeInputGivesMirroredPulses) {
  const PwpfSettings s;
  const PwpfClosedForm cf(s);
  const double E = 0.5, dt = 1e-4;
  PwpfModulator pos(s), neg(s);
  const double F = s.thruster.force;
  for (long k = 0; k < 60000; ++k) {
    ASSERT_EQ(neg.step(-E * F, dt), -pos.step(E * F, dt)) << k;
    ASSERT_EQ(neg.filter_state(), -pos.filter_state()) << k;
  }
  PwpfModulator m(s);
  const Measured r = measure(firings(run_pwpf(m, -E, dt, 60000)), dt, cf.T_on(E), cf.T_off(E), -1);
  EXPECT_GE(r.on_samples, 5);
  EXPECT_LE(r.worst_on_error, 1e-3);
  EXPECT_LE(r.worst_off_error, 1e-3);
}

TEST(PwpfModulator, NonFiniteInputsAndReset) {
  const PwpfSettings s;
  PwpfModulator a(s), b(s);
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 500; ++k) {
    a.step(3.0, 1e-3);
    b.step(3.0, 1e-3);
  }
  for (int k = 0; k < 500; ++k) {  // non-finite U behaves as U = 0
    const double U = k % 3 == 0 ? nan : (k % 3 == 1 ? inf : -inf);
    ASSERT_EQ(a.step(U, 1e-3), b.step(0.0, 1e-3)) << k;
    ASSERT_EQ(a.filter_state(), b.filter_state()) << k;
  }
  const double f = a.filter_state();
  const int u = a.output();
  for (double dt : {0.0, -1e-3, nan, inf}) {  // no-op steps
    EXPECT_EQ(a.step(100.0, dt), u);
    EXPECT_EQ(a.filter_state(), f);
  }
  a.step(1e308, 1e-3);  // finite but enormous: saturated, f stays finite
  EXPECT_TRUE(std::isfinite(a.filter_state()));
  EXPECT_EQ(a.output(), 1);
  a.reset();
  EXPECT_EQ(a.filter_state(), 0.0);
  EXPECT_EQ(a.output(), 0);
  EXPECT_EQ(a.on_time(), 0.0);
}

TEST(PwpfModulator, SettingsValidationNamesTheSetting) {
  struct Bad {
    std::function<void(PwpfSettings&)> set;
    const char* setting;
    const char* value;
  };
  const std::vector<Bad> bad = {
      {[](PwpfSettings& s) { s.Km = 0.0; }, "Km", "0"},
      {[](PwpfSettings& s) { s.Km = std::numeric_limits<double>::quiet_NaN(); }, "Km", "nan"},
      {[](PwpfSettings& s) { s.tau = -0.5; }, "tau", "-0.5"},
      {[](PwpfSettings& s) { s.u_off = -0.1; }, "u_off", "-0.1"},
      {[](PwpfSettings& s) { s.u_on = 0.15; }, "u_on", "0.15"},  // u_on = u_off
      {[](PwpfSettings& s) { s.u_on = 0.1; }, "u_on", "0.1"},
      {[](PwpfSettings& s) { s.thruster.force = -5.0; }, "thruster.force", "-5"},
      {[](PwpfSettings& s) { s.thruster.min_on_time = -1.0; }, "thruster.min_on_time", "-1"},
  };
  for (const Bad& b : bad) {
    PwpfSettings s;
    b.set(s);
    try {
      PwpfModulator m(s);
      ADD_FAILURE() << "no exception for " << b.setting;
    } catch (const std::invalid_argument& e) {
      expect_names(e.what(), "PwpfModulator", b.setting, b.value);
    }
  }
  PwpfSettings ok;
  ok.u_off = 0.0;  // allowed: a relay that switches off at f = 0
  EXPECT_NO_THROW(PwpfModulator{ok});
}
