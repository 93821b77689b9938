// MAT-files through matio (mat_file.hpp).
#include "hinf/matfile/mat_file.hpp"

#include <matio.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>
#include <vector>

#include "hinf/common/error.hpp"

namespace hinf::matfile {
namespace {

// MATLAB's namelengthmax.
constexpr std::size_t kMaxNameLength = 63;

bool is_identifier(const std::string& s) {
  if (s.empty() || s.size() > kMaxNameLength || !std::isalpha(static_cast<unsigned char>(s[0]))) return false;
  for (char c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  return true;
}

void require_identifier(const std::string& name, const std::string& where) {
  if (!is_identifier(name))
    throw Error(ErrorCode::InvalidInput, where + "'" + name +
                                             "' is not a MATLAB name (letters, digits, underscores, a letter first, at "
                                             "most 63 characters)");
}

struct VarFree {
  void operator()(matvar_t* v) const { Mat_VarFree(v); }
};
using Var = std::unique_ptr<matvar_t, VarFree>;

bool is_scalar(const Json& j) { return !j.is_array() && !j.is_object(); }

// An array of R equal-length arrays of scalars: its shape (R, C), else (0, 0).
std::pair<std::size_t, std::size_t> table_shape(const Json& j) {
  if (j.empty() || !j.front().is_array()) return {0, 0};
  const std::size_t cols = j.front().size();
  for (const Json& row : j) {
    if (!row.is_array() || row.size() != cols) return {0, 0};
    for (const Json& e : row)
      if (!is_scalar(e)) return {0, 0};
  }
  return {j.size(), cols};
}

bool all_numbers(const Json& j) {
  for (const Json& e : j)
    if (!(e.is_number() || (e.is_array() && all_numbers(e)))) return false;
  return true;
}

Var make(const std::string& name, const Json& j, const std::string& where);

Var doubles(const std::string& name, std::size_t rows, std::size_t cols, const std::vector<double>& column_major) {
  size_t dims[2] = {rows, cols};
  return Var(Mat_VarCreate(name.c_str(), MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims,
                           const_cast<double*>(column_major.data()), 0));  // matio copies the data
}

Var text(const std::string& name, const std::string& s) {
  size_t dims[2] = {1, s.size()};
  return Var(Mat_VarCreate(name.c_str(), MAT_C_CHAR, MAT_T_UTF8, 2, dims, const_cast<char*>(s.data()), 0));
}

Var cell(const std::string& name, std::size_t rows, std::size_t cols, const std::vector<const Json*>& column_major,
         const std::string& where) {
  size_t dims[2] = {rows, cols};
  Var c(Mat_VarCreate(name.c_str(), MAT_C_CELL, MAT_T_CELL, 2, dims, nullptr, 0));
  for (std::size_t k = 0; k < column_major.size(); ++k)
    Mat_VarSetCell(c.get(), static_cast<int>(k), make("", *column_major[k], where).release());
  return c;
}

Var structure(const std::string& name, const Json& j, const std::string& where) {
  std::vector<std::string> names;
  for (auto it = j.begin(); it != j.end(); ++it) {
    require_identifier(it.key(), where + "field ");
    names.push_back(it.key());
  }
  std::vector<const char*> fields;
  for (const auto& n : names) fields.push_back(n.c_str());
  size_t dims[2] = {1, 1};
  Var s(Mat_VarCreateStruct(name.c_str(), 2, dims, fields.data(), static_cast<unsigned>(fields.size())));
  for (auto it = j.begin(); it != j.end(); ++it)
    Mat_VarSetStructFieldByName(s.get(), it.key().c_str(), 0,
                                make(it.key(), it.value(), where + it.key() + ".").release());
  return s;
}

Var make(const std::string& name, const Json& j, const std::string& where) {
  if (j.is_object()) return structure(name, j, where);
  if (j.is_string()) return text(name, j.get<std::string>());
  if (j.is_boolean()) {
    std::uint8_t b = j.get<bool>() ? 1 : 0;
    size_t dims[2] = {1, 1};
    return Var(Mat_VarCreate(name.c_str(), MAT_C_UINT8, MAT_T_UINT8, 2, dims, &b, MAT_F_LOGICAL));
  }
  if (j.is_null()) return doubles(name, 0, 0, {});
  if (j.is_number()) return doubles(name, 1, 1, {j.get<double>()});
  // an array
  if (j.empty()) return doubles(name, 0, 0, {});
  const auto [rows, cols] = table_shape(j);
  if (rows > 0) {
    if (all_numbers(j)) {
      std::vector<double> v;
      v.reserve(rows * cols);
      for (std::size_t c = 0; c < cols; ++c)
        for (std::size_t r = 0; r < rows; ++r) v.push_back(j[r][c].get<double>());
      return doubles(name, rows, cols, v);
    }
    std::vector<const Json*> v;
    for (std::size_t c = 0; c < cols; ++c)
      for (std::size_t r = 0; r < rows; ++r) v.push_back(&j[r][c]);
    return cell(name, rows, cols, v, where);
  }
  if (all_numbers(j) && std::all_of(j.begin(), j.end(), [](const Json& e) { return e.is_number(); })) {
    std::vector<double> v;
    for (const Json& e : j) v.push_back(e.get<double>());
    return doubles(name, 1, v.size(), v);
  }
  std::vector<const Json*> v;
  for (const Json& e : j) v.push_back(&e);
  return cell(name, 1, v.size(), v, where);
}

// A private temporary file (matio writes to a path), removed when this goes.
class ScratchFile {
 public:
  ScratchFile() {
    const char* dir = std::getenv("TMPDIR");
    path_ = std::string(dir && *dir ? dir : "/tmp") + "/hinf-mat-XXXXXX";
    const int fd = mkstemp(path_.data());
    if (fd < 0) throw Error(ErrorCode::InvalidInput, "MAT-file: cannot create a temporary file in " + path_);
    close(fd);
  }
  ~ScratchFile() { std::remove(path_.c_str()); }
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

std::vector<std::string> csv_row(const std::string& line) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        cells.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        cells.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      cells.emplace_back();
    } else if (c != '\r') {
      cells.back() += c;
    }
  }
  return cells;
}

// A cell as a number: "" and "nan" are NaN; false if it is not a number.
bool cell_number(const std::string& s, double& v) {
  if (s.empty() || s == "nan" || s == "-nan") {
    v = std::numeric_limits<double>::quiet_NaN();
    return true;
  }
  char* end = nullptr;
  v = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size();
}

std::string identifier_from(const std::string& header) {
  std::string s;
  for (char c : header) s += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  if (s.empty() || !std::isalpha(static_cast<unsigned char>(s[0]))) s = "x" + s;
  return s.substr(0, kMaxNameLength);
}

}  // namespace

