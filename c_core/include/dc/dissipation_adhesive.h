/* Viscoelastic dissipation in adhesive (JKR) contacts, corrected form of
   review Eqs. 39-40 (Table 6, "smooth, adhesive, Brilliantov [90]").

   Seed errors (review Eqs. 39, 40 and Table 6):
   - Eq. 40's adhesive term carries E* R^1/2 delta^1/2 in front of
     (3/4) B (pi w/D)^1/2 R^1/4 ddelta delta^-3/4, i.e. one factor E* more
     than Eq. 39's (3/4) B (pi w/D)^1/2 R^3/4 ddelta delta^-1/4: the two
     cannot both be forces.
   - B = (3 eta2 - eta1) E nu q0 / (3 (1+nu)(1-2nu)) as printed has units
     Pa^2 s (viscosity times modulus); Eq. 39's adhesive term,
     B (pi w/D)^1/2 R^3/4 ddelta delta^-1/4, is a force only for B in Pa s,
     and Eq. 40's, with its extra E* R^1/2 delta^1/2, is not a force for
     either.
   - delta^-1/4 (and delta^-3/4) diverge at delta = 0 and are complex for
     delta < 0, although the JKR contact persists down to delta_break < 0.
   - Eq. 39's first term lacks the rate: it must be A ddelta/dt times the
     contact stiffness (Eq. 37).

   Corrected law (derived here; the review cites Brilliantov et al., Phys.
   Rev. E 76 (2007) 051302, whose text we could not obtain: that its
   contact-radius form is the one below is not verified). In the quasi-static
   viscoelastic regime the dissipative stress is A times the elastic stress
   of the displacement-rate field (A: the dissipative constant of review
   Eq. 37, units s). Inside the contact the surface follows the rigid
   approach, so its displacement rate is uniform, d delta/dt, whatever the
   adhesive (Boussinesq) part of the field; outside, the surface is
   traction free. The rate field is therefore that of a rigid flat punch of
   the current contact area, and
       F_dis = A (d delta/dt) k_punch(a, b),
       k_punch = pi E* a / K(e^2)  (elliptic flat punch, semi-axes a >= b,
                                    e^2 = 1 - b^2/a^2; = 2 E* a for a circle).
   For a circle, with delta = a^2/R - (2 pi w a/E*)^1/2 (JKR),
       F_dis = A (da/dt) d/da [F_H(a) - F_B(a)/3],
       F_H = 4 E* a^3/(3R), F_B = (8 pi w E* a^3)^1/2,
   the contact-radius form. Checks (tests/unit/test_dissipation_adhesive.c):
   - w -> 0: a = (R delta)^1/2 and 2 E* a = dF_Hertz/d delta, so F_dis =
     A ddelta dF_Hertz/d delta, review Eq. 37, exactly; for elliptic Hertz
     contacts k_punch = dF/d delta = 3F/(2 delta) likewise;
   - units: A [s] E* [Pa] a [m] ddelta [m/s] = N; F_dis scales as
     L^2 under R, a, delta -> L (R, a, delta), w -> L w at fixed E*, A;
   - finite for every state of the JKR branch, delta_break <= delta < 0
     included (a > 0 there);
   - the contact-radius form against finite differences of a(t).
   Sign: F_dis > 0 (repulsive) on approach (ddelta > 0), < 0 on recession. */
#ifndef DC_DISSIPATION_ADHESIVE_H
#define DC_DISSIPATION_ADHESIVE_H

#include "dc/jkr_elliptic.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Corrected review Eqs. 39-40 for an elliptic contact of semi-axes
   a >= b > 0: F_dis = A ddelta pi E* a / K(1 - b^2/a^2). A >= 0 [s],
   Estar > 0, ddelta = d delta/dt [m/s], all finite; DC_EDOM outside. Any
   b/a of the domain: where (b/a)^2 is not a normal number, K = ln(4 a/b)
   (exact to rounding there). DC_ERANGE when F_dis overflows. On any error
   *F_dis is untouched (as for every function below). */
int dc_dissip_adhesive_ab(double A, double Estar, double a, double b, double ddelta, double *F_dis);

/* The same for a JKR state (dc_jkr_sphere / dc_jkr_contact): a, b of the
   state (b <= 0 is read as b = a); zero when s->contact == 0, and when
   a <= 0 (touching). DC_EDOM also for a state in contact whose a or b is
   not finite. */
int dc_dissip_adhesive_state(double A, double Estar, const dc_jkr_state *s, double ddelta, double *F_dis);

/* Contact-radius form for spheres: F_dis =
   A (da/dt) d/da [4 E* a^3/(3R) - (8 pi w E* a^3)^1/2 / 3]. Equal to
   dc_dissip_adhesive_ab(A, E*, a, a, ddelta) when da/dt is the JKR rate.
   Domain: A >= 0, R > 0, Estar > 0, w >= 0, a > 0, da_dt, all finite
   (else DC_EDOM); DC_ERANGE when F_dis overflows. */
int dc_dissip_adhesive_radius_rate(double A, double R, double Estar, double w, double a, double da_dt,
                                   double *F_dis);

/* Elastic-adhesive plus dissipative normal force for spheres (corrected
   review Eq. 40): F = F_JKR(delta) + F_dis, state in *s. Domain: that of
   dc_jkr_sphere, A >= 0 and ddelta finite (else DC_EDOM); DC_ERANGE when
   the state or the total overflows. On any error *s and *F_total are
   untouched. */
int dc_jkr_sphere_viscoelastic(double R, double Estar, double w, double A, double delta, double ddelta,
                               dc_jkr_state *s, double *F_total);

#ifdef __cplusplus
}
#endif
#endif
