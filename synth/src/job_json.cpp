// The jobs' JSON (job_json.hpp).
#include "job_json.hpp"

#include "hinf/synth/api.hpp"

#include <yaml-cpp/yaml.h>

#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <limits>

namespace hinf::synth::job_json {
namespace {

// A plain scalar as YAML 1.2's core schema reads it (what yaml-cpp's emitter writes for a
// bool, a null, an integer or a double); nothing else converts.
Json plain_scalar(const std::string& s) {
  if (s == "true" || s == "True" || s == "TRUE") return true;
  if (s == "false" || s == "False" || s == "FALSE") return false;
  if (s.empty() || s == "~" || s == "null" || s == "Null" || s == "NULL") return nullptr;
  if (s == ".nan" || s == ".NaN" || s == ".NAN" || s == ".inf" || s == ".Inf" || s == ".INF" || s == "-.inf" ||
      s == "-.Inf" || s == "-.INF" || s == "+.inf")
    return nullptr;  // JSON has no non-finite number
  const bool numeric = s.find_first_not_of("0123456789+-.eE") == std::string::npos &&
                       s.find_first_of("0123456789") != std::string::npos;
  if (!numeric) return s;
  const char* begin = s.c_str();
  char* end = nullptr;
  if (s.find_first_of(".eE") == std::string::npos) {
    errno = 0;
    const long long v = std::strtoll(begin, &end, 10);
    if (*end == '\0' && errno == 0) return static_cast<std::int64_t>(v);
  }
  errno = 0;
  const double d = std::strtod(begin, &end);
  if (*end != '\0') return s;
  return Json(d);  // strtod rounds correctly: the file's 17 digits give back the double written
}

Json convert(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Map: {
      Json j = Json::object();
      for (const auto& kv : node) j[kv.first.Scalar()] = convert(kv.second);
      return j;
    }
    case YAML::NodeType::Sequence: {
      Json j = Json::array();
      for (const auto& e : node) j.push_back(convert(e));
      return j;
    }
    case YAML::NodeType::Scalar:
      return node.Tag() == "!" ? Json(node.Scalar()) : plain_scalar(node.Scalar());  // "!": quoted
    default:
      return nullptr;
  }
}

}  // namespace

Json envelope(std::string_view job, std::string_view kind, const std::string& config_source) {
  Json j = Json::object();
  j["schema"] = json_schema(job);
  j["kind"] = std::string(kind);
  j["config"] = config_source;
  return j;
}

Json from_yaml(const std::string& yaml_text) { return convert(YAML::Load(yaml_text)); }

std::string solved(std::string_view job, std::string_view kind, const std::string& config_source, double gamma,
                   const std::string& file_contents, const std::string& file_text) {
  Json j = envelope(job, kind, config_source);
  j["gamma"] = json_num(gamma);
  j["file_contents"] = file_contents;
  j["file"] = from_yaml(file_text);
  return json_line(j);
}

}  // namespace hinf::synth::job_json

namespace hinf::synth {

std::string json_schema(std::string_view job) {
  return "hinf-synth." + std::string(job) + "/" + std::to_string(job_json::kSchemaVersion);
}

}  // namespace hinf::synth
