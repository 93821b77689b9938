// hinf-synth sweep CONFIG (--param NAME=LO:STEP:HI | --max-feasible NAME=LO:HI)
//   [-o sweep.csv] [--json sweep.json] [--plot sweep.png] [--tolerance T]
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli_support.hpp"
#include "commands.hpp"
#include "hinf/common/atomic_file.hpp"
#include "hinf/common/gnuplot.hpp"
#include "hinf/common/input_file.hpp"
#include "hinf/synth/api.hpp"  // json_schema
#include "hinf/synth/sweep.hpp"

namespace hinf::cli {
namespace {


struct SweepArgs {
  std::string config, param, max_feasible, csv, json, plot;
  double tolerance = 1e-3;
  bool quiet = false;
  bool verbose = false;  // each point on stderr as it ends, with its time
};

// The text report's stream: stdout, stderr when the CSV or the JSON goes to stdout (-o -,
// --json -), none with -q.
std::ostream& report(const SweepArgs& a) {
  static std::ostream none(nullptr);
  return a.quiet ? none : report_stream(a.csv == "-" || a.json == "-" ? "-" : "");
}

// NAME=RANGE → (NAME, RANGE); Error InvalidInput naming the option otherwise.
std::pair<std::string, std::string> name_and_range(const std::string& text, const std::string& option) {
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
    throw Error(ErrorCode::InvalidInput, option + " '" + text + "': expected NAME=RANGE (e.g. delta_bar=0:0.05:1)",
                option);
  return {text.substr(0, eq), text.substr(eq + 1)};
}

std::string csv_field(const std::string& s) {
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string sweep_csv(const std::string& name, const std::vector<synth::SweepPoint>& points) {
  std::ostringstream os;
  os << "parameter,value,outcome,exit_code,gamma,gamma_lower,form,time_s,message\n";
  for (const auto& p : points) {
    const bool ok = p.outcome == ErrorCode::Ok;
    os << name << ',' << num(p.value) << ',' << synth::sweep_outcome_word(p.outcome) << ',' << exit_code(p.outcome) << ','
       << (ok ? num(p.gamma) : "") << ',' << (ok && p.gap_certified ? num(p.gamma_lower) : "") << ',' << p.form
       << ',' << num(p.time_s) << ',' << csv_field(p.message) << '\n';
  }
  return os.str();
}

Json point_json(const synth::SweepPoint& p) {
  const bool ok = p.outcome == ErrorCode::Ok;
  Json j = Json::object();
  j["value"] = p.value;
  j["outcome"] = synth::sweep_outcome_word(p.outcome);
  j["exit_code"] = exit_code(p.outcome);
  j["gamma"] = ok ? Json(p.gamma) : Json(nullptr);
  j["gamma_lower"] = ok && p.gap_certified ? Json(p.gamma_lower) : Json(nullptr);
  j["form"] = ok ? Json(p.form) : Json(nullptr);
  j["time_s"] = p.time_s;
  j["message"] = p.message;
  return j;
}

// γ against the parameter (log scale), the points that were not certified marked on the axis.
// `floor` is where the uncertified points are drawn (the smallest certified γ, or 1).
std::string sweep_plot_script(const std::string& name, const std::string& data, const std::string& png, double floor) {
  const std::string y = num(floor);
  std::ostringstream gp;
  gp << "set terminal pngcairo size 900,520 enhanced font 'Sans,11'\nset output " << gnuplot_quoted(png) << "\n"
     << "set grid\nset key top left\nset logscale y\nset datafile separator ','\nset datafile missing ''\n"
     << "set xlabel " << gnuplot_quoted(name) << " noenhanced\nset ylabel 'certified {/Symbol g}'\n"
     << "set title 'hinf-synth sweep: certified bound against " << name << "' noenhanced\n"
     << "plot " << gnuplot_quoted(data)
     << " every ::1 using 2:($4==0 ? $5 : 1/0) with linespoints pt 7 lc rgb '#d62728' title 'certified {/Symbol g}', "
     << gnuplot_quoted(data)
     << " every ::1 using 2:($4==0 && $6 > 0 ? $6 : 1/0) with points pt 6 lc rgb '#1f77b4' title 'verified lower bound', "
     << gnuplot_quoted(data)
     << " every ::1 using 2:($4==3 ? " << y << " : 1/0) with points pt 2 ps 1.5 lc rgb '#000000' title 'infeasible (exit 3)', "
     << gnuplot_quoted(data)
     << " every ::1 using 2:($4!=0 && $4!=3 ? " << y << " : 1/0) with points pt 4 ps 1.5 lc rgb '#ff7f0e' title 'no verdict (exit 2 or 4)'\n"
     << "set output\n";
  return gp.str();
}

// The smallest certified γ, where the uncertified points are drawn (1 if none).
double plot_floor(const std::vector<synth::SweepPoint>& points) {
  double floor = 0;
  for (const auto& p : points)
    if (p.outcome == ErrorCode::Ok && (floor == 0 || p.gamma < floor)) floor = p.gamma;
  return floor > 0 ? floor : 1.0;
}

std::string point_text(const std::string& name, const synth::SweepPoint& p) {
  std::string out = name + " = " + num(p.value) + ": ";
  if (p.outcome == ErrorCode::Ok)
    return out + "gamma = " + num(p.gamma) + " certified (" + p.form + " form)" +
           (p.gap_certified ? ", gamma* >= " + num(p.gamma_lower) : std::string());
  return out + synth::sweep_outcome_word(p.outcome) + " (exit " + std::to_string(exit_code(p.outcome)) + "): " + p.message;
}

void print_points(std::ostream& out, const std::string& name, const std::vector<synth::SweepPoint>& points) {
  for (const auto& p : points) out << point_text(name, p) << "\n";
}

// -v: each point on stderr as it ends.
synth::SweepPointObserver verbose_points(const SweepArgs& a, const std::string& name) {
  if (!a.verbose) return nullptr;
  return [name](const synth::SweepPoint& p) {
    Stages(true, "sweep").line(point_text(name, p) + " (" + num(p.time_s) + " s)");
  };
}

int run_sweep(const SweepArgs& a, const std::string& text) {
  const auto name_range = name_and_range(a.param, "--param");
  const std::string& name = name_range.first;
  const std::string& range = name_range.second;
  const std::vector<double> values = synth::parse_sweep_range(range, "--param");
  const synth::SweepParameter parameter = synth::resolve_sweep_parameter(name, text, a.config);
  const std::vector<synth::SweepPoint> points =
      synth::sweep(parameter, values, text, a.config, nullptr, verbose_points(a, name));
  print_points(report(a), name, points);
  const std::string csv = sweep_csv(name, points);
  if (!a.csv.empty()) write_output(a.csv, csv, {a.config});
  if (!a.json.empty()) {
    Json j = Json::object();
    j["schema"] = synth::json_schema("sweep");
    j["config"] = a.config;
    j["parameter"] = name;
    j["points"] = Json::array();
    for (const auto& p : points) j["points"].push_back(point_json(p));
    write_output(a.json, j.dump(2) + "\n", {a.config});
  }
  if (!a.plot.empty())
    write_png_by_gnuplot(
        a.plot, csv,
        [&](const std::string& data, const std::string& png) { return sweep_plot_script(name, data, png, plot_floor(points)); },
        {a.config});
  return 0;
}

int run_max_feasible(const SweepArgs& a, const std::string& text) {
  const auto [name, range] = name_and_range(a.max_feasible, "--max-feasible");
  const std::size_t colon = range.find(':');
  if (colon == std::string::npos || range.find(':', colon + 1) != std::string::npos)
    throw Error(ErrorCode::InvalidInput, "--max-feasible '" + a.max_feasible + "': expected NAME=LO:HI", "--max-feasible");
  const double lo = synth::parse_sweep_range(range.substr(0, colon), "--max-feasible").front();
  const double hi = synth::parse_sweep_range(range.substr(colon + 1), "--max-feasible").front();
  const synth::SweepParameter parameter = synth::resolve_sweep_parameter(name, text, a.config);
  const synth::FeasibilitySearch s =
      synth::max_feasible(parameter, lo, hi, a.tolerance, text, a.config, nullptr, verbose_points(a, name));
  print_points(report(a), name, s.evaluated);
  const synth::SweepPoint& best = s.largest_certified;
  report(a) << "largest certified " << name << " = " << num(best.value) << " (gamma = " << num(best.gamma) << ")";
  if (!s.bracketed) report(a) << ": the upper end of the range; the boundary, if any, lies above it\n";
  else {
    const synth::SweepPoint& up = *s.smallest_not_certified;
    report(a) << "; no certified filter at " << num(up.value) << " (" << synth::sweep_outcome_word(up.outcome)
              << "): bracket width " << num(s.width) << "\n";
    if (!s.smallest_infeasible)
      report(a) << "no point was verified infeasible: above " << num(best.value)
                << " the solver failed numerically, which is not a proof that no filter exists\n";
    else if (s.smallest_infeasible->value == up.value)
      report(a) << "verified infeasible at " << num(up.value) << ": the boundary lies in [" << num(best.value)
                << ", " << num(up.value) << "]\n";
    else
      report(a) << "verified infeasible from " << num(s.smallest_infeasible->value) << ": the boundary lies in ["
                << num(best.value) << ", " << num(s.smallest_infeasible->value) << "]; between " << num(up.value)
                << " and " << num(s.smallest_infeasible->value)
                << " the solver failed numerically (no verdict: neither a filter nor a proof that none exists)\n";
  }
  if (!a.json.empty()) {
    Json j = Json::object();
    j["schema"] = synth::json_schema("max-feasible");
    j["config"] = a.config;
    j["parameter"] = name;
    j["largest_certified"] = point_json(best);
    j["smallest_not_certified"] = s.smallest_not_certified ? point_json(*s.smallest_not_certified) : Json(nullptr);
    j["smallest_infeasible"] = s.smallest_infeasible ? point_json(*s.smallest_infeasible) : Json(nullptr);
    j["bracket_width"] = s.bracketed ? Json(s.width) : Json(nullptr);
    j["evaluated"] = Json::array();
    for (const auto& p : s.evaluated) j["evaluated"].push_back(point_json(p));
    write_output(a.json, j.dump(2) + "\n", {a.config});
  }
  if (!a.csv.empty()) write_output(a.csv, sweep_csv(name, s.evaluated), {a.config});
  return 0;
}

}  // namespace

void add_sweep(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand(
      "sweep", "certified gamma against one number of the config (--param), or the largest value of it with a "
               "certified filter, by bisection (--max-feasible); every point is a full solve with its certificate");
  auto a = std::make_shared<SweepArgs>();
  cmd->add_option("config", a->config, "config YAML")->required();
  auto* param = cmd->add_option("--param", a->param,
                                "NAME=LO:STEP:HI: NAME is a named parameter of the config (its design point, in its "
                                "units; its range moves along), delta_bar (hill.delta_bar), uncertainty_scale (E "
                                "multiplied by the value) or a key path of the config holding a number, e.g. "
                                "hill.sample_time");
  auto* maxf = cmd->add_option("--max-feasible", a->max_feasible, "NAME=LO:HI: the largest certified value in [LO, HI]");
  param->excludes(maxf);
  cmd->add_option("--tolerance", a->tolerance, "--max-feasible: width of the final bracket (default 1e-3)");
  cmd->add_option("-o,--output", a->csv, "CSV of every point (parameter, value, outcome, exit_code, gamma, ...; - for stdout)");
  add_quiet_flag(*cmd, a->quiet);
  add_verbose_flag(*cmd, a->verbose, "each point on stderr as it ends, with its wall time");
  cmd->add_option("--json", a->json, "the same as JSON, to this file (- for stdout)");
  cmd->add_option("--plot", a->plot, "PNG of gamma against the parameter (--param; gnuplot)");
  cmd->callback([a, &action] {
    action = [a]() -> int {
      if (a->param.empty() == a->max_feasible.empty())
        throw Error(ErrorCode::InvalidInput, "sweep: give exactly one of --param NAME=LO:STEP:HI or --max-feasible NAME=LO:HI");
      if (!a->plot.empty() && a->param.empty())
        throw Error(ErrorCode::InvalidInput, "--plot is for --param sweeps");
      if (a->csv == "-" && a->json == "-")
        throw Error(ErrorCode::InvalidInput, "-o - and --json - both write to stdout: give one of them a file", "--json");
      const std::string text = read_input_file(a->config, "config", kMaxConfigBytes);
      return a->param.empty() ? run_max_feasible(*a, text) : run_sweep(*a, text);
    };
  });
}

}  // namespace hinf::cli
