/* Mindlin no-slip tangential stiffness of elliptic and circular contacts
   (Mindlin 1949; review Eqs. 56-58).

   Review Eqs. 56-57: F_t = 2 pi G a chi delta_t, with a the semi-major axis,
   theta the angle of the force from the major axis and
     chi^-2 = [(1-nu) K + nu D]^2 cos^2 theta + [K - nu D]^2 sin^2 theta,
   K, D of e^2 = 1 - b^2/a^2. Checked independently: the displacement of the
   contact under Mindlin's traction q = F/(2 pi a b) (1 - x^2/a^2 -
   y^2/b^2)^-1/2, integrated against Cerruti's kernel (Johnson Eq. 3.86b),
   gives (2 pi G a / F) u = (1-nu) K + nu D along the major axis and K - nu D
   along the minor axis (tests/reference/gen_mindlin.py, to 1e-25), with no
   cross term. So the stiffness is diagonal in the ellipse axes:
     k_major = 2 pi a / c_major,  k_minor = 2 pi a / c_minor,
     c_major = sum_i [(1-nu_i) K + nu_i D] / G_i,  c_minor = sum_i [K - nu_i D] / G_i
   (the compliances of the two bodies add). The displacement makes the angle
   psi = atan(c_minor/c_major tan theta) with the major axis (Eq. 58).
   Circle (K = pi/2, D = pi/4): k = 8 G* a with G* = 1/sum (2-nu_i)/G_i, the
   stiffness of LIGGGHTS' hertz (its Geff). */
#ifndef DC_MINDLIN_H
#define DC_MINDLIN_H

#include "dc/hertz_elliptic.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Compliance sums of a material pair: s0 = sum 1/G_i, s1 = sum nu_i/G_i. */
typedef struct {
  double s0, s1;
} dc_mindlin_pair;

/* From Young's moduli E_i > 0 and Poisson ratios nu_i in (-1, 0.5]
   (G_i = E_i / (2 (1 + nu_i))). DC_EDOM outside; DC_ERANGE (p untouched)
   when a compliance sum overflows (E_i below ~1e-308). */
int dc_mindlin_pair_init(double E1, double nu1, double E2, double nu2, dc_mindlin_pair *p);

/* G* = 1/sum (2 - nu_i)/G_i = 1/(2 s0 - s1) and E* = 1/sum (1 - nu_i^2)/E_i
   = 2/(s0 - s1) (with (1 - nu^2)/E = (1 - nu)/(2 G)) of a material pair
   from dc_mindlin_pair_init. Inline, unchecked. */
static inline double dc_mindlin_pair_gstar(const dc_mindlin_pair *p) { return 1.0 / (2.0 * p->s0 - p->s1); }
static inline double dc_mindlin_pair_estar(const dc_mindlin_pair *p) { return 2.0 / (p->s0 - p->s1); }

/* No-slip stiffness of a circular contact of radius a: 8 G* a (G* =
   1/sum (2-nu_i)/G_i; LIGGGHTS' Geff). Inline, unchecked (G* > 0, a >= 0). */
static inline double dc_mindlin_kt_circle(double Gstar, double a) { return 8. * Gstar * a; }

/* Stiffnesses along the major and minor axes of a contact ellipse of
   semi-major axis a >= 0 whose eccentricity gives the elliptic integrals K,
   D (dc_hertz_geom, dc_ellint). Circle: both 8 G* a. DC_EDOM for a < 0,
   non-finite a or K <= 0; DC_ERANGE (outputs untouched) when a stiffness
   overflows. */
int dc_mindlin_stiffness(const dc_mindlin_pair *p, double a, double K, double D,
                         double *k_major, double *k_minor);

/* Review Eq. 57: chi for one Poisson ratio nu in [0, 0.5] and the force
   angle theta from the major axis (geometry g). DC_EDOM outside. */
int dc_mindlin_chi(const dc_hertz_geom *g, double nu, double theta, double *chi);

#ifdef __cplusplus
}
#endif
#endif
