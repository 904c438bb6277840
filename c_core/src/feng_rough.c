/* Feng et al. (2016) explicit rough-sphere law, Eq. 75 with Tables 4-6;
   variants, continuity treatment and seed notes in dc/feng_rough.h. */
#include "dc/feng_rough.h"
#include "dc/status.h"
#include "scaled_product.h"
#include <float.h>
#include <math.h>
#include <string.h>

const double dc_feng_mu_nodes[7] = {1, 2, 4, 10, 20, 35, 50};
/* Table 4 (Case I), rows b0..b3 */
const double dc_feng_table_I[4][7] = {
  {1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0},
  {-1.5786, -0.7621, -0.0452, 0.7680, 1.3038, 1.6977, 1.9339},
  {2.8588, 2.1478, 1.7448, 1.5438, 1.5539, 1.6284, 1.6988},
  {-1.2721, -0.9086, -0.6837, -0.5233, -0.4649, -0.4426, -0.4368}};
/* Table 5 (Case II), rows b0..b2 */
const double dc_feng_table_II[3][7] = {
  {0.3011, 0.4989, 0.7672, 1.2141, 1.6022, 1.9357, 2.1544},
  {0.4700, 0.7181, 0.9924, 1.3494, 1.5991, 1.7869, 1.9010},
  {0.2370, 0.2601, 0.2563, 0.2250, 0.1914, 0.1610, 0.1404}};
/* Table 6 (Case III), rows b0..b4 */
const double dc_feng_table_III[5][7] = {
  {0.3011, 0.4989, 0.7672, 1.2141, 1.6022, 1.9357, 2.1544},
  {0.4385, 0.6638, 0.8981, 1.1507, 1.2872, 1.3770, 1.4295},
  {0.2431, 0.3227, 0.3460, 0.2440, 0.1058, 0.0012, -0.0516},
  {0.0604, 0.0665, 0.0408, -0.0498, -0.1316, -0.1810, -0.1999},
  {0.0057, 0.0047, -0.0010, -0.0161, -0.0277, -0.0333, -0.0345}};

static const double nodes_I[4] = {0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0};
static const double nodes_II[3] = {0.0, 0.5, 1.0};
static const double nodes_III[5] = {-3.0, -2.25, -1.5, -0.75, 0.0};

static double poly(const double *c, int n, double x)
{
  double s = c[n - 1];
  for (int k = n - 2; k >= 0; k--) s = fma(s, x, c[k]);
  return s;
}

/* monomial coefficients of the interpolant through (x_k, y_k), k < n <= 5 */
static void interp_coeffs(const double *x, const double *y, int n, double *c)
{
  double d[5];
  memcpy(d, y, n * sizeof *d);
  for (int j = 1; j < n; j++)               /* Newton divided differences */
    for (int i = n - 1; i >= j; i--) d[i] = (d[i] - d[i - 1]) / (x[i] - x[i - j]);
  for (int k = 0; k < n; k++) c[k] = 0.0;
  c[0] = d[n - 1];
  for (int i = n - 2; i >= 0; i--) {        /* Horner on the Newton form */
    for (int k = n - 1; k >= 1; k--) c[k] = c[k - 1] - x[i] * c[k];
    c[0] = d[i] - x[i] * c[0];
  }
}

/* Fritsch-Carlson monotone cubic through (t_i, v_i), i < 7, at t. */
static double pchip(const double *t, const double *v, double x)
{
  double h[6], del[6], m[7];
  for (int i = 0; i < 6; i++) { h[i] = t[i + 1] - t[i]; del[i] = (v[i + 1] - v[i]) / h[i]; }
  for (int i = 1; i < 6; i++) {
    if (del[i - 1] * del[i] <= 0.0) { m[i] = 0.0; continue; }
    const double w1 = 2 * h[i] + h[i - 1], w2 = h[i] + 2 * h[i - 1];
    m[i] = (w1 + w2) / (w1 / del[i - 1] + w2 / del[i]);
  }
  /* one-sided three-point end slopes, limited (as in Moler's pchip) */
  for (int e = 0; e < 2; e++) {
    const int i = e ? 5 : 0, j = e ? 4 : 1, k = e ? 6 : 0;
    double s = ((2 * h[i] + h[j]) * del[i] - h[i] * del[j]) / (h[i] + h[j]);
    if (s * del[i] <= 0) s = 0;
    else if (del[i] * del[j] <= 0 && fabs(s) > 3 * fabs(del[i])) s = 3 * del[i];
    m[k] = s;
  }
  int i = 0;
  while (i < 5 && x > t[i + 1]) i++;
  const double s = (x - t[i]) / h[i], s2 = s * s, s3 = s2 * s;
  return v[i] * (2 * s3 - 3 * s2 + 1) + h[i] * m[i] * (s3 - 2 * s2 + s) +
         v[i + 1] * (-2 * s3 + 3 * s2) + h[i] * m[i + 1] * (s3 - s2);
}

