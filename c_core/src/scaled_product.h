/* A product of several factors without overflow or underflow before the
   end, for the laws' out-of-range fallbacks (private to c_core/src). */
#ifndef DC_SCALED_PRODUCT_H
#define DC_SCALED_PRODUCT_H

#include <math.h>

/* x[0] x[1] ... x[n-1]: mantissas multiplied, exponents summed, one
   scaling (rounded as the plain product would be when that stays in
   range). */
static inline double dc_scaled_product(int n, const double *x)
{
  double m = 1.0;
  int e = 0;
  for (int i = 0; i < n; i++) {
    int k;
    m *= frexp(x[i], &k);
    e += k;
    m = frexp(m, &k);
    e += k;
  }
  return ldexp(m, e);
}

#endif
