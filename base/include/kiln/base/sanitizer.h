// Whether this build is instrumented by AddressSanitizer: what a limit on address space or a
// timing tolerance has to allow for. GCC defines __SANITIZE_ADDRESS__; clang 14 answers only
// __has_feature.
#ifndef KILN_BASE_SANITIZER_H_
#define KILN_BASE_SANITIZER_H_

namespace kiln::base {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kAddressSanitizer = true;
#else
inline constexpr bool kAddressSanitizer = false;
#endif
#else
inline constexpr bool kAddressSanitizer = false;
#endif

}  // namespace kiln::base

#endif  // KILN_BASE_SANITIZER_H_