static void table_variant(double mu, dc_feng_law *law)
{
  double t[7];
  for (int i = 0; i < 7; i++) t[i] = log(dc_feng_mu_nodes[i]);
  const double x = log(mu);
  double vI[4], vII[3], vIII[5];
  for (int k = 0; k < 3; k++) {             /* Case II first: shares nodes */
    double v[7];
    for (int i = 0; i < 7; i++) {
      const double c[3] = {dc_feng_table_II[0][i], dc_feng_table_II[1][i], dc_feng_table_II[2][i]};
      v[i] = poly(c, 3, nodes_II[k]);
    }
    vII[k] = pchip(t, v, x);
  }
  for (int k = 0; k < 4; k++) {
    double v[7];
    for (int i = 0; i < 7; i++) {
      const double c[4] = {dc_feng_table_I[0][i], dc_feng_table_I[1][i], dc_feng_table_I[2][i], dc_feng_table_I[3][i]};
      v[i] = poly(c, 4, nodes_I[k]);
    }
    vI[k] = pchip(t, v, x);
  }
  vI[0] = 1.0;        /* Eq. 68 */
  vI[3] = vII[2];     /* shared node alpha = alpha' = 1 (Eq. 65) */
  for (int k = 0; k < 5; k++) {
    double v[7];
    for (int i = 0; i < 7; i++) {
      const double c[5] = {dc_feng_table_III[0][i], dc_feng_table_III[1][i], dc_feng_table_III[2][i],
                           dc_feng_table_III[3][i], dc_feng_table_III[4][i]};
      v[i] = poly(c, 5, nodes_III[k]);
    }
    vIII[k] = pchip(t, v, x);
  }
  vIII[4] = vII[0];   /* shared node alpha' = 0 (Eq. 65) */
  interp_coeffs(nodes_I, vI, 4, law->b1);
  interp_coeffs(nodes_II, vII, 3, law->b2);
  interp_coeffs(nodes_III, vIII, 5, law->b3);
}

static void fitted_variant(double mu, dc_feng_law *law)
{
  const double L = log(mu);
  /* Table 5 */
  law->b2[0] = -0.398 * L + 5.965 * pow(mu, 0.1163) - 5.677;
  law->b2[1] = 0.371 * L + 0.478 * pow(mu, -0.0015);
  law->b2[2] = 0.004858 * exp(0.0514 * mu) - 0.0035 * mu + 0.2526;
  /* Table 4 */
  law->b1[0] = 1.0;
  law->b1[1] = 1.55 * L - 1.60 * pow(mu, 0.2442);
  law->b1[2] = 1.52 / mu + 0.00655 * mu + 1.35;
  law->b1[3] = -0.055 * L - 1.15 * pow(mu, -0.619) - 0.12;
  /* continuity at alpha = 1: b3 absorbs P2*(1) - P1*(1) */
  law->b1[3] += poly(law->b2, 3, 1.0) - poly(law->b1, 4, 1.0);
  /* Table 6, b0 replaced by Case II's for continuity at alpha' = 0
     (Table 6's own: 0.2284 ln mu + 0.2769 mu^0.3913) */
  law->b3[0] = law->b2[0];
  law->b3[1] = 0.4998 * L - 0.5067 * pow(mu, 0.2724) + 0.9405;
  law->b3[2] = -0.8103 * exp(-0.6351 * mu) - 9.211 * pow(mu, 0.01958) + 9.881;
  law->b3[3] = 0.5035 * exp(-0.03976 * mu) + 0.0029 * mu - 0.4124;
  law->b3[4] = 0.05555 * exp(-0.06902 * mu) + 0.0001782 * mu - 0.04497;
}

