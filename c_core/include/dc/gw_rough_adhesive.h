/* Greenwood-Williamson rough contact with adhesive (JKR) summits: review
   Eq. 29 and Table 4 "non-smooth, GW, adhesive", implemented as the
   Fuller & Tabor (Proc. R. Soc. A 345 (1975) 327) construction with the
   summit law of dc/jkr_elliptic.h (Johnson-Greenwood elliptic JKR,
   classical JKR when circular):

     F  = n_asp int_{s0}^oo f(delta + sigma s) phi(s) ds          (Eq. 29)
     A  = n_asp int_{s0}^oo A_s(delta + sigma s) phi(s) ds        (Eq. 30)
     kn = dF/d delta = n_asp [int f'(u) phi ds + f(u0) phi(s0)/sigma]
     s0 = (u0 - delta)/sigma,   h = -delta/sigma

   phi the standard normal density, s = z/sigma the standardised summit
   height, u = delta + sigma s the compression of a summit (the review's
   z_s - d), f(u) and A_s(u) = pi a b the force and contact area of one
   summit on the stable JKR branch (dc_jkr_contact with the caller's
   dc_jkr_geom: relative radii, Estar and work of adhesion w). As in
   dc/gw_rough.h the summits carry the body-scale relative radii (the review
   puts Rc where GW have the summit radius) and n_asp absorbs the summit
   density; delta is the overlap of the nominal surfaces, > 0 in compression.

   Why not the review's literal recipe (gamma, beta of Eqs. 35-36 "from the
   JKR model"): gamma_JG and beta_JG (review Eqs. 27-28) are properties of
   one JKR contact state, i.e. of one summit compression, whereas the sum
   runs over summits at every compression; gamma_JG vanishes at zero load
   and F_3/2(h) only counts summits with u > 0, so the substitution has no
   defined value for a separated nominal contact and no tensile summits.
   Eq. 29 with f = the JKR summit law is well defined for every delta.

   Which summits are attached, chosen by the caller:
   - DC_GW_LOADING: summits attach on touch, u0 = 0; a touching summit
     contributes the finite tensile JKR force f(0) (-4/3 pi w R for a
     sphere), so kn has the attachment term f(0) phi(s0)/sigma < 0.
   - DC_GW_UNLOADING: summits stay attached down to the separation point of
     the summit law, u0 = delta_break < 0 (the dc_jkr_geom's), where f has
     a vertical tangent. This is the exact count on a monotonic separation
     from a largest overlap >= delta - delta_break (every summit above the
     lowest attached one then touched once); after a shallower approach
     the true force lies between the two branches.
   F(unloading) <= F(loading) at every delta: the unloading branch adds the
   summits with u in [delta_break, 0), and each of them pulls (f < 0
   there); its adhesive pull is the larger one.

   w -> 0: f -> the elliptic Hertz summit law and delta_break -> 0, so F, A
   and kn tend to the closed form of dc_gw_rough_elliptic with the
   geometry's dc_hertz_geom (review Eqs. 31-36). The adhesive parts are
   O(1/theta) in F and kn and O(theta^-1/2) in A (measured: (F/F_0 - 1)/w
   and (A/A_0 - 1)/w^1/2 tend to constants), theta = Estar sigma^3/2 /
   (w Rhat^1/2) the Fuller-Tabor adhesion parameter (without their
   numerical factor). With w = 0 the closed form is returned exactly.
   sigma = 0: n_asp times the summit law at delta (attached as above).

   Quadrature: in x = s - s0 >= 0, the height above the lowest attached
   summit, on panels with the 7-point Gauss / 15-point Kronrod pair (the
   value is the Kronrod sum). The Gaussian is cut where phi falls below
   e^-45 of its largest value on the range (the omitted tail is ~1e-17 of
   the total or less). With D = |delta_break|/sigma, the summit law's own length:
   - [0, x1], x1 = min(max(D/2, 1e-6), 1/2), in tau with x = x1 tau^2:
     the square root of f at the separation point (unloading) becomes a
     smooth function of tau;
   - then widths growing by 3 (x, 3x): these resolve f's complex branch
     points at |u - u0| ~ D (for a sphere at u = delta_break e^(+-2 pi i/3));
   - from 8 D to x = 2, panels in y = x^1/4, each 3 times the last in y:
     for u >> |delta_break| f is a smooth function of u^1/4 (JKR is a
     series in a^1/2 ~ u^1/4), so weak adhesion (D << 1) costs few panels;
   - widths are capped by phi: 3, and 8/s0 when s0 > 1 (phi decays like
     e^(-s0 x)); y panels by 1/(phi's slope).
   The summit law is solved at each node in increasing u, carrying the
   dc_jkr_hint from node to node. kn: circular summits from the contact
   radius, (dF/da)/(d delta/da); elliptic ones from dc_jkr_contact's kn,
   which is ~1e-9 relative (its Newton tolerance in e^2), and so is kn
   here. err: QUADPACK's qk15 estimate per panel, resasc min(1, (200
   |Kronrod - Gauss| / resasc)^1.5), summed: pessimistic (the table errors
   are below 1e-5 of it). Measured against mpmath
   (tests/unit/test_gw_rough_adhesive.c): F within 3e-15 of
   n_asp int |f| phi ds, A within 4e-15 relative.
   Cost: 60 to 230 summit evaluations (4 to 15 panels, most near 100);
   ns per call in tests/bench/bench_gw.c. */
#ifndef DC_GW_ROUGH_ADHESIVE_H
#define DC_GW_ROUGH_ADHESIVE_H

#include "dc/jkr_elliptic.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Which summits are attached (see above). */
enum { DC_GW_LOADING = 0, DC_GW_UNLOADING = 1 };

typedef struct {
  double F;      /* normal force [N], > 0 repulsive, < 0 adhesive */
  double area;   /* real contact area, sum of summit areas [m^2] */
  double kn;     /* dF/d delta [N/m] */
  double h;      /* -delta/sigma (+-1e300 for sigma = 0) */
  double err;    /* error estimate of F [N] (0 for w = 0 or sigma = 0) */
  int n_eval;    /* summit-law evaluations used */
} dc_gw_adhesive_state;

/* The rough adhesive contact for overlap delta of the nominal surfaces.
   g: from dc_jkr_geometry (summit radii, Estar, w), computed once per
   contact. Domain: n_asp > 0, sigma >= 0, delta, all finite; branch
   DC_GW_LOADING or DC_GW_UNLOADING; else DC_EDOM (state untouched).
   DC_ENOCONV if a summit solve did not converge (state filled).
   DC_ERANGE, state untouched, when F, kn, the area or a summit state
   overflows (a summit's compression delta + sigma s included). */
int dc_gw_rough_adhesive(const dc_jkr_geom *g, double n_asp, double sigma, double delta,
                         int branch, dc_gw_adhesive_state *s);

#ifdef __cplusplus
}
#endif
#endif
