// verify, check and analyze of controller files (docs/maths.md §26): the subcommands call
// these when their config declares `controller:`.
#pragma once
#include <string>

namespace hinf::cli {

// True if the config file at `path` is a controller config (it is then read again by the
// functions below; a missing or unreadable file answers false and the filter path says why).
bool is_controller_config(const std::string& path);

int verify_controller_file(const std::string& config_path, const std::string& controller_path);
int check_controller_file(const std::string& config_path, const std::string& golden_path, double rtol);
int analyze_controller_file(const std::string& config_path, const std::string& controller_path, bool json);

}  // namespace hinf::cli
