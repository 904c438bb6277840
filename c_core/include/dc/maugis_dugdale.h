/* Adhesion across the Tabor range, spheres: the Maugis-Dugdale model
   (Maugis, J. Colloid Interface Sci. 150 (1992) 243; in the non-dimensional
   form of Johnson & Greenwood, J. Colloid Interface Sci. 192 (1997) 326)
   and its DMT limit (Derjaguin, Muller & Toporov 1975), the transition the
   review names between JKR (soft, strongly adhesive, dc/jkr_sphere.h) and
   DMT (hard, weakly adhesive: review Sec. 2.2, refs. [61], [67]).

   The adhesive stress is sigma0 wherever the gap is below h0 = w/sigma0
   (a Dugdale zone a < r < c around the contact radius a), zero beyond.
   With K = 4 E* / 3 and the scales
     a = abar (pi w R^2 / K)^1/3,  F = Pbar pi w R,  delta = Dbar (pi^2 w^2 R / K^2)^1/3,
     lambda = 2 sigma0 (R / (pi w K^2))^1/3,  m = c/a,  s = (m^2 - 1)^1/2,
   the contact edge carries no stress singularity and the zone ends where
   the gap reaches h0:
     (lambda abar^2/2) [s + (m^2 - 2) arcsec m] + (4 lambda^2 abar/3) [s arcsec m - m + 1] = 1   (MD1)
     Pbar = abar^3 - lambda abar^2 [s + m^2 arcsec m]                                         (MD2)
     Dbar = abar^2 - 4/3 lambda abar s                                                        (MD3)
   (arcsec m = arctan s). lambda -> inf gives JKR (Pbar = abar^3 -
   (6 abar^3)^1/2, pull-off 3/2 pi w R), lambda -> 0 DMT (Pbar = abar^3 -
   2: Hertz less 2 pi w R, pull-off 2 pi w R); in between the pull-off
   force under load control lies between them (Johnson & Greenwood's
   adhesion map: JKR above lambda ~ 5, DMT below ~ 0.1). The Tabor
   parameter mu_T = (R w^2/(E*^2 z0^3))^1/3 of a Lennard-Jones surface
   potential with equilibrium separation z0 maps to lambda = 1.1570 mu_T
   (sigma0 the potential's largest stress 16 w/(9 3^1/2 z0), h0 = w/sigma0 =
   9 3^1/2 z0 / 16 = 0.974 z0).

   Numerics: MD1 is solved for s (its left side increases with s from -1
   at s = 0), with the bracket s + (s^2 - 1) arctan s taken from its series
   (4/3) s^3 - (8/15) s^5 + ... for s < 1/4 (JKR-like contacts, where s ~
   1/lambda and the closed form cancels), and s arctan s - (1 + s^2)^1/2 + 1
   as s arctan s - s^2/((1 + s^2)^1/2 + 1). Checked against an independent
   mpmath solution of MD1-MD3 (tests/reference/gen_maugis.py). */
#ifndef DC_MAUGIS_DUGDALE_H
#define DC_MAUGIS_DUGDALE_H

#include <float.h>
#include <math.h>
#include "dc/contract.h"
#include "dc/hertz_elliptic.h"

