// The families whose every run feeds each of their filters one measurement stream and keeps
// run 0's samples (gyroless_attitude, manoeuvring_target, gps_ins_relative, linear_plant), and
// every run's error norms for the Monte-Carlo figure: the campaign, the three files and the
// plots are the same; a family gives its functions as a
// StreamFunctions table (its outputs a StreamOutputs table) and, if it has more files, an
// `extra` hook.
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "families.hpp"
#include "hinf/sim/plots.hpp"
#include "hinf/sim/scenario.hpp"

namespace hinf::sim::families {

// One error norm of a stream family's Monte-Carlo figure (error_norms.png): its panel's y label
// with units, and its value for a sample (NaN once the filter's estimate is not finite).
template <class Sample>
struct ErrorNorm {
  const char* label;
  double (*of)(const Sample& s);
};

// What a stream family's Monte-Carlo figure draws: the norms, the experiment's filters drawn (in
// drawing order), the vertical marks (its steady-state window) and the thresholds.
template <class Sample>
struct ErrorBand {
  std::vector<ErrorNorm<Sample>> norms;
  std::vector<std::size_t> filters;
  std::vector<std::pair<double, std::string>> marks;
  std::vector<ErrorBandFigure::Threshold> thresholds = {};
};

// A stream family's output files (its <prefix>_report.cpp): trajectory.csv (run 0, every
// filter), runs.csv and summary.json (every run), the plots of run 0, and the Monte-Carlo
// figure of the error norms over every run (error_band: what it draws).
template <class Experiment, class Stats, class Sample>
struct StreamOutputs {
  using Campaign = std::vector<std::vector<Stats>>;  // [run][filter]
  using Samples = std::vector<std::vector<Sample>>;  // [filter][sample] of run 0
  std::string (*trajectory_csv)(const Experiment& e, const Samples& samples);
  std::string (*runs_csv)(const Experiment& e, const Campaign& stats, const std::vector<std::uint64_t>& seeds);
  std::string (*summary_json)(const Experiment& e, const Campaign& stats, const std::string& path, std::uint64_t seed);
  // Into temporaries of `outputs`; throws PlotError (plots.hpp).
  void (*plots)(const std::string& dir, const Experiment& e, const Samples& samples, const std::string& title,
                AtomicFileSet& outputs);
  ErrorBand<Sample> (*error_band)(const Experiment& e);
};

// One run's error norms, sample by sample, for the Monte-Carlo figure: the filters of `band`
// only (none when band is null).
template <class Sample>
class ErrorNormRecorder {
 public:
  ErrorNormRecorder(const ErrorBand<Sample>* band, std::size_t filters) : band_(band), slot_(filters, kNotDrawn) {
    if (!band_) return;
    for (std::size_t i = 0; i < band_->filters.size(); ++i) slot_.at(band_->filters[i]) = i;
    t_.resize(band_->filters.size());
    norms_.assign(band_->filters.size(), std::vector<std::vector<double>>(band_->norms.size()));
  }
  bool active() const { return band_ != nullptr; }
  void add(int filter, const Sample& s) {
    const std::size_t i = slot_[static_cast<std::size_t>(filter)];
    if (i == kNotDrawn) return;
    t_[i].push_back(s.t);
    for (std::size_t q = 0; q < band_->norms.size(); ++q) norms_[i][q].push_back(band_->norms[q].of(s));
  }
  // The run's traces (run_traces, plots.hpp).
  RunTraces traces(double window) const { return run_traces(t_, norms_, window); }
  // The norms themselves, at the instants of the filter with the most samples.
  RawNorms raw() const {
    RawNorms out{{}, norms_};
    for (const std::vector<double>& t : t_)
      if (t.size() > out.t.size()) out.t = t;
    return out;
  }

