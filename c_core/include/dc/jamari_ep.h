/* Elastic-plastic normal contact of ellipsoidal bodies: Jamari & Schipper,
   Tribol. Lett. 21 (2006) 262, as printed in the review (Kildashti, Dong &
   Yu 2023, Sec. 2.5.1, Eqs. 41-46, Table 4), with an elastic unloading and
   reloading branch derived here (the review gives loading only).

   Geometry and conventions are those of hertz_elliptic.h (R_major >=
   R_minor relative principal radii, Rc, e^2, gamma, beta, K, E of the Hertz
   ellipse, E* = 1/sum((1-nu^2)/E)). H is the hardness of the softer body.

   Loading (a curve in the overlap delta alone):
   - elastic, delta <= delta_n1: Hertz, review Eqs. 1-2, returned by
     dc_hertz_normal itself (bit for bit).
   - first yield, review Eq. 41: the maximum Hertz pressure 3F/(2A) reaches
     K_v H at
       delta_n1 = pi^2/4 Rc (beta/gamma)^2 (K_v H/E*)^2
                = 2 Rc (K_v H/E*)^2 E(e^2) K(e^2).
     The two printed forms agree: with Eqs. 11-12, (beta/gamma)^2 =
     8 E K / pi^2 (checked to 1e-40 in tests/reference/gen_jamari_ep.py).
     Sphere: delta_n1 = (pi K_v H/(2 E*))^2 R.
   - fully plastic, delta >= delta_n2, review Eqs. 42-43: the truncation
     ellipse of the undeformed surfaces, A = 2 pi (R_i R_j)^1/2 delta, at
     mean pressure c_h H, F = c_h H A. Seed error: Eq. 43 is printed with
     (R_i R_i)^0.5; it is (R_i R_j)^0.5 (Table 4 prints it so, and only then
     F = c_h H A of Eq. 42 and the force is continuous at delta_n2).
   - onset of full plasticity, review Eq. 44:
       delta_n2 = c_A lambda/(1+lambda^2) E/(K (1-e^2)^1/2) delta_n1
                = c_A rho delta_n1,  rho = Rc beta / (2 (R_i R_j)^1/2),
     i.e. the truncation area at delta_n2 is c_A times the Hertz area at
     delta_n1 (rho = Hertz area / truncation area at one overlap). It thus
     follows from Eqs. 2 and 42, not from Eqs. 1, 41 and 43 as the text
     says. lambda/(1+lambda^2) = Rc/(R_i R_j)^1/2 is the same for lambda^2 =
     R_i/R_j or R_j/R_i, so the review's ratio convention does not matter.
     rho = 1/2 for a circle (delta_n2 = c_A/2 delta_n1), 0.4982 at
     R_minor/R_major = 0.6, 0.4905 at 0.3 (the review's Fig. 8: "nearly 0.5
     for 0.6 to 1"), 0.422 at 0.01, 0.238 at 1e-12. Where Eq. 44 gives
     delta_n2 < delta_n1 (c_A rho < 1) there is no elastic-plastic range:
     delta_n2 is set to delta_n1 and the force jumps there (below).
   - elastic-plastic, delta_n1 < delta < delta_n2, review Eqs. 45-46:
       A = Ae + (Ap - Ae) (3 t^2 - 2 t^3),  t = (delta - delta_n1)/(delta_n2 - delta_n1),
       p = c_h H - (c_h - 2/3 K_v) H ln(delta_n2/delta)/ln(delta_n2/delta_n1),
       F = A p,
     with Ae, Ap the Hertz and truncation areas at delta. Evaluated as
     p = 2/3 K_v H + (c_h - 2/3 K_v) H ln(delta/delta_n1)/ln(delta_n2/delta_n1)
     with both logarithms as log1p of an exact difference over delta_n1:
     logarithms of ratios, so overlaps of any size keep full precision (no
     difference of two logarithms of tiny overlaps), full precision next to
     delta_n1, and t = 1, p = c_h H exactly at delta_n2.
   Continuity: F and A are continuous at delta_n1 (A = Ae, mean pressure
   2/3 K_v H = the Hertz mean pressure at first yield) and at delta_n2
   (A = Ap, p = c_h H), to rounding (test_jamari_ep: a few ulps). The slope
   is not continuous in general: at delta_n1 dF/d delta goes from 3/2 F/delta
   (Hertz) to (1 + kappa) F/delta, kappa = (c_h - 2/3 K_v)/(2/3 K_v
   ln(delta_n2/delta_n1)) (equal only for kappa = 1/2; defaults, nu = 0.3,
   sphere: kappa = 0.40); at delta_n2 from (1 + (c_h - 2/3 K_v)/(c_h
   ln(delta_n2/delta_n1))) F/delta to F/delta (equal only for c_h = 2/3 K_v).
   For kappa > 1/2 (defaults, sphere: nu < 0.114) the elastic-plastic curve rises
   above the Hertz curve just after yield. delta_n1 == delta_n2 (c_A rho <= 1):
   F jumps at delta_n1 from the Hertz value to c_h H Ap; no quotient by
   delta_n2 - delta_n1 or its logarithm is formed then.

   Contact ellipse: A is the law's; the semi-axes keep the Hertz shape
   b/a = (1-e^2)^1/2 (a = (A/(pi (1-e^2)^1/2))^1/2), so that a, b are
   continuous everywhere, the unloading branch included. (The truncation
   ellipse of Eq. 42 has b/a = (R_minor/R_major)^1/2; the review gives no
   shape for the elastic-plastic range.)

   Unloading and reloading (derived here): from the largest overlap
   delta_max > delta_n1 reached on the loading curve, with F_max, A_max the
   loading force and area there, the contact unloads elastically as a Hertz
   contact of the same ellipse shape whose radii are both enlarged by s >= 1
   (flattening), shifted by the residual overlap delta_res:
       F = 4/3 E* (s R_force)^1/2 (delta - delta_res)^3/2
         = F_max ((delta - delta_res)/(delta_max - delta_res))^3/2,
       A = A_max (delta - delta_res)/(delta_max - delta_res).
   F is continuous with the loading force at delta_max. The recovery u =
   delta_max - delta_res follows from the contact patch (Thornton & Ning
   1998 for spheres; Etsion, Kligerman & Kadin 2005 find the same elastic
   unloading of the plastically flattened patch): the Hertz contact of the
   shape above with radii s_A R that has the area A_max and carries the
   elastic part of the force, F* = min(F_max, F_Hertz(delta_max)):
       A_max = pi s_A R_area u,  F* = 4/3 E* (s_A R_force)^1/2 u^3/2,
   so that (eliminating s_A) u = F* / (4/3 E* R_force^1/2 (A_max/(pi R_area))^1/2),
   or with phi = F_max/F_Hertz(delta_max), alpha = A_max/A_Hertz(delta_max):
       delta_res = delta_max (1 - min(phi, 1)/alpha^1/2).
   For phi <= 1 its stiffness at delta_max, pi a E* / K(e), is that of an
   elliptic patch of area A_max. s follows from F_max = 4/3 E* (s R_force)^1/2
   u^3/2: s = alpha^3/2/phi for phi <= 1, phi^2 alpha^3/2 for phi > 1, so
   s >= 1 always (the surfaces are flattened, never sharpened). phi > 1 (the
   loading curve above the Hertz curve, possible for kappa > 1/2) counts the
   excess over the Hertz force as elastic. Limits: delta_max -> delta_n1
   gives alpha, phi -> 1, u -> delta_max, delta_res -> 0, s -> 1: the Hertz
   curve, continuously; delta_res > 0 for every delta_max > delta_n1, since
   alpha > 1 there, in doubles too (it is formed as a product: first order
   in delta_max/delta_n1 - 1 for phi < 1, second order for phi >= 1, e.g.
   1e-16 delta_max at 1e-6 above delta_n1); for a sphere u is Thornton & Ning's
   a_p^2/R_p with a_p from Eq. 46 or 42; fully plastic, delta_max >>
   delta_n2: phi -> 0 and delta_res/delta_max -> 1.
   The branch is capped by the loading curve: F = min(F_branch,
   F_load(delta)) (kn from the active one), so an unloading or reloading
   state never carries more force than loading did at the same overlap,
   and the energy dissipated by a load-unload cycle, int F_load - int
   F_unload, is >= 0 for every parameter set. The cap acts only where
   Eqs. 45-46 rise faster than the elastic branch (kappa > 1/2, delta_n2
   close to delta_n1, slender ellipses); with the defaults (c_h = 1, c_A =
   108, K_v from nu) it acts for nu below about 0.1: for a sphere wherever
   kappa > 1/2 (nu < 0.114), on branches from delta_max just above
   delta_n1 (nu = 0.11: from 1.01 delta_n1, not from 1.1); a scan of
   branches from delta_max up to 1e4 delta_n1 (test_jamari_ep) finds it up
   to nu = 0.095 for spheres, 0.11 at R_minor/R_major = 0.1, 0.17 at 1e-4,
   0.31 at 1e-6, every nu at 1e-9, and never for nu >= 0.2 down to 1e-4.
   The branch is a function of delta and the history alone: reloading
   retraces it bit for bit up to delta_max and then follows the loading
   curve, which raises delta_max. delta <= delta_res: F = 0, formed = 0.

   Geometry that changes between steps (superquadrics): the loading curve
   uses this step's geometry, the unloading branch the stored delta_max,
   delta_res, F_max, A_max (the cap and the semi-axes this step's geometry);
   a step on the loading curve with delta <= delta_n1 clears the history. */
