// MATLAB files (docs/file-formats.md "MATLAB files"): the writer (hinf/matfile/mat_file.hpp)
// read back through matio's reader, and the executables' `--format mat` against the YAML
// and CSV files the same runs write (read by yaml-cpp and strtod): every number bit for bit.
#include <gtest/gtest.h>
#include <matio.h>
#include <sys/wait.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "api_test_support.hpp"
#include "hinf/common/error.hpp"
#include "hinf/matfile/mat_file.hpp"

namespace fs = std::filesystem;
using hinf::matfile::Json;

namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

struct MatFile {
  explicit MatFile(const std::string& path) : mat(Mat_Open(path.c_str(), MAT_ACC_RDONLY)) {}
  ~MatFile() {
    if (mat) Mat_Close(mat);
  }
  struct Free {
    void operator()(matvar_t* v) const { Mat_VarFree(v); }
  };
  std::unique_ptr<matvar_t, Free> read(const char* name) const { return {Mat_VarRead(mat, name), {}}; }
  mat_t* mat;
};

// The doubles of a variable, column-major.
std::vector<double> doubles(const matvar_t* v) {
  EXPECT_EQ(v->class_type, MAT_C_DOUBLE);
  const std::size_t n = v->dims[0] * v->dims[1];
  const auto* p = static_cast<const double*>(v->data);
  return std::vector<double>(p, p + n);
}

std::string chars(const matvar_t* v) {
  EXPECT_EQ(v->class_type, MAT_C_CHAR);
  return std::string(static_cast<const char*>(v->data), v->dims[1]);
}

matvar_t* field(const matvar_t* s, const char* name) {
  EXPECT_EQ(s->class_type, MAT_C_STRUCT);
  return Mat_VarGetStructFieldByName(const_cast<matvar_t*>(s), name, 0);
}

// This process's scratch directory, removed when the tests end.
struct ScratchDir {
  fs::path dir = fs::temp_directory_path() / ("hinf_mat_" + std::to_string(::getpid()));
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
};
const ScratchDir kScratch;

std::string scratch(const std::string& name) {
  fs::create_directories(kScratch.dir);
  return (kScratch.dir / name).string();
}

void write(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

int run(const std::string& command) { return std::system((command + " > /dev/null 2>&1").c_str()); }

TEST(MatFile, EveryKindOfValueReadsBackAsWritten) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Json vars = Json::object();
  vars["gamma"] = 0.35872371288998356;
  vars["M"] = Json::array({Json::array({1.5, -0.0, 4.9406564584124654e-324}), Json::array({nan, INFINITY, 3.0})});
  vars["row"] = Json::array({1.0, 2.0, 3.0});
  vars["name"] = "hinf-gains/1";
  vars["passed"] = true;
  vars["none"] = nullptr;
  vars["s"] = {{"n", 6}, {"inner", {{"x", -2.5}}}};
  vars["mixed"] = Json::array({"a", 1.0});
  const std::string path = scratch("values.mat");
  write(path, hinf::matfile::mat_file_bytes(vars, "MATLAB 5.0 MAT-file, test"));
  const MatFile f(path);
  ASSERT_NE(f.mat, nullptr);
  EXPECT_TRUE(same_bits(doubles(f.read("gamma").get())[0], 0.35872371288998356));
  const auto M = f.read("M");
  ASSERT_EQ(M->dims[0], 2u);
  ASSERT_EQ(M->dims[1], 3u);
  const std::vector<double> m = doubles(M.get());  // column-major: (0,0) (1,0) (0,1) (1,1) (0,2) (1,2)
  EXPECT_TRUE(same_bits(m[0], 1.5));
  EXPECT_TRUE(std::isnan(m[1]));
  EXPECT_TRUE(same_bits(m[2], -0.0));
  EXPECT_TRUE(same_bits(m[3], INFINITY));
  EXPECT_TRUE(same_bits(m[4], 4.9406564584124654e-324));
  EXPECT_TRUE(same_bits(m[5], 3.0));
  const auto row = f.read("row");
  EXPECT_EQ(row->dims[0], 1u);
  EXPECT_EQ(row->dims[1], 3u);
  EXPECT_EQ(chars(f.read("name").get()), "hinf-gains/1");
  const auto passed = f.read("passed");
  EXPECT_TRUE(passed->isLogical);
  EXPECT_EQ(*static_cast<const std::uint8_t*>(passed->data), 1);
  const auto none = f.read("none");
  EXPECT_EQ(none->dims[0] * none->dims[1], 0u);
  const auto s = f.read("s");
  EXPECT_TRUE(same_bits(doubles(field(s.get(), "n"))[0], 6.0));
  EXPECT_TRUE(same_bits(doubles(field(field(s.get(), "inner"), "x"))[0], -2.5));
  EXPECT_EQ(f.read("mixed")->class_type, MAT_C_CELL);
}

TEST(MatFile, TheBytesAreTheSameForTheSameVariables) {
  const Json vars = {{"a", 1.0}, {"b", "x"}};
  EXPECT_EQ(hinf::matfile::mat_file_bytes(vars, "h"), hinf::matfile::mat_file_bytes(vars, "h"));
}

