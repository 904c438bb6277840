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

#include <float.h>
#include <math.h>
#include "dc/poly14.h"

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
   Sec. 2.2 circular limit), stable (large-contact) branch: the contact
   radius from the inverse of the JKR curve in reduced variables,
   tabulated once for all materials (tests/reference/gen_jkr_sphere_poly.py,
   within 2.2e-16 of mpmath): at the Hertz-like end (delta >= 0.575
   delta_scale, delta_scale = 2 (w^2 R/(pi^2 E*^2))^1/3) as a = psi a0,
   a0 = (R delta)^1/2, without a cube root (below); from the separation
   point up to there with one cube root for the length scale. F and a
   within 4 eps of the exact curve in units of its condition number
   (|F - F_exact| <= 4 eps (|F| + |delta dF/d delta|), 1e-14 relative
   wherever that number is below 10; tests/unit/test_jkr_elliptic.c
   against jkr_sphere_dense.csv).
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

/* The Hertz-like end of the JKR curve: with a0 = (R delta)^1/2 and kappa =
   (2 pi w a0/E*)^1/2/delta, the JKR relation delta = a^2/R - (2 pi w
   a/E*)^1/2 divided by delta reads psi^2 = 1 + kappa psi^1/2 for psi =
   a/a0, and F = 2/3 E* a0 delta psi (3 - psi^2). With nu = kappa^2: on
   nu in [0, DC_JKR_NU_S] from psi's Taylor series (dc_jkr_psi_series);
   above, from the tables of c_core/src/jkr_sphere_poly.h
   (tests/reference/gen_jkr_sphere_poly.py): on nu up to DC_JKR_NU_0 psi = (1 + nu A1(nu)) +
   kappa (1/2 + nu B1(nu)), A1 and B1 of degree 8 (dc_jkr_psi0); above, up
   to DC_JKR_NU_H and a little beyond, psi = A(nu) + kappa B(nu) on pieces
   of width 1 (dc_jkr_psi_poly, dc/poly14.h). psi within 2.2e-16; kappa <=
   4 is delta >= 0.575 delta_scale. */
#define DC_JKR_NU_0 0.25
#define DC_JKR_NU_H 16.0
#define DC_JKR_NU_PIECES 16
extern const double dc_jkr_psi0[9][2];
extern const double dc_jkr_psi_centre[DC_JKR_NU_PIECES];
extern const double dc_jkr_psi_poly[DC_JKR_NU_PIECES][DC_POLY14_NROWS][2];

/* psi at nu = kappa^2 in [0, DC_JKR_NU_S] (kappa <= 0.032, weak adhesion):
   its Taylor series at kappa = 0, exact coefficients by Lagrange inversion
   of kappa = y (2 + y)/(1 + y)^1/2, y = psi - 1:
     psi = 1 + kappa/2 - kappa^3/64 + kappa^4/128 - 9 kappa^5/4096
           + 55 kappa^7/131072 - 9 kappa^8/32768 + 1547 kappa^9/2^24
           - 11799 kappa^11/2^29 + ...
   (the kappa^2, kappa^6, kappa^10 terms vanish); cut after kappa^9, the
   rest is below 7e-22. */
#define DC_JKR_NU_S 1e-3
static inline double dc_jkr_psi_series(double nu, double kappa)
{
  const double even = 1.0 + nu * nu * (1.0 / 128.0 - 9.0 / 32768.0 * (nu * nu));
  const double odd = 0.5 + nu * (-1.0 / 64.0 + nu * (-9.0 / 4096.0 + nu * (55.0 / 131072.0 + nu * (1547.0 / 16777216.0))));
  return even + kappa * odd;
}

/* psi at nu = kappa^2 in [DC_JKR_NU_S, DC_JKR_NU_0]: A1 and B1 by
   Estrin's scheme (the generator's order). */
