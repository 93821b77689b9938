#include "codegen_test_support.hpp"

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace hinf::test {

TempDir::TempDir() {
  std::string templ = (std::filesystem::temp_directory_path() / "hinf_codegen_XXXXXX").string();
  std::vector<char> buf(templ.begin(), templ.end());
  buf.push_back('\0');
  if (::mkdtemp(buf.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
  path_ = buf.data();
}

TempDir::~TempDir() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

CommandResult run(const std::string& command) {
  const std::string full = command + " 2>&1";
  FILE* pipe = ::popen(full.c_str(), "r");
  if (pipe == nullptr) return {-1, "popen failed"};
  std::string out;
  std::array<char, 4096> buf{};
  std::size_t got = 0;
  while ((got = std::fread(buf.data(), 1, buf.size(), pipe)) > 0) out.append(buf.data(), got);
  const int status = ::pclose(pipe);
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return {code, out};
}

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + path);
}

std::string list_dir(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return "";
  std::set<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(path))
    names.insert(e.path().filename().string());
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : " ") + n;
  return s.empty() ? "(empty)" : s;
}

Eigen::MatrixXd random_matrix(std::uint64_t seed, Eigen::Index rows, Eigen::Index cols) {
  std::mt19937_64 gen(seed);
  Eigen::MatrixXd m(rows, cols);
  for (Eigen::Index i = 0; i < rows; ++i)
    for (Eigen::Index j = 0; j < cols; ++j)
      m(i, j) = std::ldexp(static_cast<double>(gen() >> 11), -52) - 1.0;
  return m;
}

runtime_yaml::GainsFile random_gains(std::uint64_t seed, int n, int m, int l) {
  runtime_yaml::GainsFile g;
  Eigen::MatrixXd A = random_matrix(seed, n, n);
  const double rho = A.eigenvalues().cwiseAbs().maxCoeff();
  g.A_F = A * (0.9 / rho);
  // Mixed magnitudes: columns of B scaled over 1e-3..1e2, rows of C over 1e-2..1e1.
  g.B_F = random_matrix(seed + 1, n, m);
  for (int j = 0; j < m; ++j) g.B_F.col(j) *= std::pow(10.0, -3.0 + 5.0 * j / std::max(1, m - 1));
  g.C_F = random_matrix(seed + 2, l, n);
  for (int i = 0; i < l; ++i) g.C_F.row(i) *= std::pow(10.0, -2.0 + 3.0 * i / std::max(1, l - 1));
  g.gamma = 1.2345678901234567;
  g.tool = "test_codegen random_gains";
  return g;
}

runtime_yaml::GainsFile random_filtered_gains(std::uint64_t seed, int n, int m, int l) {
  runtime_yaml::GainsFile g = random_gains(seed, n, m, l);
  g.observer_form = true;
  g.filtered = true;
  g.K = g.B_F;
  g.M = random_matrix(seed + 3, n, m);
  g.D_F = random_matrix(seed + 4, l, m);
  return g;
}

runtime_yaml::GainsFile with_known_input(runtime_yaml::GainsFile g, std::uint64_t seed, int r) {
  if (!g.observer_form) {
    g.observer_form = true;
    g.K = g.B_F;
  }
  g.G_F = random_matrix(seed + 5, g.A_F.rows(), r);
  return g;
}

namespace {
std::string yaml_matrix(const Eigen::MatrixXd& m) {
  std::ostringstream os;
  os.precision(17);
  os << "\n";
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    os << "    - [";
    for (Eigen::Index j = 0; j < m.cols(); ++j) os << (j ? ", " : "") << m(i, j);
    os << "]\n";
  }
  return os.str();
}
}  // namespace

std::string gains_yaml(const runtime_yaml::GainsFile& g) {
  std::ostringstream os;
  os.precision(17);
  os << "format: hinf-gains/1\n";
  if (!g.tool.empty()) os << "tool: " << g.tool << "\n";
  if (!g.config_sha256.empty()) os << "config_sha256: " << g.config_sha256 << "\n";
  os << "dimensions: {n: " << g.A_F.rows() << ", m: " << g.B_F.cols() << ", l: " << g.C_F.rows()
     << "}\n";
  if (g.gamma) os << "gamma: " << *g.gamma << "\n";
  os << "filter:\n";
  if (g.observer_form) os << "  form: observer\n";
  if (g.filtered) os << "  estimate: filtered\n";
  os << "  A_F:" << yaml_matrix(g.A_F) << "  B_F:" << yaml_matrix(g.B_F) << "  C_F:" << yaml_matrix(g.C_F);
  if (g.observer_form) os << "  K:" << yaml_matrix(g.K);
  if (g.filtered) os << "  M:" << yaml_matrix(g.M) << "  D_F:" << yaml_matrix(g.D_F);
  if (g.G_F.cols() > 0) os << "  G_F:" << yaml_matrix(g.G_F);
  return os.str();
}

Eigen::MatrixXd pinv_svd(const Eigen::MatrixXd& C) {
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(C, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd s = svd.singularValues();
  const double tol = static_cast<double>(std::max(C.rows(), C.cols())) * s(0) *
                     Eigen::NumTraits<double>::epsilon();
  Eigen::VectorXd s_inv = Eigen::VectorXd::Zero(s.size());
  for (Eigen::Index i = 0; i < s.size(); ++i)
    if (s(i) > tol) s_inv(i) = 1.0 / s(i);
  return svd.matrixV() * s_inv.asDiagonal() * svd.matrixU().transpose();
}

Eigen::MatrixXd reference_outputs(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B,
                                  const Eigen::MatrixXd& C, const Eigen::MatrixXd& D,
                                  const Eigen::VectorXd& z0, const Eigen::MatrixXd& Y) {
  return reference_outputs(A, B, C, D, Eigen::MatrixXd::Zero(A.rows(), 0), z0, Y,
                           Eigen::MatrixXd::Zero(Y.rows(), 0));
}

Eigen::MatrixXd reference_outputs(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B,
                                  const Eigen::MatrixXd& C, const Eigen::MatrixXd& D,
                                  const Eigen::MatrixXd& G, const Eigen::VectorXd& z0,
                                  const Eigen::MatrixXd& Y, const Eigen::MatrixXd& U) {
  Eigen::VectorXd x = pinv_svd(C) * z0;
  Eigen::MatrixXd Z(Y.rows(), C.rows());
  for (Eigen::Index k = 0; k < Y.rows(); ++k) {
    Z.row(k) = (C * x + D * Y.row(k).transpose()).transpose();
    x = A * x + B * Y.row(k).transpose() + G * U.row(k).transpose();
  }
  return Z;
}

Eigen::MatrixXd to_float(const Eigen::MatrixXd& m) {
  return m.cast<float>().cast<double>();
}

std::string strict_c_flags(bool is_float) {
  std::string f = "-std=c99 -Wall -Wextra -Wpedantic -Werror -Wshadow -Wconversion "
                  "-Wdouble-promotion";
  if (is_float) f += " -Wfloat-conversion";
  return f;
}

}  // namespace hinf::test
