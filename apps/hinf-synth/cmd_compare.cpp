// hinf-synth compare CONFIG GAINS [-o sigma.csv] [--plot sigma.png] [--points N] [--json]
#include <cmath>
#include <iostream>
#include <sstream>

#include "cli_support.hpp"
#include "hinf/synth/filter_file.hpp"
#include "commands.hpp"
#include "hinf/common/atomic_file.hpp"
#include "hinf/common/gnuplot.hpp"  // gnuplot_quoted
#include "hinf/common/number_text.hpp"
#include "hinf/synth/api.hpp"  // json_schema
#include "hinf/synth/comparison.hpp"

namespace hinf::cli {
namespace {

std::string sigma_csv(const synth::Comparison& c, std::optional<double> T) {
  std::ostringstream os;
  os << "theta_rad_per_sample,frequency_hz,sigma_filter,sigma_kalman\n";
  for (std::size_t i = 0; i < c.theta.size(); ++i)
    os << num(c.theta[i]) << ',' << (T ? num(c.theta[i] / (2 * kPi * *T)) : "") << ',' << num(c.filter.sigma[i])
       << ',' << num(c.kalman.sigma[i]) << '\n';
  return os.str();
}

// The Kalman filter set beside the given one: the predictor, or x̂(k|k) beside a filtered estimate.
const char* kalman_name(bool filtered) { return filtered ? "Kalman filter x_hat(k|k)" : "Kalman predictor"; }

// gamma: the gains file's certified bound, drawn as a horizontal line (the σ curve of the
// filter stays below it on the nominal plant; the robust bound covers every admissible F).
std::string sigma_plot_script(const std::string& data, const std::string& png, const std::string& gains, bool hz,
                              bool filtered, std::optional<double> gamma) {
  std::ostringstream gp;
  const std::string x = hz ? "2" : "1";
  gp << "set terminal pngcairo size 900,520 enhanced font 'Sans,11'\nset output " << gnuplot_quoted(png) << "\n"
     << "set grid\nset key top left\nset logscale xy\nset datafile separator ','\n"
     << "set xlabel " << (hz ? "'frequency (Hz)'" : "'frequency (rad/sample)'") << "\n"
     << "set ylabel 'largest singular value of the error system'\n"
     << "set title 'estimation error gain: the filter beside the " << kalman_name(filtered) << "' noenhanced\n";
  if (gamma)
    gp << "set arrow from graph 0, first " << significant_text(*gamma, 17) << " to graph 1, first "
       << significant_text(*gamma, 17) << " nohead dt 2 lw 1.5 lc rgb '#d62728'\n"
       << "set label " << gnuplot_quoted("certified gamma = " + num(*gamma)) << " at graph 0.99, first "
       << significant_text(*gamma, 17) << " right offset 0,0.7 tc rgb '#d62728' noenhanced\n";
  gp << "plot " << gnuplot_quoted(data) << " every ::1 using " << x << ":3 with lines lw 2 lc rgb '#d62728' title "
     << gnuplot_quoted(gains) << " noenhanced, " << gnuplot_quoted(data) << " every ::1 using " << x
     << ":4 with lines lw 2 lc rgb '#1f77b4' title '" << kalman_name(filtered) << "' noenhanced\nset output\n";
  return gp.str();
}

Json figures_json(const std::string& name, const synth::FilterFigures& f) {
  const auto number = [](double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); };
  Json j;
  j["name"] = name;
  j["hinf_norm_nominal"] = number(f.hinf_norm_nominal);
  j["hinf_peak_theta"] = number(f.hinf_peak_theta);
  j["robust_bound"] = number(f.robust_bound);
  j["h2_norm_nominal"] = number(f.h2_norm_nominal);
  j["sigma"] = Json::array();
  for (double s : f.sigma) j["sigma"].push_back(number(s));
  return j;
}

// --json: both filters' figures and σ curves at every frequency (schema hinf-synth.compare/1).
Json comparison_json(const std::string& config, const std::string& gains, const synth::Comparison& c,
                     std::optional<double> T, bool filtered) {
  Json j;
  j["schema"] = synth::json_schema("compare");
  j["config"] = config;
  j["gains"] = gains;
  j["sample_time_s"] = T ? Json(*T) : Json(nullptr);
  j["theta_rad_per_sample"] = c.theta;
  j["frequency_hz"] = Json::array();
  for (double theta : c.theta) j["frequency_hz"].push_back(T ? Json(theta / (2 * kPi * *T)) : Json(nullptr));
  j["filter"] = figures_json(gains, c.filter);
  j["kalman"] = figures_json(kalman_name(filtered), c.kalman);
  return j;
}

void print_row(std::FILE* out, const std::string& name, const synth::FilterFigures& f) {
  std::fprintf(out, "%-28s %-24s %-24s %s\n", name.c_str(), num(f.hinf_norm_nominal).c_str(),
               std::isnan(f.robust_bound) ? "-" : num(f.robust_bound).c_str(), num(f.h2_norm_nominal).c_str());
}

}  // namespace

