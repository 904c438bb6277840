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

#ifdef __cplusplus
}
#endif
#endif