#ifdef __cplusplus
extern "C" {
#endif

/* lambda from the Tabor parameter (Lennard-Jones surfaces): 1.1570 mu_T,
   exactly (32 / (9 3^1/2)) (9 / (16 pi))^1/3 mu_T. */
double dc_md_lambda_of_tabor(double mu_T);

/* The state on the contact branch at the non-dimensional contact radius
   abar > 0 and lambda > 0: m = c/a (MD1), Pbar (MD2), Dbar (MD3).
   The domain: lambda in [1e-10, 1e10], abar in [1e-20, 1e20] (DEM contacts
   lie far inside); DC_EDOM outside, DC_ENOCONV if MD1 does not converge
   (outputs untouched on error). */
int dc_md_state(double lambda, double abar, double *m, double *Pbar, double *Dbar);

/* The contact branch where the contact radius vanishes (abar -> 0, c > 0):
   the zone's non-dimensional radius cbar = lim abar m, from MD1's limit
   (pi lambda/4) cbar^2 + (4 lambda^2/3) (pi/2 - 1) cbar = 1, the force
   Pbar0 = -(pi/2) lambda cbar^2 and the overlap Dbar0 = -(4/3) lambda cbar.
   DC_EDOM unless lambda lies in [1e-10, 1e10]. */
int dc_md_state_zero(double lambda, double *cbar, double *Pbar0, double *Dbar0);

/* Pull-off force under load control: the least Pbar of the contact branch
   over abar >= 0 (Pbarc in [-2, -3/2]), and the abar where it occurs (0 when
   it is the abar -> 0 end): golden-section search around the least of 97
   samples on [0, 3]. DC_EDOM unless lambda lies in [1e-10, 1e10]. */
int dc_md_pulloff(double lambda, double *Pbarc, double *abarc);

/* The contact branch's lowest overlap, where an overlap-controlled contact
   separates: the least Dbar over abar >= 0 (MD3) and the abar where it
   occurs (0: the abar -> 0 end, where the branch meets the separated
   states of a Dugdale zone alone). JKR: Dbar = -3 6^-2/3 at abar = 6^-1/3;
   the search as dc_md_pulloff's. DC_EDOM unless lambda lies in [1e-10, 1e10]. */
int dc_md_separation(double lambda, double *Dbar_sep, double *abar_sep);

/* The state on the stable contact branch (abar >= abar_sep, where Dbar
   grows with abar) at the overlap Dbar: *contact = 1 with abar, m and Pbar,
   or *contact = 0 and zeros below the separation overlap. At the abar -> 0
   end m is reported as +inf. DC_EDOM unless lambda lies in [1e-10, 1e10]
   and |Dbar| <= 1e30; DC_ENOCONV if a solve fails (outputs untouched on
   error). The reference evaluation: the separation search, then a root in
   abar of MD3 with MD1 solved at each trial, about 0.1 ms a call; not a
   DEM hot path. */
int dc_md_at_overlap(double lambda, double Dbar, int *contact, double *abar, double *m, double *Pbar);

/* The contact branch at s = (m^2 - 1)^1/2 in (0, inf): explicit, since
   MD1 is a quadratic in abar (A abar^2 + B abar = 1, A = (lambda/2)
   [s + (s^2 - 1) arctan s], B = (4 lambda^2/3) [s arctan s - (1 + s^2)^1/2
   + 1]): abar, Pbar (MD2), Dbar (MD3) and dDbar/ds. Dbar falls from +inf
   as s -> 0 (large contacts) to the abar -> 0 end as s -> inf, through
   the fold (its least value, the separation overlap) where lambda is
   above about 0.93. DC_EDOM unless lambda lies in [1e-10, 1e10] and s in
   [1e-30, 1e30]; DC_ERANGE if a result overflows. The DEM path
   (dc_md_step) solves Dbar(s) = Dbar by Newton in s. */
int dc_md_branch_s(double lambda, double s, double *abar, double *Pbar, double *Dbar, double *dDds);

/* The zone-only states (no contact: a Dugdale zone r < c alone, the gap
   h0 at r = c; Johnson & Greenwood 1997): with the surfaces' approach
   under a uniform stress sigma0 on a circle (4 sigma0 c / (pi E*) at its
   edge, 2 sigma0 c / E* at its centre),
     Dbar = cbar^2/2 - (8 lambda/(3 pi)) cbar - 2/(pi lambda),   Pbar = -(pi/2) lambda cbar^2,
   which meet the contact branch's abar -> 0 end (dc_md_state_zero) where
   the centre's gap closes. The stable part (Dbar growing with cbar) is
   cbar >= c_z = 8 lambda/(3 pi), present only when the end's cbar0 > c_z
   (lambda below about 0.93): *zone = 1 with cbar, Pbar there for
   Dbar between its fold -c_z^2/2 - 2/(pi lambda) and the end's Dbar0;
   else *zone = 0 and zeros. DC_EDOM unless lambda lies in [1e-10, 1e10]
   and |Dbar| <= 1e30. */
int dc_md_zone(double lambda, double Dbar, int *zone, double *cbar, double *Pbar);

/* A bound on how far before touch the model acts, in units of Dbar: the
   approach reaches the zone at Dbar = -2/(pi lambda), the last attached
   state lies at the contact branch's separation overlap (within [-1, 0]
   for every lambda: JKR's -0.909, -0.997 near lambda 0.85; unit test) or
   the zone's fold: max(1, c_z^2/2 + 2/(pi lambda) where the zone is
   stable). NaN outside lambda's domain. */
double dc_md_reach(double lambda);

/* An overlap-controlled Maugis-Dugdale contact (a DEM contact's history):
   phase DC_MD_APART, DC_MD_ZONE (x = cbar) or DC_MD_CONTACT (x = abar,
   s = (m^2 - 1)^1/2), lambda of the pair, Pc the pull-off force under
   load control (0 until dc_md_friction_load asks), Dsep and sfold the
   separation overlap and the fold's s (0: no fold; both found as the
   contact first enters the branch; Dsep 0: not yet), Dlast, dsdD and
   curve the last overlap on the branch, ds/dDbar there and d^2 s/dDbar^2
   from the last two steps (the next step's second-order predictor).
   Zeros: apart. */
enum { DC_MD_APART = 0, DC_MD_ZONE = 1, DC_MD_CONTACT = 2 };
typedef struct {
  double phase, x, s, lambda, Pc, Dsep, sfold, Dlast, dsdD, curve;
} dc_md_contact;
#define DC_MD_CONTACT_NFIELDS 10
extern const dc_history_field dc_md_history[DC_MD_CONTACT_NFIELDS];   /* none flips */

/* One step of the contact h at the overlap Dbar (Johnson & Greenwood's
   overlap-controlled loop): apart until Dbar reaches -2/(pi lambda), where
   the state jumps to the zone's stable state (if the zone is stable there)
   or to the contact branch; the zone's states until Dbar passes the
   branch end's Dbar0 (contact) or the zone's fold (apart); the stable
   contact branch down to its separation overlap, then the zone or apart.
   On the branch: Newton in s (dc_md_branch_s) from a second-order
   predictor (the last two states), safeguarded by a bracket, the last
   step below 1e-7 s taken to first order; the fold searched once per
   contact (about 100 branch evaluations). *Pbar the force, *abar the
   contact radius (0 unless in contact); h updated. DC_EDOM for h->lambda
   outside [1e-10, 1e10] or |Dbar| > 1e30; DC_ENOCONV if the solve fails
   (h untouched on error). */
int dc_md_step(double Dbar, dc_md_contact *h, double *Pbar, double *abar);

/* The load that bounds friction, F + 2 |F_c| with F_c the pull-off force
   under load control (JKR's and DMT's choice: dc_jkr_friction_load, the
   DMT contact), F and the result in units of pi w R; the pull-off kept in
   h->Pc, searched (dc_md_pulloff) on the contact's first call. NaN if the
   search fails. */
double dc_md_friction_load(dc_md_contact *h, double Pbar);

/* Spheres in SI units: a type pair's constants (E*, w, the Lennard-Jones
   equilibrium separation z0 giving sigma0 = 16 w/(9 3^1/2 z0), h0 =
   w/sigma0) and the law a Tabor parameter picks. */
typedef struct {
  double Lam;       /* lambda = Lam R^1/3 */
  double Cd, Ca;    /* the overlap's and the radius' scales, Cd R^1/3 and Ca R^2/3 */
  double piw;       /* the force's scale pi w R */
  double h0;        /* the zone's reach before touch [m] */
  double R_jkr, R_dmt;   /* Tabor 5 and 0.1: the effective radii above and below which JKR and DMT hold */
} dc_md_sphere_pair;

/* The constants; DC_EDOM (with err) unless Estar > 0, w > 0 and z0 > 0,
   all finite, with finite scales. */
int dc_md_sphere_pair_of(double Estar, double w, double z0, dc_md_sphere_pair *p, dc_param_error *err);

/* The adhesion law the Tabor parameter mu_T = lambda / 1.1570 of the
   effective radius R picks (Johnson & Greenwood's adhesion map): JKR above
   mu_T = 5, DMT below 0.1, Maugis-Dugdale between. */
enum { DC_ADHESION_JKR = 0, DC_ADHESION_DMT = 1, DC_ADHESION_MD = 2 };
static inline int dc_md_tabor_law(const dc_md_sphere_pair *p, double R)
{
  return R > p->R_jkr ? DC_ADHESION_JKR : R < p->R_dmt ? DC_ADHESION_DMT : DC_ADHESION_MD;
}

/* A sphere contact of effective radius R [m] at overlap delta [m]: one
   dc_md_step in SI units. *F [N] and *a [m]; h's lambda set as the
   contact leaves DC_MD_APART (R is the pair's for the contact's life).
   Apart with delta <= -h0: nothing computed. DC_EDOM for R <= 0, a
   non-finite delta or a lambda outside [1e-10, 1e10] (h untouched);
   DC_ERANGE if F overflows (h holds the step's state); else dc_md_step's
   status. */
int dc_md_sphere(const dc_md_sphere_pair *p, double R, double delta, dc_md_contact *h, double *F, double *a);

/* An elliptic contact (superquadrics) of geometry g (dc_hertz_geometry of
   the relative principal radii): dc_md_sphere on the sphere of elliptic
   Hertz's force radius R_force (F_Hertz = 4/3 E* R_force^1/2 delta^3/2),
   the scales from the current R_force, lambda from it as the contact
   forms (kept for its life). Assumptions: the contact and the Dugdale
   zone are circles (Maugis-Dugdale of the sphere that carries the
   ellipse's Hertz force), so the elastic part is exact (elliptic Hertz as
   the load grows) and the adhesion is that of a sphere of radius R_force
   instead of the ellipse's: DMT's attraction 2 pi w R_force against
   2 pi w (R_major R_minor)^1/2 (2 % high at R_minor/R_major = 0.5, 23 %
   at 0.1); doc/adhesion_tabor.md gives the errors at both ends of the
   Tabor range (Johnson-Greenwood's elliptic JKR at the other). Chosen over
   the Gaussian radius (R_major R_minor)^1/2, whose exact DMT adhesion
   comes with Hertz's one-radius error: 1.6 pull-off forces at 10 overlap
   scales for R_minor/R_major = 0.1 against 0.22. DC_EDOM for R_force
   outside (0, DBL_MAX], else as dc_md_sphere. */
int dc_md_ellipse(const dc_md_sphere_pair *p, const dc_hertz_geom *g, double delta, dc_md_contact *h, double *F,
                  double *a);

/* DMT (the lambda -> 0 limit) of an elliptic Hertz contact, relative
   principal radii R_major, R_minor: the adhesive force of the rigid gap
   x^2/(2 R_major) + y^2/(2 R_minor), whose area below the gap h is
   2 pi h (R_major R_minor)^1/2, is 2 pi w (R_major R_minor)^1/2 (any stress
   law of work w; the Derjaguin approximation), so
     F = F_Hertz(delta) - 2 pi w (R_major R_minor)^1/2,   pull-off 2 pi w (R_major R_minor)^1/2
   (spheres: 2 pi w R). Returns the pull-off force [N]; NaN outside the
   domain (w >= 0, radii > 0, all finite). */
double dc_dmt_pulloff(double R_major, double R_minor, double w);

/* The DMT contact of geometry g (dc_hertz_geometry) at overlap delta:
   delta > 0: F = F_Hertz - F_po (F_po = dc_dmt_pulloff of g's radii), the
   Hertz stiffness, area and ellipse, friction load F + 2 F_po = F_Hertz +
   F_po (as for JKR, dc_jkr_friction_load), formed; delta <= 0: no contact
   (all zero, formed 0): the attraction's range before touch (of the order
   of the equilibrium separation z0) lies below the overlaps a DEM step
   resolves, and the force jumps by F_po at touch both ways (no hysteresis:
   a DMT contact dissipates nothing). DC_EDOM for w < 0, Estar <= 0 or a
   non-finite input; DC_ERANGE as dc_hertz_contact (c untouched on error). */
int dc_dmt_contact(const dc_hertz_geom *g, double Estar, double w, double delta, dc_contact *c);

/* The sphere hot path of dc_dmt_contact (geometry dc_hertz_geometry_circle
   of R, inputs in its domain): where that returns DC_OK, its F and kn to
   the bit, and the Hertz root (R delta)^1/2; 0 and nothing written where
   delta <= 0 or a product is not finite (call dc_dmt_contact). */
static inline int dc_dmt_sphere(double R, double Estar, double w, double delta, double *F, double *kn, double *root)
{
  if (!(delta > 0.0)) return 0;
  const double r = sqrt(R * delta);
  const double f = 4.0 / 3.0 * Estar * r * delta - 2.0 * M_PI * w * sqrt(R) * sqrt(R), k = 2.0 * Estar * r;
  if (!(fabs(f) <= DBL_MAX && k <= DBL_MAX)) return 0;
  *F = f;
  *kn = k;
  *root = r;
  return 1;
}

#ifdef __cplusplus
}
#endif
#endif
