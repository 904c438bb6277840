/* Adhesive elastic contact: Johnson-Greenwood approximate JKR theory for
   elliptical contacts (review = Kildashti, Dong & Yu 2023, Eqs. 19-28 and
   Table 4 "smooth, adhesive"; original: Johnson & Greenwood, J. Phys. D 38
   (2005) 1042), with classical JKR for spheres as its exact circular limit.

   Conventions (derived afresh and checked, see below):
   - R_major >= R_minor are the relative principal radii (as in
     hertz_elliptic.h). The contact ellipse has semi-axes a >= b, a along the
     direction of R_major; g = b/a, e^2 = m = 1 - g^2.
   - Rhat = sqrt(R_major R_minor) (the review's R_c1), lambda^2 = R_minor /
     R_major <= 1. Seed error: the review defines lambda = (R_i/R_j)^1/2 and
     requires lambda < 1, but under its Eqs. 3-4 R_i >= R_j; Eqs. 22-23 hold
     with lambda^2 = R_j/R_i = R_minor/R_major (derivation below; the w -> 0
     limit then gives the Hertz eccentricity of hertz_elliptic.h).
   - w is the work of adhesion (J/m^2 = N/m), Estar = 1/sum((1-nu^2)/E).

   Derivation (JG 2005): pressure p = (al + be X^2 + ga Y^2)/sqrt(1-X^2-Y^2),
   X = x/a, Y = y/b. Matching the displacement inside the ellipse to
   delta - x^2/(2 R_major) - y^2/(2 R_minor) fixes be, ga (two curvature
   equations) and delta; the energy-release rate K_I^2/(2 Estar) = w is
   imposed at the ends of both axes, K_I = (al+be) sqrt(pi a) and
   (al+ga) sqrt(pi b). With the elliptic integrals K, B, D, C of m:
     Delta = D B + g^2 C D + B C,
     Pi2   = ((1+lambda^2) C + D) / (lambda Delta)             (Eq. 23)
     Pi1   = (lambda + 1/lambda - B Pi2) / D                   (Eq. 22)
     Q     = g^2 Pi2 - Pi1 = ((1-lambda^2) B - m (D - C)) / (lambda Delta)
     u     = 1 - g^1/2,  rho = Q/u
     X     = g^2 Pi2 K + Q B - 2 K rho    (= Eq. 20's bracket)
     Y     = g^2 Pi2/3 + Q/3 - rho        (= Eq. 19's bracket)
     a^3 = (8 w Rhat^2 / (pi Estar)) g / rho^2,   b = g a,  A = pi a b
     delta = a^2 X / (2 Rhat),   F = 8 w Rhat g Y / rho^2.
   The Q/u form is algebraically equal to the review's (Pi1 - Pi2 g^5/2)/
   (1 - g^1/2) etc. but has no cancellation at g -> 1 (1 - g^1/2 -> 0), where
   both Q and u vanish: the review's brackets lose all digits as R_minor ->
   R_major. Eqs. 19, 20, 21, 22, 23 and 27 agree with this derivation
   (checked in tests/reference/gen_jkr_elliptic.py, which solves the same
   problem independently from the potential integrals of the pressure by
   quadrature, 1e-25 agreement). Seed error in Eq. 28 (and Table 4, beta):
   the denominator needs 2 K, not K: beta_JG = 2 g / X; with K the Hertz
   circle gives X = 0 and an infinite area, with 2 K it gives beta_JG = 1
   (A = pi R delta). gamma_JG = (3 pi sqrt2 / 2) Y / X^3/2 (Eq. 27) so that
   F = 4/3 Estar Rhat^1/2 delta^3/2 gamma_JG and A = pi Rhat delta beta_JG.
   For R_minor = R_major, g = 1 and rho = (8 w R^2 /(pi Estar a^3))^1/2 turn
   these into classical JKR exactly: F = 4 Estar a^3/(3R) - (8 pi w Estar
   a^3)^1/2, delta = a^2/R - (2 pi w a/Estar)^1/2.

   Branches. For R_minor < R_major the states form one family in e^2 in
   (0, e2_hertz): e^2 -> e2_hertz is the large, Hertz-like contact (a -> oo),
   e^2 -> 0 a vanishing, circular one. delta(e^2) has one minimum, the
   separation point (e2_break, delta_break: vertical tangent of F(delta));
   F(e^2) has one minimum, the pull-off point under load control
   (F_pull < 0; the pull-off force is -F_pull). Under overlap control (DEM)
   the contact follows the large-contact branch e^2 in [e2_break, e2_hertz),
   on which a increases with delta (the elastic-plus-surface energy is a
   minimum in the contact size at fixed delta); F falls from F_break to
   F_pull (dF/d delta -> -oo at the separation point) and then rises. The
   small-contact branch is an energy maximum and is never taken. The contact forms when
   delta reaches 0 on approach and is kept, with negative overlaps, until
   delta < delta_break (dc_jkr_in_contact). For spheres: F_pull =
   -3/2 pi w R, delta_break = -3/4 (pi^2 w^2 R / Estar^2)^1/3, F_break =
   -5/6 pi w R. */
