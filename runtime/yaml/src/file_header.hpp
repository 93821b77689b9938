// The header fields a gains file and a controller file share, read one way (private to
// hinf_runtime_yaml).
#pragma once
#include <algorithm>
#include <cctype>
#include <string>

#include "hinf/common/yaml_reader.hpp"

namespace hinf::runtime_yaml {

// `config_sha256`, the SHA-256 of the synthesis config the file came from: 64 hexadecimal
// digits when present, "" when absent; anything else is Error(InvalidInput) naming the key.
inline std::string read_config_sha256(const YamlMap& top) {
  const std::string sha = top.word("config_sha256", "");
  const bool hex64 = sha.size() == 64 && std::all_of(sha.begin(), sha.end(), [](char c) {
                       return std::isxdigit(static_cast<unsigned char>(c)) != 0;
                     });
  if (top.has("config_sha256") && !hex64) top.fail("config_sha256", "expected 64 hexadecimal digits, got '" + sha + "'");
  return sha;
}

}  // namespace hinf::runtime_yaml
