/* Greenwood-Williamson rough contact of two non-spherical bodies, smooth-GW
   (non-adhesive) variant: review Eqs. 29-36 and Table 4 "non-smooth".

     F = 4/3 n_asp E* Rc^1/2 sigma^3/2 gamma F_3/2(h)      (Eqs. 31, 33, 35)
     A = pi  n_asp Rc sigma beta F_1(h)                      (Eqs. 32, 34, 36)
     h = d/sigma = -delta/sigma

   with Rc, gamma, beta from the elliptic Hertz geometry (dc_hertz_geom,
   review Eqs. 5, 11-12), n_asp = N A_n the number of summits in the nominal
   area, sigma the rms summit height of the combined surface and delta the
   overlap of the nominal (mean) surfaces, > 0 in compression (DEM sign; the
   review's separation d is -delta). gamma* = gamma F_3/2(h) and
   beta* = beta F_1(h) are the review's Eqs. 35-36 (Eq. 36 corrected, see
   dc/gw_integrals.h). Dimensions: n_asp [-], E* Rc^1/2 sigma^3/2 [N],
   Rc sigma [m^2].

   Smooth limit: as sigma -> 0 at fixed delta > 0, h -> -inf and
   sigma^3/2 F_3/2(h) = delta^3/2 (1 + 3 sigma^2/(8 delta^2) + ...),
   sigma F_1(h) -> delta, so F -> n_asp x (elliptic Hertz force) and
   A -> n_asp x (Hertz area); with n_asp = 1 this is exactly
   dc_hertz_contact. For sigma <= 1e-80 delta (correction < 1e-160) and for
   sigma = 0 the Hertz expressions are used directly, so the limit is exact.

   The review builds the summit-scale law on the body-scale Rc (Eq. 31 puts
   Rc where the GW model has the summit radius): the law is implemented as
   printed, and n_asp absorbs the summit density. Hot path: no allocation;
   for a geometry that repeats, dc_gw_bound_force (F_3/2 and F_1/2 from
   degree-9 pieces, ~100 instructions against ~500 here). */
#ifndef DC_GW_ROUGH_H
#define DC_GW_ROUGH_H

#include <float.h>
#include <math.h>
#include "dc/feng_rough.h"
#include "dc/gw_integrals.h"
#include "dc/gw_rough_table.h"
#include "dc/hertz_elliptic.h"
#include "dc/status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
  double F;      /* normal force [N] */
  double area;   /* real contact area [m^2] */
  double kn;     /* dF/d delta = 2 n_asp E* Rc^1/2 sigma^1/2 gamma F_1/2(h) [N/m] */
  double h;      /* standardised separation -delta/sigma (-inf reported as -1e300) */
} dc_gw_rough_state;

/* Domain: Estar > 0, n_asp > 0, sigma >= 0, all finite; delta finite (any
   sign; with sigma = 0 and delta <= 0 the force is 0). DC_EDOM otherwise;
   DC_ERANGE when F, kn or the area overflows. The state is written only
   on DC_OK. g: from dc_hertz_geometry. */
int dc_gw_rough_elliptic(const dc_hertz_geom *g, double Estar, double n_asp,
                         double sigma, double delta, dc_gw_rough_state *s);

/* The closed form bound to one geometry, material pair and sigma > 0, for
   contacts whose geometry repeats (spheres of one size per type pair, a
   sphere on walls): the products of dc_gw_rough_elliptic formed once, in
   its order, so F and kn differ from it only by F_3/2 and F_1/2 from
   dc_gw_F32_F12 (dc/gw_integrals.h: within 3e-16 relative) on
   -10 <= h < 3, the range of settled and approaching contacts; elsewhere
   dc_gw_rough_elliptic itself. About a fifth of its instructions. The
   material part (dc_gw_bound_material) is formed once per pair; a contact
   of another geometry binds it again (dc_gw_bound_bind: one square root). */
typedef struct {
  dc_hertz_geom g;
  double Estar, n_asp, sigma;
  double inv_sigma;
  double ss;   /* sigma^1/2 */
  double kF;   /* n_asp 4/3 E* */
  double kk;   /* n_asp 2 E* */
  double cF;   /* n_asp 4/3 E* Rc^1/2 sigma^3/2 gamma */
  double ck;   /* n_asp 2 E* Rc^1/2 sigma^1/2 gamma */
} dc_gw_bound;

/* Domain of dc_gw_rough_elliptic with sigma > 0 (DC_EDOM); DC_ERANGE when
   1/sigma, cF or ck is not a finite normal number. *b untouched on error. */
int dc_gw_bound_init(const dc_hertz_geom *g, double Estar, double n_asp, double sigma, dc_gw_bound *b);

/* The material part of dc_gw_bound_init (no geometry bound yet: bind one
   with dc_gw_bound_bind before dc_gw_bound_force). Its domain (DC_EDOM);
   DC_ERANGE when 1/sigma is not a finite normal number. *b untouched on
   error. */
int dc_gw_bound_material(double Estar, double n_asp, double sigma, dc_gw_bound *b);

/* Binds geometry g to b (from dc_gw_bound_material or dc_gw_bound_init):
   the same bits as dc_gw_bound_init(g, ...) of b's material. DC_ERANGE
   when cF, ck or the material's n_asp E* products are not finite normal
   numbers: then cF and ck are set to
   +inf, so that dc_gw_bound_force takes dc_gw_rough_elliptic's checked
   form at every overlap. g is stored either way. */
