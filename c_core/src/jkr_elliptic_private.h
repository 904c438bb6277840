/* Declarations shared by the elliptic JKR sources (private to c_core/src):
   jkr_elliptic.c (the Johnson-Greenwood map and the geometry) and
   jkr_elliptic_solve.c (dc_jkr_contact), with jkr_common.h's helpers. */
#ifndef DC_JKR_ELLIPTIC_PRIVATE_H
#define DC_JKR_ELLIPTIC_PRIVATE_H

#include "dc/jkr_elliptic.h"
#include "jkr_common.h"

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
