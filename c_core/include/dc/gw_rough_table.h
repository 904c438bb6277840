/* Rough-sphere normal force tabulated from the full Greenwood-Williamson
   solver (dc/gw_solver.h; Feng et al. 2016, Secs. 2-6): the exact GW law
   at the cost of the explicit Feng law (dc/feng_rough.h).

   Reduced variables. In the solver's sigma-form (Feng Eqs. 27-29) the
   radius R, the moduli and sigma scale out exactly:
     P = P_h(sigma) P*(alpha', mu),  P_h(sigma) = 4/3 E* R^1/2 sigma^3/2,
     alpha' = delta/sigma,  mu = (8/3) sigma N (2 R beta)^1/2 (Feng Eq. 22),
   so P* depends on alpha' and mu only: sigma/R does not enter (the GW
   sphere model is a small-slope half-space model; sigma/R matters only
   through mu, which the user gives). One table covers every material.

   Table. ln P* at 209 nodes in alpha' times a Chebyshev series of degree 11
   in ln mu on [ln 1, ln 50] (c_core/src/gw_rough_table_data.h, written by
   tests/reference/gen_gw_rough_table.c from the solver at the 12 Chebyshev
   points of ln mu). Nodes: alpha' = -6 + k/16 (k < 112) and
   2^e (1 + j/8) (e = 0..11, j = 0..7) and 4096. dc_gw_table_init evaluates
   the series at one mu (once per material pair) and builds the not-a-knot
   cubic spline of P* through the nodes: P* is C2 in alpha' inside
   (-6 + 1/16, 4096), C1 at those two nodes, and smooth in mu.
   Beyond the table:
   - alpha' <= -6: P* = 0. The first cell is the cubic Hermite from
     (0, slope 0) to the spline's value and slope at -6 + 1/16 (the solver's
     P* at -6 is 1.05e-9 mu/50: below alpha' ~ -4.5 it is proportional to mu).
   - alpha' >= 4096 (alpha = sigma/delta <= 1/4096): the delta-form
     P/P_h(delta) = 1 - A q^2/3 - B q, q = 4096/alpha' (the two leading terms
     of the approach to Hertz, Feng Sec. 4), A and B matched to the spline's
     value and slope at 4096: C1, and exactly Hertz as sigma/delta -> 0.

   Error against the solver (tests/unit/test_gw_rough_table.c, points off
   the nodes, mu in [1, 50], solver at other m and domain than the
   generator's): relative, where P* >= 1e-6, at most 2.9e-5 (measured at
   every cell midpoint for 8 mu; worst in the tail alpha' ~ -4.8; 4.7e-6 in
   the resting range alpha' = -2.4 .. -2.8; 1.7e-5 at alpha' = 9900, where
   the solver itself is uncertain by ~5e-6); absolute in P* below 1e-6 at
   most 1.05e-9, the solver's P*(-6, mu = 50) that the cut at -6 drops.
   Stated bounds: DC_GW_TABLE_REL_ERR, DC_GW_TABLE_ABS_ERR. Against the GW
   model itself add the solver's error (~3e-7, dc/gw_solver.h).

   The force is C1 in delta (C2 between -6 + 1/16 and 4096 sigma) and
   monotone (checked on a dense sweep for 21 mu); dP/d delta is the
   derivative of the same cubic. It acts from delta = -6 sigma on (the Feng
   law from -3 sigma, where the solver's P* is still 1.1e-4 at mu = 1 and
   5.6e-3 at mu = 50): a wrapper's contact reach must be 6 sigma.

   Hot path: dc_gw_table_pair_force (inline, no checks, about 4 ns as the
   Feng law's dc_feng_pair_force) on a dc_gw_table_pair bound once per
   material pair (6.7 kB: the law at its mu); dc_gw_table_force is the
   checked form. */
#ifndef DC_GW_ROUGH_TABLE_H
#define DC_GW_ROUGH_TABLE_H

