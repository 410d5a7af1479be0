#pragma once

// Whether the tests run under AddressSanitizer (PHIGS_SANITIZE=ON). Property tests run fewer
// random members there: the sanitizers look for memory and undefined-behaviour errors, which
// the code paths of the first members already reach, and the plain build runs them all.

#if defined(__SANITIZE_ADDRESS__)
#define PHIGS_TEST_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define PHIGS_TEST_SANITIZED 1
#endif
#endif

#ifdef PHIGS_TEST_SANITIZED
inline constexpr bool kSanitizedBuild = true;
#else
inline constexpr bool kSanitizedBuild = false;
#endif

/// `count` in the plain build, a quarter of it (at least one) under the sanitizers.
constexpr int membersForBuild(int count) {
    return kSanitizedBuild ? (count + 3) / 4 : count;
}
