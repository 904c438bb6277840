/* Adhesive elastic contact of spheres: classical JKR (Johnson, Kendall &
   Roberts, Proc. R. Soc. A 324 (1971) 301), the circular limit of the
   Johnson-Greenwood elliptic theory of dc/jkr_elliptic.h (review =
   Kildashti, Dong & Yu 2023, Sec. 2.2), whose header derives both.

   R is the effective radius, Estar = 1/sum((1-nu^2)/E), w the work of
   adhesion (J/m^2 = N/m). With the contact radius a,
     F = 4 Estar a^3/(3R) - (8 pi w Estar a^3)^1/2,
     delta = a^2/R - (2 pi w a/Estar)^1/2.
   Under overlap control (DEM) the contact follows the large-contact branch
   (a increasing with delta) from delta = 0 on approach down to the
   separation overlap delta_break = -3/4 (pi^2 w^2 R / Estar^2)^1/3 on
   unloading, where F = -5/6 pi w R; the pull-off force under load control
   is 3/2 pi w R. */
#ifndef DC_JKR_SPHERE_H
#define DC_JKR_SPHERE_H

#ifdef __cplusplus
extern "C" {
#endif

/* One contact state (of spheres here, and of elliptic contacts in
   dc/jkr_elliptic.h). */
typedef struct {
  int contact;   /* 1 in contact; 0: delta below delta_break, all zero     */
  double F;      /* normal force [N], > 0 repulsive, < 0 adhesive           */
  double delta;  /* overlap [m]                                              */
  double a, b;   /* semi-axes of the contact ellipse [m], a >= b            */
  double area;   /* pi a b [m^2]                                             */
  double e2;     /* e^2 = 1 - (b/a)^2                                        */
  double kn;     /* dF/d delta on the stable branch [N/m]; grows without
                    bound at delta_break, returned finite (<= 1e300)        */
} dc_jkr_state;

/* Classical JKR for spheres (Johnson, Kendall & Roberts 1971; review
   Sec. 2.2 circular limit): the quartic in a^1/2 is solved from a rational
   starting value by two Halley steps (no transcendental call, one cube
   root for the length scale). Stable (large-contact) branch.
   Domain: R > 0, Estar > 0, w >= 0, delta finite (else DC_EDOM). w = 0
   is Hertz. delta < delta_break gives contact = 0 and a zero state (DC_OK).
   DC_ERANGE when a result, or the adhesion overlap scale (w/Estar)^2/3
   R^1/3 itself, overflows (only far outside physical magnitudes). A
   contact radius below the smallest double gives the touching state
   (contact = 1, the rest 0). On any error *s is untouched. */
int dc_jkr_sphere(double R, double Estar, double w, double delta, dc_jkr_state *s);

/* Classical JKR state for a given contact radius a > 0 (either branch).
   Domain: R > 0, Estar > 0, w >= 0, a > 0, all finite (else DC_EDOM);
   DC_ERANGE when a result overflows. On any error *s is untouched. */
int dc_jkr_sphere_at_radius(double R, double Estar, double w, double a, dc_jkr_state *s);

/* Pull-off force 3/2 pi w R (load control) and separation overlap
   delta_break = -3/4 (pi^2 w^2 R / Estar^2)^1/3 (overlap control).
   Domain: R > 0, Estar > 0, w >= 0, all finite; NaN outside. Inside, the
   value to rounding, free of intermediate overflow and underflow: +inf
   (pull-off) or -inf (delta_break) only when the value itself exceeds
   DBL_MAX, and 0 or a subnormal only when it is that small. */
double dc_jkr_sphere_pulloff(double R, double w);
double dc_jkr_sphere_delta_break(double R, double Estar, double w);

#ifdef __cplusplus
}
#endif
#endif
