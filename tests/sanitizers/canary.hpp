// A header of this repository with undefined behaviour on demand, for the sanitizer canary
// (test_canary.cpp): UBSan must report it although the sanitizer build exempts the
// system's headers from UBSan (cmake/ubsan-system-headers.txt).
#pragma once

namespace hinf::test {

// Signed addition; overflows (undefined behaviour) when a + b is not an int.
inline int add_in_project_header(int a, int b) { return a + b; }

}  // namespace hinf::test