#ifndef DC_JAMARI_EP_H
#define DC_JAMARI_EP_H

#include <float.h>
#include <stddef.h>
#include "dc/contract.h"
#include "dc/hertz_elliptic.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Material parameters of a type pair (deck property names in quotes).
   Defaults: none for H; K_v from Chang, Etsion & Bogy (J. Tribol. 109
   (1987) 257) with nu of the softer body; c_h = 1 and c_A = 108, the
   circular limit of Zhao, Maietta & Chang (J. Tribol. 122 (2000) 86),
   whose elastic-plastic law Jamari & Schipper extend to ellipses: mean
   pressure H at full plasticity, delta_n2 = 54 delta_n1 for spheres (Eq. 44
   with rho = 1/2). The review prints no values for c_h, c_A. */
typedef struct {
  double H;    /* "hardness" [Pa]: hardness of the softer body, > 0 */
  double K_v;  /* "plasticityKv" [-]: maximum pressure at first yield over H,
                  > 0; default 0.454 + 0.41 nu */
  double c_h;  /* "plasticityCh" [-]: mean pressure at full plasticity over H,
                  >= 2/3 K_v (the mean pressure rises from 2/3 K_v H); default 1 */
  double c_A;  /* "plasticityCa" [-]: truncation area at delta_n2 over Hertz
                  area at delta_n1, >= 2 (delta_n2 >= delta_n1 for a circle);
                  default 108 */
} dc_jamari_params;

