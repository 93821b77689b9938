// The sanitizer build's canary: proves that the scope of cmake/ubsan-system-headers.txt is
// what it claims. `ubsan` overflows a signed int in a header of this repository (UBSan must
// still check the repository's headers); `asan` reads past a heap array through an
// Eigen::Map, in the SSE packet loads of Eigen's vectorised sum (ASan must still instrument
// Eigen and the compiler's intrinsics, whose UBSan checks are off). Each mode
// must end in its sanitizer's report; tests/sanitizers/CMakeLists.txt matches the report.
#include <Eigen/Dense>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "canary.hpp"

namespace {

int overflow_in_project_header(int argc) {
  // argc keeps the operands unknown to the compiler, so the overflow happens at run time.
  return hinf::test::add_in_project_header(INT_MAX - 1 + (argc > 0 ? 1 : 0), argc);
}

double read_past_heap_array_through_eigen(int argc) {
  std::vector<double> three(3, 1.0);
  const Eigen::Map<const Eigen::Vector4d> four(three.data());  // one element too many
  return four.sum() + argc;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  if (mode == "ubsan") {
    std::printf("%d\n", overflow_in_project_header(argc));
  } else if (mode == "asan") {
    std::printf("%g\n", read_past_heap_array_through_eigen(argc));
  } else {
    std::fprintf(stderr, "usage: test_sanitizers ubsan|asan\n");
    return 2;
  }
  std::fprintf(stderr, "test_sanitizers: no sanitizer report for %s\n", mode.c_str());
  return 1;
}
