/* A hint that the cache line holding *p will be read soon: the CPU fetches it while the
 * kernel goes on, where a load would stall the core on a cache miss (docs/benchmarks.md,
 * Prefetching and coverage windows). OpenCL's prefetch() is a no-op on PoCL, so x86-64 and AArch64
 * CPUs get Clang's built-in (one prefetch instruction, which never faults); any other device
 * gets OpenCL's prefetch(), which it may ignore. A hint only: no result depends on it. */
#ifndef CLR_COMMON_PREFETCH_CL
#define CLR_COMMON_PREFETCH_CL

#if defined(__x86_64__) || defined(__aarch64__)
#define CLR_PREFETCH(p) __builtin_prefetch(p)
#else
#define CLR_PREFETCH(p) prefetch(p, 1)
#endif

#endif /* CLR_COMMON_PREFETCH_CL */
