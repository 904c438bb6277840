/* Rough contact with adhesive (JKR) summits, tabulated: the adhesive part
   of dc/gw_rough_adhesive.h (review Eq. 29, Fuller-Tabor construction) for
   circular summits at DEM cost, to be added to the elastic GW force.

   Reduced variables. For circular summits of radius R the summit law is
   f(u) = F_s fbar(u/delta_c) with fbar a pure function (classical JKR:
   fbar = 4/(3 pi) A^3 - A^3/2, u/delta_c = 2 A^2 - pi A^1/2, A = a/a_s),
     F_s = 8 w R,  a_s = (8 w R^2/(pi E*))^1/3,  delta_c = a_s^2/(2R),
   so with u = delta + sigma s = sigma (s - h) the adhesive part
     F_adh = F - F_gw = n_asp F_s G_b(h, tau),
     G_b(h, tau) = int_{s0}^oo [fbar - fbar_Hertz](tau (s - h)) phi(s) ds
                   (+ the pulling summits below touch, fbar alone)
   depends only on h = -delta/sigma, tau = sigma/delta_c (the summits'
   adhesion parameter: theta = E* sigma^3/2/(w R^1/2) = (2 sqrt2/pi)
   tau^3/2, the Fuller-Tabor parameter without their factor) and the
   branch b (loading / unloading). E*, w, R, sigma, n_asp enter only through
   F_s, delta_c and tau. F_gw is the closed form of dc_gw_rough_elliptic
   (review Eqs. 31-36) for the same n_asp and sigma. For elliptic summits
   the summit law also depends on R_minor/R_major: no equivalent circle
   stands in for it (the table at R = (R_major R_minor)^1/2 is 2.6e-2 from
   the elliptic law's adhesive part at a ratio of 0.5, 0.27 at 0.1;
   tests/reference/gwa_elliptic_factor.c), so elliptic summits take the
   circular table at matched scales times a correction tabulated in the
   ratio ("Elliptic summits" below).
   G < 0 everywhere (every attached summit pulls more than its Hertz
   counterpart; checked at every node by the generator). Deep in
   compression G -> -pi/8 (f_JKR - f_Hertz -> -pi w R), with a u^-3/4 tail.

   Table (c_core/src/gw_rough_adhesive_table_data.h, written by
   tests/reference/gen_gw_rough_adhesive_table.c from the c_core law):
   L = ln(-T) at nodes with its first and cross derivatives, bicubic
   Hermite, so L, and the force, is C1 in delta and in tau. T = G for
   loading; for unloading see the kink term below. x = h (loading) or
   x = h - D (unloading; D = -delta_break/sigma, x is then the height s0 of
   the lowest attached summit). eta = ln tau rows 1/4 apart on [-4.5, 8]
   (theta 1.1e-3 to 1.5e5; above, the law's F - F_gw loses digits to the
   elastic part). Two regions in x, blended by a quintic step on
   [-6.5, -4.5]:
   - near, x in [-6.5, 8]: nodes 1/16 apart in x, rows at fixed x (the
     Gaussian of the lowest attached summits, whose features stay at fixed x);
   - deep, x in [-255, -4.5]: nodes 12 per unit of u = ln(-x) + eta =
     ln(-tau x), rows at fixed u. The summits' mean compression is
     -tau x (+ delta_break/delta_c unloading), so G varies with eta
     mostly through u; rows at fixed x, as the first version had them,
     resolve that variation only to ~5e-5 at small tau. Row j + 1 holds the
     node of the same u three places shallower.
   Unloading, the kink term: G's Hertz part (the closed form subtracted)
   is c_H tau^3/2 F_3/2(h), c_H = 4/(3 pi 2^3/2), whose summits' d^3/2
   kink sits at h ~ 0, i.e. on x = -D, a line across the grid (at small
   tau one eta row moves it by D/4 in x). Interpolated across, it gave
   errors up to 4.2e-3 at tau 0.01 to 0.5 (the first version; its stated
   3.8e-4 came from too sparse a sample). So the table holds
   T = G + C, C = c_H w(x) tau^3/2 [F_3/2(h) - s^3/2 F_3/2(h/s)],
   s^2 = 1 + K(eta) (B/tau)^2 (dc_gwa_table_kink), and C is subtracted
   again, exactly, after the interpolation: T keeps the kink smoothed over
   a width (tau^2 + K B^2)^1/2 in the compression, B = 1, which the grid
   resolves; F_3/2 is convex, so s^3/2 F_3/2(h/s) >= F_3/2(h) and
   T <= G < 0. w falls from 1 to 0 over x in [-2, 1] (C stays out of G's
   Gaussian tail) and K over eta in [0, 3] (tau > 20: no term, no cost).
   Beyond the table:
   - x > 8: L continued linearly (C1; G < 1e-15 there);
   - x < x_end = -255.1 (every summit pressed, the Gaussian 1/|x| of the mean
     compression d = delta/delta_c): G = g(d) + (G_end - g(d_end))
     (x_end/x)^11/4, g = fbar - fbar_Hertz of one summit (exact, from the
     JKR contact radius; the correction is the tau^2 g''/2 term's decay),
     matched in value at x_end (the slope to ~1e-7);
   - eta outside its range is clamped (theta > 1.5e5: the adhesive part is
     below ~1e-5 of the elastic one; theta < 1.1e-3: not covered, the
     error is not stated there).

   History (dc_gwa_table_history): gwa_touched (0 / 1) and gwa_delta_max
   (the largest overlap reached [m]). Loading branch while delta >= the
   largest overlap; the unloading branch once delta <= delta_max +
   delta_break (every summit that ever touched and is above the separation
   point is attached: the exact count of dc/gw_rough_adhesive.h); between
   the two (the partly attached band, D sigma wide, D = |delta_break|/sigma
   = 1.725/tau) F = F_L + w (F_U - F_L) with w the Gaussian fraction of the
   summits the unloading branch counts (heights h - D to h) that touched
   (above h_min = -delta_max/sigma): w = P(h_min < S < h)/P(h - D < S < h).
   It is exact where the summits' tensile force is the same at every
   stretch (it varies between -0.33 and -0.59 F_s): against the exact
   force of the attached summits (F_L plus their integral) within 0.055 of
   |F_U - F_L| at tau 0.08 to 36 (the smoothstep in xi = (delta_max -
   delta)/|delta_break| of the first version was off by up to 0.97, and
   gave a contact that only grazed, at h = 12 and back at 12.5, a pull of
   9e-4 n_asp 8 w R). Like the truth, the force has a kink where loading
   turns to unloading. The history resets (next step loads afresh) when
   the lowest attached summit is beyond x = 8 (force below 3.3e-16 n_asp
   8 w R); a contact that has not touched starts at h = X_CUT = 8
   (dc_gwa_table_apart).
   Work of adhesion 0: force and stiffness exactly 0.
   Error against the exact law (tests/unit/test_gw_rough_adhesive_table.c:
   every cell of the table, 4 points per eta cell, 60 per x band, and 1500
   random points in physical units): relative, where |F| >= 1e-6 n_asp 8 w R,
   loading 3.1e-7 in the table, 1.5e-6 beyond it (x < x_end), dF/d delta
   6.7e-7; unloading 2.5e-5, dF/d delta 2.9e-5 (worst at tau 0.2 to 1, x in
   -5..-2, where the kink crosses the near region; elsewhere mostly below
   5e-6); absolute below 1.9e-12 n_asp 8 w R. Pull-off force within 4.8e-6.
   Cost (the unit test, one core): 31 ns per dc_gwa_table_step_radius at
   tau > 20, 62 ns at tau ~ 5 (the kink term on unloading: two
   dc_gw_F_all); setting the radius up at each call (dc_gwa_table_step)
   adds ~70 ns (cbrt, log). Exact law ~9.5 us. With the contact's record
   (dc_gwa_table_step_contact: the radius set up once per contact, and the
   cubic of the last cell kept) a settled contact's step reads that cubic:
   19 ns against 30 ns with the radius kept (unit test, tau 36, one
   cell). A settled contact (touched, wholly on one branch, in the near
   cell it kept, above the blend, no kink term) takes a short path
   without the set-up, inline in the caller (dc_gwa_table_step_settled
   below): in the monodisperse bench scene (callgrind, 10000 steps, tau ~
   36) 91 % of the steps; the wrapper's call with the step inline takes
   232 instructions on average (4.9 G over 21.1 M calls; 256 with the
   step out of line, of which the step 175 on average and 216 before
   the short path);
   polydisperse spheres: the record gave the whole run 17 % fewer
   instructions than with the radius set up and the cells formed at
   every step. The interpolation is in the cubic's
   powers of t and e^L is an inline polynomial (within 2 ulp of exp): the
   errors above are unchanged in their stated digits. */