static inline double dc_jkr_psi_near(double nu, double kappa)
{
  const double x2 = nu * nu, x4 = x2 * x2, x8 = x4 * x4;
  double y[2];
  for (int f = 0; f < 2; f++) {
    const double *c = &dc_jkr_psi0[0][f];
    const double q0 = c[0] + c[2] * nu, q1 = c[4] + c[6] * nu, q2 = c[8] + c[10] * nu, q3 = c[12] + c[14] * nu;
    y[f] = ((q0 + q1 * x2) + (q2 + q3 * x2) * x4) + c[16] * x8;
  }
  return (1.0 + nu * y[0]) + kappa * (0.5 + nu * y[1]);
}

/* psi at nu = kappa^2 in [0, DC_JKR_NU_H] (and a little beyond) */
static inline double dc_jkr_psi(double nu, double kappa)
{
  if (nu <= DC_JKR_NU_S) return dc_jkr_psi_series(nu, kappa);
  if (nu <= DC_JKR_NU_0) return dc_jkr_psi_near(nu, kappa);
  const int p = nu - DC_JKR_NU_0 < DC_JKR_NU_PIECES - 1 ? (int)(nu - DC_JKR_NU_0) : DC_JKR_NU_PIECES - 1;
  double y[2], s[2];
  dc_poly14(&dc_jkr_psi_poly[p][0][0], 2, 2, nu - dc_jkr_psi_centre[p], y, s);
  return dc_jkr_psi_poly[p][0][0] + (s[0] + kappa * y[1]);
}

/* What a material pair fixes for the Hertz-like end: E* and c = 2 pi w/E*
   where E* and w lie in (1e-60, 1e60), the range of the inline path
   (dc_jkr_sphere_nu_); elsewhere c is NaN, so that nu is NaN and the
   path's test of nu turns every contact away. Built once per pair, it
   saves a division and the range checks of E* and w per contact. */
typedef struct {
  double Estar, c;
} dc_jkr_sphere_pair;

static inline dc_jkr_sphere_pair dc_jkr_sphere_pair_of(double Estar, double w)
{
  dc_jkr_sphere_pair p;
  p.Estar = Estar;
  p.c = Estar > 1e-60 && Estar < 1e60 && w > 1e-60 && w < 1e60 ? 2.0 * M_PI * w / Estar : NAN;
  return p;
}

/* a0 and nu = a0 c/delta^2 for R in (1e-60, 1e60), 0 < delta < 1e60 with
   R delta a normal number, c of a pair (no other intermediate can leave
   the doubles; 1/delta^2 overflowing gives nu = inf, a NaN c nu = NaN); 0
   (nothing written) outside. */
static inline int dc_jkr_sphere_nu_(double R, double c, double delta, double *a0, double *nu)
{
  if (!(R > 1e-60 && R < 1e60 && delta > 0.0 && delta < 1e60 && R * delta >= DBL_MIN)) return 0;
  const double id = 1.0 / delta;
  *a0 = sqrt(R * delta);
  *nu = *a0 * (c * (id * id));   /* one product after the square root */
  return 1;
}

/* F = 2/3 E* a0 delta psi (3 - psi^2) */
static inline double dc_jkr_sphere_force_(double Estar, double a0, double delta, double psi)
{
  return 2.0 / 3.0 * Estar * a0 * delta * psi * (3.0 - psi * psi);
}

/* The hot path of dc_jkr_sphere, inline: where nu <= DC_JKR_NU_H (kappa
   <= 4, delta >= 0.575 delta_scale: the Hertz-like end where compressed
   DEM contacts spend their time), p's c not NaN and R, delta as for
   dc_jkr_sphere_nu_, the contact radius *a and force *F of
   dc_jkr_sphere(R, p->Estar, w, delta) to the bit, and 1; elsewhere 0 and
   nothing written (call dc_jkr_sphere). */
static inline int dc_jkr_sphere_near_hertz(const dc_jkr_sphere_pair *p, double R, double delta, double *a, double *F)
{
  double a0, nu;
  if (!dc_jkr_sphere_nu_(R, p->c, delta, &a0, &nu) || !(nu <= DC_JKR_NU_H)) return 0;
  const double psi = dc_jkr_psi(nu, sqrt(nu));
  *a = a0 * psi;
  *F = dc_jkr_sphere_force_(p->Estar, a0, delta, psi);
  return 1;
}

#ifdef __cplusplus
}
#endif
#endif
