#include "hinf/sim/report.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace hinf::sim {
namespace {

void append_num(std::string& out, double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  out += buf;
}

std::string json_num(double v) {
  if (!std::isfinite(v)) throw std::logic_error("summary.json: refusing to write a non-finite number");
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string json_opt(const std::optional<double>& v) { return v ? json_num(*v) : "null"; }

std::string json_str(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\', out += c;
    else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else out += c;
  }
  return out + "\"";
}

std::string json_stats(const std::vector<std::optional<double>>& values) {
  const MetricStats s = compute_stats(values);
  if (s.count == 0) return "null";
  return "{\"mean\": " + json_num(s.mean) + ", \"std\": " + json_num(s.std) + ", \"min\": " + json_num(s.min) +
         ", \"max\": " + json_num(s.max) + ", \"count\": " + std::to_string(s.count) + "}";
}

}  // namespace

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
    for (int i = 0; i < 6; ++i) out += ',', append_num(out, tr.truth[k](i));
    for (int i = 0; i < 3; ++i) out += ',', append_num(out, tr.measurement[k].cartesian(i));
    for (int i = 0; i < 3; ++i) out += ',', append_num(out, tr.measurement[k].rae(i));
    for (int i = 0; i < 3; ++i) out += ',', append_num(out, tr.thrust[k](i));
    for (const auto& f : tr.filters)
      for (int i = 0; i < 6; ++i) out += ',', append_num(out, f.estimate[k](i));
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
  std::ostringstream os;
  os << "{\n";
  os << "  \"format\": \"hinf-sim-summary/1\",\n";
  os << "  \"scenario\": " << json_str(ctx.scenario_path) << ",\n";
  os << "  \"seed\": " << ctx.seed << ",\n";
  os << "  \"runs\": " << runs.size() << ",\n";
  os << "  \"duration_s\": " << json_num(s.duration) << ",\n";
  os << "  \"sample_time_s\": " << json_num(s.sample_time) << ",\n";
  os << "  \"truth_delta\": " << json_num(s.truth_delta) << ",\n";
  os << "  \"steady_state_start_s\": " << json_num(ms.steady_state_start_s) << ",\n";
  os << "  \"converge_threshold_m\": " << json_num(ms.converge_threshold_m) << ",\n";
  os << "  \"converge_window_s\": " << json_num(ms.converge_window_s) << ",\n";
  os << "  \"gains\": {";
  bool first = true;
  for (const auto& [name, info] : ctx.gains) {
    os << (first ? "\n" : ",\n") << "    " << json_str(name) << ": {\"origin\": " << json_str(info.origin)
       << ", \"gamma\": " << json_opt(info.gamma) << "}";
    first = false;
  }
  os << (first ? "},\n" : "\n  },\n");
  os << "  \"filters\": {";
  const std::size_t nf = runs.empty() ? 0 : runs.front().filters.size();
  for (std::size_t f = 0; f < nf; ++f) {
    os << (f ? ",\n" : "\n") << "    " << json_str(runs.front().filters[f].name) << ": {";
    if (runs.size() == 1) {
      const FilterOutcome& o = runs.front().filters[f];
      const FilterMetrics& m = o.metrics;
      os << "\"position_rms_m\": " << json_opt(m.position_rms_m) << ", \"velocity_rms_mps\": "
         << json_opt(m.velocity_rms_mps) << ", \"position_max_m\": " << json_opt(m.position_max_m)
         << ", \"converge_time_s\": " << json_opt(m.converge_time_s)
         << ", \"converge_time_pointwise_s\": " << json_opt(m.converge_time_pointwise_s) << ", \"converged\": "
         << (m.converge_time_s ? "true" : "false") << ", \"diverged\": " << (m.diverged ? "true" : "false")
         << ", \"diverged_at_s\": " << json_opt(m.diverged_at_s) << ", \"failed_steps\": " << o.health.failed_steps;
      if (o.health.failed_steps > 0)
        os << ", \"first_failure\": " << json_str(o.health.first_failure)
           << ", \"first_failure_t_s\": " << json_num(o.health.first_failure_t);
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
      os << "\n      \"position_rms_m\": " << json_stats(prms) << ",\n      \"velocity_rms_mps\": " << json_stats(vrms)
         << ",\n      \"position_max_m\": " << json_stats(pmax) << ",\n      \"converge_time_s\": " << json_stats(conv)
         << ",\n      \"converge_time_pointwise_s\": " << json_stats(conv_pointwise)
         << ",\n      \"diverged_runs\": " << diverged << ", \"never_converged_runs\": " << never
         << ", \"runs_with_failed_steps\": " << failed_runs << "\n    ";
    }
    os << "}";
  }
  os << (nf ? "\n  }\n" : "}\n");
  os << "}\n";
  return os.str();
}

}  // namespace hinf::sim
