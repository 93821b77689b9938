#include "config/sha256.hpp"

#include <openssl/evp.h>

#include "hinf/synth/status.hpp"

namespace hinf::synth {

std::string sha256_hex(const std::string& data) {
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  if (EVP_Digest(data.data(), data.size(), digest, &length, EVP_sha256(), nullptr) != 1 ||
      length != 32)
    throw Error(ErrorCode::NumericalFailure, "SHA-256: OpenSSL EVP_Digest failed");
  static const char hex[] = "0123456789abcdef";
  std::string out(64, '0');
  for (unsigned i = 0; i < 32; ++i) {
    out[2 * i] = hex[digest[i] >> 4];
    out[2 * i + 1] = hex[digest[i] & 0xF];
  }
  return out;
}

}  // namespace hinf::synth
