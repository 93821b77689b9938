// What the experiment families share (private to sim/): their accessors, listed once in
// family_registry.cpp, and the Monte-Carlo campaign with a request's runs, jobs, seed and
// progress.
#pragma once
#include <vector>

#include "hinf/sim/family.hpp"
#include "hinf/sim/monte_carlo.hpp"

namespace hinf::sim::families {

const Family& hill();                // sim/families/hill
const Family& tumbling_hold();       // sim/families/tumbling_hold
const Family& gps_ins_relative();    // sim/families/gps_ins_relative
const Family& gyroless_attitude();   // sim/families/gyroless_attitude
const Family& manoeuvring_target();  // sim/families/manoeuvring_target
const Family& linear_plant();        // sim/families/linear_plant

// The Monte-Carlo runs of a family (run_family_campaign) with the request's runs, jobs, seed
// progress and interruption: stats[run][filter], run 0's samples into *samples when given.
template <class Stats, class Sample, class RunOne>
std::vector<std::vector<Stats>> campaign(const CampaignRequest& r, std::vector<std::vector<Sample>>* samples,
                                         const RunOne& run_one) {
  return run_family_campaign<Stats, Sample>(r.runs, r.jobs, r.seed, samples, run_one, r.progress, r.interrupted);
}

}  // namespace hinf::sim::families
