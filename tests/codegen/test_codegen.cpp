// Generated C code (the compiled-code tests generate it with the real `hinf-synth codegen`
// from seeded random gains the generator has never seen, and the paper's gains):
// compiled with gcc and clang under strict warnings, linked into
// a harness and compared with an independent Eigen evaluation of docs/maths.md (5)–(6);
// no heap / libm symbols; cppcheck clean; two filters in one binary; deterministic.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <regex>
#include <set>
#include <sstream>

#include "codegen_test_support.hpp"
#include "hinf/runtime/lti_filter.hpp"
#include "hinf/runtime_yaml/gains_file.hpp"
#include "hinf/runtime_yaml/lti_filter_from_gains.hpp"
#include "hinf/codegen/codegen.hpp"
#include "hinf/common/error.hpp"

namespace {

using hinf::runtime_yaml::GainsFile;
using hinf::codegen::CodegenOptions;
using hinf::test::TempDir;
using Real = CodegenOptions::Real;

constexpr int kSteps = 250;

std::vector<std::string> compilers() {
  std::vector<std::string> c;
  if (std::string(HINF_TEST_GCC).size() > 0) c.emplace_back(HINF_TEST_GCC);
  if (std::string(HINF_TEST_CLANG).size() > 0) c.emplace_back(HINF_TEST_CLANG);
  return c;
}

std::string compiler_tag(const std::string& cc) {
  return cc.find("clang") != std::string::npos ? "clang" : "gcc";
}

// A C program that reads z0 and then y(0), y(1), ... (each y(k) followed by u(k) for a filter
// with a known input, r > 0) from a text file and prints z(k) for each step, one line per
// step, 17 significant digits.
std::string harness_source(const std::string& p, bool is_float, Eigen::Index r) {
  std::string P = p;
  for (auto& c : P) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  const std::string fmt = is_float ? "%f" : "%lf";
  std::ostringstream os;
  os << "#include <stdio.h>\n#include \"" << p << ".h\"\n"
     << "int main(int argc, char **argv)\n{\n"
     << "  " << p << "_state s;\n  " << p << "_real z0[" << P << "_NZ];\n"
     << "  " << p << "_real y[" << P << "_NY];\n  " << p << "_real z[" << P << "_NZ];\n"
     << (r > 0 ? "  " + p + "_real u[" + P + "_NU];\n" : "")
     << "  FILE *f;\n"
     << "  if (argc != 2) { return 2; }\n"
     << "  f = fopen(argv[1], \"r\");\n  if (f == NULL) { return 2; }\n"
     << "  for (int i = 0; i < " << P << "_NZ; ++i) {\n"
     << "    if (fscanf(f, \"" << fmt << "\", &z0[i]) != 1) { fclose(f); return 2; }\n  }\n"
     << "  " << p << "_init(&s, z0);\n"
     << "  for (;;) {\n    int i;\n"
     << "    for (i = 0; i < " << P << "_NY; ++i) {\n"
     << "      if (fscanf(f, \"" << fmt << "\", &y[i]) != 1) { break; }\n    }\n"
     << "    if (i < " << P << "_NY) { break; }\n"
     << (r > 0 ? "    for (i = 0; i < " + P + "_NU; ++i) {\n      if (fscanf(f, \"" + fmt +
                     "\", &u[i]) != 1) { fclose(f); return 2; }\n    }\n"
               : "")
     << "    " << p << (r > 0 ? "_step(&s, y, u, z);\n" : "_step(&s, y, z);\n")
     << "    for (i = 0; i < " << P << "_NZ; ++i) { printf(\"%.17g \", (double)z[i]); }\n"
     << "    printf(\"\\n\");\n  }\n  fclose(f);\n  return 0;\n}\n";
  return os.str();
}

Eigen::MatrixXd parse_outputs(const std::string& text, Eigen::Index rows, Eigen::Index cols) {
  std::istringstream in(text);
  Eigen::MatrixXd Z(rows, cols);
  for (Eigen::Index k = 0; k < rows; ++k)
    for (Eigen::Index i = 0; i < cols; ++i) {
      std::string tok;
      if (!(in >> tok)) throw std::runtime_error("harness output too short");
      Z(k, i) = std::strtod(tok.c_str(), nullptr);
    }
  return Z;
}

// Undefined symbols of an object file.
std::set<std::string> undefined_symbols(const std::string& object) {
  const auto r = hinf::test::run(std::string(HINF_TEST_NM) + " -u " + object);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  std::set<std::string> syms;
  std::istringstream in(r.output);
  std::string kind, name;
  while (in >> kind >> name) syms.insert(name);
  return syms;
}

void expect_no_heap_or_libm(const std::string& object) {
  static const std::set<std::string> forbidden{
      "malloc", "calloc", "realloc", "free", "aligned_alloc", "posix_memalign", "alloca",
      "sqrt", "sqrtf", "fabs", "fabsf", "sin", "sinf", "cos", "cosf", "exp", "expf", "log",
      "logf", "pow", "powf", "floor", "floorf", "ceil", "ceilf", "fma", "fmaf", "round",
      "roundf", "tan", "atan2", "hypot"};
  // Only the block moves a compiler may emit for plain loops are acceptable.
  static const std::set<std::string> allowed{"memcpy", "memmove", "memset"};
  for (const auto& s : undefined_symbols(object)) {
    EXPECT_EQ(forbidden.count(s), 0u) << object << " references " << s;
    EXPECT_EQ(allowed.count(s), 1u) << object << " references unexpected symbol " << s;
  }
}

struct Reference {
  Eigen::MatrixXd A, B, C, D, G;  // coefficients the code implements (D = 0 without a feedthrough,
                                  // G n×0 without a known input)
  Eigen::VectorXd z0;
  Eigen::MatrixXd Y;        // kSteps × m
  Eigen::MatrixXd U;        // kSteps × r, the known input (r = 0: none)
  Eigen::MatrixXd Z;        // kSteps × l, double Eigen loop
  Eigen::MatrixXd Z_lti;    // kSteps × l, the runtime's LtiFilter as its gains-file loader builds it
};

// The filter the runtime flies from a gains file: hinf::runtime_yaml::make_lti_filter on the
// file's text (the coefficients as the generated code has them), driven by the same inputs.
Eigen::MatrixXd loaded_filter_outputs(GainsFile g, const Reference& r) {
  g.A_F = r.A;
  g.B_F = r.B;
  g.C_F = r.C;
  g.G_F = r.G;
  if (g.filtered) g.D_F = r.D;
  hinf::runtime::LtiFilter lti =
      hinf::runtime_yaml::make_lti_filter(hinf::runtime_yaml::parse_gains_yaml(hinf::test::gains_yaml(g), "g.yaml"));
  lti.init(r.z0);
  Eigen::MatrixXd Z(r.Y.rows(), r.C.rows());
  for (Eigen::Index k = 0; k < r.Y.rows(); ++k)
    Z.row(k) = (r.U.cols() > 0 ? lti.step(r.Y.row(k).transpose(), r.U.row(k).transpose())
                               : lti.step(r.Y.row(k).transpose()))
                   .transpose();
  return Z;
}

// How the harness starts the filter: from a random initial estimate z0 (x_F(0) = pinv(C_F) z0),
// or from z0 = 0 (x_F(0) = 0 exactly in every implementation).
enum class Start { RandomEstimate, Zero };

Reference make_reference(const GainsFile& g, bool is_float, std::uint64_t seed, Start start) {
  const auto rounded = [is_float](const Eigen::MatrixXd& M) { return is_float ? hinf::test::to_float(M) : M; };
  Reference r;
  r.A = rounded(g.A_F);
  r.B = rounded(g.B_F);
  r.C = rounded(g.C_F);
  r.D = rounded(g.filtered ? g.D_F : Eigen::MatrixXd::Zero(g.C_F.rows(), g.B_F.cols()));
  r.G = rounded(g.G_F.cols() > 0 ? g.G_F : Eigen::MatrixXd::Zero(g.A_F.rows(), 0));
  r.z0 = start == Start::Zero ? Eigen::VectorXd::Zero(g.C_F.rows())
                              : Eigen::VectorXd(rounded(hinf::test::random_matrix(seed, g.C_F.rows(), 1).col(0) * 3.0));
  r.Y = rounded(hinf::test::random_matrix(seed + 7, kSteps, g.B_F.cols()) * 2.0);
  r.U = rounded(hinf::test::random_matrix(seed + 11, kSteps, r.G.cols()) * 2.0);
  r.Z = hinf::test::reference_outputs(r.A, r.B, r.C, r.D, r.G, r.z0, r.Y, r.U);
  r.Z_lti = loaded_filter_outputs(g, r);
  return r;
}

// Normwise a-priori bound on |z_float(k) − z(k)| for the float code (derived here,
// independently of the generator's componentwise bound): with u = 2^-24,
// γ_k = k u/(1 − k u), X a bound on ‖x(k)‖∞,
//   ‖e(0)‖ ≤ (γ_l + 2u)‖pinv‖ ‖z0‖       (float dot products + pinv rounded to float)
//   ‖δ_j‖ ≤ γ_{n+m+r}(‖A‖ X + ‖B‖ ‖y‖max + ‖G‖ ‖u‖max)  (rounding in one step)
//   |z err(k)| ≤ ‖C A^k‖ ‖e(0)‖ + Σ_{i<k} ‖C A^i‖ δ + γ_n ‖C‖ X,
// the last term γ_{n+m} (‖C‖ X + ‖D‖ ‖y‖max) with the feedthrough D of a filtered estimate.
double float_error_bound(const Reference& r) {
  const double u = std::ldexp(1.0, -24);
  const auto gam = [u](double k) { return k * u / (1.0 - k * u); };
  const double n = static_cast<double>(r.A.rows()), m = static_cast<double>(r.B.cols()),
               l = static_cast<double>(r.C.rows()), nu = static_cast<double>(r.G.cols());
  const double u_max = r.U.size() > 0 ? r.U.cwiseAbs().maxCoeff() : 0.0;
  const auto norm = [](const Eigen::MatrixXd& M) { return M.cwiseAbs().rowwise().sum().maxCoeff(); };
  // State bound: the exact states, plus a margin far above any rounding effect.
  Eigen::VectorXd x = hinf::test::pinv_svd(r.C) * r.z0;
  double X = x.cwiseAbs().maxCoeff();
  for (Eigen::Index k = 0; k < r.Y.rows(); ++k) {
    x = r.A * x + r.B * r.Y.row(k).transpose() + r.G * r.U.row(k).transpose();
    X = std::max(X, x.cwiseAbs().maxCoeff());
  }
  X *= 1.01;
  const double e0 = (gam(l) + 2 * u) * norm(hinf::test::pinv_svd(r.C)) * r.z0.cwiseAbs().maxCoeff();
  const double known = nu > 0 ? norm(r.G) * u_max : 0.0;
  const double delta = gam(n + m + nu) * (norm(r.A) * X + norm(r.B) * r.Y.cwiseAbs().maxCoeff() + known);
  Eigen::MatrixXd power = Eigen::MatrixXd::Identity(r.A.rows(), r.A.cols());
  double sum_ca = 0.0, max_ca = 0.0;
  for (Eigen::Index i = 0; i < r.Y.rows(); ++i) {
    const double ca = norm(r.C * power);
    sum_ca += ca;
    max_ca = std::max(max_ca, ca);
    power = r.A * power;
  }
  const double output = r.D.isZero(0.0) ? gam(n) * norm(r.C) * X
                                         : gam(n + m) * (norm(r.C) * X + norm(r.D) * r.Y.cwiseAbs().maxCoeff());
  return max_ca * e0 + sum_ca * delta + output;
}

// The program whose `codegen` subcommand is tested: hinf-synth, or $HINF_CODEGEN_CLI.
std::string codegen_program() {
  const char* env = std::getenv("HINF_CODEGEN_CLI");
  return env != nullptr && *env != '\0' ? env : HINF_TEST_CODEGEN_CLI;
}

// Generates with `hinf-synth codegen`, compiles with each compiler, checks symbols, runs the generated check
// driver and the harness, and compares with the Eigen reference.
void check_generated(const GainsFile& g, const std::string& prefix, Real real, std::uint64_t seed,
                     Start start = Start::RandomEstimate) {
  const bool is_float = real == Real::Float;
  TempDir dir;
  // Through the real command line: gains file (17 digits, exact round trip) -> hinf-synth codegen.
  hinf::test::write_text(dir / "gains.yaml", hinf::test::gains_yaml(g));
  const auto gen = hinf::test::run(codegen_program() + " codegen " + (dir / "gains.yaml") +
                                   " --prefix " + prefix + " -o " + dir.path() +
                                   (is_float ? " --real float" : " --real double"));
  ASSERT_EQ(gen.exit_code, 0) << gen.output;
  const Reference ref = make_reference(g, is_float, seed, start);
  {
    std::ostringstream in;
    in.precision(17);
    for (Eigen::Index i = 0; i < ref.z0.size(); ++i) in << ref.z0(i) << " ";
    in << "\n";
    for (Eigen::Index k = 0; k < ref.Y.rows(); ++k) {
      for (Eigen::Index j = 0; j < ref.Y.cols(); ++j) in << ref.Y(k, j) << " ";
      for (Eigen::Index j = 0; j < ref.U.cols(); ++j) in << ref.U(k, j) << " ";
      in << "\n";
    }
    hinf::test::write_text(dir / "inputs.txt", in.str());
  }
  hinf::test::write_text(dir / "harness.c", harness_source(prefix, is_float, ref.G.cols()));
  const std::string flags = hinf::test::strict_c_flags(is_float);
  const double scale = ref.Z.cwiseAbs().maxCoeff();
  const double tol = is_float ? float_error_bound(ref) : 1e-12 * scale;
  ASSERT_GT(scale, 0.0);
  ASSERT_FALSE(compilers().empty()) << "no C compiler found at configure time";
  for (const std::string& cc : compilers()) {
    SCOPED_TRACE(cc + " " + prefix);
    const std::string tag = compiler_tag(cc);
    for (const char* opt_level : {"-O0", "-O2"}) {
      const std::string obj = dir / (prefix + "_" + tag + opt_level + ".o");
      const auto c = hinf::test::run(cc + " " + flags + " " + opt_level + " -c " +
                                     (dir / (prefix + ".c")) + " -o " + obj);
      ASSERT_EQ(c.exit_code, 0) << c.output;
      EXPECT_EQ(c.output, "") << "compiler output (warnings) for " << opt_level;
      expect_no_heap_or_libm(obj);
    }
    // The generated on-target check driver.
    const std::string check_exe = dir / (prefix + "_check_" + tag);
    auto c = hinf::test::run(cc + " " + flags + " -O2 " + (dir / (prefix + ".c")) + " " +
                             (dir / (prefix + "_check.c")) + " -o " + check_exe);
    ASSERT_EQ(c.exit_code, 0) << c.output;
    EXPECT_EQ(c.output, "");
    c = hinf::test::run(check_exe);
    EXPECT_EQ(c.exit_code, 0) << c.output;
    EXPECT_NE(c.output.find("PASS"), std::string::npos) << c.output;
    std::cout << "[ generated check ] " << c.output;
    // The harness against the independent reference.
    const std::string harness_exe = dir / ("harness_" + tag);
    c = hinf::test::run(cc + " " + flags + " -O2 -I" + dir.path() + " " + (dir / "harness.c") +
                        " " + (dir / (prefix + ".c")) + " -o " + harness_exe);
    ASSERT_EQ(c.exit_code, 0) << c.output;
    EXPECT_EQ(c.output, "");
    c = hinf::test::run(harness_exe + " " + (dir / "inputs.txt"));
    ASSERT_EQ(c.exit_code, 0) << c.output;
    const Eigen::MatrixXd Z = parse_outputs(c.output, kSteps, ref.Z.cols());
    const double err = (Z - ref.Z).cwiseAbs().maxCoeff();
    std::cout << "[ harness ] " << prefix << " " << tag << " " << (is_float ? "float" : "double")
              << ": " << kSteps << " steps, max |z - z_ref| = " << err << ", signal scale "
              << scale << ", relative " << err / scale << ", tolerance " << tol << "\n";
    EXPECT_LE(err, tol);
    const double err_lti = (Z - ref.Z_lti).cwiseAbs().maxCoeff();
    std::cout << "[ harness ] vs hinf::runtime::LtiFilter: max |z - z_lti| = " << err_lti << "\n";
    EXPECT_LE(err_lti, tol);
    if (is_float) {
      // The float code must really compute in float: a double evaluation would
      // agree with the reference to ~1e-16 relative.
      EXPECT_GT(err, 1e-10 * scale) << "float code agrees with double to double precision";
    }
  }
}

GainsFile paper_gains() { return hinf::runtime_yaml::load_gains_file(HINF_TEST_PAPER_GAINS); }

TEST(CodegenCompiled, PaperGainsDouble) { check_generated(paper_gains(), "nav", Real::Double, 11); }
TEST(CodegenCompiled, PaperGainsFloat) { check_generated(paper_gains(), "navf", Real::Float, 12); }
TEST(CodegenCompiled, RandomGains5x2x3Double) {
  check_generated(hinf::test::random_gains(20261126, 5, 2, 3), "rnd", Real::Double, 13);
}
TEST(CodegenCompiled, RandomGains5x2x3Float) {
  check_generated(hinf::test::random_gains(20261126, 5, 2, 3), "rndf", Real::Float, 14);
}
TEST(CodegenCompiled, RandomGainsTallC3x1x5Double) {  // l > n: least-squares init
  check_generated(hinf::test::random_gains(77, 3, 1, 5), "tall", Real::Double, 15);
}
TEST(CodegenCompiled, RandomGains7x4x1Float) {
  check_generated(hinf::test::random_gains(5, 7, 4, 1), "wide7", Real::Float, 16);
}

// The generated check driver must be able to fail: a perturbed coefficient is caught.
// The filtered estimate's feedthrough z = C_F x_F + D_F y (docs/maths.md (140)).
TEST(CodegenCompiled, FilteredEstimate4x2x3Double) {
  check_generated(hinf::test::random_filtered_gains(41, 4, 2, 3), "fnav", Real::Double, 41);
}
TEST(CodegenCompiled, FilteredEstimate4x2x3Float) {
  check_generated(hinf::test::random_filtered_gains(42, 4, 2, 3), "fnavf", Real::Float, 42);
}

// The known input u (docs/maths.md (121)): NAME_step(s, y, u, z), x_F(k+1) gains G_F u(k); with
// and without the filtered estimate's feedthrough.
TEST(CodegenCompiled, KnownInput5x2x3Double) {
  check_generated(hinf::test::with_known_input(hinf::test::random_gains(51, 5, 2, 3), 51, 2), "unav", Real::Double, 51);
}
TEST(CodegenCompiled, KnownInput5x2x3Float) {
  check_generated(hinf::test::with_known_input(hinf::test::random_gains(52, 5, 2, 3), 52, 2), "unavf", Real::Float, 52);
}
TEST(CodegenCompiled, KnownInputFilteredEstimate4x3x2Double) {
  check_generated(hinf::test::with_known_input(hinf::test::random_filtered_gains(53, 4, 3, 2), 53, 3), "ufnav",
                  Real::Double, 53);
}
TEST(CodegenCompiled, KnownInputFilteredEstimate4x3x2Float) {
  check_generated(hinf::test::with_known_input(hinf::test::random_filtered_gains(54, 4, 3, 2), 54, 3), "ufnavf",
                  Real::Float, 54);
}

// Every kind of gains file the tool writes, written by `hinf-synth solve` itself: the runtime
// loader's filter, the compiled C and the independent loop agree on the same inputs (to
// 1e-12 of the signal in double). The kinds are asserted, so the list cannot silently shrink.
TEST(CodegenCompiled, EveryKindOfGainsFileTheToolWrites) {
  struct Kind {
    const char* config;
    const char* prefix;
    bool observer, filtered, known_input;
  };
  const Kind kinds[] = {
      {HINF_TEST_CONFIGS_DIR "/paper-dbar0.05.yaml", "aug", false, false, false},
      {HINF_TEST_PLANTS_DIR "/double-integrator.yaml", "obs", true, false, false},
      {HINF_TEST_PLANTS_DIR "/double-integrator-filtered.yaml", "obsf", true, true, false},
      {HINF_TEST_PLANTS_DIR "/triple-integrator-known-input.yaml", "obsu", true, false, true},
      {HINF_TEST_PLANTS_DIR "/triple-integrator-known-input-filtered.yaml", "obsfu", true, true, true},
  };
  std::uint64_t seed = 60;
  // A synthesised filtered estimate has C_F = L − L M C nearly singular where M C ≈ I on the
  // measured states (double integrator: C_F(0,0) = 8.5e-8), so pinv(C_F) z0 is ill-conditioned
  // and two correct pseudo-inverses (the implementations' COD, the reference's SVD) differ by
  // cond(C_F)·u; those start at x_F(0) = 0. The init from a random z0 is compared on the
  // well-conditioned random gains above.
  for (const Kind& kind : kinds) {
    SCOPED_TRACE(kind.config);
    TempDir dir;
    const auto solve = hinf::test::run(codegen_program() + " solve " + kind.config + " -o " + (dir / "gains.yaml"));
    ASSERT_EQ(solve.exit_code, 0) << solve.output;
    const GainsFile g = hinf::runtime_yaml::load_gains_file(dir / "gains.yaml");
    EXPECT_EQ(g.observer_form, kind.observer);
    EXPECT_EQ(g.filtered, kind.filtered);
    EXPECT_EQ(g.G_F.cols() > 0, kind.known_input);
    check_generated(g, kind.prefix, Real::Double, ++seed, kind.filtered ? Start::Zero : Start::RandomEstimate);
  }
}

TEST(CodegenCompiled, CheckDriverDetectsAPerturbedCoefficient) {
  for (const Real real : {Real::Double, Real::Float}) {
    const bool is_float = real == Real::Float;
    TempDir dir;
    CodegenOptions opt;
    opt.prefix = "pert";
    opt.real = real;
    auto files = hinf::codegen::generate_c(paper_gains(), opt);
    // Perturb A_F(0,0) = -0.6126 by 1e-5 relative (below the paper's printed precision).
    std::string& src = files.files[1].contents;
    const std::string old = is_float ? "-0.612600029f" : "-0.61260000000000003";
    const std::string pert = is_float ? "-0.612606f" : "-0.612606126";
    const auto pos = src.find(old);
    ASSERT_NE(pos, std::string::npos) << src.substr(0, 800);
    src.replace(pos, old.size(), pert);
    hinf::codegen::write_generated_files(files, dir.path());
    const std::string exe = dir / "pert_check";
    auto c = hinf::test::run(std::string(HINF_TEST_GCC) + " -std=c99 -O2 " + (dir / "pert.c") +
                             " " + (dir / "pert_check.c") + " -o " + exe);
    ASSERT_EQ(c.exit_code, 0) << c.output;
    c = hinf::test::run(exe);
    EXPECT_EQ(c.exit_code, 1) << c.output;
    EXPECT_NE(c.output.find("FAIL"), std::string::npos) << c.output;
  }
}

TEST(CodegenCompiled, CppcheckClean) {
  if (std::string(HINF_TEST_CPPCHECK).empty()) GTEST_SKIP() << "cppcheck not found";
  for (const Real real : {Real::Double, Real::Float}) {
    TempDir dir;
    CodegenOptions opt;
    opt.prefix = "cc";
    opt.real = real;
    hinf::codegen::write_generated_files(hinf::codegen::generate_c(paper_gains(), opt), dir.path());
    const auto c = hinf::test::run(
        std::string(HINF_TEST_CPPCHECK) +
        " --enable=warning,style,performance,portability --error-exitcode=1 --std=c99 -q "
        "--inline-suppr -I" + dir.path() + " " + (dir / "cc.c") + " " + (dir / "cc_check.c"));
    EXPECT_EQ(c.exit_code, 0) << c.output;
    EXPECT_EQ(c.output, "") << c.output;
  }
}

// Another prefix's files in the same directory are never replaced, and a prefix that
// differs from one there only in case is refused (shared macros and include guards).
TEST(CodegenFiles, OtherPrefixesInTheDirectoryAreProtected) {
  TempDir dir;
  CodegenOptions nav;
  nav.prefix = "nav";
  hinf::codegen::write_generated_files(hinf::codegen::generate_c(paper_gains(), nav), dir.path());
  const std::string before = hinf::test::read_text(dir / "nav_vectors.h");
  for (const char* other : {"Nav", "NAV", "nav_vectors", "nav_check"}) {
    CodegenOptions o;
    o.prefix = other;
    try {
      hinf::codegen::write_generated_files(hinf::codegen::generate_c(paper_gains(), o), dir.path());
      ADD_FAILURE() << "prefix " << other << " accepted beside 'nav'";
    } catch (const hinf::Error& e) {
      EXPECT_EQ(e.code(), hinf::ErrorCode::InvalidInput);
      EXPECT_NE(std::string(e.what()).find("generated for prefix 'nav'"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(hinf::test::read_text(dir / "nav_vectors.h"), before);
  EXPECT_FALSE(std::filesystem::exists(dir / "Nav.h"));
  EXPECT_FALSE(std::filesystem::exists(dir / "nav_vectors.c"));
  // the same prefix again replaces its own files; an unrelated one sits beside them
  EXPECT_NO_THROW(hinf::codegen::write_generated_files(hinf::codegen::generate_c(paper_gains(), nav), dir.path()));
  CodegenOptions guidance;
  guidance.prefix = "guidance";
  EXPECT_NO_THROW(
      hinf::codegen::write_generated_files(hinf::codegen::generate_c(paper_gains(), guidance), dir.path()));
}

TEST(CodegenCompiled, TwoFiltersLinkIntoOneBinary) {
  TempDir dir;
  CodegenOptions a;
  a.prefix = "nav_a";
  CodegenOptions b;
  b.prefix = "nav_b";
  b.real = Real::Float;
  hinf::codegen::write_generated_files(hinf::codegen::generate_c(paper_gains(), a), dir.path());
  hinf::codegen::write_generated_files(
      hinf::codegen::generate_c(hinf::test::random_gains(3, 5, 2, 3), b), dir.path());
  hinf::test::write_text(dir / "main.c",
                         "#include <stdio.h>\n#include \"nav_a.h\"\n#include \"nav_b.h\"\n"
                         "int main(void)\n{\n"
                         "  nav_a_state sa;\n  nav_b_state sb;\n"
                         "  const double za0[NAV_A_NZ] = {1.0, 2.0, 3.0, 0.0, 0.0, 0.0};\n"
                         "  const double ya[NAV_A_NY] = {1.0, 2.0, 3.0};\n"
                         "  const float zb0[NAV_B_NZ] = {1.0f, 2.0f, 3.0f};\n"
                         "  const float yb[NAV_B_NY] = {0.5f, -0.5f};\n"
                         "  double za[NAV_A_NZ];\n  float zb[NAV_B_NZ];\n"
                         "  nav_a_init(&sa, za0);\n  nav_b_init(&sb, zb0);\n"
                         "  nav_a_step(&sa, ya, za);\n  nav_b_step(&sb, yb, zb);\n"
                         "  printf(\"%.17g %.9g\\n\", za[0], (double)zb[0]);\n"
                         "  return 0;\n}\n");
  for (const std::string& cc : compilers()) {
    const std::string exe = dir / ("two_" + compiler_tag(cc));
    auto c = hinf::test::run(cc + " " + hinf::test::strict_c_flags(true) + " -O2 " +
                             (dir / "main.c") + " " + (dir / "nav_a.c") + " " +
                             (dir / "nav_b.c") + " -o " + exe);
    ASSERT_EQ(c.exit_code, 0) << c.output;
    EXPECT_EQ(c.output, "");
    c = hinf::test::run(exe);
    EXPECT_EQ(c.exit_code, 0) << c.output;
    // z(0) = C_F pinv(C_F) z0: for the paper's invertible C_F this is z0 itself.
    std::istringstream in(c.output);
    double za0 = 0, zb0 = 0;
    in >> za0 >> zb0;
    EXPECT_NEAR(za0, 1.0, 1e-12);
    // nav_b: l = 3 < n = 5, C_F has full row rank, so C_F pinv(C_F) = I as well.
    EXPECT_NEAR(zb0, 1.0, 1e-5);
  }
}

TEST(CodegenOutput, ByteIdenticalForTheSameInput) {
  const GainsFile g = paper_gains();
  for (const Real real : {Real::Double, Real::Float}) {
    CodegenOptions opt;
    opt.prefix = "nav";
    opt.real = real;
    const auto first = hinf::codegen::generate_c(g, opt);
    const auto second = hinf::codegen::generate_c(g, opt);
    ASSERT_EQ(first.files.size(), 4u);
    ASSERT_EQ(second.files.size(), 4u);
    for (std::size_t i = 0; i < first.files.size(); ++i) {
      EXPECT_EQ(first.files[i].name, second.files[i].name);
      EXPECT_EQ(first.files[i].contents, second.files[i].contents);
      // No timestamp of any usual form.
      EXPECT_FALSE(std::regex_search(first.files[i].contents,
                                     std::regex(R"(\b20[0-9]{2}-[01][0-9]-[0-3][0-9]\b)")));
      EXPECT_FALSE(std::regex_search(first.files[i].contents,
                                     std::regex(R"(\b[0-2][0-9]:[0-5][0-9]:[0-5][0-9]\b)")));
    }
  }
}

TEST(CodegenOutput, FileNamesProvenanceAndGuards) {
  GainsFile g = hinf::test::random_gains(9, 4, 2, 2);
  g.config_sha256 = std::string(64, 'a');
  g.gamma = 0.125;
  CodegenOptions opt;
  opt.prefix = "MyFilt";
  opt.generator = "hinf-synth 9.9.9";
  const auto out = hinf::codegen::generate_c(g, opt);
  ASSERT_EQ(out.files.size(), 4u);
  EXPECT_EQ(out.files[0].name, "MyFilt.h");
  EXPECT_EQ(out.files[1].name, "MyFilt.c");
  EXPECT_EQ(out.files[2].name, "MyFilt_vectors.h");
  EXPECT_EQ(out.files[3].name, "MyFilt_check.c");
  for (const auto& f : out.files) {
    EXPECT_NE(f.contents.find("Generated by hinf-synth 9.9.9"), std::string::npos) << f.name;
    EXPECT_NE(f.contents.find("Do not edit."), std::string::npos) << f.name;
    EXPECT_NE(f.contents.find("Config sha256: " + std::string(64, 'a')), std::string::npos);
    EXPECT_NE(f.contents.find("Gamma (certified l2-gain bound): 0.125"), std::string::npos);
  }
  const std::string& h = out.files[0].contents;
  for (const char* s : {"#ifndef MYFILT_H_GENERATED", "extern \"C\" {", "#define MYFILT_NX 4",
                        "#define MYFILT_NY 2", "#define MYFILT_NZ 2",
                        "typedef struct {\n  double x[MYFILT_NX];\n} MyFilt_state;",
                        "void MyFilt_init(MyFilt_state *s, const double z0[MYFILT_NZ]);",
                        "void MyFilt_step(MyFilt_state *s, const double y[MYFILT_NY], "
                        "double z[MYFILT_NZ]);"})
    EXPECT_NE(h.find(s), std::string::npos) << s;
  const std::string& c = out.files[1].contents;
  EXPECT_NE(c.find("static const double MyFilt_A_F[MYFILT_NX][MYFILT_NX]"), std::string::npos);
  for (const char* banned : {"malloc", "free(", "#include <math.h>", "static double", "goto"})
    EXPECT_EQ(c.find(banned), std::string::npos) << banned;
  // Hostile text from a gains file cannot end the provenance comment.
  g.tool = "evil */ int x; /*";
  const auto evil = hinf::codegen::generate_c(g, opt);
  EXPECT_EQ(evil.files[0].contents.find("*/ int x;"), std::string::npos);
}

TEST(CodegenOutput, FloatCodeHasNoDoubleAnywhere) {
  CodegenOptions opt;
  opt.prefix = "f";
  opt.real = Real::Float;
  const auto out = hinf::codegen::generate_c(paper_gains(), opt);
  // Outside comments, the filter and its vectors never mention double.
  const std::regex comment(R"(/\*[\s\S]*?\*/)");
  for (std::size_t i = 0; i < 3; ++i) {
    const std::string code = std::regex_replace(out.files[i].contents, comment, "");
    EXPECT_EQ(code.find("double"), std::string::npos) << out.files[i].name;
  }
  // Every floating literal in the filter source carries the f suffix.
  const std::string& c = out.files[1].contents;
  const std::regex literal(R"([-+]?[0-9]+\.[0-9]*(e[-+]?[0-9]+)?[f]?)");
  int count = 0;
  for (auto it = std::sregex_iterator(c.begin(), c.end(), literal); it != std::sregex_iterator();
       ++it) {
    const std::string s = it->str();
    if (s.find('.') == std::string::npos) continue;
    ++count;
    EXPECT_EQ(s.back(), 'f') << s;
  }
  EXPECT_GE(count, 36 + 18 + 36 + 36);  // A_F, B_F, C_F, pinv(C_F)
}

// Every emitted coefficient reads back to the gains-file value exactly.
TEST(CodegenOutput, CoefficientsRoundTripExactly) {
  const GainsFile g = hinf::test::random_gains(42, 5, 2, 3);
  for (const Real real : {Real::Double, Real::Float}) {
    CodegenOptions opt;
    opt.prefix = "rt";
    opt.real = real;
    const std::string c = hinf::codegen::generate_c(g, opt).files[1].contents;
    const auto begin = c.find("rt_A_F[RT_NX][RT_NX] = {");
    const auto end = c.find("};", begin);
    ASSERT_NE(begin, std::string::npos);
    std::string body = c.substr(begin, end - begin);
    body = body.substr(body.find('=') + 1);
    const std::regex number(R"([-+]?[0-9][0-9.eE+-]*)");
    std::vector<double> values;
    for (auto it = std::sregex_iterator(body.begin(), body.end(), number);
         it != std::sregex_iterator(); ++it)
      values.push_back(real == Real::Float ? static_cast<double>(std::strtof(it->str().c_str(), nullptr))
                                           : std::strtod(it->str().c_str(), nullptr));
    ASSERT_EQ(values.size(), 25u);
    for (int i = 0; i < 5; ++i)
      for (int j = 0; j < 5; ++j) {
        const double expected = real == Real::Float
                                    ? static_cast<double>(static_cast<float>(g.A_F(i, j)))
                                    : g.A_F(i, j);
        EXPECT_EQ(values[static_cast<std::size_t>(i * 5 + j)], expected) << i << "," << j;
      }
  }
}

TEST(CodegenPrefix, AcceptsOrdinaryIdentifiers) {
  for (const char* p : {"nav", "NavFilter", "hinf_chaser_1", "f", "x9", "e_1", "is", "sig_1",
                        "pri", "Int8", "a_prefix_of_22_chars_x"})
    EXPECT_NO_THROW(hinf::codegen::validate_codegen_prefix(p)) << p;
}

TEST(CodegenPrefix, RefusesInvalidAndReservedNames) {
  const std::vector<std::pair<std::string, std::string>> bad{
      {"", "empty"},
      {"1nav", "start with a letter"},
      {"_nav", "start with a letter"},
      {"nav-filter", "C identifier"},
      {"nav filter", "C identifier"},
      {"na\xc3\xafve", "C identifier"},
      {"nav__x", "'__'"},
      {"nav_", "end with '_'"},
      {"int", "keyword"},
      {"class", "keyword"},
      {"main", "keyword"},
      {"strfilter", "reserved"},
      {"isnav", "reserved"},
      {"tonav", "reserved"},
      {"memx", "reserved"},
      {"ekf", "<errno.h>"},
      {"E2", "<errno.h>"},
      {"signal", "<signal.h>"},
      {"sig", "<signal.h>"},
      {"lc", "<locale.h>"},
      {"prix", "<inttypes.h>"},
      {"a_very_long_prefix_name_x", "too long"}};
  for (const auto& [prefix, why] : bad) {
    try {
      hinf::codegen::validate_codegen_prefix(prefix);
      ADD_FAILURE() << "accepted '" << prefix << "'";
    } catch (const hinf::Error& e) {
      EXPECT_EQ(e.code(), hinf::ErrorCode::InvalidInput);
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << prefix << ": " << e.what();
      EXPECT_NE(std::string(e.what()).find("--prefix"), std::string::npos) << e.what();
    }
  }
}

TEST(CodegenWrite, FailureLeavesNothingBehind) {
  TempDir dir;
  CodegenOptions opt;
  opt.prefix = "nav";
  const auto files = hinf::codegen::generate_c(paper_gains(), opt);
  // nav.c is a directory: nav.h is renamed first, then the rename of nav.c fails;
  // everything must be rolled back, leaving only the obstacle.
  const std::string out = dir / "out";
  std::filesystem::create_directories(out + "/nav.c");
  try {
    hinf::codegen::write_generated_files(files, out);
    ADD_FAILURE() << "writing over a directory succeeded";
  } catch (const hinf::Error& e) {
    EXPECT_EQ(e.code(), hinf::ErrorCode::InvalidInput);
    EXPECT_NE(std::string(e.what()).find("nav.c"), std::string::npos) << e.what();
  }
  EXPECT_EQ(hinf::test::list_dir(out), "nav.c");
  // A directory that cannot be created (its parent is a file): nothing created.
  hinf::test::write_text(dir / "file", "x");
  EXPECT_THROW(hinf::codegen::write_generated_files(files, dir / "file/sub/dir"),
               hinf::Error);
  EXPECT_EQ(hinf::test::list_dir(dir.path()), "file out");
  // A failure after the directory was created removes the directory again.
  hinf::codegen::GeneratedFiles bad = files;
  bad.files.push_back({"sub/evil.c", "x"});
  EXPECT_THROW(hinf::codegen::write_generated_files(bad, dir / "fresh/nested"), hinf::Error);
  EXPECT_EQ(hinf::test::list_dir(dir.path()), "file out");
  // Success into a new nested directory.
  hinf::codegen::write_generated_files(files, dir / "new/nested");
  EXPECT_EQ(hinf::test::list_dir(dir / "new/nested"), "nav.c nav.h nav_check.c nav_vectors.h");
}

TEST(CodegenInput, RejectsNonFiniteAndOverflowingCoefficients) {
  GainsFile g = hinf::test::random_gains(1, 3, 1, 1);
  CodegenOptions opt;
  opt.prefix = "ok";
  g.B_F(2, 0) = 1e300;
  opt.real = Real::Float;
  try {
    hinf::codegen::generate_c(g, opt);
    ADD_FAILURE() << "1e300 accepted for float";
  } catch (const hinf::Error& e) {
    EXPECT_EQ(e.code(), hinf::ErrorCode::InvalidInput);
    EXPECT_NE(std::string(e.what()).find("filter.B_F(2,0)"), std::string::npos) << e.what();
  }
  g.B_F(2, 0) = std::numeric_limits<double>::quiet_NaN();
  opt.real = Real::Double;
  EXPECT_THROW(hinf::codegen::generate_c(g, opt), hinf::Error);
}

}  // namespace
