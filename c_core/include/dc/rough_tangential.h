/* Tangential stiffness of rough elastic contact, no slip (Hisakado &
   Tsukizoe 1974 as given by the review, Eqs. 78-84 and Table 5):

     F_t = k_t delta_t,
     k_t = 2 pi n_asp G chi sqrt(R_asp sigma) F_1/2(h),  h = -delta/sigma  (Eq. 83)
     chi = {[(1-nu) K + nu D]^2 cos^2 theta + [K - nu D]^2 sin^2 theta}^-1/2
                                                (Mindlin, review Table 5)

   with K, D the elliptic integrals of the contact (dc_hertz_geom), theta the
   angle between the slip direction and the major axis, G the shear modulus
   (of the elastic body against a rigid rough one; for two bodies the
   effective G of the tangential model), n_asp = N A_n the number of summits
   and R_asp the radius that sets the summit contact radius
   a_k = sqrt(R_asp (z - d)) (Eq. 81).

   Seed errors found (review, OCR text):
   - Eq. 79 reads delta_t = sum F_tk; it is F_t = sum_k F_tk.
   - Eq. 78 gives the summit compliance as (2-nu)/(2 pi G a_k); Mindlin's
     no-slip result for a circle is delta_t = (2-nu) F_tk/(8 G a_k). Eq. 80
     (F_t = 2 pi G delta_t chi sum a_k) is right with chi: for a circle
     K = pi/2, D = pi/4, chi = 4/(pi (2-nu)) and 2 pi G a chi = 8 G a/(2-nu).
     This is what is implemented.
   - Eq. 81 writes a_k = sqrt((z - d) a_c) and Table 5 sqrt(R_j sigma): a
     Hertz summit contact radius is sqrt(radius x overlap); R_asp is that
     radius, an input.
   - Eq. 84 (chi* in I-Bessel form) = chi F_1/2(h) only with the prefactor
     sqrt(pi)/(4 sqrt(2h)) (Table 5 prints sqrt(pi)/(4 sqrt(2) h)); see
     dc/gw_integrals.h.
   Smooth limit: sigma -> 0 gives k_t -> 2 pi n_asp G chi sqrt(R_asp delta),
   Mindlin's stiffness with a = sqrt(R_asp delta), per summit. */
#ifndef DC_ROUGH_TANGENTIAL_H
#define DC_ROUGH_TANGENTIAL_H

#include "dc/hertz_elliptic.h"
#include "dc/mindlin.h"

#ifdef __cplusplus
extern "C" {
#endif

/* chi (Mindlin, review Eq. 57) is dc_mindlin_chi in dc/mindlin.h. */
/* k_t of Eq. 83. Domain: G > 0, n_asp > 0, R_asp > 0, sigma >= 0, chi > 0,
   all finite; delta finite (k_t = 0 when sigma = 0 and delta <= 0).
   DC_EDOM outside; DC_ERANGE, kt untouched, when k_t overflows. */
int dc_rough_tangential_stiffness(double G, double chi, double n_asp, double R_asp,
                                  double sigma, double delta, double *kt);

/* The summits' contact patch for a tangential law (Eq. 83 as one
   Mindlin contact): semi-axes

     a_r = n_asp (R_asp sigma)^1/2 F_1/2(h),  b_r = a_r (1 - e^2)^1/2,
     R_asp = 2 R_major D/K,  h = -delta/sigma,

   the ellipse of the contact's eccentricity whose Mindlin no-slip
   stiffness (proportional to its semi-axis, dc_cmd_stiffness) is Eq. 83's
   k_t: 2 pi G chi a_r = 2 pi n_asp G chi (R_asp sigma)^1/2 F_1/2(h).
   R_asp is the smooth contact's a^2/delta (dc_hertz_contact: a sphere's
   R), so that as sigma -> 0 (sigma^1/2 F_1/2(h) -> delta^1/2) the patch
   becomes n_asp times the Hertz ellipse: with n_asp = 1 the smooth law's
   stiffness. For sigma <= 1e-80 delta and for sigma = 0 the Hertz
   expression itself (dc_hertz_contact's a: the same bits for n_asp = 1);
   sigma = 0 and delta <= 0 give 0. Before touch (delta < 0, sigma > 0)
   the summits alone carry the patch (0 where F_1/2 underflows, h > ~38).
   g from dc_hertz_geometry. Domain: n_asp > 0, sigma >= 0, delta, all
   finite; DC_EDOM outside, DC_ERANGE (outputs untouched) when a_r
   overflows. */
int dc_rough_tangential_axes(const dc_hertz_geom *g, double n_asp, double sigma, double delta, double *a, double *b);

#ifdef __cplusplus
}
#endif
#endif