 private:
  static constexpr std::size_t kNotDrawn = static_cast<std::size_t>(-1);
  const ErrorBand<Sample>* band_;
  std::vector<std::size_t> slot_;                       // experiment filter -> drawn filter
  std::vector<std::vector<double>> t_;                  // [drawn filter][sample]
  std::vector<std::vector<std::vector<double>>> norms_;  // [drawn filter][norm][sample]
};

// Run 0's norms of the figure's filters at every sample (the raw traces of a one-run figure).
template <class Sample>
RawNorms raw_norms(const ErrorBand<Sample>& band, const std::vector<std::vector<Sample>>& samples) {
  ErrorNormRecorder<Sample> recorder(&band, samples.size());
  for (std::size_t f = 0; f < samples.size(); ++f)
    for (const Sample& s : samples[f]) recorder.add(static_cast<int>(f), s);
  return recorder.raw();
}

template <class Experiment, class Stats, class Sample>
struct StreamFunctions {
  using Outputs = StreamOutputs<Experiment, Stats, Sample>;
  using Campaign = typename Outputs::Campaign;
  using Samples = typename Outputs::Samples;
  using Scenario = decltype(Experiment::scenario);
  using Filters = decltype(Experiment::filters);
  using RunOptions = decltype(Experiment::options);  // has on_sample
  const char* name;
  Experiment (*parse)(const std::string& text, const std::string& path);
  void (*shorten)(Experiment& e, double duration);  // --duration, already checked
  // One run of every filter on `scenario` (the experiment's own, or a variant) with `seed`.
  std::vector<Stats> (*run)(const Scenario& scenario, const Filters& filters, const RunOptions& options,
                            std::uint64_t seed);
  Outputs outputs;
  // More files from more campaigns (gps_ins_relative's table1.csv), or nullptr.
  void (*extra)(const CampaignRequest& r, const Experiment& e, const Campaign& stats,
                std::vector<std::pair<std::string, std::string>>& files) = nullptr;
  // The files the experiment read beside the scenario (no output may replace them), or nullptr.
  std::vector<std::string> (*inputs)(const Experiment& e) = nullptr;
};

// The Monte-Carlo runs of e on `scenario`, stats[run][filter] (for_each_run's contract): run 0's
// samples into *samples when given (sized by the caller), and with `band` every run's traces of
// its error norms into *traces (moving RMS over `window` s).
template <class Experiment, class Stats, class Sample>
std::vector<std::vector<Stats>> stream_campaign(const StreamFunctions<Experiment, Stats, Sample>& f,
                                                const CampaignRequest& r, const Experiment& e,
                                                const decltype(Experiment::scenario)& scenario,
                                                typename StreamFunctions<Experiment, Stats, Sample>::Samples* samples,
                                                const ErrorBand<Sample>* band = nullptr,
                                                std::vector<RunTraces>* traces = nullptr, double window = 0) {
  std::vector<std::vector<Stats>> stats(static_cast<std::size_t>(r.runs));
  if (traces) traces->assign(static_cast<std::size_t>(r.runs), RunTraces{});
  for_each_run(
      r.runs, r.jobs,
      [&](long i) {
        const auto run = static_cast<std::size_t>(i);
        ErrorNormRecorder<Sample> recorder(traces ? band : nullptr, e.filters.size());
        const bool keep = i == 0 && samples;
        auto options = e.options;
        if (keep || recorder.active())
          options.on_sample = [&](int filter, const Sample& s) {
            if (keep) (*samples)[static_cast<std::size_t>(filter)].push_back(s);
            recorder.add(filter, s);
          };
        stats[run] = f.run(scenario, e.filters, options, run_seed(r.seed, i));
        if (recorder.active()) (*traces)[run] = recorder.traces(window);
      },
      r.progress, r.interrupted);
  return stats;
}

// The Monte-Carlo figure's settings (plots.hpp) for `band` of experiment e.
template <class Experiment, class Sample>
ErrorBandFigure error_band_figure(const Experiment& e, const ErrorBand<Sample>& band, const std::string& title,
                                  double window) {
  ErrorBandFigure fig;
  fig.file = "error_norms.png";
  fig.title = title;
  for (std::size_t f : band.filters) fig.filters.push_back(e.filters[f].name);
  for (const ErrorNorm<Sample>& n : band.norms) fig.norms.push_back(n.label);
  fig.window_s = window;
  fig.marks = band.marks;
  fig.thresholds = band.thresholds;
  return fig;
}

template <class Experiment, class Stats, class Sample>
class StreamFamily final : public Family {
 public:
  using Functions = StreamFunctions<Experiment, Stats, Sample>;
  explicit constexpr StreamFamily(const Functions& f) : f_(f) {}
  const char* name() const override { return f_.name; }
  void parse(const std::string& text, const std::string& path) const override { f_.parse(text, path); }

  CampaignResult simulate(const CampaignRequest& r) const override {
    Experiment loaded = f_.parse(r.scenario_text, r.scenario_path);
    if (r.duration) f_.shorten(loaded, checked_duration(*r.duration, loaded.scenario.sample_time));
    const auto e = std::make_shared<const Experiment>(std::move(loaded));
    const auto samples = std::make_shared<typename Functions::Samples>(e->filters.size());
    const auto band = std::make_shared<const ErrorBand<Sample>>(f_.outputs.error_band(*e));
    const auto traces = std::make_shared<std::vector<RunTraces>>();
    const double window = e->scenario.duration / kPlotWindowsPerRun;
    const typename Functions::Campaign stats =
        stream_campaign(f_, r, *e, e->scenario, samples.get(), band.get(), e->plots ? traces.get() : nullptr, window);
    CampaignResult out;
    const typename Functions::Outputs& o = f_.outputs;
    out.files = {{"trajectory.csv", o.trajectory_csv(*e, *samples)},
                 {"runs.csv", o.runs_csv(*e, stats, run_seeds(r.seed, r.runs))},
                 {"summary.json", o.summary_json(*e, stats, r.scenario_path, r.seed)}};
    if (f_.extra) f_.extra(r, *e, stats, out.files);
    if (f_.inputs) out.inputs = f_.inputs(*e);
    out.plots = e->plots;
    out.draw_plots = [e, samples, band, traces, window, plots = o.plots, seed = r.seed, runs = r.runs](
                         const std::string& dir, const std::string& title, AtomicFileSet& outputs) {
      plots(dir, *e, *samples, plot_title(title, seed, runs), outputs);
      write_error_band_figure(dir, error_band_figure(*e, *band, plot_title(title, seed, runs), window), *traces,
                              runs == 1 ? raw_norms(*band, *samples) : RawNorms{}, outputs);
    };
    return out;
  }

 private:
  Functions f_;
};

}  // namespace hinf::sim::families