#ifndef DC_GW_ROUGH_ADHESIVE_TABLE_H
#define DC_GW_ROUGH_ADHESIVE_TABLE_H

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>
#include "dc/contract.h"
#include "dc/gw_rough_adhesive.h"
#include "dc/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* near region: x in [X_LO, X_HI], X_PER_UNIT nodes per unit */
#define DC_GWA_TABLE_X_LO (-6.5)
#define DC_GWA_TABLE_X_HI 8.0
#define DC_GWA_TABLE_X_PER_UNIT 16
#define DC_GWA_TABLE_NNEAR 232          /* cells on [X_LO, X_HI] */
/* eta rows: ETA_LO + j / ETA_PER_UNIT, j < NETA (eta_hi = 8) */
#define DC_GWA_TABLE_ETA_LO (-4.5)
#define DC_GWA_TABLE_ETA_PER_UNIT 4
#define DC_GWA_TABLE_NETA 51
/* deep region: node k at x = X_B e^(k / U_PER_UNIT), K_MIN <= k <= K_MAX,
   stored at index k - K_MIN; U_PER_UNIT / ETA_PER_UNIT = 3 nodes per row
   (the shear of u = ln(-x) + eta); the table ends at k = K_END */
#define DC_GWA_TABLE_X_B (-6.0)
#define DC_GWA_TABLE_U_PER_UNIT 12
#define DC_GWA_TABLE_K_MIN (-7)
#define DC_GWA_TABLE_K_END 45
#define DC_GWA_TABLE_K_MAX 48
#define DC_GWA_TABLE_NDEEP (DC_GWA_TABLE_K_MAX - DC_GWA_TABLE_K_MIN + 1)
/* near and deep regions are blended on [BLEND_LO, BLEND_HI] */
#define DC_GWA_TABLE_BLEND_LO (-6.5)
#define DC_GWA_TABLE_BLEND_HI (-4.5)

/* x at near node i in [0, NNEAR] and at deep node k in [K_MIN, K_MAX] */
static inline double dc_gwa_table_x_near(int i)
{
  return DC_GWA_TABLE_X_LO + (double)i / DC_GWA_TABLE_X_PER_UNIT;
}
static inline double dc_gwa_table_x_deep(int k)
{
  return DC_GWA_TABLE_X_B * exp((double)k / DC_GWA_TABLE_U_PER_UNIT);
}

