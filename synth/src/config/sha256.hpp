// SHA-256 (FIPS 180-4) of a byte string, via OpenSSL's libcrypto (Debian libssl-dev).
#pragma once
#include <string>

namespace hinf::synth {

// Lowercase hex digest (64 characters) of the bytes of `data`.
std::string sha256_hex(const std::string& data);

}  // namespace hinf::synth
