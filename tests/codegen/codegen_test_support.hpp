// Helpers for the codegen tests: temporary directories, running commands,
// seeded random gains, an independent reference implementation of docs/maths.md (5)-(6).
#pragma once
#include <Eigen/Dense>
#include <cstdint>
#include <string>

#include "hinf/runtime_yaml/gains_file.hpp"

namespace hinf::test {

// A fresh directory under /tmp, removed (with its contents) on destruction.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::string& path() const { return path_; }
  std::string operator/(const std::string& name) const { return path_ + "/" + name; }

 private:
  std::string path_;
};

struct CommandResult {
  int exit_code;       // -1 if the command did not exit normally
  std::string output;  // stdout and stderr together
};
CommandResult run(const std::string& command);

std::string read_text(const std::string& path);
void write_text(const std::string& path, const std::string& text);
// Sorted names of the entries of a directory ("" for a missing directory).
std::string list_dir(const std::string& path);

// Seeded random filter of the given size; A_F scaled to spectral radius 0.9 so a
// few hundred steps stay bounded; entries of mixed magnitudes.
runtime_yaml::GainsFile random_gains(std::uint64_t seed, int n, int m, int l);
// The same with a filtered estimate's feedthrough D_F (l×m, docs/maths.md (140)) and the
// observer gains K, M it comes with (form observer, estimate filtered).
runtime_yaml::GainsFile random_filtered_gains(std::uint64_t seed, int n, int m, int l);
// The same filter given a known input u (docs/maths.md (121)): G_F (n×r) random, in observer
// form (K = B_F) as the tool writes it (the augmented form has no known input).
runtime_yaml::GainsFile with_known_input(runtime_yaml::GainsFile g, std::uint64_t seed, int r);
// A gains file (format hinf-gains/1) with 17 significant digits.
std::string gains_yaml(const runtime_yaml::GainsFile& g);

// Deterministic inputs uniform in [-1, 1) (std::mt19937_64, own mapping).
Eigen::MatrixXd random_matrix(std::uint64_t seed, Eigen::Index rows, Eigen::Index cols);

// docs/maths.md (5)-(6) in double with an Eigen loop: x(0) = pinv(C) z0 (pinv by JacobiSVD),
// row k of the result = z(k) = C x(k) + D y(k) (D = 0: the predictor), x(k+1) = A x(k) + B y(k)
// (+ G u(k) with a known input, (121): row k of U = u(k); G n×0 and U N×0 without).
Eigen::MatrixXd reference_outputs(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B,
                                  const Eigen::MatrixXd& C, const Eigen::MatrixXd& D,
                                  const Eigen::VectorXd& z0, const Eigen::MatrixXd& Y);
Eigen::MatrixXd reference_outputs(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B,
                                  const Eigen::MatrixXd& C, const Eigen::MatrixXd& D,
                                  const Eigen::MatrixXd& G, const Eigen::VectorXd& z0,
                                  const Eigen::MatrixXd& Y, const Eigen::MatrixXd& U);
Eigen::MatrixXd pinv_svd(const Eigen::MatrixXd& C);

// Rounds every entry to float (and back).
Eigen::MatrixXd to_float(const Eigen::MatrixXd& m);

// Strict flags for the generated C (the brief's list; float adds -Wfloat-conversion).
std::string strict_c_flags(bool is_float);

}  // namespace hinf::test