/* The unloading branch's smoothing of the summits' Hertz kink (header
   comment): C(x, eta) = c_H w(x) tau^3/2 [F_3/2(h) - s^3/2 F_3/2(h/s)],
   s^2 = 1 + K(eta) (B/tau)^2, c_H = 4/(3 pi 2^3/2); w and K quintic steps
   from 1 to 0 over [W_LO, W_HI] in x and [K_LO, K_HI] in eta. */
#define DC_GWA_KINK_B 1.0
#define DC_GWA_KINK_W_LO (-2.0)
#define DC_GWA_KINK_W_HI 1.0
#define DC_GWA_KINK_K_LO 0.0
#define DC_GWA_KINK_K_HI 3.0

/* C and dC/dx at (x, eta) (0 where K or w vanish); the generator adds it
   to the unloading branch's G before taking the logarithm. Finite for
   finite x and |eta| <= 50 (the step passes the table's eta). */
void dc_gwa_table_kink(double x, double eta, double *C, double *Cx);

/* One material (type) pair: E*, w, sigma, n_asp of dc_gw_rough_adhesive. */
typedef struct {
  double Estar, w, sigma, n_asp;
  double inv_sigma;
  double ln_sigma_dc;  /* ln(sigma / delta_c(R = 1 m)); eta = this - ln(R)/3 */
  double dc_coef;      /* delta_c = dc_coef R^1/3 */
  double F_coef;       /* n_asp F_s / R = 8 w n_asp */
  double ub;           /* delta_break / delta_c of the circular summit (< 0) */
} dc_gwa_table_pair;

/* Parameter check (dc/contract.h): workOfAdhesion w >= 0, roughness
   sigma > 0, asperityCount n_asp > 0, Estar > 0, all finite. */
int dc_gwa_table_check(double Estar, double w, double sigma, double n_asp, dc_param_error *err);

/* Set-up per material pair (the parameters of dc_gw_rough_adhesive, with
   circular summits): DC_EDOM outside the domain of dc_gwa_table_check,
   DC_ERANGE where 1/sigma, 8 w n_asp or delta_c's coefficient leaves the
   doubles; *p untouched on both. */
int dc_gwa_table_pair_init(double Estar, double w, double sigma, double n_asp, dc_gwa_table_pair *p);

/* G_b and dG/dx in the reduced variables (branch DC_GW_LOADING /
   DC_GW_UNLOADING of dc/gw_rough_adhesive.h; x as above; eta = ln tau).
   DC_EDOM for non-finite x, eta or another branch (outputs untouched). */
int dc_gwa_table_reduced(int branch, double x, double eta, double *G, double *dGdx);

/* Adhesive force part (< 0) and its d/d delta on one branch, for relative
   radius R > 0 at overlap delta (finite, any sign). F + the smooth-GW
   force of dc_gw_rough_elliptic = dc_gw_rough_adhesive's force. DC_EDOM
   for non-finite input or R <= 0; DC_ERANGE if a result overflows
   (outputs untouched on error). */
int dc_gwa_table_force(const dc_gwa_table_pair *p, double R, int branch, double delta,
                       double *F, double *kn);

/* The eta cell of the table: eta clamped to the table's range, row j,
   position ue in it, the cubic Hermite weights at ue (a row's value, its
   eta slope, the next row's value and slope). */
typedef struct {
  int j;
  double ue, eta;
  double w[4];
} dc_gwa_table_eta;

