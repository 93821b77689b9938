// Thruster pulse modulators: from a continuous force command U (N) on one body axis to the
// on/off force of a +-F thruster pair, u(t) F with u(t) in {-1, 0, +1}. A pulse, once
// started, lasts at least the minimum on-time t_min; there is no minimum off-time. Both
// modulators are scalar (one axis); a vehicle uses one instance per axis.
//
// PwmModulator: pulse-width modulation with impulse carry. Once per modulation period T_m,
// at the start of the period, the command U is sampled and
//
//     I_req = U T_m + c                                   requested impulse (N s)
//     n     = round(min(|I_req| / F, T_m) / delta)        on-time in ticks of the
//                                                         resolution delta (ties away from 0)
//     n < n_min (or n = 0):  no pulse,               c <- I_req
//     otherwise:             u = sign(I_req) for n delta from the period start,
//                            c <- I_req - sign(I_req) n delta F
//     c <- clamp(c, -c_max, +c_max)                  (c <- 0 if carry_remainder is false)
//
// with n_min = ceil(t_min / delta) (t_min / delta itself when it is a whole number to a
// relative 1e-9; n_min = 1 when t_min = 0) and c_max = carry_limit. The carry c is the
// impulse requested but not yet delivered: over any run of periods in which the clamp is
// inactive, delivered impulse = sum U T_m + c_first - c_last, so from reset() the impulse
// error (commanded - delivered) is c itself, |c| <= c_max. Without a pulse
// |c| < F delta (n_min - 1/2), with an unsaturated pulse
// |c| <= F delta / 2; so when c_max >= F delta (n_min - 1/2) (= F (t_min - delta/2) for the
// defaults) the clamp acts only in saturation, |I_req| > F T_m + c_max. The pulse
// length is kept as a whole number of ticks (Pulse::on_ticks), so a simulator stepping on
// the delta grid asks Pulse::output_at_tick(k) for the output over [k delta, (k+1) delta)
// of the period, free of floating-point edge effects. Non-finite U: no pulse, carry kept.
//
// PwpfModulator: pulse-width pulse-frequency modulation, a Schmitt trigger in a first-order
// loop (Wie, Space Vehicle Dynamics and Control, PWPF modulator). With r = U / F,
//
//     tau df/dt = K_m (r - u) - f
//
// advanced over a step dt with the exact solution for r and u held over the step,
//
//     f <- f e^{-dt/tau} + K_m (r - u) (1 - e^{-dt/tau}),
//
// then the trigger (a relay with hysteresis, u_off < u_on) sets u for the next step:
//
//     u = +1:  u <- 0 when f <= +u_off    (and the pulse has lasted >= t_min)
//     u = -1:  u <- 0 when f >= -u_off    (and the pulse has lasted >= t_min)
//     u =  0:  u <- +1 when f >= u_on,  u <- -1 when f <= -u_on
//
// The rules are applied in this order within one step, so a pulse that was held on past
// its natural end by t_min while f went beyond the opposite on-threshold is followed
// directly by the opposite pulse (the relay is a static function of f there). The on-time
// of a pulse is the sum of the dt of the steps during which it was applied; it counts as
// reaching t_min within a millionth of the last step (summation round-off).
//
// Timing of PwpfModulator::step(U, dt) at time t_k: the interval [t_k, t_k + dt) is
// integrated with r = U / F and with u = output() before the call (the output applied
// to that interval); the trigger is then evaluated on f(t_k + dt), and the returned value
// (= output() after the call) is the output for the NEXT interval [t_k + dt, t_k + 2 dt).
// A simulator therefore applies output() over an interval and then calls step() for it.
// Non-finite U is treated as U = 0; |r| is limited to 1e6 (a million times full thrust,
// far into saturation) so that f stays finite for any finite U. A step with dt <= 0 or
// non-finite dt changes nothing and returns output().
// On a time grid the trigger switches at the first grid point after the continuous
// threshold crossing, so pulse and gap lengths differ from the continuous-time static
// characteristics by O(dt): for the defaults at dt = 1 ms up to 6.6 ms (gap at E = 0.15)
// and 14 ms (3.8 s gap just above the dead zone, where f nears u_on very slowly).
//
// Construction validates the settings and throws std::invalid_argument naming the setting
// and its value. The step functions (begin_period, step) never throw, never allocate and
// use no global state. No Eigen needed.
#pragma once

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace hinf::runtime {

// One +-F thruster pair on one axis.
struct ThrusterSettings {
  double force = 5.0;         // F (N), thrust of each of the pair
  double min_on_time = 0.04;  // t_min (s), a started pulse lasts at least this long
};

struct PwmSettings {
  double period = 1.0;          // T_m (s), modulation period
  double resolution = 1e-3;     // delta (s), on-time quantum; T_m must be a multiple of it
  bool carry_remainder = true;  // carry the undelivered impulse to the next period
  double carry_limit = 0.2;     // c_max (N s), |carry| <= c_max (0.2 = F t_min for the defaults)
  ThrusterSettings thruster;
};

struct PwpfSettings {
  double Km = 4.5;     // K_m, loop gain
  double tau = 0.58;   // tau (s), filter time constant
  double u_on = 0.45;  // trigger on-threshold
  double u_off = 0.15; // trigger off-threshold, 0 <= u_off < u_on
  ThrusterSettings thruster;
};

namespace detail {

[[noreturn]] inline void throw_pulse_setting(const char* cls, const char* setting, const char* requirement,
                                             double value) {
  std::ostringstream os;
  os.precision(10);
  os << "hinf::runtime::" << cls << ": " << setting << " must be " << requirement << "; got " << value;
  throw std::invalid_argument(os.str());
}

inline void check_thruster_settings(const char* cls, const ThrusterSettings& t) {
  if (!(std::isfinite(t.force) && t.force > 0.0))
    throw_pulse_setting(cls, "thruster.force", "finite and > 0", t.force);
  if (!(std::isfinite(t.min_on_time) && t.min_on_time >= 0.0))
    throw_pulse_setting(cls, "thruster.min_on_time", "finite and >= 0", t.min_on_time);
}

// x as a whole number if it is one to within a relative 1e-9 (binary round-off of
// decimal settings such as 1.0 / 1e-3), otherwise ceil(x). 0 <= x <= 1e12 assumed.
inline long whole_or_ceil(double x) {
  const double k = std::round(x);
  if (std::abs(x - k) <= 1e-9 * (x > 1.0 ? x : 1.0)) return static_cast<long>(k);
  return static_cast<long>(std::ceil(x));
}

}  // namespace detail

// ---------------------------------------------------------------------------------------
// Pulse-width modulation with impulse carry (see the file comment).
class PwmModulator {
 public:
  // The pulse of one modulation period: u = sign from the period start for on_ticks
  // ticks of the resolution (on_time = on_ticks * resolution seconds), then u = 0.
  struct Pulse {
    int sign = 0;          // -1, 0 or +1; 0 means no pulse this period
    double on_time = 0.0;  // s; 0 when sign == 0
    long on_ticks = 0;     // on_time in ticks of the resolution; 0 when sign == 0

    // Output over the tick [k delta, (k+1) delta) of the period (k = tick_in_period).
    int output_at_tick(long tick_in_period) const {
      return (tick_in_period >= 0 && tick_in_period < on_ticks) ? sign : 0;
    }
  };

  // Throws std::invalid_argument naming the setting and its value.
  explicit PwmModulator(const PwmSettings& settings = PwmSettings()) : s_(settings) {
    const char* cls = "PwmModulator";
    detail::check_thruster_settings(cls, s_.thruster);
    if (!(std::isfinite(s_.period) && s_.period > 0.0)) detail::throw_pulse_setting(cls, "period", "finite and > 0", s_.period);
    if (!(std::isfinite(s_.resolution) && s_.resolution > 0.0))
      detail::throw_pulse_setting(cls, "resolution", "finite and > 0", s_.resolution);
    if (!(s_.resolution <= s_.period))
      detail::throw_pulse_setting(cls, "resolution", "<= period", s_.resolution);
    const double ticks = s_.period / s_.resolution;
    if (!(ticks <= 1e12))
      detail::throw_pulse_setting(cls, "period / resolution", "<= 1e12 ticks per period", ticks);
    ticks_per_period_ = static_cast<long>(std::round(ticks));
    if (std::abs(ticks - static_cast<double>(ticks_per_period_)) > 1e-9 * ticks)
      detail::throw_pulse_setting(cls, "period / resolution", "a whole number (period a multiple of resolution)", ticks);
    if (!(s_.thruster.min_on_time <= s_.period))
      detail::throw_pulse_setting(cls, "thruster.min_on_time", "<= period", s_.thruster.min_on_time);
    if (!(std::isfinite(s_.carry_limit) && s_.carry_limit >= 0.0))
      detail::throw_pulse_setting(cls, "carry_limit", "finite and >= 0", s_.carry_limit);
    min_on_ticks_ = detail::whole_or_ceil(s_.thruster.min_on_time / s_.resolution);
    if (min_on_ticks_ < 1) min_on_ticks_ = 1;  // a pulse of 0 ticks is no pulse
  }

  // Start of a modulation period with the command U (N): the pulse to fire from now on,
  // see the file comment. Non-finite U: no pulse, carry unchanged. Never throws.
  Pulse begin_period(double U) {
    Pulse p;
    if (!std::isfinite(U)) return p;
    const double F = s_.thruster.force;
    const double I_req = U * s_.period + carry_;  // may be +-inf only for |U| near DBL_MAX
    const double t_want = std::fmin(std::abs(I_req) / F, s_.period);
    long n = std::lround(t_want / s_.resolution);
    if (n > ticks_per_period_) n = ticks_per_period_;
    double c = I_req;
    if (n >= min_on_ticks_) {
      p.sign = I_req > 0.0 ? 1 : -1;
      p.on_ticks = n;
      p.on_time = static_cast<double>(n) * s_.resolution;
      c = I_req - static_cast<double>(p.sign) * p.on_time * F;
    }
    carry_ = s_.carry_remainder ? std::fmax(-s_.carry_limit, std::fmin(c, s_.carry_limit)) : 0.0;
    return p;
  }

  // Output of pulse p at time t (s) since the period start. t is taken on the resolution
  // grid: the tick is floor(t / delta + 1e-6), so t = k delta computed in floating point
  // falls in tick k. Same as p.output_at_tick(tick); 0 for t < 0 or NaN.
  int output_at_time(const Pulse& p, double t_in_period) const {
    if (!(t_in_period >= 0.0)) return 0;
    return (t_in_period / s_.resolution + 1e-6 < static_cast<double>(p.on_ticks)) ? p.sign : 0;
  }

  double carry() const { return carry_; }  // N s, impulse owed to the following periods
  void reset() { carry_ = 0.0; }

  const PwmSettings& settings() const { return s_; }
  long ticks_per_period() const { return ticks_per_period_; }  // T_m / delta
  long min_on_ticks() const { return min_on_ticks_; }          // shortest pulse, in ticks

 private:
  PwmSettings s_;
  long ticks_per_period_ = 0;
  long min_on_ticks_ = 1;
  double carry_ = 0.0;
};

// ---------------------------------------------------------------------------------------
// Pulse-width pulse-frequency modulator (see the file comment).
class PwpfModulator {
 public:
  // Throws std::invalid_argument naming the setting and its value.
  explicit PwpfModulator(const PwpfSettings& settings = PwpfSettings()) : s_(settings) {
    const char* cls = "PwpfModulator";
    detail::check_thruster_settings(cls, s_.thruster);
    if (!(std::isfinite(s_.Km) && s_.Km > 0.0)) detail::throw_pulse_setting(cls, "Km", "finite and > 0", s_.Km);
    if (!(std::isfinite(s_.tau) && s_.tau > 0.0)) detail::throw_pulse_setting(cls, "tau", "finite and > 0", s_.tau);
    if (!(std::isfinite(s_.u_off) && s_.u_off >= 0.0))
      detail::throw_pulse_setting(cls, "u_off", "finite and >= 0", s_.u_off);
    if (!(std::isfinite(s_.u_on) && s_.u_on > s_.u_off))
      detail::throw_pulse_setting(cls, "u_on", "finite and > u_off", s_.u_on);
  }

  // Integrates [t_k, t_k + dt) with r = U / F and u = output(), then applies the trigger;
  // returns the output for [t_k + dt, t_k + 2 dt). See the file comment. Never throws.
  int step(double U, double dt) {
    if (!(std::isfinite(dt) && dt > 0.0)) return u_;
    if (dt != last_dt_) {
      last_dt_ = dt;
      decay_ = std::exp(-dt / s_.tau);    // e^{-dt/tau}
      gain_ = -std::expm1(-dt / s_.tau);  // 1 - e^{-dt/tau}
    }
    double r = std::isfinite(U) ? U / s_.thruster.force : 0.0;
    r = std::fmax(-kMaxCommand, std::fmin(r, kMaxCommand));
    f_ = f_ * decay_ + s_.Km * (r - static_cast<double>(u_)) * gain_;

    if (u_ != 0) {
      on_time_ += dt;
      const bool held = on_time_ + 1e-6 * dt < s_.thruster.min_on_time;
      if (!held && static_cast<double>(u_) * f_ <= s_.u_off) {
        u_ = 0;
        on_time_ = 0.0;
      }
    }
    if (u_ == 0) {
      if (f_ >= s_.u_on) {
        u_ = 1;
        on_time_ = 0.0;
      } else if (f_ <= -s_.u_on) {
        u_ = -1;
        on_time_ = 0.0;
      }
    }
    return u_;
  }

  double filter_state() const { return f_; }  // f
  int output() const { return u_; }           // u for the next interval
  double on_time() const { return on_time_; } // s the current pulse has lasted (0 when off)
  void reset() {
    f_ = 0.0;
    u_ = 0;
    on_time_ = 0.0;
  }

  const PwpfSettings& settings() const { return s_; }

  static constexpr double kMaxCommand = 1e6;  // |r| limit (normalised command)

 private:
  PwpfSettings s_;
  double f_ = 0.0;
  int u_ = 0;
  double on_time_ = 0.0;
  double last_dt_ = -1.0;  // dt of the cached decay_/gain_ (none yet)
  double decay_ = 1.0;
  double gain_ = 0.0;
};

}  // namespace hinf::runtime
