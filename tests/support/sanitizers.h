// Whether this build runs under AddressSanitizer (PROCEX_SANITIZE), where
// Debug code is 20-100x slower: the heaviest test inputs are trimmed there.
#pragma once

#if defined(__SANITIZE_ADDRESS__)
#define PROCEX_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define PROCEX_ASAN 1
#endif
#endif

namespace procex {

#if defined(PROCEX_ASAN)
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif

}  // namespace procex