TEST(MatFile, ANameMatlabCannotHoldIsRefusedNamingIt) {
  try {
    hinf::matfile::mat_file_bytes({{"s", {{"bad-name", 1.0}}}}, "h");
    FAIL() << "no error";
  } catch (const hinf::Error& e) {
    EXPECT_EQ(e.code(), hinf::ErrorCode::InvalidInput);
    EXPECT_NE(std::string(e.what()).find("'bad-name'"), std::string::npos) << e.what();
  }
}

TEST(MatFile, CsvColumnsAreNamedColumnsWithNanForEmptyCells) {
  const Json t = hinf::matfile::csv_columns("t,x-1,label\n0,1.5,a\n0.1,,\"b,c\"\n", "t.csv");
  ASSERT_EQ(t.size(), 3u);
  EXPECT_TRUE(t.contains("x_1"));
  EXPECT_TRUE(std::isnan(t["x_1"][1][0].get<double>()));
  EXPECT_EQ(t["label"][1][0], "b,c");
  EXPECT_THROW(hinf::matfile::csv_columns("a,b\n1\n", "t.csv"), hinf::Error);
}

// solve -o X.yaml and -o X.mat: the MAT-file's variables are the YAML's keys, bit for bit.
TEST(MatFile, SolveWritesTheGainsFileAsMatlabVariables) {
  const std::string config = std::string(HINF_SOURCE_DIR) + "/configs/paper-dbar0.05.yaml";
  const std::string yaml_path = scratch("gains.yaml"), mat_path = scratch("gains.mat");
  ASSERT_EQ(run(std::string(HINF_SYNTH_EXE) + " solve " + config + " -o " + yaml_path), 0);
  ASSERT_EQ(run(std::string(HINF_SYNTH_EXE) + " solve " + config + " -o " + mat_path), 0);
  const YAML::Node y = YAML::LoadFile(yaml_path);
  const MatFile f(mat_path);
  ASSERT_NE(f.mat, nullptr);
  EXPECT_EQ(chars(f.read("format").get()), "hinf-gains/1");
  EXPECT_TRUE(same_bits(doubles(f.read("gamma").get())[0], y["gamma"].as<double>()));
  const auto filter = f.read("filter");
  for (const char* name : {"A_F", "B_F", "C_F"}) {
    const matvar_t* v = field(filter.get(), name);
    const YAML::Node rows = y["filter"][name];
    ASSERT_EQ(v->dims[0], rows.size()) << name;
    ASSERT_EQ(v->dims[1], rows[0].size()) << name;
    const std::vector<double> d = doubles(v);
    for (std::size_t r = 0; r < v->dims[0]; ++r)
      for (std::size_t c = 0; c < v->dims[1]; ++c)
        EXPECT_TRUE(same_bits(d[c * v->dims[0] + r], rows[r][c].as<double>())) << name << "(" << r << "," << c << ")";
  }
  const auto certificate = f.read("certificate");
  const matvar_t* passed = field(certificate.get(), "passed");
  EXPECT_TRUE(passed->isLogical);
  EXPECT_TRUE(same_bits(doubles(field(certificate.get(), "robust_bound"))[0],
                        y["certificate"]["robust_bound"].as<double>()));
  // what reads gains files refuses the MAT-file, naming it
  EXPECT_EQ(WEXITSTATUS(run(std::string(HINF_SYNTH_EXE) + " verify " + config + " " + mat_path)), 2);
}

TEST(MatFile, HinfSimWritesRunMatBesideItsCsvFiles) {
  const std::string out = scratch("run");
  ASSERT_EQ(run(std::string(HINF_SIM_EXE) + " " + HINF_SOURCE_DIR +
                "/configs/scenarios/paper-no-control.yaml -o " + out +
                " --runs 2 --seed 7 --duration 300 --no-plots --quiet --format mat"),
            0);
  const MatFile f(out + "/run.mat");
  ASSERT_NE(f.mat, nullptr);
  const auto trajectory = f.read("trajectory");
  const std::string csv = hinf::test::slurp(out + "/trajectory.csv");
  std::istringstream in(csv);
  std::string header, line;
  std::getline(in, header);
  const std::string first = header.substr(0, header.find(','));
  const matvar_t* t = field(trajectory.get(), first.c_str());
  ASSERT_NE(t, nullptr) << first;
  const std::vector<double> column = doubles(t);
  std::size_t k = 0;
  while (std::getline(in, line)) {
    ASSERT_LT(k, column.size());
    EXPECT_TRUE(same_bits(column[k++], std::strtod(line.c_str(), nullptr)));
  }
  EXPECT_EQ(k, column.size());
  EXPECT_EQ(t->dims[1], 1u);  // a column
  const auto summary = f.read("summary");
  EXPECT_EQ(chars(field(summary.get(), "format")), "hinf-sim-summary/1");
  EXPECT_NE(f.read("runs"), nullptr);
}

}  // namespace
