/* Helpers shared by the JKR sources (private to c_core/src): classical
   JKR (jkr_sphere.c) and the elliptic law built on it (jkr_elliptic.c,
   jkr_elliptic_solve.c, through jkr_elliptic_private.h). Below both: it
   reads only dc/jkr_sphere.h. */
#ifndef DC_JKR_COMMON_H
#define DC_JKR_COMMON_H

#include "dc/jkr_sphere.h"
#include "jkr_cbrt.h"
#include <float.h>
#include <math.h>
#include <string.h>

#define DC_JKR_KN_MAX 1e300

/* num/den, or +-DC_JKR_KN_MAX when that is not a finite number below it
   (the stiffness grows without bound at the separation point). */
static inline double dc_jkr_finite_kn_(double num, double den)
{
  if (den > 0.0 && num < DC_JKR_KN_MAX * den) return num / den;
  return num >= 0.0 ? DC_JKR_KN_MAX : -DC_JKR_KN_MAX;
}

/* Every double of the state finite (the outputs of a DC_OK). */
static inline int dc_jkr_state_finite_(const dc_jkr_state *s)
{
  return isfinite(s->F) && isfinite(s->delta) && isfinite(s->a) && isfinite(s->b) && isfinite(s->area) &&
         isfinite(s->e2) && isfinite(s->kn);
}

/* The JKR length scale (8 w R^2/(pi Estar))^1/3: as one (fast) cube root
   when 8 w/(pi Estar) and R^2 are normal numbers, as before; otherwise
   from the cube roots of the factors, free of their overflow or underflow
   (R^2 for R outside about [1e-154, 1e154], w/Estar beyond the doubles). */
static inline double dc_jkr_length_scale_(double w, double Estar, double R)
{
  if (w == 0.0) return 0.0;
  const double p = 8.0 * w / (M_PI * Estar), q = R * R;
  if (p >= DBL_MIN && p <= DBL_MAX && q >= DBL_MIN && q <= DBL_MAX) return dc_jkr_cbrt_scale_(p, q);
  const double cR = cbrt(R);
  return cbrt(8.0 / M_PI) * (cbrt(w) / cbrt(Estar)) * cR * cR;
}

/* a^2/(2R) for the length scales a of JKR (a^3 ~ w R^2/E*): as written
   when that is a normal number, else as a (a/(2R)), which avoids the
   overflow or underflow of a^2 where the quotient is representable. */
static inline double dc_jkr_delta_scale_(double a, double R)
{
  const double d = a * a / (2.0 * R);
  if (d >= DBL_MIN && d <= DBL_MAX) return d;
  return a * (a / (2.0 * R));
}

/* The state out of contact: all zero, the overlap kept. */
static inline void dc_jkr_zero_state_(double delta, dc_jkr_state *s)
{
  memset(s, 0, sizeof *s);
  s->delta = delta;
}

#endif
