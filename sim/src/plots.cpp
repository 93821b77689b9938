#include "hinf/sim/plots.hpp"

#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>

#include "hinf/common/atomic_file.hpp"
#include "hinf/common/gnuplot.hpp"

namespace hinf::sim {
namespace {

const std::map<std::string, std::string> kColour = {
    {"hinf", "#d62728"}, {"published", "#ff7f0e"}, {"ekf", "#1f77b4"}, {"ekf_no_control", "#7f7f7f"}, {"rekf", "#2ca02c"}};

std::string colour(const std::string& name) {
  const auto it = kColour.find(name);
  return it == kColour.end() ? "#000000" : it->second;
}

std::string quoted(const std::string& s) { return gnuplot_quoted(s); }

// Data: t, thrust (3), then |e_p|, |e_v| per filter.
std::string plot_data(const Trajectory& tr) {
  std::ostringstream os;
  os.precision(9);
  for (std::size_t k = 0; k < tr.t.size(); ++k) {
    os << tr.t[k] << ' ' << tr.thrust[k](0) << ' ' << tr.thrust[k](1) << ' ' << tr.thrust[k](2);
    for (const auto& f : tr.filters) {
      const Vector6 e = f.estimate[k] - tr.truth[k];
      if (e.allFinite()) os << ' ' << e.head<3>().norm() << ' ' << e.tail<3>().norm();
      else os << " NaN NaN";
    }
    os << '\n';
  }
  return os.str();
}

// The gnuplot script drawing `data` into png[0..2] (position error, velocity error, thrust).
std::string plot_script(const Trajectory& tr, const std::string& title, const std::string& data,
                        const std::vector<std::string>& png) {
  std::ostringstream gp;
  gp << "set terminal pngcairo size 1000,560 enhanced font 'Sans,11'\n"
     << "set grid\nset key outside right top\nset xlabel 'time (s)'\n"
     << "set datafile missing 'NaN'\n";
  // Drawing order: the noisiest (LTI) traces first, so that they do not hide the others.
  std::vector<std::size_t> order;
  for (const char* name : {"published", "hinf", "ekf_no_control", "ekf", "rekf"})
    for (std::size_t f = 0; f < tr.filters.size(); ++f)
      if (tr.filters[f].name == name) order.push_back(f);
  auto error_plot = [&](int which, const std::string& out, const std::string& ylabel, const std::string& what) {
    gp << "set output " << quoted(out) << "\nset logscale y\nset format y '10^{%L}'\n"
       << "set ylabel " << quoted(ylabel) << "\nset title " << quoted(title + ": " + what) << " noenhanced\n"
       << "plot ";
    for (std::size_t i = 0; i < order.size(); ++i) {
      const std::size_t f = order[i];
      const int col = 5 + 2 * static_cast<int>(f) + which;
      gp << (i ? ", " : "") << quoted(data) << " using 1:" << col << " with lines lw 1.5 lc rgb "
         << quoted(colour(tr.filters[f].name)) << " title " << quoted(tr.filters[f].name) << " noenhanced";
    }
    gp << "\nunset logscale y\nset format y '%g'\n";
  };
  error_plot(0, png[0], "position error |r̂ − r| (m)", "position error");
  error_plot(1, png[1], "velocity error |v̂ − v| (m/s)", "velocity error");
  gp << "set output " << quoted(png[2]) << "\nset ylabel 'thrust (N)'\nset title "
     << quoted(title + ": thrust u = K x") << " noenhanced\n"
     << "plot " << quoted(data) << " using 1:2 with lines lw 1.5 title 'F_x', " << quoted(data)
     << " using 1:3 with lines lw 1.5 title 'F_y', " << quoted(data) << " using 1:4 with lines lw 1.5 title 'F_z'\n"
     << "set output\n";
  return gp.str();
}

}  // namespace

void run_plot_script(const std::string& script, const std::vector<std::string>& png,
                     const std::vector<std::string>& names) {
  namespace fs = std::filesystem;
  const int rc = run_gnuplot(script);
  if (rc != 0)
    throw PlotError(rc < 0 ? "cannot run gnuplot (is the gnuplot package installed?); use --no-plots to skip plots"
                           : "gnuplot failed with exit status " + std::to_string(rc));
  for (std::size_t i = 0; i < names.size(); ++i) {
    std::error_code ec;
    if (!fs::exists(png[i], ec) || fs::file_size(png[i], ec) == 0)
      throw PlotError("gnuplot produced no output for " + names[i]);
  }
}

std::vector<std::string> write_plots(const std::string& dir, const Trajectory& tr, const std::string& title,
                                     AtomicFileSet& outputs) {
  namespace fs = std::filesystem;
  const std::vector<std::string> names = {"position_error.png", "velocity_error.png", "thrust.png"};
  std::vector<std::string> png;
  for (const auto& n : names) png.push_back(outputs.reserve((fs::path(dir) / n).string()));
  AtomicFileSet scratch;  // never committed: removed on return
  const std::string data = scratch.add((fs::path(dir) / "plot.dat").string(), plot_data(tr));
  const std::string script = scratch.add((fs::path(dir) / "plot.gp").string(), plot_script(tr, title, data, png));
  run_plot_script(script, png, names);
  return names;
}

}  // namespace hinf::sim