std::string mat_file_bytes(const Json& variables, const std::string& description) {
  if (!variables.is_object()) throw Error(ErrorCode::InvalidInput, "MAT-file: the variables must be named");
  std::vector<Var> vars;
  for (auto it = variables.begin(); it != variables.end(); ++it) {
    require_identifier(it.key(), "MAT-file variable ");
    vars.push_back(make(it.key(), it.value(), it.key() + "."));
  }
  const ScratchFile scratch;
  mat_t* mat = Mat_CreateVer(scratch.path().c_str(), description.c_str(), MAT_FT_MAT5);
  if (!mat) throw Error(ErrorCode::NumericalFailure, "MAT-file: matio cannot create " + scratch.path());
  int failed = 0;
  for (const Var& v : vars) failed |= Mat_VarWrite(mat, v.get(), MAT_COMPRESSION_NONE);
  Mat_Close(mat);
  if (failed) throw Error(ErrorCode::NumericalFailure, "MAT-file: matio failed to write a variable");
  std::ifstream in(scratch.path(), std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

Json csv_columns(const std::string& csv_text, const std::string& name) {
  std::istringstream in(csv_text);
  std::string line;
  if (!std::getline(in, line)) return Json::object();
  const std::vector<std::string> header = csv_row(line);
  std::vector<std::vector<std::string>> cells(header.size());
  std::size_t row = 1;
  while (std::getline(in, line)) {
    ++row;
    std::vector<std::string> r = csv_row(line);
    if (r.size() != header.size())
      throw Error(ErrorCode::InvalidInput, name + ": row " + std::to_string(row) + " has " + std::to_string(r.size()) +
                                               " cells, the header " + std::to_string(header.size()));
    for (std::size_t c = 0; c < r.size(); ++c) cells[c].push_back(std::move(r[c]));
  }
  Json out = Json::object();
  for (std::size_t c = 0; c < header.size(); ++c) {
    std::vector<double> numbers(cells[c].size());
    bool numeric = true;
    for (std::size_t r = 0; r < cells[c].size() && numeric; ++r) numeric = cell_number(cells[c][r], numbers[r]);
    Json column = Json::array();
    for (std::size_t r = 0; r < cells[c].size(); ++r)
      column.push_back(Json::array({numeric ? Json(numbers[r]) : Json(cells[c][r])}));
    out[identifier_from(header[c])] = std::move(column);
  }
  return out;
}

}  // namespace hinf::matfile