#include <math.h>
#include <stdint.h>
#include <string.h>
#include "dc/contract.h"

#ifdef __cplusplus
extern "C" {
#endif

#define DC_GW_TABLE_MU_MIN 1.0
#define DC_GW_TABLE_MU_MAX 50.0
/* alpha' grid: uniform cells of 1/16 on [-6, 1), 8 cells per octave on [1, 4096) */
#define DC_GW_TABLE_X_LO (-6.0)
#define DC_GW_TABLE_PER_UNIT 16
#define DC_GW_TABLE_NUNIFORM 112
#define DC_GW_TABLE_PER_OCTAVE_LOG2 3
#define DC_GW_TABLE_OCTAVES 12
#define DC_GW_TABLE_X_HI 4096.0
#define DC_GW_TABLE_NCELL (DC_GW_TABLE_NUNIFORM + (DC_GW_TABLE_OCTAVES << DC_GW_TABLE_PER_OCTAVE_LOG2))
#define DC_GW_TABLE_NNODE (DC_GW_TABLE_NCELL + 1)
#define DC_GW_TABLE_NMU 12
/* Stated error against the solver (measured 2.9e-5 and 1.05e-9, above):
   relative where P* >= 1e-6, absolute in P* = P/P_h(sigma) below. */
#define DC_GW_TABLE_REL_ERR 1e-4
#define DC_GW_TABLE_ABS_ERR 1.1e-9

/* alpha' at node i in [0, DC_GW_TABLE_NNODE) */
static inline double dc_gw_table_node(int i)
{
  if (i < DC_GW_TABLE_NUNIFORM) return DC_GW_TABLE_X_LO + (double)i / DC_GW_TABLE_PER_UNIT;
  const int k = i - DC_GW_TABLE_NUNIFORM, n = 1 << DC_GW_TABLE_PER_OCTAVE_LOG2;
  return ldexp(1.0 + (double)(k % n) / n, k / n);
}

/* The law at one mu: P* on cell i is c[i][0] + t (c[i][1] + t (c[i][2] +
   t c[i][3])), t in [0, 1) the position in the cell. */
typedef struct {
  double mu;
  double c[DC_GW_TABLE_NCELL][4];
  double A, B;      /* alpha' >= 4096: P/P_h(delta) = 1 - A q^2/3 - B q */
} dc_gw_table_law;

/* The law bound to one material pair (E*, sigma > 0). */
typedef struct {
  dc_gw_table_law law;
  double c;         /* 4/3 E*: P_h(x) = c R^1/2 x^3/2 */
  double sigma, inv_sigma;
  double c_sigma;   /* c sigma^3/2 */
} dc_gw_table_pair;

/* The law at mu in [1, 50] (once per material pair; DC_EDOM outside). */
int dc_gw_table_init(double mu, dc_gw_table_law *law);

/* P* = P/P_h(sigma) and its derivative in alpha' at alpha' = delta/sigma
   (any finite value; DC_EDOM for NaN or Inf, DC_ERANGE where P* overflows,
   alpha' beyond ~1e205). */
int dc_gw_table_pstar(const dc_gw_table_law *law, double alpha_p, double *P, double *dP);

/* Binds law to E* > 0 and sigma > 0, both finite (DC_EDOM otherwise);
   DC_ERANGE when 4/3 E*, 1/sigma or 4/3 E* sigma^3/2 is not a finite
   normal number (dc_gw_table_force covers those inputs). */
int dc_gw_table_pair_init(const dc_gw_table_law *law, double Estar, double sigma, dc_gw_table_pair *p);

/* P* and its derivative in x on the table at x in (X_LO, X_HI): the cubic
   of x's cell (uniform cells below 1; above, the cell and the position in
   it are read off the bits of x = 2^e (1 + f): exact, no division). */
static inline void dc_gw_table_cell_(const dc_gw_table_law *L, double x, double *v, double *d)
{
  const double *c;
  double t, inv_h;
  if (x < 1.0) {
    const double u = (x - DC_GW_TABLE_X_LO) * DC_GW_TABLE_PER_UNIT;
    int i = (int)u;
    if (i > DC_GW_TABLE_NUNIFORM - 1) i = DC_GW_TABLE_NUNIFORM - 1;  /* x + 6 rounded up to 7 */
    t = u - i;
    c = L->c[i];
    inv_h = DC_GW_TABLE_PER_UNIT;
  } else {
    uint64_t b;
    memcpy(&b, &x, sizeof b);
    const int s = DC_GW_TABLE_PER_OCTAVE_LOG2, e = (int)(b >> 52) - 1023;
    const uint64_t f = b & ((UINT64_C(1) << 52) - 1);
    c = L->c[DC_GW_TABLE_NUNIFORM + (e << s) + (int)(f >> (52 - s))];
    t = (double)(f & ((UINT64_C(1) << (52 - s)) - 1)) * (1.0 / (double)(UINT64_C(1) << (52 - s)));
    const uint64_t bh = (uint64_t)(1023 + s - e) << 52;   /* 1/h = 2^s / 2^e */
    memcpy(&inv_h, &bh, sizeof inv_h);
  }
  *v = ((c[3] * t + c[2]) * t + c[1]) * t + c[0];
  *d = ((3.0 * c[3] * t + 2.0 * c[2]) * t + c[1]) * inv_h;
}

/* The kernel of dc_gw_table_pair_force with the pair's constants passed
   (c = 4/3 E*, c_sigma = c sigma^3/2). */
static inline void dc_gw_table_kernel_(const dc_gw_table_law *L, double c, double inv_sigma, double c_sigma,
                                       double sqrtR, double delta, double *P, double *kn)
{
  const double x = delta * inv_sigma;
  if (!(x > DC_GW_TABLE_X_LO)) { *P = *kn = 0.0; return; }   /* also NaN */
  if (x < DC_GW_TABLE_X_HI) {
    double v, d;
    dc_gw_table_cell_(L, x, &v, &d);
    const double cs = c_sigma * sqrtR;
    *P = cs * v;
    *kn = cs * d * inv_sigma;
    return;
  }
  /* Hertz asymptote, q = X_HI sigma/delta in (0, 1] */
  const double q = DC_GW_TABLE_X_HI / x, q23 = cbrt(q * q), sd = sqrt(delta), cR = c * sqrtR;
  *P = cR * delta * sd * (1.0 - L->A * q23 - L->B * q);
  *kn = cR * sd * (1.5 - 5.0 / 6.0 * L->A * q23 - 0.5 * L->B * q);
}

/* P = P_h(sigma) P*(delta/sigma) and dP/d delta at overlap delta (any
   sign) for sqrtR = R^1/2 > 0: the table, zero at and below -6 sigma, the
   Hertz asymptote from 4096 sigma on (in the delta-form: no overflow of
   (delta/sigma)^3/2). NaN delta gives 0. */
static inline void dc_gw_table_pair_force(const dc_gw_table_pair *p, double sqrtR, double delta,
                                          double *P, double *kn)
{
  dc_gw_table_kernel_(&p->law, p->c, p->inv_sigma, p->c_sigma, sqrtR, delta, P, kn);
}

/* Force and stiffness dP/d delta for overlap delta (any sign), roughness
   sigma >= 0, E* > 0, R > 0, all finite (else DC_EDOM). sigma = 0 is
   Hertz. Where the bound pair's constants or the kernel's products leave
   the range of doubles, the same law is evaluated with the scales applied
   last; DC_ERANGE when P or kn itself overflows. */
int dc_gw_table_force(const dc_gw_table_law *law, double Estar, double R, double sigma,
                      double delta, double *P, double *kn);

/* Parameter check (dc/contract.h): roughnessMu mu in [1, 50]. */
int dc_gw_table_check(double mu, dc_param_error *err);

#ifdef __cplusplus
}
#endif
#endif
