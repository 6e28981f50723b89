// Offsets and lengths read from a binary file (a .glb's buffer views and
// accessors) are chosen by whoever made the file: up to 2^64, so
// `offset + length <= size` can wrap and pass. Every such range is taken
// through here, checked without overflow, before a byte is copied.
#pragma once

#include <cstdint>
#include <optional>
#include <span>

namespace procex {

// The bytes [offset, offset + length) of buffer, or nullopt if they do not
// all lie inside it.
inline std::optional<std::span<const unsigned char>> byte_range(std::span<const unsigned char> buffer,
                                                                 std::uint64_t offset, std::uint64_t length) {
  if (offset > buffer.size() || length > buffer.size() - offset) return std::nullopt;
  return buffer.subspan(static_cast<std::size_t>(offset), static_cast<std::size_t>(length));
}

// count * size, or nullopt if the product does not fit in 64 bits.
inline std::optional<std::uint64_t> checked_product(std::uint64_t count, std::uint64_t size) {
  std::uint64_t out = 0;
  if (__builtin_mul_overflow(count, size, &out)) return std::nullopt;
  return out;
}

}  // namespace procex
