/* Greenwood-Williamson rough contact with elastic, elastic-plastic and
   fully plastic summits: Jeng & Wang (J. Tribol. 125 (2003) 232, "JW"),
   review Eqs. 47-53 and Table 4 ("elastic-plastic or fully plastic
   regime", non-smooth); JW write the Zhao, Maietta & Chang transition
   (J. Tribol. 122 (2000) 86, "ZMC") for elliptic summits.

   Summit law: one summit pressed by omega >= 0, with the elliptic Hertz
   geometry of dc_hertz_geom (Rc, gamma, beta of review Eqs. 5, 11-12;
   R_force = Rc gamma^2, R_area = Rc beta; for a sphere both are R):
     elastic          omega < w1:  f = 4/3 E* R_force^1/2 omega^3/2,
                                   A = pi R_area omega           (Eqs. 1-2)
     elastic-plastic  w1 <= omega <= w2, x = (omega - w1)/(w2 - w1):
                      A = pi R_area omega [1 + (lambda - 1)(3x^2 - 2x^3)]
                      f = A H [c_h - (c_h - 2K_v/3) ln(w2/omega)/ln(w2/w1)]
     fully plastic    omega > w2:  A = lambda pi R_area omega,  f = c_h H A
   w1 = (pi K_v H/(2 E*))^2 R_area^2/R_force: yield where the summit's
        largest Hertz pressure reaches K_v H (review Eq. 41, both printed
        forms); its mean pressure is then 2/3 K_v H, so f is continuous;
   w2 = (c_A/lambda) w1: the fully plastic area at w2 is c_A times the
        Hertz area at w1 (dc/jamari_ep.h's reading of review Eq. 44);
        c_A = 108 gives ZMC's w2 = 54 w1 for circles (full plasticity at
        ~400 times the yield load). Where c_A <= lambda, w2 = w1: no
        elastic-plastic range, f jumps at w1 (kn then holds the jump's
        point mass, below);
   lambda: fully plastic over elastic area at equal compression, 2 for
        circular summits (ZMC: 2 pi R omega); for elliptic ones
        - DC_GW_PLASTIC_AREA_JW (default): lambda = 4 eps/beta (Eqs. 47-49)
          = K/(K - D) = K/B with the geometry's elliptic integrals: JW's
          plastic ellipse keeps the Hertz aspect ratio, 4 eps Rc omega =
          2 R_minor (a/b) omega (with the exact eccentricity relation);
        - DC_GW_PLASTIC_AREA_TRUNCATED: the truncated paraboloid, review
          Eq. 42: lambda = 2 (R_major R_minor)^1/2 / R_area.
        lambda is 2 for circles; from 2 up to 16.6 (JW) and 4.2
        (truncation) at R_minor/R_major = 1e-12; >= 1 always.
   JW and ZMC take c_h = 1 (fully plastic mean pressure = hardness) and
   write K for 2K_v/3 (the mean pressure at yield over H).
   Properties of the summit law (tested): f and A are continuous at w1 and
   w2 and nondecreasing in omega (lambda >= 1 and c_h >= 2K_v/3 are
   required); df/d omega jumps at both: at w1 by the factor
   2/3 (1 + (c_h/(2K_v/3) - 1)/ln(w2/w1)) (0.934 for K_v = 0.577, c_h = 1,
   w2/w1 = 54), at w2 by 1/(1 + (1 - 2K_v/(3c_h))/ln(w2/w1)) (0.866).
   Where the factor at w1 exceeds 1 (slender summits: w2/w1 = c_A/lambda
   small) the elastic-plastic summit carries more than Hertz just past
   w1; spheres with the defaults stay below Hertz.

   Rough contact (review Eqs. 29, 33-34 with gamma*, beta* of Eqs. 47-48,
   corrected): s the standardised summit height, phi its standard normal
   density, h = -delta/sigma, u = omega/sigma = s - h:
     F  = n_asp int f(delta + sigma s) phi(s) ds = n_asp (P_E J_e + P_H J_p)
     A  = n_asp pi R_area sigma J_A
     kn = dF/d delta = n_asp (2 E* R_force^1/2 sigma^1/2 J_e12 + pi R_area H J_dp)
   P_E = 4/3 E* R_force^1/2 sigma^3/2 (gw_rough's factor), P_H = pi R_area
   sigma H, and the summit integrals over u >= 0 with weight phi(u + h),
   a = w1/sigma, b = w2/sigma (dc_gw_plastic_integrals):
     J_e = int_0^a u^3/2,  J_e12 = int_0^a u^1/2                 (elastic)
     J_p = int_a^b u A(x) P(u) + lambda c_h int_b^oo u            (plastic)
     J_dp = int_a^b (u A P)' + lambda c_h int_b^oo 1 [+ (lambda c_h - 2K_v/3) a phi(h + a) if b = a]
     J_A = int_0^a u + int_a^b u A(x) + lambda int_b^oo u
   A(x) = 1 + (lambda-1)(3x^2-2x^3), P(u) = c_h - (c_h - 2K_v/3) ln(b/u)/ln(b/a).
   In the review's notation (Eqs. 33-34) gamma* = gamma J_e + (3 pi beta
   H/(4 E*)) (Rc/sigma)^1/2 J_p and beta* = beta J_A (the corrected
   Eq. 47 is checked against F by the generator).
   All-elastic limit: where phi over the yielded summits (u > a) stays
   below e^-60 of its largest value (h + a > (max(h,0)^2 + 120)^1/2),
   J_e = F_3/2(h), J_e12 = F_1/2(h), J_A = F_1(h), J_p = J_dp = 0 and F,
   kn, A are bit for bit those of dc_gw_rough_elliptic (same expressions;
   tested); H -> oo reaches it for every delta. sigma = 0 (or sigma <=
   1e-80 |delta|): n_asp times the summit law at delta (below w1 through
   dc_hertz_contact, exactly as gw_rough).
   Rough flat (GW's nominal pressure): spherical summits of radius R_s,
   eta summits per unit area: p = eta (P_E J_e + P_H J_p) with R_force =
   R_area = R_s, lambda = 2 (dc_gw_plastic_flat).
   F and A are continuous and nondecreasing in delta (tested).

   Evaluation of the integrals: the plastic tail beyond b in closed form,
   int_b^oo u phi = F_1(h+b) + b F_0(h+b), int_b^oo phi = F_0(h+b)
   (dc/gw_integrals.h, the rounding of h + b corrected); the elastic and
   elastic-plastic regimes by 10-point Gauss-Legendre panels over each
   regime's Gaussian window (phi above e^-45 of its largest value on the
   regime), panel widths in s shrinking with |s| and growing where phi is
   small, at most doubling from u = 0 (u^1/2, ln u); the first elastic
   panel in u = p tau^2 (u^3/2, u^1/2 polynomial). A regime whose largest
   phi is below e^-60 of the largest over all summits is skipped (adds
   < 1e-21 of F). Error against mpmath (tests/unit/test_gw_rough_plastic.c,
   198 integral rows, h from -1e4 to 35, a from 1e-4 to 100, w2/w1 from 1
   to 1000): the F and kn combinations 1e-15, each integral 2e-15 relative
   to itself where it carries more than 1e-20 of its sum; the rough
   contact 3e-15. Cost (test_gw_rough_plastic prints it): no panels where
   the window lies in one closed-form regime (all elastic or all fully
   plastic: 1.1 times dc_gw_rough_elliptic); 9-11 panels for h in (-3, 3]
   when the regimes meet there (8-9 times dc_gw_rough_elliptic, 1.6-1.8 us
   measured on a loaded machine; exp and log take a third). Not tabulated: the integrals depend on h, a, w2/w1,
   lambda, 2K_v/3 and c_h (a per contact for polydisperse spheres, lambda
   and w2/w1 per contact for ellipsoids), too many for a fitted table.

   Loading only: this is the loading curve (delta increasing). A summit
   unloads elastically from its largest compression with a residual
   interference (for spheres Etsion, Kligerman & Kadin, J. Tribol. 127
   (2005) 456); with delta_max kept per contact every summit's largest
   compression is delta_max + sigma s, so an unloading branch needs only
   that one history value plus an unloading law for elliptic summits, which
   the seeds do not give: not implemented.

   Seed errors found (review, OCR text), each checked by continuity of the
   summit law and against mpmath quadrature of the corrected integrals:
   - Eq. 47, third term: (3 pi H/E)(Rc/sigma)^1/2 int (z - h) phi lacks the
     factor eps: the fully plastic summit force must be 4 eps pi Rc omega H,
     the x = 1 end of the second term's area; as printed f jumps at w2 by
     the factor eps unless eps = 1 (circles); measured in the generator:
     1.734 = eps for R_minor/R_major = 0.2.
   - Eq. 48, last term: the lower limit is h + delta_n2*, not
     h + delta_n1* (as printed the elastic-plastic summits count twice).
   - Eq. 47's bracket 1 - (1 - K)(...) gives the mean pressure K H at w1,
     while the elastic summit's mean pressure at yield (Eq. 41, largest
     pressure K_v H) is 2/3 K_v H; with K = K_v as the text names it
     ("maximum contact pressure factor") the force jumps by 3/2 at w1.
     Consistent: K -> 2K_v/3 (Eq. 45's form), as used here.
   - Eq. 47's log argument, ln delta_n2* - ln(2 eps) - ln(2 Rc) -
     2 ln delta* + ln(a_l* b_l*), mixes ln Rc with scaled lengths; with Rc
     read as Rc/sigma and a_l b_l from Eqs. 50-52 the bracket's ratio is
     [ln(w2/w) + ln(C/2)]/[ln(w2/w1) + ln(vs/2)] (vs = varsigma of Eq. 52).
     Eqs. 49 and 52 satisfy 2 eps vs = beta identically, so Eq. 50 at w1
     is the Hertz a b = Rc beta w1 and the ratio is 1 at w1 for any k_l;
     it is 0 at w2 only if C(w2) = 2, i.e. 2t^2 + k_l(2 - vs)t - 2 = 0 with
     t = w1/w2 (k_l = 107.96 for circles and w2 = 54 w1), else f jumps at w2.
     k_l is given nowhere in the seeds. Implemented: the plastic ellipse
     a_l b_l = 4 eps Rc omega (C = 2), which turns the bracket into ZMC's
     ln(w2/omega)/ln(w2/w1) (Eq. 45's form) and keeps f continuous.
   - Eq. 53: the truncated Taylor series of phi (through z^8) diverges
     from phi beyond |z| ~ 2 (at z = 4 it gives 110/sqrt(2 pi) for
     e^-8/sqrt(2 pi)), and the integrals reach |z| ~ 9: not used.
   - Eq. 49 (eps) and Eq. 52 (varsigma) are consistent as printed (above).
   Hot path: no allocation. */