#define DC_JAMARI_CH_DEFAULT 1.0
#define DC_JAMARI_CA_DEFAULT 108.0

/* K_v of Chang, Etsion & Bogy for Poisson's ratio nu of the softer body. */
static inline double dc_jamari_kv_default(double nu) { return 0.454 + 0.41 * nu; }

/* The defaults above for hardness H and Poisson's ratio nu. */
static inline dc_jamari_params dc_jamari_defaults(double H, double nu)
{
  dc_jamari_params p = {H, dc_jamari_kv_default(nu), DC_JAMARI_CH_DEFAULT, DC_JAMARI_CA_DEFAULT};
  return p;
}

/* delta_n1 / R of a circular contact of effective radius R (Rc = R/2):
   (pi K_v H / (2 E*))^2, Eq. 41 with E = K = pi/2. For a wrapper's elastic
   fast path (inputs as dc_jamari_onsets; unchecked). Never NaN there:
   within a few ulps wherever the value is a normal number, +inf where it
   overflows (no yield within the doubles), 0 where it underflows. Where
   pi/2 K_v or pi/2 K_v H leaves the normal range, the mantissas are
   multiplied and the exponents summed (it gave inf or lost digits). */
static inline double dc_jamari_circle_yield_ratio(double Estar, const dc_jamari_params *p)
{
  const double a = 1.5707963267948966 * p->K_v, b = a * p->H;
  double q = b / Estar;
  if (!(a >= DBL_MIN && b >= DBL_MIN && b <= DBL_MAX)) {
    int ek, eh, ee;
    const double mk = frexp(p->K_v, &ek), mh = frexp(p->H, &eh), me = frexp(Estar, &ee);
    q = ldexp(1.5707963267948966 * mk * mh / me, ek + eh - ee);
  }
  return q * q;
}