/* Elliptic summits (superquadric contacts, relative radii R_major >=
   R_minor, ratio rho = R_minor/R_major): the circular table at matched
   scales times a correction. The matched scales are those of the elliptic
   JKR summit's separation point (dc_jkr_geometry): delta_c = delta_break
   / ub, F_s = F_break/(-5 pi/48), so D and the unloading x are exact;
   with them G_ell = r T - k_e C (loading: C = 0), T = G + C the circular
   table's smoothed value and C its kink term (dc_gwa_table_kink), k_e the
   elliptic summits' Hertz closed form over the matched circle's, and r
   tabulated as ln r in (ln rho, xi(x), eta) (unloading: z(x, eta) for xi,
   below) by tests/reference/gen_gw_rough_adhesive_elliptic.c from the
   exact law (dc_gw_rough_adhesive with dc_jkr_geometry summits):
   Catmull-Rom in xi (z) and eta (C1 in x; unloading: eta below); in ln
   rho cubic Hermite with three-point slopes
   (Catmull-Rom where cells are even), NR1 cells on [ln 1e-4, 0] and NR2
   per branch on [ln RHO_MIN, ln 1e-4], RHO_MIN = 1e-6 the law's limit
   (DC_JKR_RATIO_MIN; the ghost node below it cubic from the last four).
   The ln rho interpolation alone below 1e-4 (against the law at three
   points per cell, every xi node, eta every 1/2): with cells 1, 1.2, 1.5,
   2 times those above, loading 1.3e-5, -, 3.7e-5, 7.2e-5; unloading
   2.7e-5, 4.8e-5, 9.6e-5, 2.2e-4 (near the summits' kink, tau < 0.2;
   elsewhere 1.3e-5, 2.0e-5, 3.6e-5, -), hence NR2 8 and 10 (a straight
   extension, 12 and 12, costs 46k floats more). Loading: xi = x for
   x >= -6 and -6 - 6 LAMBDA ln(1 + ln(x/-6)/LAMBDA) below (C1; nodes
   1/XI_PER_UNIT apart on [XI_LO, XI_HI], x from -1.36e4 to 8), eta rows
   1/4 apart. Unloading: at small tau (D = 1.725/tau large) ln r is nearly
   a function of x/D (the attached summits all sit at about the same
   stretch), falling e.g. from 3.1 to 1.8 over x ~ -0.9 D to -0.4 D at rho
   1e-6; on the xi grid those nodes were 10 to 90 apart in x and the
   features moved across the eta rows, which left 2.4e-4 at rho >= 1e-4
   and 1.9e-3 below (xi nodes 1/8 apart still 1.1e-4). So unloading is
   tabulated against z(x, eta) of dc_gwae_z: xi made C3 at x = -6, minus
   Z_A = 12 units of a logistic step in c = -x/(D_t + 1) (D_t = |ub|/tau
   at the table's eta) around c = 0.7 (x/D ~ -0.7 at small tau: there rows
   meet at the same x/D), plus Z_B = Z_E = 3 units of ones in x around 1
   and -2 (width 0.6: the ends of the kink term's w, a quintic step, where
   the third derivative of ln r jumps, sharply at small tau and rho with
   k_e up to 60; one step of 2 units around 0.5 left kn errors of 1.8e-3
   at x ~ -1.9 and 1, rho < 4e-6); nodes 1/4 apart in z on [XI_LO -
   Z_OFF, XI_HI] (Z_OFF = Z_A + Z_B + Z_E), x from the same x_lo to 8 and
   at small tau beyond (those nodes only neighbours: r is held at x > 8);
   eta rows 1/8 apart on [ETA_LO, 2] and 1/4 on [2, 8], cubic Hermite in
   eta (C1) with five-point slopes (one-sided at the table's ends,
   three-point at the seam; Catmull-Rom left 1.6e-4 at rho ~1e-6, tau ~
   0.1, where ln r's third derivative in eta is ~5; rows 1/4 apart
   throughout left 2.7e-4 at rho >= 1e-4 and tau < 0.14; above tau ~ 7
   they give the same errors). The circular table's eta clamping applies. The scales (ln(delta_c / delta_c,circle(R_major)),
   ln(F_s/8 w R_major), k_e, ln r_oo) at 32 nodes per cell of ln(1e4)/NR1
   on [ln RHO_MIN, 0]. Beyond the grid: r held at x > 8 (force below
   2.4e-16 n_asp 8 w R_major); below x_lo = x(XI_LO) every summit is pressed
   and the kink-free ratio R = G_ell/G = r_oo + A s + B s^2, s = (x_lo/x)^3/4
   (one summit's adhesive part is a series in d^-3/4; the kink term decays
   as d^-1/2 and would spoil the tail of r): r_oo that of one summit's
   adhesive parts at infinite compression (the generator's fit of that
   series, within 2e-10), A and B from R and dR/dx at x_lo, the slope from
   the four nodes there; the grid's own (Catmull-Rom) slope, ~1 % off, is
   joined C1 by D s^12 (s - 1). rho < RHO_MIN is taken as RHO_MIN: the
   caller warns; at a fixed overlap the exact force falls 3.4 to 4.3 times
   per decade of rho near 1e-6, so the clamp overestimates it (r_oo, the
   correction, is 1.8 at 1e-3, 4.4 at 1e-4, 12 at 1e-5, 35 at 1e-6).
   Error against the exact law, relative where |F| >= 1e-6 n_asp 8 w
   R_major, with the sampling of tests/unit/test_gw_rough_adhesive_elliptic.c
   (physical units, tau over the table, x uniform in [-8, 8] or
   log-uniform in [-400, -6]; beyond the grid x_lo to 1e3 x_lo), 1e5 points
   per branch and range of rho (the test takes 30000 and 15000):
   - rho 1e-4 to 1: loading 5.8e-5, unloading 4.1e-5; dF/d delta 4.4e-4
     and 7.2e-4 (Catmull-Rom slopes; kn is the exact derivative of the
     interpolated F); absolute below 3.0e-11 n_asp 8 w R_major;
   - rho 1e-5 to 1e-4: loading 7.8e-5, unloading 6.1e-5; dF/d delta
     4.0e-4 and 4.1e-4; absolute 2.7e-11;
   - rho 1e-6 to 1e-5: loading 9.6e-5, unloading 8.6e-5 (at tau ~ 0.02,
     x ~ -280 to -380: the z interpolation, nodes ~70 apart in x there);
     dF/d delta 6.0e-4 and 8.0e-4; absolute 1.3e-11 and 6.0e-11 (with
     Catmull-Rom in eta and the single z step unloading was 1.6e-4, kn
     1.8e-3, absolute 1.06e-10; ln rho nodes twice as dense below 1e-4
     gave 1.5e-4, eta rows 1/16 apart 1.1e-4);
   - beyond x_lo: 4.0e-5 of the adhesive part at rho >= 1e-4 (near x_lo
     at rho ~0.2: the grid's own error there, carried on), 3.4e-5 below,
     4.1e-8 of the whole force, kn within 9e-9 of |kn| + |F|/sigma (both
     branches; the former tail, one term matched in value only with r_oo
     from the law at x = -1e4, eta = 8, noisy to 1e-4, was off by 3.0e-4).
   The matched scales within 5.7e-10 of dc_jkr_geometry. 741k floats (the
   data header 7.8 MB; 694k, 7.3 MB with the single z step; 629k, 6.6 MB
   with unloading on the xi grid).
   Cost: ~205 ns per set-up and step (the unit test's bench, 198 to 215
   against 183 to 186 with Catmull-Rom in eta and the single z step in
   the same runs; 2890 against 2580 instructions per call, callgrind),
   against ~30 us for the exact law. */
