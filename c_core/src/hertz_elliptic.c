/* Elliptic Hertz contact: eccentricity, correction factors, force and area
   (review Eqs. 1-5, 11-14; conventions and seed corrections in the header). */
#include "dc/hertz_elliptic.h"
#include "dc/status.h"
#include "scaled_product.h"
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "hertz_geometry_poly.h"
#include "dc/poly14.h"

#if DC_HG_NROWS != DC_POLY14_NROWS || DC_HG_NLANES != 8
#error "hertz_geometry_poly.h: row or lane count differs from dc_poly14 and dc_hertz_geometry below"
#endif

int dc_hertz_eccentricity_approx(double ratio, double *e2)
{
  if (!(ratio >= DC_HERTZ_RATIO_MIN && ratio <= 1.0)) return DC_EDOM;
  /* review Eq. 14: a/b = -0.177 + (ln(16/r)/(2r))^1/2 + 0.16 ln r */
  const double a_over_b = -0.177 + sqrt(0.5 / ratio * log(16.0 / ratio)) + 0.16 * log(ratio);
  *e2 = fmax(0.0, 1.0 - 1.0 / (a_over_b * a_over_b));
  return DC_OK;
}

/* The variables of hertz_geometry_poly.h at r in [DC_HERTZ_RATIO_MIN, 1):
   t = ln r, its piece p (from the exponent and the two leading mantissa
   bits of u = DC_HG_TAU - t) and x = t - dc_hg_tc[p]. With r = 2^k m, m in
   [2^-1/2, 2^1/2), t = k ln 2 + ln m and x = (k LN2_HI - tc) + (ln m + k
   LN2_LO), the first bracket exact (fdlibm's split of ln 2): x is off by
   ~1e-16 however large |t|, where log(r) itself is off by up to 2e-15. */
typedef struct {
  double t, x;
  int p;
} hg_var;

static inline hg_var hg_variables(double r)
{
  static const double LN2_HI = 6.93147180369123816490e-01, LN2_LO = 1.90821492927058770002e-10;
  uint64_t b;
  memcpy(&b, &r, sizeof b);
  int k = (int)(b >> 52) - 1023;   /* r is normal and positive */
  b = (b & 0x000fffffffffffffull) | 0x3ff0000000000000ull;
  double m;
  memcpy(&m, &b, sizeof m);
  if (m > M_SQRT2) {
    m *= 0.5;
    k++;
  }
  const double th = k * LN2_HI, tl = log(m) + k * LN2_LO;
  hg_var v;
  v.t = th + tl;
  const double u = DC_HG_TAU - v.t;
  memcpy(&b, &u, sizeof b);
  const int p = (int)(b >> 50) - (1023 << 2) - 2;
  v.p = p < 0 ? 0 : p < DC_HG_PIECES ? p : DC_HG_PIECES - 1;
  v.x = (th - dc_hg_tc[v.p]) + tl;
  return v;
}

/* R_major (head + s) for the lane value head + s of R_force/R_major,
   |s| <= 0.22 head, R_major < 1e300: R_major split in halves of 26 bits
   (Veltkamp) makes both products with the 26-bit head exact, so the
   result has two small roundings and one at full size (< 0.75 ulp), not
   those of the lane value and of a product (1 ulp). */
static inline double r_force(double Rmaj, double head, double s)
{
  const double c = 134217729.0 * Rmaj, hi = c - (c - Rmaj), lo = Rmaj - hi;   /* 2^27 + 1 */
  return hi * head + (lo * head + Rmaj * s);
}

/* e^2 and 1 - e^2 from lane 0 (y0) at t = ln r in piece p: e^2 = -t y0 near
   the circle, 1 - e^2 = r y0 below; the other by one subtraction, which
   loses nothing (the one computed is below about 1/2). */
static inline void hg_eccentricity(int p, double t, double ratio, double y0, double *m, double *m1)
{
  if (p < DC_HG_TOP_PIECES) {
    *m = -t * y0;
    *m1 = 1.0 - *m;
  } else {
    *m1 = ratio * y0;
    *m = 1.0 - *m1;
  }
}

int dc_hertz_eccentricity(double ratio, double *e2, double *m1)
{
  if (!(ratio >= DC_HERTZ_RATIO_MIN && ratio <= 1.0)) return DC_EDOM;
  if (ratio == 1.0) {
    *e2 = 0.0;
    *m1 = 1.0;
    return DC_OK;
  }
  const hg_var v = hg_variables(ratio);
  double y0, s0;
  dc_poly14(&dc_hg_poly[v.p][0][0], DC_HG_NLANES, 1, v.x, &y0, &s0);
  hg_eccentricity(v.p, v.t, ratio, y0, e2, m1);
  return DC_OK;
}