static inline int dc_gw_bound_bind(dc_gw_bound *b, const dc_hertz_geom *g)
{
  /* dc_gw_rough_elliptic's products, in its order, without the F_n */
  const double sRc = sqrt(g->Rc);
  b->g = *g;
  b->cF = b->kF * sRc * b->sigma * b->ss * g->gamma;
  b->ck = b->kk * sRc * b->ss * g->gamma;
  /* (a subnormal n_asp E* product carries too few bits into cF and ck) */
  if (isnormal(b->cF) && isnormal(b->ck) && isnormal(b->kF) && isnormal(b->kk)) return DC_OK;
  b->cF = b->ck = HUGE_VAL;
  return DC_ERANGE;
}

/* F and kn = dF/d delta at overlap delta (finite, any sign): status and
   results as dc_gw_rough_elliptic (outputs untouched on error), except
   that where only its area overflows (DC_ERANGE there) this returns F and
   kn with DC_OK: it has no area. */
static inline int dc_gw_bound_force(const dc_gw_bound *b, double delta, double *F, double *kn)
{
  const double h = -delta * b->inv_sigma;
  if (h >= DC_GW_F32P_LO && h < DC_GW_F32P_HI) {
    double F32, F12;
    dc_gw_F32_F12(h, &F32, &F12);
    const double f = b->cF * F32, k = b->ck * F12;
    if (isfinite(f) && isfinite(k)) {
      *F = f;
      *kn = k;
      return DC_OK;
    }   /* a product overflowed: the checked form rescales or reports it */
  }
  dc_gw_rough_state s;
  const int st = dc_gw_rough_elliptic(&b->g, b->Estar, b->n_asp, b->sigma, delta, &s);
  if (st != DC_OK) return st;
  *F = s.F;
  *kn = s.kn;
  return DC_OK;
}

/* rms summit height of a contact of two rough surfaces with rms summit
   heights sigma_i, sigma_j >= 0 (independent Gaussian heights):
   sigma = (sigma_i^2 + sigma_j^2)^1/2. Inline, unchecked; hypot where the
   squares overflow or underflow (sigma beyond ~1e154 or below ~1e-154,
   which gave inf or 0). */
static inline double dc_gw_roughness_combine(double sigma_i, double sigma_j)
{
  const double s2 = sigma_i * sigma_i + sigma_j * sigma_j;
  return s2 >= DBL_MIN && s2 <= DBL_MAX ? sqrt(s2) : hypot(sigma_i, sigma_j);
}

/* The law contract's output (dc/contract.h) of a rough contact with force
   F and stiffness kn at overlap delta (any finite sign): the nominal
   (smooth) contact ellipse of geometry g at max(delta, 0), its area, formed
   while the rough force acts (F > 0), friction load max(F, 0). DC_EDOM for
   non-finite inputs or Estar <= 0 (c untouched). */
int dc_gw_rough_normal(const dc_hertz_geom *g, double Estar, double delta, double F, double kn, dc_contact *c);

/* Parameter check (dc/contract.h): asperityCount n_asp > 0 and finite. */
int dc_gw_rough_check(double n_asp, dc_param_error *err);

/* The rough-sphere law of one material pair, a setting: the Feng explicit
   law (dc/feng_rough.h; the default) or the law tabulated from the full
   solver (dc/gw_rough_table.h). Both take roughnessMu in [1, 50]. */
enum { DC_GW_SPHERE_FENG = 0, DC_GW_SPHERE_TABULATED = 1 };

typedef struct {
  int law;                  /* DC_GW_SPHERE_* */
  dc_feng_pair feng;        /* law == DC_GW_SPHERE_FENG (else zero) */
  dc_gw_table_pair table;   /* law == DC_GW_SPHERE_TABULATED (else zero) */
} dc_gw_sphere_pair;

/* Binds law (DC_GW_SPHERE_*; feng_variant DC_FENG_TABLE or DC_FENG_FITTED,
   read by the Feng law only) at mu to E* and sigma > 0: the status of
   dc_feng_init / dc_gw_table_init, then of the pair's init; DC_EDOM for
   another law. *p untouched on error. */
int dc_gw_sphere_pair_init(int law, int feng_variant, double mu, double Estar, double sigma,
                           dc_gw_sphere_pair *p);

/* Force and dP/d delta of the bound law at overlap delta (any sign),
   sqrtR = R^1/2: dc_feng_pair_force or dc_gw_table_pair_force, unchanged. */
static inline void dc_gw_sphere_pair_force(const dc_gw_sphere_pair *p, double sqrtR, double delta,
                                           double *P, double *kn)
{
  if (p->law == DC_GW_SPHERE_TABULATED) dc_gw_table_pair_force(&p->table, sqrtR, delta, P, kn);
  else dc_feng_pair_force(&p->feng, sqrtR, delta, P, kn);
}

/* The overlap, in units of sigma, at and below which the law's force is 0
   (a wrapper's contact reach): -3 (Feng Eq. 64) or -6 (tabulated). The
   laws scale delta by their rounded 1/sigma, so at delta = reach x sigma
   as a wrapper rounds it the force may be of rounding size (under 1e-15
   of 4/3 E* R^1/2 sigma^3/2); it is exactly 0 from
   reach x sigma x (1 + 8 DBL_EPSILON) down (tests/unit/test_fuzz.c). */
static inline double dc_gw_sphere_reach(int law)
{
  return law == DC_GW_SPHERE_TABULATED ? DC_GW_TABLE_X_LO : -3.0;
}

#ifdef __cplusplus
}
#endif
#endif