#define DC_GWAE_RHO_MIN 1e-6             /* the exact law's DC_JKR_RATIO_MIN */
#define DC_GWAE_NR1 24                   /* ln rho cells on [ln 1e-4, 0] */
#define DC_GWAE_NR2_L 8                  /* on [ln RHO_MIN, ln 1e-4], loading */
#define DC_GWAE_NR2_U 10                 /* and unloading */
#define DC_GWAE_NRS 36                   /* scale cells on [ln RHO_MIN, 0] */
#define DC_GWAE_LAMBDA 1.0
#define DC_GWAE_XI_LO (-19.0)
#define DC_GWAE_XI_HI 8.0
#define DC_GWAE_XI_PER_UNIT 4
#define DC_GWAE_NXI 108                 /* cells on [XI_LO, XI_HI] */
#define DC_GWAE_ETA_PER_UNIT_L 4
#define DC_GWAE_ETA_PER_UNIT_U 8         /* on [ETA_LO, ETA_MID_U], 4 above */
#define DC_GWAE_ETA_MID_U 2.0
#define DC_GWAE_NETA_L 50               /* eta cells on [ETA_LO, 8] */
#define DC_GWAE_NETA_U 76               /* 52 + 24 */
#define DC_GWAE_SCALE_PER_CELL 32
/* the unloading grid's z (dc_gwae_z): nodes 1/XI_PER_UNIT apart on
   [XI_LO - Z_OFF, XI_HI] */
#define DC_GWAE_Z_A 12.0
#define DC_GWAE_Z_C0 0.7
#define DC_GWAE_Z_W 0.5
#define DC_GWAE_Z_D0 1.0
#define DC_GWAE_Z_B 3.0
#define DC_GWAE_Z_XM 1.0
#define DC_GWAE_Z_WB 0.6
#define DC_GWAE_Z_E 3.0
#define DC_GWAE_Z_XE (-2.0)
#define DC_GWAE_Z_WE 0.6
#define DC_GWAE_Z_OFF (DC_GWAE_Z_A + DC_GWAE_Z_B + DC_GWAE_Z_E)   /* z's offset below XI_LO */
#define DC_GWAE_NZ_U 180                /* cells on [XI_LO - Z_OFF, XI_HI] */

/* -ln rho at node i of a branch's ln rho grid (n2 its NR2; i = -1 and
   NR1 + n2 + 1 the ghosts) */
static inline double dc_gwae_L_node(int i, int n2)
{
  const double L1 = 9.210340371976184;   /* ln 1e4 */
  return i <= DC_GWAE_NR1 ? i * (L1 / DC_GWAE_NR1) : L1 + (i - DC_GWAE_NR1) * (4.605170185988092 / n2);
}

/* eta at node j of the unloading rows (j = -1 and NETA_U + 1 the ghosts) */
static inline double dc_gwae_eta_node_u(int j)
{
  const int n1 = (int)((DC_GWAE_ETA_MID_U - DC_GWA_TABLE_ETA_LO) * DC_GWAE_ETA_PER_UNIT_U + 0.5);
  return j <= n1 ? DC_GWA_TABLE_ETA_LO + (double)j / DC_GWAE_ETA_PER_UNIT_U
                 : DC_GWAE_ETA_MID_U + (double)(j - n1) / (DC_GWAE_ETA_PER_UNIT_U / 2);
}

/* xi(x) of the correction grid and dxi/dx */
static inline double dc_gwae_xi(double x, double *dxi)
{
  if (x >= -6.0) { *dxi = 1.0; return x; }
  const double L = log(x / -6.0), q = 1.0 + L / DC_GWAE_LAMBDA;
  *dxi = -6.0 / (x * q);
  return -6.0 - 6.0 * DC_GWAE_LAMBDA * log(q);
}

/* x at xi (the inverse of dc_gwae_xi) */
static inline double dc_gwae_x_of_xi(double xi)
{
  return xi >= -6.0 ? xi : -6.0 * exp(DC_GWAE_LAMBDA * expm1((-6.0 - xi) / (6.0 * DC_GWAE_LAMBDA)));
}

/* 1 / (D_t + Z_D0) at eta (the unloading coordinate's scale) */
static inline double dc_gwae_z_scale(double eta)
{
  return 1.0 / (0.375 * 4.60115111447049 * exp(-eta) + DC_GWAE_Z_D0);
}

/* z of the unloading grid at x >= x(XI_LO), zs = dc_gwae_z_scale; *dz =
   dz/dx: z = xs - Z_A psi(c) + Z_B (sb - 1) + Z_E (se - 1) with
   - xs = xi + u^2 (a + b u) e^u, u = x + 6 < 0 (xs = xi above): xi made
     C3 at x = -6 (a = -1/6, b = 1/6 - 7/216 cancel its second and third
     derivatives' jumps; dxs/dx >= 0.8 dxi/dx);
   - psi(c) = 1 / (1 + e^-(c - Z_C0)/Z_W), c = -x zs: Z_A more cells at
     c ~ Z_C0, i.e. at fixed x/D for small tau, where ln r's features lie;
   - sb = 1 / (1 + e^-(x - Z_XM)/Z_WB), se the same at Z_XE, Z_WE: Z_B
     and Z_E more cells near the ends of the circular table's kink term's
     weight (x = 1 and -2). */