int dc_hertz_geometry(double R1, double R2, dc_hertz_geom *out)
{
  if (!(R1 > 0.0 && R2 > 0.0 && isfinite(R1) && isfinite(R2))) return DC_EDOM;
  const double Rmaj = R1 > R2 ? R1 : R2, Rmin = R1 > R2 ? R2 : R1;
  const double ratio = Rmin / Rmaj;
  if (ratio < DC_HERTZ_RATIO_MIN) return DC_EDOM;
  dc_hertz_geom g;
  g.R_major = Rmaj;
  g.R_minor = Rmin;
  /* Eq. 5; where R_major R_minor would overflow or leave the normal range,
     the equal R_minor/(1 + ratio), which cannot */
  const double prod = Rmaj * Rmin;
  g.Rc = prod >= DBL_MIN && prod <= DBL_MAX ? prod / (Rmaj + Rmin) : Rmin / (1.0 + ratio);
  if (ratio == 1.0) {
    g.e2 = 0.0; g.m1 = 1.0;
    g.K = g.E = 0.5 * M_PI; g.D = 0.25 * M_PI;
    g.gamma = M_SQRT2; g.beta = 2.0;
    g.R_force = Rmaj;        /* = Rc gamma^2 exactly */
    g.R_area = Rmaj;         /* = Rc beta exactly */
    *out = g;
    return DC_OK;
  }
  /* every output from one evaluation of the lanes of hertz_geometry_poly.h
     at t = ln r (Eqs. 11-13 to an ulp or two): e^2 or 1 - e^2; B, E, D
     (K = B + D, so that K - D is B to a rounding); gamma and beta times
     r^1/2; R_force/R_major = gamma^2 r/(1 + r) and R_area/(R_major r^1/2)
     = beta r^1/2/(1 + r), both at most 1 (so R_force and R_area cannot
     overflow) */
  const hg_var v = hg_variables(ratio);
  const double sr = sqrt(ratio);
  double y[DC_HG_NLANES], s[DC_HG_NLANES];
  dc_poly14(&dc_hg_poly[v.p][0][0], DC_HG_NLANES, DC_HG_NLANES, v.x, y, s);
  hg_eccentricity(v.p, v.t, ratio, y[0], &g.e2, &g.m1);
  g.K = y[1] + y[3];   /* B + D */
  g.E = y[2];
  g.D = y[3];
  g.gamma = y[4] / sr;                                    /* Eq. 11 */
  g.beta = y[5] / sr;                                     /* Eq. 12 */
  g.R_force = y[6] >= 1.0 ? Rmaj : Rmaj < 1e300 ? r_force(Rmaj, dc_hg_poly[v.p][0][6], s[6]) : Rmaj * y[6];
  g.R_area = Rmaj * (y[7] * sr < 1.0 ? y[7] * sr : 1.0);
  *out = g;
  return DC_OK;
}


int dc_hertz_contact(const dc_hertz_geom *g, double Estar, double delta, dc_hertz_state *s)
{
  if (!(Estar > 0.0 && isfinite(Estar) && delta >= 0.0 && isfinite(delta))) return DC_EDOM;
  const double root = sqrt(g->R_force * delta);
  dc_hertz_state h;
  h.F = 4.0 / 3.0 * Estar * root * delta;                 /* Eq. 1 */
  h.kn = 2.0 * Estar * root;
  h.area = M_PI * g->R_area * delta;                      /* Eq. 2 */
  h.a = sqrt(2.0 * g->R_major * delta * g->D / g->K);
  h.b = h.a * sqrt(g->m1);
  /* where an intermediate product overflowed: the same expression without
     overflow before the end; DC_ERANGE if a result itself does */
  const double sR = sqrt(g->R_force), sd = sqrt(delta);
  if (!isfinite(h.F)) h.F = dc_scaled_product(5, (const double[]){4.0 / 3.0, Estar, sR, sd, delta});
  if (!isfinite(h.kn)) h.kn = dc_scaled_product(4, (const double[]){2.0, Estar, sR, sd});
  if (!isfinite(h.area)) h.area = dc_scaled_product(3, (const double[]){M_PI, g->R_area, delta});
  if (!isfinite(h.a)) {
    h.a = dc_scaled_product(3, (const double[]){sqrt(2.0 * g->D / g->K), sqrt(g->R_major), sd});
    h.b = h.a * sqrt(g->m1);
  }
  if (!(isfinite(h.F) && isfinite(h.kn) && isfinite(h.area) && isfinite(h.a))) return DC_ERANGE;
  *s = h;
  return DC_OK;
}

int dc_hertz_normal(const dc_hertz_geom *g, double Estar, double delta, dc_contact *c)
{
  dc_hertz_state s = {0.0, 0.0, 0.0, 0.0, 0.0};
  if (!isfinite(delta)) return DC_EDOM;
  if (delta > 0.0) {
    const int st = dc_hertz_contact(g, Estar, delta, &s);
    if (st != DC_OK) return st;
  } else if (!(Estar > 0.0 && isfinite(Estar))) {
    return DC_EDOM;
  }
  c->F = c->F_bound = s.F;
  c->kn = s.kn;
  c->area = s.area;
  c->a = s.a;
  c->b = s.b;
  c->formed = delta > 0.0;
  return DC_OK;
}
