/* Feng, Zhao, Kato & Zhou (2016) explicit normal interaction law for rough
   spheres (Feng Eq. 75, Tables 4-6):

     P = P_h(delta) P1*(alpha, mu)       delta >= sigma      (Case I,  alpha = sigma/delta)
       = P_h(sigma) P2*(alpha', mu)      0 < delta < sigma   (Case II, alpha' = delta/sigma)
       = P_h(sigma) P3*(alpha', mu)      -3 sigma < delta <= 0  (Case III)
       = 0                               delta <= -3 sigma   (Case IV)
     P_h(x) = 4/3 E* R^1/2 x^3/2  (Hertz, Feng Eq. 11)

   P1* cubic in alpha (Eq. 66, Table 4), P2* quadratic in alpha' (Eq. 71,
   Table 5), P3* quartic in alpha' (Eq. 73, Table 6); mu = (8/3) sigma N
   sqrt(2 R beta) (Eq. 22) in [1, 50], DC_EDOM outside.

   Two coefficient variants:
   - DC_FENG_TABLE: the polynomials are interpolants of P* through fixed
     nodes (alpha = 0, 1/3, 2/3, 1; alpha' = 0, 1/2, 1; alpha' = -3, -9/4,
     -3/2, -3/4, 0; Feng Sec. 7). The nodal values at the seven tabulated mu
     are recovered from the table, interpolated in ln mu by a monotone cubic
     (Fritsch-Carlson), and the polynomials rebuilt. At a tabulated mu this
     reproduces the table to rounding. Interpolating nodal values rather
     than coefficients keeps the shared nodes shared: P1*(1) = P2*(1) and
     P2*(0) = P3*(0) hold for every mu, not just at the seven.
   - DC_FENG_FITTED: the fitted formulas of Tables 4-6. They do not share
     the boundary values (e.g. at mu = 1, Table 5 b0 = 0.3011 gives
     -5.677 + 5.965 = 0.288 and Table 6 b0 gives 0.2769), so for continuity
     Case III takes b0 from the Case II formula and Case I's b3 absorbs
     P2*(1) - P1*(1) (|change| <= 0.03 over [1, 50]); documented deviation.
   Continuity at alpha' = -3: Eq. 64 sets P* = 0 below -3 while P3*(-3) is
   ~1e-3 to 1e-2, a jump. This implementation subtracts P3*(-3) (alpha'/-3)^4,
   which is 0 with three zero derivatives at alpha' = 0 (so the Case II/III
   joint is untouched) and removes the jump (deviation <= |P3*(-3)|).
   P3* is also floored at 0.

   Seed errors: Table 6's caption reads "-3 <= alpha' <= 0" but the text
   after Eq. 74 re-uses the Case II wording ("P2*(1/2) = P*(1/2)"); the five
   nodes it names (-3, -9/4, -6/4, -3/4, 0) are what the coefficients
   interpolate (checked: the tabulated b0 of Tables 5 and 6 agree, and the
   full solver reproduces the nodal values, see test_feng_rough.c). Eq. 71
   and 73 are printed in alpha; they are polynomials in alpha'.

   The paper notes P* < 1 near alpha = 0 (a defect of the GW model, kept by
   the law: P1* interpolates the solver there). Hot path: dc_feng_pair_force
   (inline, no checks) on a dc_feng_pair set up once per material pair;
   dc_feng_force is the checked form of the same kernel. */
#ifndef DC_FENG_ROUGH_H
#define DC_FENG_ROUGH_H

#include <math.h>
#include "dc/contract.h"

