// The output files of a linear_plant run directory (linear_plant_report.hpp).
#include "linear_plant_report.hpp"

#include <algorithm>
#include <filesystem>
#include <limits>
#include <sstream>

#include "hinf/common/gnuplot.hpp"
#include "hinf/sim/plots.hpp"
#include "summary_json.hpp"

namespace hinf::sim {
namespace {

// The error components drawn, one panel each (the first ones of z when l is larger).
constexpr int kMaxPlottedComponents = 6;

using LinearSamples = std::vector<std::vector<LinearPlantSample>>;
using LinearCampaign = std::vector<std::vector<LinearPlantStatistics>>;

// The metrics of one filter in one run, in the order of runs.csv and summary.json: the run's
// truth first — each named parameter's value in its units (`truth.parameters`), else the δ
// of each of F's blocks (NaN for a default Stats, which only names the columns); the diverged
// flag only in runs.csv (summary.json: `diverged` or `diverged_runs`, as every family).
enum class Diverged { Column, Apart };
std::vector<std::pair<std::string, double>> metric_list(const LinearPlantStatistics& s,
                                                        const LinearPlantScenario& scenario, Diverged d) {
  std::vector<std::pair<std::string, double>> out;
  const auto& parameters = scenario.truth_parameters;
  for (int b = 0; b < scenario.uncertainty_blocks(); ++b) {
    const double delta = b < s.delta.size() ? s.delta(b) : std::numeric_limits<double>::quiet_NaN();
    if (parameters.empty()) {
      out.emplace_back("delta_" + std::to_string(b + 1), delta);
    } else {
      const TruthParameter& p = parameters[static_cast<std::size_t>(b)];
      out.emplace_back(p.name, p.nominal + delta * p.radius);
    }
  }
  out.insert(out.end(), {{"error_rms", s.error_rms},
                         {"predicted_error_rms", s.predicted_rms},
                         {"error_max", s.error_max}});
  if (d == Diverged::Column) out.emplace_back("diverged", s.diverged ? 1.0 : 0.0);
  return out;
}

std::vector<std::string> component_names(const char* prefix, Eigen::Index l) {
  std::vector<std::string> names;
  for (Eigen::Index i = 1; i <= l; ++i) names.push_back(prefix + std::to_string(i));
  return names;
}

// samples[f] = filter f's samples of run 0: t, z_1 … z_l, then per filter ẑ and z − ẑ.
std::string format_linear_plant_trajectory_csv(const LinearPlantExperiment& e, const LinearSamples& samples) {
  const Eigen::Index l = e.scenario.plant.l();
  std::string out = "t";
  append_columns(out, "", component_names("z", l));
  for (const auto& f : e.filters) {
    append_columns(out, f.name + "_", component_names("zhat", l));
    append_columns(out, f.name + "_", component_names("err", l));
  }
  out += '\n';
  const std::size_t steps = samples.empty() ? 0 : samples.front().size();
  for (std::size_t k = 0; k < steps; ++k) {
    append_num(out, samples.front()[k].t);
    append_cells(out, samples.front()[k].z, static_cast<int>(l));
    for (const auto& filter : samples) {
      append_cells(out, filter[k].z_hat, static_cast<int>(l));
      append_cells(out, filter[k].z - filter[k].z_hat, static_cast<int>(l));
    }
    out += '\n';
  }
  return out;
}

// stats[r][f] = filter f's statistics in run r.
std::string format_linear_plant_runs_csv(const LinearPlantExperiment& e, const LinearCampaign& stats,
                                         const std::vector<std::uint64_t>& seeds) {
  return metrics_runs_csv(e.filters, stats, seeds, [&](const LinearPlantStatistics& s) {
    return metric_list(s, e.scenario, Diverged::Column);
  });
}

std::string format_linear_plant_summary_json(const LinearPlantExperiment& e, const LinearCampaign& stats,
                                             const std::string& scenario_path, std::uint64_t seed) {
  const LinearPlantScenario& s = e.scenario;
  Json j = summary_header(scenario_path, seed, stats.size(), s.duration);
  j["scenario_family"] = "linear_plant";
  j["config"] = s.config_path;
  j["sample_time_s"] = json_num(s.sample_time);
  j["noise"] = {{"process_std", json_num(s.process_std)},
                {"measurement_std", json_num(s.measurement_std)},
                {"initial_state_std", json_num(s.initial_state_std)}};
  if (s.truth_parameters.empty()) {
    j["uncertainty_delta"] = s.random_uncertainty ? Json("random") : json_num(s.uncertainty_delta);
  } else {
    Json truth = Json::object();
    for (const TruthParameter& p : s.truth_parameters) truth[p.name] = p.value ? json_num(*p.value) : Json("random");
    j["truth_parameters"] = std::move(truth);
  }
  j["steady_state_start_s"] = json_num(e.options.window_start);
  j["headline_metrics"] = {"error_rms", "predicted_error_rms", "error_max"};  // hinf-sim's end-of-run table
  Json filters = Json::object();
  for (std::size_t f = 0; f < e.filters.size(); ++f) {
    const LinearPlantFilter& filter = e.filters[f];
    Json m = Json::object();
    m["type"] = filter.type;
    m["origin"] = filter.origin;
    m["gamma"] = json_opt(filter.gamma);
    add_metrics_json(m, metrics_per_run(stats, f, [&](const LinearPlantStatistics& x) {
                       return metric_list(x, s, Diverged::Apart);
                     }));
    long diverged = 0;
    for (const auto& run : stats) diverged += run[f].diverged ? 1 : 0;
    if (stats.size() == 1) m["diverged"] = diverged > 0;
    else m["diverged_runs"] = diverged;
    filters[filter.name] = m;
  }
  j["filters"] = filters;
  return j.dump(2) + "\n";
}

// plot.dat: t, then per filter its l error components.
std::string plot_data(const LinearSamples& samples, Eigen::Index l) {
  std::string out;
  const std::size_t steps = samples.empty() ? 0 : samples.front().size();
  for (std::size_t k = 0; k < steps; ++k) {
    append_num(out, samples.front()[k].t);
    for (const auto& filter : samples)
      for (Eigen::Index i = 0; i < l; ++i) out += ' ', append_num(out, filter[k].z(i) - filter[k].z_hat(i));
    out += '\n';
  }
  return out;
}

// DIR/error.png: run 0, one panel per component of z − ẑ (at most kMaxPlottedComponents),
// every filter in its colour, into temporaries of `outputs`. Throws PlotError (plots.hpp).
void write_linear_plant_plots(const std::string& dir, const LinearPlantExperiment& e, const LinearSamples& samples,
                              const std::string& title, hinf::AtomicFileSet& outputs) {
  namespace fs = std::filesystem;
  const Eigen::Index l = e.scenario.plant.l();
  const int panels = static_cast<int>(std::min<Eigen::Index>(l, kMaxPlottedComponents));
  const std::vector<std::string> png{outputs.reserve((fs::path(dir) / "error.png").string())};
  hinf::AtomicFileSet scratch;  // never committed: removed on return
  const std::string data = scratch.add((fs::path(dir) / "plot.dat").string(), plot_data(samples, l));
  const auto ylabel = [](int c) { return "z_" + std::to_string(c + 1) + " - zhat_" + std::to_string(c + 1); };
  const auto curves = [&](int c) {
    std::ostringstream plot;
    for (std::size_t f = 0; f < e.filters.size(); ++f)
      plot << (f ? ", " : "") << gnuplot_quoted(data) << " using 1:" << 2 + static_cast<Eigen::Index>(f) * l + c
           << " with lines lw 1 lc " << f + 1 << " title " << gnuplot_quoted(e.filters[f].name) << " noenhanced";
    return plot.str();
  };
  std::ostringstream gp;
  gp << "set terminal pngcairo size 1000," << 200 + 180 * panels
     << " enhanced font 'Sans,10'\nset grid\nset lmargin 12\nset rmargin 24\n"
     << gnuplot_stacked_figure(png.front(), title + ": estimate error z - zhat, run 0", panels, ylabel, curves)
     << "set output\n";
  const std::string script = scratch.add((fs::path(dir) / "plot.gp").string(), gp.str());
  run_plot_script(script, png, {"error.png"});
}

// The Monte-Carlo figure (error_norms.png): |z − ẑ| of every filter, the steady-state window's
// start marked.
double estimate_error_norm(const LinearPlantSample& s) { return (s.z - s.z_hat).norm(); }
families::ErrorBand<LinearPlantSample> linear_plant_error_band(const LinearPlantExperiment& e) {
  families::ErrorBand<LinearPlantSample> band{
      {{"|z - zhat|", estimate_error_norm}}, {}, {{e.options.window_start, "steady state"}}};
  for (std::size_t f = 0; f < e.filters.size(); ++f) band.filters.push_back(f);
  return band;
}

}  // namespace

namespace families {

const StreamOutputs<LinearPlantExperiment, LinearPlantStatistics, LinearPlantSample>& linear_plant_outputs() {
  static const StreamOutputs<LinearPlantExperiment, LinearPlantStatistics, LinearPlantSample> outputs{
      format_linear_plant_trajectory_csv, format_linear_plant_runs_csv, format_linear_plant_summary_json,
      write_linear_plant_plots, linear_plant_error_band};
  return outputs;
}

}  // namespace families
}  // namespace hinf::sim