static inline double dc_gwae_z(double x, double zs, double *dz)
{
  double dxi, xi = dc_gwae_xi(x, &dxi), sb = 0.0, se = 0.0;
  if (x < -6.0) {
    const double u = x + 6.0, E = exp(u), a = -1.0 / 6.0, b = 1.0 / 6.0 - 7.0 / 216.0;
    xi += u * u * (a + b * u) * E;
    dxi += E * u * (2.0 * a + 3.0 * b * u + u * (a + b * u));
  }
  if (x > DC_GWAE_Z_XM - 40.0 * DC_GWAE_Z_WB) sb = 1.0 / (1.0 + exp((DC_GWAE_Z_XM - x) * (1.0 / DC_GWAE_Z_WB)));
  if (x > DC_GWAE_Z_XE - 40.0 * DC_GWAE_Z_WE) se = 1.0 / (1.0 + exp((DC_GWAE_Z_XE - x) * (1.0 / DC_GWAE_Z_WE)));
  const double e1 = exp((DC_GWAE_Z_C0 + x * zs) * (1.0 / DC_GWAE_Z_W)), psi = 1.0 / (1.0 + e1);
  *dz = dxi + DC_GWAE_Z_A * zs * (1.0 / DC_GWAE_Z_W) * psi * (1.0 - psi) +
        DC_GWAE_Z_B * (1.0 / DC_GWAE_Z_WB) * sb * (1.0 - sb) + DC_GWAE_Z_E * (1.0 / DC_GWAE_Z_WE) * se * (1.0 - se);
  return xi - DC_GWAE_Z_A * psi + DC_GWAE_Z_B * (sb - 1.0) + DC_GWAE_Z_E * (se - 1.0);
}

/* The correction's cell for one contact: ln rho and eta weights. */
typedef struct {
  int on;           /* 0: circular summits, no correction */
  int i[2];         /* ln rho cell per branch */
  int j[2];         /* eta cell per branch (unloading: its first of six rows) */
  double wr[2][4];  /* cubic weights in ln rho, per branch */
  double we[2][6];  /* in eta, per branch (loading 4 rows, unloading 6) */
  double ke;        /* k_e */
  double lr_inf;    /* ln r_oo */
  double zs;        /* dc_gwae_z_scale at the table's eta */
  double rho;       /* the ratio used (rho clamped to [RHO_MIN, 1]) */
} dc_gwa_table_ell;

/* The eta cell at eta (clamped to the table's rows): the row j and
   position ue, and the cubic Hermite weights at ue of a row's value, its
   eta slope, the next row's value and slope. */
static inline void dc_gwa_table_eta_cell(double eta, dc_gwa_table_eta *c)
{
  const double emax = DC_GWA_TABLE_ETA_LO + (double)(DC_GWA_TABLE_NETA - 1) / DC_GWA_TABLE_ETA_PER_UNIT;
  const double de = 1.0 / DC_GWA_TABLE_ETA_PER_UNIT;
  if (eta < DC_GWA_TABLE_ETA_LO) eta = DC_GWA_TABLE_ETA_LO;
  if (eta > emax) eta = emax;
  c->eta = eta;
  double ue = (eta - DC_GWA_TABLE_ETA_LO) * DC_GWA_TABLE_ETA_PER_UNIT;
  int j = (int)ue;
  if (j > DC_GWA_TABLE_NETA - 2) j = DC_GWA_TABLE_NETA - 2;
  ue -= j;
  const double u2 = ue * ue, u3 = u2 * ue;
  c->j = j;
  c->ue = ue;
  c->w[0] = 2 * u3 - 3 * u2 + 1;
  c->w[1] = (u3 - 2 * u2 + ue) * de;
  c->w[2] = -2 * u3 + 3 * u2;
  c->w[3] = (u3 - u2) * de;
}

/* What a contact's relative radius R fixes, for dc_gwa_table_step_radius:
   a caller may keep it while R stays the same (monodisperse spheres, a
   sphere on walls). */
typedef struct {
  double R;            /* [m] */
  double Fs;           /* n_asp 8 w R [N] */
  double db;           /* |delta_break| of a summit [m] */
  double D;            /* db / sigma */
  double reach;        /* dc_gwa_table_reach [m] */
  dc_gwa_table_eta cell;   /* eta = ln tau */
  dc_gwa_table_ell ell;    /* elliptic summits (on = 0 for circles) */
} dc_gwa_table_radius;

/* Set-up per radius R > 0 (else DC_EDOM, *r untouched; DC_ERANGE if a
   product overflows). w = 0: only r->R is set. */
int dc_gwa_table_radius_init(const dc_gwa_table_pair *p, double R, dc_gwa_table_radius *r);

/* Set-up for elliptic summits of relative radii R_major >= R_minor > 0
   (a superquadric contact): *r then serves dc_gwa_table_step_radius as
   for a circle (R = R_major; R_minor = R_major gives the circle's forces
   within the correction's error). DC_EDOM for radii out of order, not
   positive or not finite; DC_ERANGE as dc_gwa_table_radius_init. */
int dc_gwa_table_radius_init_elliptic(const dc_gwa_table_pair *p, double R_major, double R_minor,
                                      dc_gwa_table_radius *r);

/* The circular table's G, dG/dx (dc_gwa_table_reduced) and the kink
   term's C, dC/dx (dc_gwa_table_kink; 0 on loading) at (x, eta) on branch
   b: what the correction reads at the end of its grid, given by the
   caller (the step), so that the correction sits below the table. */