void add_compare(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand(
      "compare", "a filter beside the Kalman predictor of the same plant (the Kalman filter x_hat(k|k) beside a filtered "
                 "estimate): worst-case gain, robust bound, RMS error under white noise, and sigma(omega) of both error "
                 "systems (CSV, PNG)");
  const auto args = add_config_gains_args(*cmd, "gains YAML of the filter to compare");
  auto csv = std::make_shared<std::string>();
  auto plot = std::make_shared<std::string>();
  auto points = std::make_shared<int>(400);
  auto json = std::make_shared<bool>(false);
  auto quiet = std::make_shared<bool>(false);
  auto verbose = std::make_shared<bool>(false);
  cmd->add_option("-o,--output", *csv, "CSV: theta_rad_per_sample, frequency_hz, sigma_filter, sigma_kalman (- for stdout)");
  add_quiet_flag(*cmd, *quiet);
  add_verbose_flag(*cmd, *verbose);
  cmd->add_option("--plot", *plot, "PNG of both sigma curves (gnuplot)");
  cmd->add_option("--points", *points, "log-spaced frequencies (default 400; both peaks are added)")
      ->check(CLI::Range(2, synth::kMaxComparisonPoints));
  cmd->add_flag("--json", *json, "print JSON (schema hinf-synth.compare/1: the figures and both sigma curves) instead of text");
  cmd->callback([=, &action] {
    action = [=]() -> int {
      require_one_use_of_stdout(*csv, *json);
      const Stages stage(*verbose, "compare");
      const synth::ConfigAndFilter in = stage("read " + args->config + " and " + args->gains,
                                              [&] { return synth::load_config_and_filter(args->config, args->gains); });
      const synth::Comparison c = stage("both filters' figures and sigma curves computed", [&] {
        return synth::compare_with_kalman(in.config.plant, in.filter, in.config.settings, *points, in.config.kalman_noise);
      });
      const std::optional<double> T = in.config.sample_time();
      if (*json) {
        print_json(comparison_json(args->config, args->gains, c, T, in.filter.filtered()));
      } else if (!*quiet) {
        std::FILE* out = *csv == "-" ? stderr : stdout;  // the CSV alone on stdout with -o -
        std::fprintf(out, "%-28s %-24s %-24s %s\n", "", "worst-case gain (nominal)", "robust bound", "RMS error (H2)");
        print_row(out, args->gains, c.filter);
        print_row(out, kalman_name(in.filter.filtered()), c.kalman);
        std::fflush(out);
      }
      const std::string data = sigma_csv(c, T);
      if (!csv->empty()) stage("wrote " + *csv, [&] { write_output(*csv, data, {args->config, args->gains}); });
      if (!plot->empty())
        stage("drew " + *plot, [&] {
          const auto script = [&](const std::string& d, const std::string& png) {
            return sigma_plot_script(d, png, args->gains, T.has_value(), in.filter.filtered(), in.gains.gamma);
          };
          write_png_by_gnuplot(*plot, data, script, {args->config, args->gains});
        });
      return 0;
    };
  });
}

}  // namespace hinf::cli
