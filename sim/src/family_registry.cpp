// The experiment families (sim/family.hpp): a new family is its folder sim/families/<name>/
// and one line in kFamilies.
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "families.hpp"
#include "hinf/common/yaml_reader.hpp"
#include "hinf/sim/run_directory.hpp"

namespace hinf::sim {
namespace {

using Accessor = const Family& (*)();
constexpr std::array kFamilies{&families::hill,
                               &families::tumbling_hold,
                               &families::gps_ins_relative,
                               &families::gyroless_attitude,
                               &families::manoeuvring_target,
                               &families::linear_plant};

}  // namespace

const Family& family_of(const std::string& text, const std::string& path) {
  const YamlReader reader(path);
  const YAML::Node root = reader.load(text, "empty scenario; expected a map");
  if (!root.IsMap() || !root["scenario"]) return families::hill();
  std::vector<std::string> names;
  for (const Accessor family : kFamilies)
    if (*family().name() != '\0') names.emplace_back(family().name());
  const std::string name = reader.choice(root["scenario"], "scenario", names);
  for (const Accessor family : kFamilies)
    if (name == family().name()) return family();
  return families::hill();  // not reached: choice() accepts the names above only
}

CampaignResult simulate(const CampaignRequest& request) {
  return family_of(request.scenario_text, request.scenario_path).simulate(request);
}

RunDirectoryReplaced write_campaign(const CampaignResult& result, const std::string& out_dir,
                                    const std::string& scenario_path, bool plots) {
  std::vector<std::string> read = result.inputs;
  read.push_back(scenario_path);
  const std::string title = std::filesystem::path(scenario_path).stem().string();
  std::function<void(AtomicFileSet&)> draw;
  if (plots && result.plots && result.draw_plots)
    draw = [&](AtomicFileSet& outputs) { result.draw_plots(out_dir, title, outputs); };
  return write_run_directory(out_dir, result.files, read, draw);
}

}  // namespace hinf::sim