typedef void (*dc_gwa_table_circle_fn)(int b, double x, double eta, double *G, double *Gx, double *C, double *Cx);

/* The correction applied to the circular table's G, dG/dx at (x, eta) on
   branch b, kc = C and dC/dx of dc_gwa_table_kink there (0 on loading);
   below the grid (x < x_lo) it reads circle at x_lo: used by the step. */
void dc_gwa_table_ell_apply(const dc_gwa_table_ell *e, int b, double x, double eta, const double *kc,
                            dc_gwa_table_circle_fn circle, double *G, double *Gx);

/* Per-contact history: gwa_touched, gwa_delta_max (no sign flips). */
enum { DC_GWA_TABLE_HISTORY_NFIELDS = 2 };
extern const dc_history_field dc_gwa_table_history[DC_GWA_TABLE_HISTORY_NFIELDS];

typedef struct {
  double F;        /* adhesive part of the normal force [N] (<= 0) */
  double kn;       /* dF/d delta [N/m] */
  double weight;   /* 0 loading branch, 1 unloading branch, between: blend */
} dc_gwa_table_out;

/* One DEM step: the adhesive force at overlap delta with the branch from
   hist (updated). w = 0: F = kn = 0 exactly, hist untouched. Errors as
   dc_gwa_table_force, hist and *o untouched. */
int dc_gwa_table_step(const dc_gwa_table_pair *p, double R, double delta, double *hist,
                      dc_gwa_table_out *o);

/* dc_gwa_table_step with the radius set up by dc_gwa_table_radius_init
   (the same results). */
int dc_gwa_table_step_radius(const dc_gwa_table_pair *p, const dc_gwa_table_radius *r, double delta, double *hist,
                             dc_gwa_table_out *o);

/* What a sphere contact keeps between steps, as plain doubles that map
   onto history values (dc_gwa_table_contact_history, in this order): what
   its relative radius R fixes (a sphere pair's R = r_i r_j/(r_i + r_j), a
   wall's r_i: the same for the contact's life) and the cubic of the last
   table cell it used. Keyed by R: a caller sets it up by
   dc_gwa_table_contact_init whenever the stored R differs from the
   contact's (all zeros, a new contact, differs from every R > 0; a
   restart keeps it). The material pair is taken to stay the one it was
   set up with. */
typedef struct {
  double R;       /* [m] the radius the rest belongs to (0: none) */
  double db;      /* |delta_break| of a summit [m] */
  double eta;     /* ln tau, clamped to the table's range */
  double cell[5]; /* the last table cell used: which (0: none; else a small
                     integer naming branch, region and index), then its
                     cubic in x or u: L = c0 + c1 t + c2 t^2 +
                     c3 t^3, t in [0, 1] across the cell */
} dc_gwa_table_contact;
enum { DC_GWA_TABLE_CONTACT_NFIELDS = 8 };
extern const dc_history_field dc_gwa_table_contact_history[DC_GWA_TABLE_CONTACT_NFIELDS];

/* Set-up of a contact's record for radius R > 0: R, db and eta as
   dc_gwa_table_radius_init (same errors, *c untouched on error), no cell
   kept. w = 0: only c->R is set (the rest 0). */
int dc_gwa_table_contact_init(const dc_gwa_table_pair *p, double R, dc_gwa_table_contact *c);

/* The key of a contact's kept cell (dc_gwa_table_contact's cell[0]): 1 +
   the cell's place among branch b's near cells (i < NNEAR), then its deep
   cells (NNEAR + k - K_MIN). */
#define DC_GWA_TABLE_CELL_KEY_NEAR(b, i) (1 + (b) * (DC_GWA_TABLE_NNEAR + DC_GWA_TABLE_NDEEP) + (i))

/* A kept cell's cubic c0 + c1 t + c2 t^2 + c3 t^3 at t: value and d/dt */
static inline void dc_gwa_cubic(const double *c, double t, double *v, double *dv)
{
  *v = ((c[3] * t + c[2]) * t + c[1]) * t + c[0];
  *dv = (3.0 * c[3] * t + 2.0 * c[2]) * t + c[1];
}

/* 2^(j/32), j < 32 (dc_gwa_exp) */
extern const double dc_gwa_exp2_32[32];

/* e^L for the table's L (< 0.5): 2^e 2^(j/32) e^r with k = 32 e + j the
   nearest integer to 32 L/ln 2 and r = L - k ln2/32 in [-ln2/64, ln2/64]
   (Cody-Waite: k ln2_hi/32 is exact, ln2_hi having 32 bits), e^r by its
   Taylor polynomial of degree 6 (truncation below 4e-18 relative); within
   2 ulp of exp. L at or below -708 (subnormal results), above 709 or NaN:
   the library's exp. */
static inline double dc_gwa_exp(double L)
{
  if (!(L > -708.0 && L < 709.0)) return exp(L);
  const double shifter = 0x1.8p52;
  const double kd = (L * (32.0 / 0.6931471805599453) + shifter) - shifter;
  const double r = (L - kd * (6.9314718036912382e-01 / 32)) - kd * (1.9082149292705877e-10 / 32);
  const double r2 = r * r;
  const double q = 1.0 + r + r2 * ((0.5 + r * (1.0 / 6)) + r2 * ((1.0 / 24 + r * (1.0 / 120)) + r2 * (1.0 / 720)));
  const int k = (int)kd;
  const uint64_t bits = (uint64_t)((k >> 5) + 1023) << 52;   /* floor(k/32): arithmetic shift */
  double scale;
  memcpy(&scale, &bits, sizeof scale);
  return dc_gwa_exp2_32[k & 31] * q * scale;
}

