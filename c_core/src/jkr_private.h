/* Declarations shared by the JKR sources (private to c_core/src):
   jkr_sphere.c (classical JKR), jkr_elliptic.c (the Johnson-Greenwood map
   and the geometry) and jkr_elliptic_solve.c (dc_jkr_contact). */
#ifndef DC_JKR_PRIVATE_H
#define DC_JKR_PRIVATE_H

#include "dc/jkr_elliptic.h"
#include <string.h>

#define DC_JKR_KN_MAX 1e300

/* num/den, or +-DC_JKR_KN_MAX when that is not a finite number below it
   (the stiffness grows without bound at the separation point). */
static inline double dc_jkr_finite_kn_(double num, double den)
{
  if (den > 0.0 && num < DC_JKR_KN_MAX * den) return num / den;
  return num >= 0.0 ? DC_JKR_KN_MAX : -DC_JKR_KN_MAX;
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
