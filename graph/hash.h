// hash.h -- the 128-bit hash that keys every cached node result.
//
// Not cryptographic: a fast streaming mix (two 64-bit lanes folded through
// 64x64->128 multiplies). Keys only decide cache reuse, so what matters is a
// good spread and speed on small inputs (a node key hashes ~100 bytes).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <string>
#include <string_view>
#include <type_traits>

namespace procex {

struct Hash128 {
  std::uint64_t lo = 0;
  std::uint64_t hi = 0;

  friend bool operator==(const Hash128&, const Hash128&) = default;
  friend auto operator<=>(const Hash128&, const Hash128&) = default;
  bool is_zero() const { return lo == 0 && hi == 0; }
  // 32 lowercase hex digits, hi first.
  std::string hex() const;
};

struct Hash128Hasher {
  std::size_t operator()(const Hash128& h) const noexcept { return static_cast<std::size_t>(h.lo ^ (h.hi * 0x9E3779B97F4A7C15ull)); }
};

// Streaming hasher: feed words, bytes, strings and other hashes; take result().
// The same sequence of calls always gives the same hash (on every platform with
// the same endianness; files never store hashes, so this is enough).
class Hasher {
 public:
  Hasher() = default;
  explicit Hasher(std::uint64_t seed) : a_(kSeedA ^ seed), b_(kSeedB + seed) {}

  Hasher& u64(std::uint64_t w) {
    a_ = mix(a_ ^ w, kMulA);
    b_ = mix(b_ + rotl(w, 29), kMulB);
    return *this;
  }
  Hasher& i64(std::int64_t v) { return u64(static_cast<std::uint64_t>(v)); }
  Hasher& boolean(bool v) { return u64(v ? 0x6a09e667f3bcc909ull : 0xbb67ae8584caa73bull); }
  // -0.0 and 0.0 hash alike, every NaN hashes alike: values that compare or
  // print the same must share a key.
  Hasher& f64(double v) {
    if (v == 0.0) v = 0.0;
    if (v != v) return u64(0x7ff8000000000000ull);
    std::uint64_t w;
    std::memcpy(&w, &v, sizeof w);
    return u64(w);
  }
  Hasher& bytes(const void* data, std::size_t n);
  Hasher& str(std::string_view s) { return bytes(s.data(), s.size()); }
  Hasher& hash(const Hash128& h) { return u64(h.lo).u64(h.hi); }

  Hash128 result() const;

 private:
  static constexpr std::uint64_t kSeedA = 0x243f6a8885a308d3ull;
  static constexpr std::uint64_t kSeedB = 0x13198a2e03707344ull;
  static constexpr std::uint64_t kMulA = 0xa0761d6478bd642full;
  static constexpr std::uint64_t kMulB = 0xe7037ed1a0b428dbull;

  static std::uint64_t rotl(std::uint64_t x, int r) { return (x << r) | (x >> (64 - r)); }
  static std::uint64_t mix(std::uint64_t a, std::uint64_t b) {
    __extension__ using u128 = unsigned __int128;
    const u128 p = static_cast<u128>(a) * b;
    return static_cast<std::uint64_t>(p) ^ static_cast<std::uint64_t>(p >> 64);
  }

  std::uint64_t a_ = kSeedA;
  std::uint64_t b_ = kSeedB;
  std::uint64_t n_ = 0;  // bytes fed through bytes(), folded into result()
};

}  // namespace procex
