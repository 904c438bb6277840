/* Hot-path helpers of the laws. DC_INLINE: a static helper of a law's hot path, always inlined where the
   compiler supports it, so that the values a step passes between its parts
   stay in registers (an out-of-line helper's arrays go through memory).
   DC_COLD: a static helper of a rare branch, kept out of line (it takes
   its vectors by value, so that the hot path's stay in registers). */
#ifndef DC_INLINE_H
#define DC_INLINE_H

#if defined(__GNUC__)
#define DC_INLINE static inline __attribute__((always_inline))
#define DC_COLD static __attribute__((noinline, cold, unused))
#else
#define DC_INLINE static inline
#define DC_COLD static inline
#endif

/* Before a loop over the (at most 3) components of a vector: GCC's -O2
   leaves such loops rolled, their sums going through memory. */
#define DC_UNROLL3 _Pragma("GCC unroll 3")

/* 0 for a finite x, NaN otherwise: a sum of them is 0 exactly when every
   term is finite (never overflows), so one comparison checks many inputs
   without a branch each. */
static inline double dc_nf(double x) { return x - x; }

/* Whether the three components are finite (one comparison). */
DC_INLINE int dc_finite3(const double *v) { return dc_nf(v[0]) + dc_nf(v[1]) + dc_nf(v[2]) == 0.0; }

DC_INLINE double dc_dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

#endif
