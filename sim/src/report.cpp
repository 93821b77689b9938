#include "hinf/sim/report.hpp"

#include "summary_json.hpp"

namespace hinf::sim {

std::string format_trajectory_csv(const Trajectory& tr) {
  std::string out;
  out.reserve(tr.t.size() * (18 + tr.filters.size() * 6) * 24);
  out += "t,true_x,true_y,true_z,true_vx,true_vy,true_vz,meas_x,meas_y,meas_z,meas_rho,meas_alpha,meas_beta,"
         "thrust_x,thrust_y,thrust_z";
  for (const auto& f : tr.filters)
    for (const char* c : {"_x", "_y", "_z", "_vx", "_vy", "_vz"}) out += "," + f.name + c;
  out += '\n';
  for (std::size_t k = 0; k < tr.t.size(); ++k) {
    append_num(out, tr.t[k]);
    append_cells(out, tr.truth[k], 6);
    append_cells(out, tr.measurement[k].cartesian, 3);
    append_cells(out, tr.measurement[k].rae, 3);
    append_cells(out, tr.thrust[k], 3);
    for (const auto& f : tr.filters)
      append_cells(out, f.estimate[k], 6);
    out += '\n';
  }
  return out;
}

std::string format_runs_csv(const std::vector<RunResult>& runs) {
  std::string out = "run,seed";
  if (runs.empty()) return out + "\n";
  for (const auto& f : runs.front().filters)
    for (const char* c : {"_position_rms_m", "_velocity_rms_mps", "_position_max_m", "_converge_time_s",
                          "_converge_time_pointwise_s", "_diverged"})
      out += "," + f.name + c;
  out += '\n';
  auto cell = [&](const std::optional<double>& v) {
    out += ',';
    if (v) append_num(out, *v);
  };
  for (std::size_t r = 0; r < runs.size(); ++r) {
    out += std::to_string(r) + "," + std::to_string(runs[r].seed);
    for (const auto& f : runs[r].filters) {
      cell(f.metrics.position_rms_m);
      cell(f.metrics.velocity_rms_mps);
      cell(f.metrics.position_max_m);
      cell(f.metrics.converge_time_s);
      cell(f.metrics.converge_time_pointwise_s);
      out += f.metrics.diverged ? ",1" : ",0";
    }
    out += '\n';
  }
  return out;
}

std::string format_summary_json(const Scenario& s, const std::vector<RunResult>& runs, const SummaryContext& ctx) {
  const MetricSettings ms = s.metric_settings();
  Json j = summary_header(ctx.scenario_path, ctx.seed, runs.size(), s.duration);
  j["sample_time_s"] = json_num(s.sample_time);
  j["truth_delta"] = json_num(s.truth_delta);
  j["steady_state_start_s"] = json_num(ms.steady_state_start_s);
  j["converge_threshold_m"] = json_num(ms.converge_threshold_m);
  j["converge_window_s"] = json_num(ms.converge_window_s);
  Json& gains = j["gains"] = Json::object();
  for (const auto& [name, info] : ctx.gains) {
    Json& g = gains[name] = Json::object();
    g["origin"] = info.origin;
    g["gamma"] = json_opt(info.gamma);
  }
  Json& filters = j["filters"] = Json::object();
  const std::size_t nf = runs.empty() ? 0 : runs.front().filters.size();
  for (std::size_t f = 0; f < nf; ++f) {
    Json& out = filters[runs.front().filters[f].name] = Json::object();
    if (runs.size() == 1) {
      const FilterOutcome& o = runs.front().filters[f];
      const FilterMetrics& m = o.metrics;
      out["position_rms_m"] = json_opt(m.position_rms_m);
      out["velocity_rms_mps"] = json_opt(m.velocity_rms_mps);
      out["position_max_m"] = json_opt(m.position_max_m);
      out["converge_time_s"] = json_opt(m.converge_time_s);
      out["converge_time_pointwise_s"] = json_opt(m.converge_time_pointwise_s);
      out["converged"] = m.converge_time_s.has_value();
      out["diverged"] = m.diverged;
      out["diverged_at_s"] = json_opt(m.diverged_at_s);
      out["failed_steps"] = o.health.failed_steps;
      if (o.health.failed_steps > 0) {
        out["first_failure"] = o.health.first_failure;
        out["first_failure_t_s"] = json_num(o.health.first_failure_t);
      }
    } else {
      std::vector<std::optional<double>> prms, vrms, pmax, conv, conv_pointwise;
      long diverged = 0, never = 0, failed_runs = 0;
      for (const auto& run : runs) {
        const FilterOutcome& o = run.filters[f];
        prms.push_back(o.metrics.position_rms_m);
        vrms.push_back(o.metrics.velocity_rms_mps);
        pmax.push_back(o.metrics.position_max_m);
        conv.push_back(o.metrics.converge_time_s);
        conv_pointwise.push_back(o.metrics.converge_time_pointwise_s);
        diverged += o.metrics.diverged ? 1 : 0;
        never += (!o.metrics.diverged && !o.metrics.converge_time_s) ? 1 : 0;
        failed_runs += o.health.failed_steps > 0 ? 1 : 0;
      }
      out["position_rms_m"] = json_stats(prms);
      out["velocity_rms_mps"] = json_stats(vrms);
      out["position_max_m"] = json_stats(pmax);
      out["converge_time_s"] = json_stats(conv);
      out["converge_time_pointwise_s"] = json_stats(conv_pointwise);
      out["diverged_runs"] = diverged;
      out["never_converged_runs"] = never;
      out["runs_with_failed_steps"] = failed_runs;
    }
  }
  // A path that is not UTF-8 is written with U+FFFD rather than refused.
  return j.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

}  // namespace hinf::sim
