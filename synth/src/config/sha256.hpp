// SHA-256 (FIPS 180-4) of a byte string — the config file's `sha256`, written to the gains
// file as `config_sha256` — private to synth, via Nettle (Debian nettle-dev): no library
// initialisation and no system configuration file (OpenSSL 3's EVP_Digest reads
// openssl.cnf and loads its provider on first use: measured 3 ms, 2 % of `solve` on the
// paper config; Nettle 0.04 ms).
#pragma once
#include <string>

namespace hinf::synth {

// Lowercase hex digest (64 characters) of the bytes of `data`.
std::string sha256_hex(const std::string& data);

}  // namespace hinf::synth