#ifndef DC_JKR_ELLIPTIC_H
#define DC_JKR_ELLIPTIC_H

#include "dc/hertz_elliptic.h"
#include "dc/contract.h"
#include "dc/jkr_sphere.h"   /* dc_jkr_state and classical JKR, dc_jkr_sphere* */

#ifdef __cplusplus
extern "C" {
#endif

/* Smallest R_minor/R_major accepted by dc_jkr_geometry. */
#define DC_JKR_RATIO_MIN 1e-6
/* Below this 1 - R_minor/R_major the contact is treated as circular with
   R = Rhat (the elliptic correction is O(1 - ratio) in the force). */
#define DC_JKR_CIRCULAR_TOL 1e-13

/* Everything about one contact that does not depend on the overlap.
   Computed once per contact (and whenever the radii, w or Estar change). */
typedef struct {
  double R_major, R_minor, Rhat; /* Rhat = sqrt(R_major R_minor)            */
  double lambda, lam2, l2c;      /* lambda = sqrt(R_minor/R_major), lam2 =
                                    R_minor/R_major, l2c = 1 - lam2 (each
                                    rounded once from the radii)            */
  double Estar, w;
  int circular;                  /* 1: classical JKR with R = Rhat          */
  dc_hertz_geom hertz;           /* the w = 0 contact (dc_hertz_contact)    */
  double e2_hertz;               /* e^2 of the Hertz ellipse                 */
  double a_scale;                /* (8 w Rhat^2 / (pi Estar))^1/3            */
  double delta_scale;            /* a_scale^2 / (2 Rhat)                     */
  double F_scale;                /* 8 w Rhat                                 */
  double e2_break, delta_break, F_break; /* separation point (min delta)    */
  double dbar_break;             /* delta_break / delta_scale, as evaluated */
  double e2_pull, delta_pull, F_pull;    /* load-controlled pull-off (min F) */
  double guess_c1, guess_c2;     /* starting-value model of the solver       */
  /* first order in rho about the Hertz state: X = X0 + X1 rho, g = g0 + g1 rho,
     F / (F_scale dbar^3/2) = P0 + P1 rho, rho = g0^1/2 X0^3/4 dbar^-3/4,
     where the distance to the Hertz state is < 1e-8 of its e^2 scale */
  double pert_X0, pert_X1, pert_g0, pert_g1, pert_P0, pert_P1;
  double pert_rho0;              /* g0^1/2 X0^3/4: rho = pert_rho0 dbar^-3/4 */
  double dbar_switch;            /* delta/delta_scale above which it is used */
  int use_m1;                    /* solver variable: 1 - e^2 (slender) or e^2 */
  double v_hertz, v_break;       /* e2_hertz, e2_break in that variable      */
} dc_jkr_geom;

/* Geometry of an elliptic adhesive contact from the two relative principal
   radii (either order), Estar and w: the Hertz eccentricity, the
   separation point and the pull-off point (review Eqs. 19-23) and the
   solver's expansion at the Hertz end, in reduced variables functions of
   R_minor/R_major alone, from tables in ln(R_minor/R_major) fitted to the
   extrema found with mpmath (tests/reference/gen_jkr_geometry_poly.py):
   e^2 of the three states within 2 ulp of them, the reduced overlaps and
   forces at separation and pull-off within 4 (test_jkr_elliptic against
   jkr_geometry_dense.csv), in about 0.17 us with dc_hertz_geometry.
   Domain: radii > 0 finite, R_minor/R_major >= DC_JKR_RATIO_MIN,
   Estar > 0, w >= 0 finite. DC_EDOM outside, DC_ERANGE when a quantity of
   the geometry overflows (only far outside physical magnitudes). On any
   error *g is untouched. */
int dc_jkr_geometry(double R1, double R2, double Estar, double w, dc_jkr_geom *g);

/* Forward map (review Eqs. 19-21): the state with contact eccentricity
   e2 (axis ratio g = (1-e2)^1/2), either branch, with delta and F.
   Domain: elliptic contacts with w > 0 (not circular), 0 < e2 < e2_hertz;
   DC_EDOM outside (NaN e2 included). Every e2 of the domain is taken as
   given, down to the subnormals: below 1e-20 (1 - R_minor/R_major) from
   the leading order of the map in e2 (F ~ e2, delta ~ e2^1/3, a ~ e2^2/3;
   the neglected terms are below 1e-20 relative), where the full form
   would overflow (rho ~ 1/e2) from e2 ~ 1e-150 on. DC_ERANGE when e2 is
   within rounding of e2_hertz (the contact size grows without bound
   there) or a result overflows. On any error *s is untouched. */
int dc_jkr_at_eccentricity(const dc_jkr_geom *g, double e2, dc_jkr_state *s);

/* Per-contact solver memory of dc_jkr_contact, kept between time steps.
   Start from all zeros ({0}). v: the solver variable of the previous solve
   (e^2, or 1 - e^2 when e2_hertz > 1/2); L, dudL: the log-log slope there
   (the predictor), dudL = 0 when unknown. Any content is safe: a v outside
   the stable branch is ignored, dudL <= 0 means start at v. */
typedef struct {
  double v, L, dudL;
} dc_jkr_hint;

/* The contact state for overlap delta on the stable branch: the DEM call
   (review Eqs. 19-21 inverted for e^2 at given delta).
   hint: per-contact solver memory (above), or NULL (cold start, about
   three evaluations of the elliptic integrals). Unused for circular
   contacts and w = 0. With the hint of the previous time step the solve
   predicts the new e^2 from the previous one and the slope of
   ln((v - v_b)/(v_H - v)) against ln(delta - delta_break) and usually
   takes one or two evaluations. w = 0 returns exactly dc_hertz_contact;
   circular contacts use dc_jkr_sphere. delta < delta_break: contact = 0,
   zero state, DC_OK. Domain: delta finite (else DC_EDOM). DC_ERANGE when
   a result overflows; on DC_EDOM and DC_ERANGE *s and *hint are
   untouched. DC_ENOCONV: *s (and *hint) hold the last iterate when it is
   finite, else they are untouched. */
int dc_jkr_contact(const dc_jkr_geom *g, double delta, dc_jkr_hint *hint, dc_jkr_state *s);

/* Contact hysteresis: a new contact forms when delta >= 0; an existing one
   persists while delta >= delta_break (< 0 for w > 0). Returns 1 or 0. */
int dc_jkr_in_contact(const dc_jkr_geom *g, int was_in_contact, double delta);

/* The law contract (dc/contract.h). Per-contact history: the formed flag
   (jkr_contact), then a dc_jkr_hint (elliptic contacts only); no field
   changes sign when i and j swap. */
enum { DC_JKR_HISTORY_NFIELDS = 4 };
extern const dc_history_field dc_jkr_history[DC_JKR_HISTORY_NFIELDS];

/* Parameter check: workOfAdhesion w >= 0 and finite [J/m^2]. */
int dc_jkr_check(double w, dc_param_error *err);

/* Normal force that bounds friction, |F_t| <= mu (F + 2 F_pulloff), with
   F_pulloff > 0 the load-controlled pull-off force (Thornton & Yin 1991;
   LAMMPS GRANULAR's jkr does the same): >= F_pulloff > 0 on the stable
   branch, so friction acts while the neck is in tension. */
static inline double dc_jkr_friction_load(double F, double F_pulloff) { return F + 2.0 * F_pulloff; }

/* The law contract's output (dc/contract.h) of a JKR state s (dc_jkr_sphere,
   dc_jkr_contact) with pull-off force F_pulloff > 0: force, stiffness,
   area, semi-axes, friction load (dc_jkr_friction_load), formed =
   s->contact. */
void dc_jkr_normal(const dc_jkr_state *s, double F_pulloff, dc_contact *c);

#ifdef __cplusplus
}
#endif
#endif
