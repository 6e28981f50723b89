// Whether this build runs under AddressSanitizer (PROCEX_SANITIZE), where
// Debug code is 20-100x slower: the heaviest test inputs are trimmed there.
#pragma once

namespace procex {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif
#else
inline constexpr bool kSanitized = false;
#endif

}  // namespace procex