#ifndef DC_GW_ROUGH_PLASTIC_H
#define DC_GW_ROUGH_PLASTIC_H

#include "dc/contract.h"
#include "dc/gw_rough.h"
#include "dc/hertz_elliptic.h"

#ifdef __cplusplus
extern "C" {
#endif

/* How the fully plastic area of an elliptic summit is taken (above). */
enum { DC_GW_PLASTIC_AREA_JW = 0, DC_GW_PLASTIC_AREA_TRUNCATED = 1 };

/* Material parameters of a type pair; deck property names in quotes, the
   names and meanings of dc/jamari_ep.h (the smooth law). */
typedef struct {
  double hardness;  /* "hardness" H [Pa] of the softer body, > 0 */
  double K_v;       /* "plasticityKv" [-]: a summit yields when its largest
                       pressure reaches K_v H; > 0, default 0.454 + 0.41 nu
                       (Chang, Etsion & Bogy 1987) */
  double c_h;       /* "plasticityCh" [-]: fully plastic mean pressure c_h H;
                       >= 2 K_v/3, default 1 (JW, ZMC) */
  double c_A;       /* "plasticityCa" [-]: a summit's fully plastic area at w2
                       over its Hertz area at w1, w2 = (c_A/lambda) w1; >= 2,
                       default 108 (ZMC's w2 = 54 w1 for circles) */
  int plastic_area; /* DC_GW_PLASTIC_AREA_*, default JW (a setting) */
} dc_gw_plastic_params;

/* The defaults above for hardness H and Poisson's ratio nu of the
   softer body (unchecked). */
dc_gw_plastic_params dc_gw_plastic_default_params(double hardness, double nu);

/* Parameter check (dc/contract.h), in the order hardness (0, inf),
   plasticityKv (0, inf), plasticityCh [2/3 plasticityKv, inf), plasticityCa
   [2, inf), all finite, plastic_area one of the enum (reported as
   "plasticArea"). */
int dc_gw_plastic_check(const dc_gw_plastic_params *p, dc_param_error *err);

/* One summit's law bound to a geometry and a material (per contact). */
typedef struct {
  double w1, w2;      /* onset of yield and of full plasticity [m] (0: all
                         summits plastic; +inf: all elastic) */
  double ratio;       /* w2/w1 */
  double lambda;      /* plastic over elastic area, >= 1 */
  double Km, c_h;     /* 2 K_v/3 and c_h */
  double inv_log_ratio;  /* 1/ln(w2/w1) */
  double H, Estar;
  double R_force, R_area;
} dc_gw_plastic_summit;

/* Binds params (checked by dc_gw_plastic_check) to geometry g and Estar > 0
   (finite); DC_EDOM for a bad Estar or params. w1 may underflow to 0 (all
   summits fully plastic) or overflow to +inf (all elastic): both are the
   law's limits, not errors (K_v near DBL_MAX with H/E* underflowing to 0
   gives w1 = 0, not NaN); DC_ERANGE where w1 has no such limit. */
int dc_gw_plastic_summit_init(const dc_hertz_geom *g, double Estar, const dc_gw_plastic_params *p,
                              dc_gw_plastic_summit *s);

/* The summit law (above) at compression omega (finite; <= 0 gives zeros):
   force f [N], contact area [m^2], df/d omega [N/m] (at w1 and w2 that of
   the elastic-plastic branch, or of the plastic one when w2 = w1). DC_EDOM
   for non-finite omega; DC_ERANGE when a result overflows (outputs
   untouched). */
int dc_gw_plastic_summit_law(const dc_gw_plastic_summit *s, double omega, double *f, double *area,
                             double *df);

/* The non-dimensional summit law of the integrals. */
typedef struct {
  double a, b;          /* w1/sigma, w2/sigma */
  double lambda, Km, c_h;
} dc_gw_plastic_shape;

/* The summit integrals at h (above). */
typedef struct {
  double Je, Je12;      /* int_0^a u^3/2 phi, int_0^a u^1/2 phi */
  double Jp, Jdp;       /* plastic summits' force / P_H and its u-derivative */
  double JA;            /* area / (pi R_area sigma) */
  int n_panels;         /* Gauss-Legendre panels used (0: closed forms only) */
} dc_gw_plastic_sums;

/* Domain: 0 < a < b finite with b/a <= 1e6 (as computed by the caller),
   lambda >= 1, 0 < Km <= c_h, all finite; h finite, h >= DC_GW_H_MIN.
   DC_EDOM otherwise, DC_ERANGE where a sum overflows (lambda or c_h near
   the largest doubles); J untouched on both. */
int dc_gw_plastic_integrals(const dc_gw_plastic_shape *sh, double h, dc_gw_plastic_sums *J);

/* The rough contact of two bodies with geometry g (elliptic or circular),
   the gw_rough law with these summits: F, A, kn as above, h = -delta/sigma.
   Domain as dc_gw_rough_elliptic (Estar > 0, n_asp > 0, sigma >= 0, all
   finite, delta finite) and params passing dc_gw_plastic_check; DC_EDOM
   otherwise, DC_ERANGE when F, kn or the area overflows; the state is
   written only on DC_OK. The contract output:
   dc_gw_rough_normal (dc/gw_rough.h) with this F and kn. */
int dc_gw_rough_plastic(const dc_hertz_geom *g, double Estar, const dc_gw_plastic_params *p,
                        double n_asp, double sigma, double delta, dc_gw_rough_state *s);

/* A rough flat pressed on a smooth rigid flat (GW): spherical summits of
   radius R_s > 0, eta > 0 summits per m^2, rms summit height sigma > 0,
   delta = -d the compression of the summits' mean plane (d: GW's
   separation). */
typedef struct {
  double p;          /* nominal pressure [Pa] */
  double area_ratio; /* real over nominal area [-] */
  double dp;         /* dp/d delta [Pa/m] */
  double h;          /* d/sigma */
} dc_gw_plastic_flat_state;

/* Domain: params passing dc_gw_plastic_check, Estar, R_s, eta, sigma > 0
   and finite, delta finite with -delta/sigma >= DC_GW_H_MIN; DC_EDOM
   otherwise, DC_ERANGE as dc_gw_rough_plastic or where h = d/sigma
   overflows. */
int dc_gw_plastic_flat(const dc_gw_plastic_params *p, double Estar, double R_s, double eta,
                       double sigma, double delta, dc_gw_plastic_flat_state *st);

#ifdef __cplusplus
}
#endif
#endif
