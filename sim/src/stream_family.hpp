// The families whose every run feeds each of their filters one measurement stream and keeps
// run 0's samples (gyroless_attitude, manoeuvring_target, gps_ins_relative, linear_plant): the campaign,
// the three files and the plots are the same; a family gives its functions as a
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
#include "hinf/sim/scenario.hpp"

namespace hinf::sim::families {

// A stream family's output files (its <prefix>_report.cpp): trajectory.csv (run 0, every
// filter), runs.csv and summary.json (every run), and the plots of run 0.
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
};

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

// The Monte-Carlo runs of e on `scenario` (run 0's samples into *samples when given).
template <class Experiment, class Stats, class Sample>
std::vector<std::vector<Stats>> stream_campaign(const StreamFunctions<Experiment, Stats, Sample>& f,
                                                const CampaignRequest& r, const Experiment& e,
                                                const decltype(Experiment::scenario)& scenario,
                                                typename StreamFunctions<Experiment, Stats, Sample>::Samples* samples) {
  return campaign<Stats, Sample>(r, samples, [&](std::uint64_t seed, const std::function<void(int, const Sample&)>& on) {
    auto options = e.options;
    options.on_sample = on;
    return f.run(scenario, e.filters, options, seed);
  });
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
    const typename Functions::Campaign stats = stream_campaign(f_, r, *e, e->scenario, samples.get());
    CampaignResult out;
    const typename Functions::Outputs& o = f_.outputs;
    out.files = {{"trajectory.csv", o.trajectory_csv(*e, *samples)},
                 {"runs.csv", o.runs_csv(*e, stats, run_seeds(r.seed, r.runs))},
                 {"summary.json", o.summary_json(*e, stats, r.scenario_path, r.seed)}};
    if (f_.extra) f_.extra(r, *e, stats, out.files);
    if (f_.inputs) out.inputs = f_.inputs(*e);
    out.plots = e->plots;
    out.draw_plots = [e, samples, plots = o.plots, seed = r.seed, runs = r.runs](
                         const std::string& dir, const std::string& title, AtomicFileSet& outputs) {
      plots(dir, *e, *samples, plot_title(title, seed, runs), outputs);
    };
    return out;
  }

 private:
  Functions f_;
};

}  // namespace hinf::sim::families