/* dc_gwa_table_step_contact for any contact (below) */
int dc_gwa_table_step_contact_any(const dc_gwa_table_pair *p, dc_gwa_table_contact *c, double delta, double *hist,
                                  dc_gwa_table_out *o);

/* The step of a settled contact: touched, wholly on one branch, in the
   near cell it kept (c), above the blend and without the kink term; 1 when
   the contact is one (the step done: hist and *o as
   dc_gwa_table_step_contact), else 0 with nothing changed (the caller
   takes dc_gwa_table_step_contact_any). The operations of the full step on
   that path, in its order (the same bits; the fuzz and the unit test
   compare). xi = (dmax - delta)/db is compared without the division: for
   db > 0 and dmax - delta >= 0, xi >= 1 exactly when dmax - delta >= db
   (the quotient of a number below db rounds below 1). Non-finite input
   returns 0. */
static inline int dc_gwa_table_step_settled(const dc_gwa_table_pair *p, dc_gwa_table_contact *c, double delta,
                                            double *hist, dc_gwa_table_out *o)
{
  if (!(hist[0] == 1.0 && fabs(hist[1]) <= DBL_MAX && c->db > 0.0)) return 0;
  const double dmax = delta > hist[1] ? delta : hist[1];
  const double du = dmax - delta;
  int b;
  double x = -delta * p->inv_sigma;
  if (!(du > 0.0)) b = DC_GW_LOADING;
  else if (du >= c->db) { b = DC_GW_UNLOADING; x -= c->db * p->inv_sigma; }
  else return 0;
  if (!(x >= DC_GWA_TABLE_BLEND_HI && x <= DC_GWA_TABLE_X_HI) ||
      (b == DC_GW_UNLOADING && x < DC_GWA_KINK_W_HI && c->eta < DC_GWA_KINK_K_HI))
    return 0;
  const double cx = (x - DC_GWA_TABLE_X_LO) * DC_GWA_TABLE_X_PER_UNIT;
  int i = (int)cx;
  if (i > DC_GWA_TABLE_NNEAR - 1) i = DC_GWA_TABLE_NNEAR - 1;
  if (c->cell[0] != DC_GWA_TABLE_CELL_KEY_NEAR(b, i)) return 0;
  double L, Lc;
  dc_gwa_cubic(c->cell + 1, cx - i, &L, &Lc);
  const double Lx = Lc * DC_GWA_TABLE_X_PER_UNIT;
  const double G = -dc_gwa_exp(L), Gx = G * Lx;
  const double Fs = p->F_coef * c->R;
  const double F = Fs * G, kn = -Fs * Gx * p->inv_sigma;
  if (!(isfinite(F) && isfinite(kn))) return 0;
  hist[0] = 1.0;
  hist[1] = dmax;
  o->F = F;
  o->kn = kn;
  o->weight = b == DC_GW_UNLOADING ? 1.0 : 0.0;
  return 1;
}

/* dc_gwa_table_step_radius for a contact whose record c was set up by
   dc_gwa_table_contact_init (for the contact's R and this pair): the same
   bits; the cell kept in c is read when the step lands in it (a settled
   contact, inline) and otherwise replaced by the cell the step formed. */
static inline int dc_gwa_table_step_contact(const dc_gwa_table_pair *p, dc_gwa_table_contact *c, double delta,
                                            double *hist, dc_gwa_table_out *o)
{
  if (dc_gwa_table_step_settled(p, c, delta, hist, o)) return DC_OK;
  return dc_gwa_table_step_contact_any(p, c, delta, hist, o);
}

/* Reach (dc_gwa_table_reach) from a contact's record: the same bits. */
static inline double dc_gwa_table_contact_reach(const dc_gwa_table_pair *p, const dc_gwa_table_contact *c)
{
  return c->db + DC_GWA_TABLE_X_HI * p->sigma;
}

/* Apart: a contact that has not touched (hist[0] = 0) with the summits
   more than X_CUT sigma apart (h > X_CUT) feels no force and stays
   untouched: the step returns F = kn = 0 and leaves hist as it is. X_CUT
   is where the table ends (X_HI) and where the history resets: there G is
   below 3.3e-16 on every eta row and both branches (the exact law's below
   3.26e-16), so the cut is a jump below 3.3e-16 n_asp 8 w R (2.4e-16 n_asp
   8 w R_major with elliptic summits), 6000 times below the table's stated
   absolute error. (At 12, as before, the jump was 2.6e-30, but contacts
   that came within 12 sigma and no nearer, common on polydisperse spheres,
   took the band and beyond-table paths for that force: 7 % of the
   polydisperse bench's instructions.) A caller may test it before setting
   anything else up (it reads only sigma): with a contact distance well
   beyond the reach (polydisperse spheres need it) most close pairs are
   that far apart. */
#define DC_GWA_TABLE_X_CUT DC_GWA_TABLE_X_HI
static inline int dc_gwa_table_apart(const dc_gwa_table_pair *p, double delta, const double *hist)
{
  return hist[0] == 0.0 && -delta * p->inv_sigma > DC_GWA_TABLE_X_CUT;
}

/* Reach: the separation (-delta) beyond which the force is below
   3.3e-16 n_asp 8 w R on either branch: (D + 8) sigma. */
double dc_gwa_table_reach(const dc_gwa_table_pair *p, double R);

#ifdef __cplusplus
}
#endif
#endif