#ifdef __cplusplus
extern "C" {
#endif

enum { DC_FENG_TABLE = 0, DC_FENG_FITTED = 1 };

#define DC_FENG_MU_MIN 1.0
#define DC_FENG_MU_MAX 50.0

typedef struct {
  double mu;
  double b1[4];   /* Case I:  P1*(alpha)  = sum b1[k] alpha^k  */
  double b2[3];   /* Case II: P2*(alpha') = sum b2[k] alpha'^k */
  double b3[5];   /* Case III, before the alpha' = -3 taper     */
  double p3m3;    /* P3*(-3), removed by the taper              */
  double c3[5];   /* Case III as evaluated: b3 - p3m3 (alpha'/3)^4 */
} dc_feng_law;

/* The law bound to one material pair (E*, sigma > 0). */
typedef struct {
  dc_feng_law law;
  double c;         /* 4/3 E*: P_h(x) = c R^1/2 x^3/2 */
  double sigma, inv_sigma;
  double c_sigma;   /* c sigma^3/2 */
} dc_feng_pair;

/* Coefficients for one mu in [1, 50] (once per material pair). */
int dc_feng_init(double mu, int variant, dc_feng_law *law);

/* Non-dimensional load: P/P_h(delta) in Case I (x = alpha = sigma/delta in
   [0, 1]) ... use dc_feng_pstar_sigma for the sigma form. */
double dc_feng_P1(const dc_feng_law *law, double alpha);
/* P/P_h(sigma) as a function of alpha' = delta/sigma (any real): Cases
   I-IV in the sigma form (Case I: P1*(1/alpha') alpha'^3/2). */
double dc_feng_pstar_sigma(const dc_feng_law *law, double alpha_p);

/* Force and stiffness dP/d delta for overlap delta (any sign), roughness
   sigma >= 0, E* > 0, R > 0, all finite (Eq. 75; else DC_EDOM). sigma = 0
   is Hertz. Where the bound pair's constants or the kernel's products would
   leave the range of doubles (e.g. subnormal sigma), the same law is
   evaluated with the scales applied last; DC_ERANGE when P or kn itself
   overflows. */
int dc_feng_force(const dc_feng_law *law, double Estar, double R, double sigma,
                  double delta, double *P, double *kn);

/* Binds law to E* > 0 and sigma > 0, both finite (DC_EDOM otherwise).
   DC_ERANGE when 4/3 E*, 1/sigma or 4/3 E* sigma^3/2 is not a finite
   normal number (E* near DBL_MAX, sigma subnormal or so small that
   E* sigma^3/2 underflows): the unchecked kernel would return Inf or NaN
   there; dc_feng_force covers those inputs. */
int dc_feng_pair_init(const dc_feng_law *law, double Estar, double sigma, dc_feng_pair *p);

/* Eq. 75: force P and dP/d delta at overlap delta (any sign) for
   sqrtR = R^1/2 > 0. Cases I-IV as above, P3* floored at 0. */
static inline void dc_feng_pair_force(const dc_feng_pair *p, double sqrtR, double delta,
                                      double *P, double *kn)
{
  const double *b;
  if (delta >= p->sigma) {                    /* Case I, x = alpha = sigma/delta */
    b = p->law.b1;
    const double rd = 1.0 / delta, x = p->sigma * rd, sd = sqrt(delta), c = p->c * sqrtR;
    const double P1 = ((b[3] * x + b[2]) * x + b[1]) * x + b[0];
    const double d1 = (3.0 * b[3] * x + 2.0 * b[2]) * x + b[1];
    *P = c * delta * sd * P1;
    *kn = c * sd * (1.5 * P1 - d1 * x);
    return;
  }
  const double x = delta * p->inv_sigma, c = p->c_sigma * sqrtR;
  double v, d;
  if (x > 0.0) {                              /* Case II */
    b = p->law.b2;
    v = (b[2] * x + b[1]) * x + b[0];
    d = 2.0 * b[2] * x + b[1];
  } else if (x > -3.0) {                      /* Case III */
    b = p->law.c3;
    v = (((b[4] * x + b[3]) * x + b[2]) * x + b[1]) * x + b[0];
    d = ((4.0 * b[4] * x + 3.0 * b[3]) * x + 2.0 * b[2]) * x + b[1];
    if (v < 0.0) v = d = 0.0;
  } else {                                    /* Case IV */
    v = d = 0.0;
  }
  *P = c * v;
  *kn = c * d * p->inv_sigma;
}

/* The published tables (Tables 4-6), for tests: mu nodes and coefficients. */
extern const double dc_feng_mu_nodes[7];
extern const double dc_feng_table_I[4][7], dc_feng_table_II[3][7], dc_feng_table_III[5][7];

/* Parameter check (dc/contract.h): roughnessMu mu in [1, 50]. */
int dc_feng_check(double mu, dc_param_error *err);

#ifdef __cplusplus
}
#endif
#endif
