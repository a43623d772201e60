// Whether a suite is built under a sanitizer, whichever compiler builds it:
// GCC says so with __SANITIZE_ADDRESS__ and __SANITIZE_THREAD__, clang 14
// (scripts/sanitize.sh) with __has_feature only. Defines RBS_UNDER_ASAN and
// RBS_UNDER_TSAN when they apply.
#pragma once

#if defined(__SANITIZE_ADDRESS__)
#define RBS_UNDER_ASAN 1
#endif
#if defined(__SANITIZE_THREAD__)
#define RBS_UNDER_TSAN 1
#endif
#if defined(__has_feature)
#if __has_feature(address_sanitizer) && !defined(RBS_UNDER_ASAN)
#define RBS_UNDER_ASAN 1
#endif
#if __has_feature(thread_sanitizer) && !defined(RBS_UNDER_TSAN)
#define RBS_UNDER_TSAN 1
#endif
#endif