/* Parameter check (dc/contract.h), in the order hardness (0, inf),
   plasticityKv (0, inf), plasticityCh [2/3 plasticityKv, inf), plasticityCa
   [2, inf), all finite, and hardness at most DBL_MAX / max(plasticityKv,
   plasticityCh) (the yield pressures K_v H and c_h H are doubles): DC_OK,
   or DC_EDOM with err naming the first bad one. */
int dc_jamari_check(const dc_jamari_params *p, dc_param_error *err);

/* Per-contact history: plain doubles, all zero at the start (no plastic
   memory); written only on the loading curve beyond delta_n1. */
typedef struct {
  double delta_max;  /* largest overlap reached beyond delta_n1 [m]; 0: none */
  double delta_res;  /* residual overlap of the unloading branch [m] */
  double F_max;      /* loading force at delta_max [N] */
  double area_max;   /* loading area at delta_max [m^2] */
} dc_jamari_state;

/* Its field table (dc/contract.h), in struct order ("jamari_delta_max",
   "jamari_delta_res", "jamari_F_max", "jamari_area_max"; none flips): a
   wrapper registers DC_JAMARI_HISTORY_NFIELDS doubles and views them as a
   dc_jamari_state. */
enum { DC_JAMARI_HISTORY_NFIELDS = (int)(sizeof(dc_jamari_state) / sizeof(double)) };
extern const dc_history_field dc_jamari_history[DC_JAMARI_HISTORY_NFIELDS];

/* Inputs of every function below: g from dc_hertz_geometry; E* > 0
   finite; p passing dc_jamari_check (else DC_EDOM); delta finite (else
   DC_EDOM). DC_ERANGE when a result overflows, when delta_n1 underflows
   below DBL_MIN for an overlap beyond it, or when one of K_v H, c_h H
   overflows; on any error the outputs (and the history) are untouched. */

/* delta_n1 (Eq. 41) and delta_n2 (Eq. 44, raised to delta_n1 where it is
   smaller); DC_ERANGE when one leaves the normal range (the loading curve
   then is elastic for every finite overlap if delta_n1 overflows). */
int dc_jamari_onsets(const dc_hertz_geom *g, double Estar, const dc_jamari_params *p,
                     double *delta_n1, double *delta_n2);

/* The loading curve at overlap delta (Eqs. 1-2, 45-46, 42-43): force,
   tangent stiffness dF/d delta (at delta_n1 the Hertz slope, at delta_n2 the
   fully plastic one),
   area, semi-axes, F_bound = F; delta <= 0 gives zeros and formed = 0;
   delta <= delta_n1 is dc_hertz_normal exactly. */
int dc_jamari_loading(const dc_hertz_geom *g, double Estar, const dc_jamari_params *p, double delta,
                      dc_contact *c);

/* One step of one contact (the DEM call): the loading curve where delta >=
   h->delta_max, else the unloading branch (above); updates h on the loading
   curve. h: all zero or left by earlier calls; any finite content is safe
   (a history without 0 <= delta_res < delta_max, F_max > 0, area_max > 0
   counts as no memory), a non-finite field is DC_EDOM. No allocation; no
   elliptic integrals (they come with g); beyond delta_n1 two logarithms and an
   expm1 at most. */
int dc_jamari_step(const dc_hertz_geom *g, double Estar, const dc_jamari_params *p, double delta,
                   dc_jamari_state *h, dc_contact *c);

#ifdef __cplusplus
}
#endif
#endif