int dc_feng_init(double mu, int variant, dc_feng_law *law)
{
  if (!(mu >= DC_FENG_MU_MIN && mu <= DC_FENG_MU_MAX) || (variant != DC_FENG_TABLE && variant != DC_FENG_FITTED))
    return DC_EDOM;
  law->mu = mu;
  if (variant == DC_FENG_TABLE) table_variant(mu, law);
  else fitted_variant(mu, law);
  law->p3m3 = poly(law->b3, 5, -3.0);
  memcpy(law->c3, law->b3, sizeof law->c3);
  law->c3[4] -= law->p3m3 / 81.0;           /* (alpha'/-3)^4 = alpha'^4 / 81 */
  return DC_OK;
}

int dc_feng_pair_init(const dc_feng_law *law, double Estar, double sigma, dc_feng_pair *p)
{
  if (!(Estar > 0 && isfinite(Estar) && sigma > 0 && isfinite(sigma))) return DC_EDOM;
  const double c = 4.0 / 3.0 * Estar, inv_sigma = 1.0 / sigma, c_sigma = c * sigma * sqrt(sigma);
  /* the kernel needs these as normal numbers (sigma subnormal: 1/sigma
     overflows) */
  if (!(isfinite(c) && isfinite(inv_sigma) && c_sigma >= DBL_MIN && c_sigma <= DBL_MAX)) return DC_ERANGE;
  p->law = *law;
  p->c = c;
  p->sigma = sigma;
  p->inv_sigma = inv_sigma;
  p->c_sigma = c_sigma;
  return DC_OK;
}

double dc_feng_P1(const dc_feng_law *law, double alpha)
{
  return poly(law->b1, 4, alpha);
}

double dc_feng_pstar_sigma(const dc_feng_law *law, double ap)
{
  /* the kernel in units sigma = 1, P_h(sigma) = 1 (c = 1, R = 1) */
  const dc_feng_pair unit = {*law, 1.0, 1.0, 1.0, 1.0};
  double P, kn;
  dc_feng_pair_force(&unit, 1.0, ap, &P, &kn);
  return P;
}


/* Eq. 75 for finite inputs in the domain with sigma > 0, where the bound
   pair's constants or the kernel's products leave the range of doubles:
   the kernel in units of the length L (delta in Case I, sigma otherwise)
   and of the force c R^1/2 L^3/2, then the scales applied without
   intermediate overflow. */
static void feng_force_scaled(const dc_feng_law *law, double Estar, double R, double sigma, double delta,
                              double *P, double *kn)
{
  double L, Pu, knu;
  if (delta >= sigma) {                      /* Case I at alpha = sigma/delta <= 1 */
    const dc_feng_pair unit = {*law, 1.0, sigma / delta, 0.0, 1.0};
    dc_feng_pair_force(&unit, 1.0, 1.0, &Pu, &knu);
    L = delta;
  } else {                                   /* Cases II-IV at alpha' = delta/sigma */
    const dc_feng_pair unit = {*law, 1.0, 1.0, 1.0, 1.0};
    dc_feng_pair_force(&unit, 1.0, delta / sigma, &Pu, &knu);
    L = sigma;
  }
  dc_rough_sphere_scale(Estar, R, L, Pu, knu, P, kn);
}

int dc_feng_force(const dc_feng_law *law, double Estar, double R, double sigma,
                  double delta, double *P, double *kn)
{
  if (!(Estar > 0 && isfinite(Estar) && R > 0 && isfinite(R) && sigma >= 0 &&
        isfinite(sigma) && isfinite(delta)))
    return DC_EDOM;
  double Pv, knv;
  if (sigma == 0.0) {                         /* Hertz */
    dc_rough_sphere_hertz(Estar, R, delta, &Pv, &knv);
  } else {
    dc_feng_pair p;
    Pv = knv = NAN;
    if (dc_feng_pair_init(law, Estar, sigma, &p) == DC_OK) dc_feng_pair_force(&p, sqrt(R), delta, &Pv, &knv);
    if (!(isfinite(Pv) && isfinite(knv))) feng_force_scaled(law, Estar, R, sigma, delta, &Pv, &knv);
  }
  if (!(isfinite(Pv) && isfinite(knv))) return DC_ERANGE;
  *P = Pv;
  *kn = knv;
  return DC_OK;
}

int dc_feng_check(double mu, dc_param_error *err)
{
  return dc_param_check("roughnessMu", mu, DC_FENG_MU_MIN, 0, DC_FENG_MU_MAX, 0, "[1, 50]", err);
}
