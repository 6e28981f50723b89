#include "graph/hash.h"

namespace procex {

std::string Hash128::hex() const {
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string s(32, '0');
  for (int i = 0; i < 16; ++i) {
    s[15 - i] = kDigits[(hi >> (4 * i)) & 0xF];
    s[31 - i] = kDigits[(lo >> (4 * i)) & 0xF];
  }
  return s;
}

Hasher& Hasher::bytes(const void* data, std::size_t n) {
  const auto* p = static_cast<const unsigned char*>(data);
  n_ += n;
  u64(n);  // length first: "ab"+"c" and "a"+"bc" differ
  for (; n >= 8; n -= 8, p += 8) {
    std::uint64_t w;
    std::memcpy(&w, p, 8);
    u64(w);
  }
  if (n > 0) {
    std::uint64_t w = 0;
    std::memcpy(&w, p, n);
    u64(w);
  }
  return *this;
}

Hash128 Hasher::result() const {
  std::uint64_t a = mix(a_ ^ n_, kMulB);
  std::uint64_t b = mix(b_ ^ rotl(a, 31), kMulA);
  a = mix(a ^ rotl(b, 17), kMulA ^ kSeedB);
  b = mix(b + a, kMulB ^ kSeedA);
  return Hash128{a, b};
}

}  // namespace procex
