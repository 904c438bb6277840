/* Fast cube roots of the JKR laws (private to c_core/src): the length
   scales of dc_jkr_sphere and dc_jkr_geometry and the contact size of the
   elliptic map take one cube root each. */
#ifndef DC_JKR_CBRT_H
#define DC_JKR_CBRT_H

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

/* Cube root of a positive normal double, to < 1 ulp (the libm cbrt costs
   ~30 ns here, through frexp/scalbn). Exponent/3 by integer arithmetic on
   the high word (~6% error), a degree-4 polynomial correction in r = t^3/x
   (fdlibm's cbrt coefficients, ~23 bits), rounding of t to 21 bits so that
   t^2 is exact, and one Halley-like step t + t (x/t^2 - t)/(2t + x/t^2),
   exact to rounding. Zero, subnormal, huge and non-finite x go to cbrt(). */
static inline double dc_jkr_cbrt_(double x)
{
  if (!(x >= DBL_MIN && x <= DBL_MAX)) return cbrt(x);
  uint64_t u;
  memcpy(&u, &x, sizeof u);
  u = ((u >> 32) / 3 + 715094163u) << 32;       /* (1023 - 1023/3 - 0.03306235651) 2^20 */
  double t;
  memcpy(&t, &u, sizeof t);
  double r = (t * t) * (t / x);
  t = t * ((1.87595182427177009643 + r * (-1.88497979543377169875 + r * 1.621429720105354466140)) +
           ((r * r) * r) * (-0.758397934778766047437 + r * 0.145996192886612446982));
  memcpy(&u, &t, sizeof u);
  u = (u + 0x80000000u) & 0xffffffffc0000000ull;
  memcpy(&t, &u, sizeof t);
  const double s = t * t;
  r = x / s;
  r = (r - t) / ((t + t) + r);
  return t + t * r;
}

/* (p q)^1/3 for p, q > 0, as one cube root when p q is a normal number,
   else as the product of two (w/E* and R^2 can be far apart). */
static inline double dc_jkr_cbrt_scale_(double p, double q)
{
  const double pq = p * q;
  if (pq >= DBL_MIN && pq <= DBL_MAX) return dc_jkr_cbrt_(pq);
  return cbrt(p) * cbrt(q);
}

#endif
