/* Declarations shared by the JKR sources (private to c_core/src):
   jkr_sphere.c (classical JKR), jkr_elliptic.c (the Johnson-Greenwood map
   and the geometry) and jkr_elliptic_solve.c (dc_jkr_contact). */
#ifndef DC_JKR_PRIVATE_H
#define DC_JKR_PRIVATE_H

#include "dc/jkr_elliptic.h"
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

/* One point of the Johnson-Greenwood family: the values at m = e^2 and
   their derivatives in the solver variable v (jkr_elliptic.c). */
typedef struct {
  double m, m1, g, rho, X, Y, abar, dbar, Pbar; /* values                    */
  double dg, drho, dX, dY, dabar, ddbar, dPbar; /* d/dv                      */
} jg_point;

/* Review Eqs. 19-23 at m = e^2, m1 = 1 - e^2, derivatives times sv = dm/dv
   (jkr_elliptic.c). */
void dc_jkr_eval_m_(const dc_jkr_geom *G, double m, double m1, double sv, jg_point *p);

/* The point at solver variable v: v = m = e^2, or v = m1 = 1 - e^2 for
   slender contacts (G->use_m1). */
static inline void jg_eval(const dc_jkr_geom *G, double v, jg_point *p)
{
  if (G->use_m1) dc_jkr_eval_m_(G, 1.0 - v, v, -1.0, p);
  else dc_jkr_eval_m_(G, v, 1.0 - v, 1.0, p);
}

/* The state of point p, with the remaining Newton correction s_m (in the
   solver variable) applied to first order (jkr_elliptic.c). */
void dc_jkr_elliptic_fill_(const dc_jkr_geom *G, const jg_point *p, double s_m, dc_jkr_state *s);

#endif
