/* Greenwood-Williamson height integrals F_n(h), n = 0, 1/2, 1, 3/2: fast
   piecewise-Chebyshev path and the Bessel closed forms (formulas, seed
   corrections and accuracy in dc/gw_integrals.h). */
#include "dc/gw_integrals.h"
#include "dc/status.h"
#include "gw_integrals_cheb.h"
#include "gw_F32_poly.h"
#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_bessel.h>
#include <gsl/gsl_sf_erf.h>
#include <math.h>

#define SQRT_2PI 2.5066282746310005024
#define SQRT_PI 1.7724538509055160273

/* exp(-h^2/2) with h^2 split exactly (fma), so the rounding of h*h does not
   cost log10(h^2) digits at large h. */
static double exp_mhh2(double h)
{
  if (fabs(h) > 40.0) return 0.0;   /* below the subnormals; h^2 may overflow */
  const double hh = h * h, err = fma(h, h, -hh);
  return exp(-0.5 * hh) * (1.0 - 0.5 * err);
}

/* F_n(0) = 2^{n/2} Gamma((n+1)/2) / (2 sqrt pi), n = 0, 1/2, 1, 3/2. */
static const double F_at_zero[4] = {
  0.5, 0.41108947933122927617, 0.39894228040143267794, 0.43001999366225976769};
/* Gamma(n+1) for the large-h series. */
static const double gamma_n1[4] = {
  1.0, 0.88622692545275801365, 1.0, 1.3293403881791370205};

/* Clenshaw's recurrence. fma() rounds once wherever it runs, so the clone
   for processors with FMA instructions (chosen at load time) returns the
   same bits as the default one, which calls the library's fma, only
   faster. */
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__clang__)
#define DC_FMA_CLONES __attribute__((target_clones("fma", "default")))
#else
#define DC_FMA_CLONES
#endif

DC_FMA_CLONES static double clenshaw(const double *c, double x)
{
  double b1 = 0.0, b2 = 0.0;
  const double x2 = 2.0 * x;
  for (int j = DC_GW_CHEB_NCOEF - 1; j >= 1; j--) {
    const double t = fma(x2, b1, c[j] - b2);
    b2 = b1;
    b1 = t;
  }
  return fma(x, b1, c[0] - b2);
}

/* the four orders' recurrences side by side on one interval (independent
   chains: each gives the bits of clenshaw) */
DC_FMA_CLONES static void clenshaw4(int k, double x, double out[4])
{
  double b1[4] = {0.0, 0.0, 0.0, 0.0}, b2[4] = {0.0, 0.0, 0.0, 0.0};
  const double x2 = 2.0 * x;
  for (int j = DC_GW_CHEB_NCOEF - 1; j >= 1; j--)
    for (int o = 0; o < 4; o++) {
      const double t = fma(x2, b1[o], dc_gw_cheb[o][k][j] - b2[o]);
      b2[o] = b1[o];
      b1[o] = t;
    }
  for (int o = 0; o < 4; o++) out[o] = fma(x, b1[o], dc_gw_cheb[o][k][0] - b2[o]);
}

/* h < DC_GW_CHEB_HLO: F_n = sum_j C(n,2j) (2j-1)!! x^{n-2j}, x = -h;
   ratio of terms (n-2j)(n-2j-1)/((2j+2) x^2). Terminates for n = 0, 1. */
static double series_negative(int order, double x)
{
  const double n = 0.5 * order, ix2 = 1.0 / (x * x);
  double term = 1.0, sum = 1.0;
  for (int j = 0; j < 40; j++) {
    term *= (n - 2 * j) * (n - 2 * j - 1) / (2 * j + 2) * ix2;
    sum += term;
    if (fabs(term) < 1e-18 * sum) break;
  }
  const double xn = order == 0 ? 1.0 : order == 1 ? sqrt(x) : order == 2 ? x : x * sqrt(x);
  return xn * sum;
}

/* h >= DC_GW_CHEB_HHI: G_n = F_n/phi = sum_k (-1/2)^k/k! Gamma(n+2k+1) h^-(n+2k+1);
   ratio -(n+2k+1)(n+2k+2)/(2(k+1)h^2). Asymptotic; at h >= 20 the terms fall
   below 1e-18 long before they start to grow. */
static double series_G_large(int order, double h)
{
  const double n = 0.5 * order, ih2 = 1.0 / (h * h);
  double term = 1.0, sum = 1.0;
  for (int k = 0; k < 40; k++) {
    term *= -(n + 2 * k + 1) * (n + 2 * k + 2) / (2 * (k + 1)) * ih2;
    sum += term;
    if (fabs(term) < 1e-18 * sum) break;
  }
  const double hn1 = order == 0 ? h : order == 1 ? h * sqrt(h) : order == 2 ? h * h : h * h * sqrt(h);
  return gamma_n1[order] * sum / hn1;
}

static double large_h(int order, double h)
{
  if (h > 40.0) return 0.0;  /* F < phi(40) < 1e-348: below the subnormals */
  /* F = e^{-h^2/4} (e^{-h^2/4} G/sqrt(2 pi)): each factor stays normal up to
     h = 40, so the product underflows gradually, never to garbage */
  const double hh = h * h, err = fma(h, h, -hh), e4 = exp(-0.25 * hh);
  return e4 * (e4 * series_G_large(order, h) / SQRT_2PI) * (1.0 - 0.5 * err);
}

int dc_gw_F(int order, double h, double *F)
{
  if (order < 0 || order > 3 || !(h >= DC_GW_H_MIN) || !isfinite(h)) return DC_EDOM;
  if (h < DC_GW_CHEB_HLO) {
    *F = series_negative(order, -h);
  } else if (h < 0.0) {
    const double fl = floor(h);
    *F = clenshaw(dc_gw_cheb[order][(int)fl - DC_GW_CHEB_HLO], 2.0 * (h - fl) - 1.0);
  } else if (h < DC_GW_CHEB_HHI) {
    const double fl = floor(h), scale = exp_mhh2(h) / SQRT_2PI;
    *F = clenshaw(dc_gw_cheb[order][(int)fl - DC_GW_CHEB_HLO], 2.0 * (h - fl) - 1.0) * scale;
  } else {
    *F = large_h(order, h);
  }
  return DC_OK;
}

int dc_gw_F_all(double h, double F[4])
{
  if (!(h >= DC_GW_H_MIN) || !isfinite(h)) return DC_EDOM;
  if (h < DC_GW_CHEB_HLO) {
    for (int o = 0; o < 4; o++) F[o] = series_negative(o, -h);
  } else if (h < DC_GW_CHEB_HHI) {
    const double fl = floor(h), x = 2.0 * (h - fl) - 1.0;
    const int k = (int)fl - DC_GW_CHEB_HLO;
    const double scale = h < 0.0 ? 1.0 : exp_mhh2(h) / SQRT_2PI;
    clenshaw4(k, x, F);
    for (int o = 0; o < 4; o++) F[o] *= scale;
  } else {
    for (int o = 0; o < 4; o++) F[o] = large_h(o, h);
  }
  return DC_OK;
}

/* F_3/2 and F_1/2 from the degree-9 pieces of gw_F32_poly.h (Estrin's
   scheme; the terms fall fast, |t| <= 1) */
#if DC_GW_F32P_NCOEF != 10 || DC_GW_F32P_NPIECE != 104 || DC_GW_F32P_PER_UNIT != 8
#error "gw_F32_poly.h: piece layout differs from dc_gw_F32_F12"
#endif
static inline double poly9(const double *c, double t, double t2, double t4)
{
  const double a0 = c[0] + c[1] * t, a1 = c[2] + c[3] * t, a2 = c[4] + c[5] * t;
  const double a3 = c[6] + c[7] * t, a4 = c[8] + c[9] * t;
  return (a0 + a1 * t2) + ((a2 + a3 * t2) + a4 * t4) * t4;
}

int dc_gw_F32_F12(double h, double *F32, double *F12)
{
  /* [LO, HI) = the pieces' [H_LO, H_LO + NPIECE/PER_UNIT) (test_gw_integrals) */
  if (h >= DC_GW_F32P_LO && h < DC_GW_F32P_HI) {
    const double u = (h - DC_GW_F32P_H_LO) * DC_GW_F32P_PER_UNIT;
    int p = (int)u;
    if (p > DC_GW_F32P_NPIECE - 1) p = DC_GW_F32P_NPIECE - 1;   /* u rounded up to the end */
    /* h - h_p exact (h_p a multiple of 1/8, |h - h_p| < 1/8 up to the
       rounding of u): t carries no rounding of h + 10 */
    const double t = 2.0 * DC_GW_F32P_PER_UNIT * (h - (DC_GW_F32P_H_LO + (double)p / DC_GW_F32P_PER_UNIT)) - 1.0;
    const double t2 = t * t, t4 = t2 * t2;
    *F32 = poly9(dc_gw_f32_poly[p][0], t, t2, t4);
    *F12 = poly9(dc_gw_f32_poly[p][1], t, t2, t4);
    return DC_OK;
  }
  double F[4];
  const int st = dc_gw_F_all(h, F);
  if (st != DC_OK) return st;
  *F32 = F[DC_GW_F32];
  *F12 = F[DC_GW_F12];
  return DC_OK;
}

/* ---- closed forms (GSL) ---- */

int dc_gw_F_closed(int order, double h, double *Fout)
{
  if (order < 0 || order > 3 || !(h >= DC_GW_H_MIN) || !isfinite(h)) return DC_EDOM;
  double F;
  if (order == 0 || order == 2) {
    /* erfc(t) is 2 below t = -28 and 0 above 28 to the last bit (GSL's
       erfc returns NaN for |t| beyond ~1e82) */
    const double t = h / M_SQRT2;
    const double F0 = t > 28.0 ? 0.0 : t < -28.0 ? 1.0 : 0.5 * gsl_sf_erfc(t);
    F = order == 0 ? F0 : exp_mhh2(h) / SQRT_2PI - h * F0;
    *Fout = F;
    return DC_OK;
  }
  /* |h| < 1e-20: F_n(h) = F_n(0) (1 + O(1e-20)), and the Bessel forms fail
     where h^2/4 underflows */
  if (fabs(h) < 1e-20) { *Fout = F_at_zero[order]; return DC_OK; }
  gsl_error_handler_t *old = gsl_set_error_handler_off();
  gsl_sf_result r14, r34, i14, i34;
  int st;
  if (h > 0.0) {
    const double z = 0.25 * h * h;
    if (h > 40.0) { gsl_set_error_handler(old); *Fout = 0.0; return DC_OK; }
    st = gsl_sf_bessel_Knu_scaled_e(0.25, z, &r14) | gsl_sf_bessel_Knu_scaled_e(0.75, z, &r34);
    /* e^{-h^2/4} K(z) = e^{-h^2/2} Kscaled(z) */
    const double pre = exp_mhh2(h) / (4.0 * SQRT_PI);
    if (order == 1)
      F = pre * h * sqrt(h) * (r34.val - r14.val);
    else
      F = pre * sqrt(h) * ((h * h + 1.0) * r14.val - h * h * r34.val);
  } else {
    const double x = -h, z = 0.25 * x * x;
    st = gsl_sf_bessel_Inu_scaled_e(0.25, z, &i14) | gsl_sf_bessel_Inu_scaled_e(0.75, z, &i34);
    /* I_-nu = I_nu + (sqrt 2/pi) K_nu for nu = 1/4, 3/4; scaled by e^{-z} */
    double k14 = 0.0, k34 = 0.0;
    if (z < 350.0) {
      st |= gsl_sf_bessel_Knu_scaled_e(0.25, z, &r14) | gsl_sf_bessel_Knu_scaled_e(0.75, z, &r34);
      const double e2z = exp(-2.0 * z) * M_SQRT2 / M_PI;
      k14 = e2z * r14.val;
      k34 = e2z * r34.val;
    }
    const double Fm = sqrt(M_PI / 8.0) * sqrt(x) * (2.0 * i14.val + k14);
    const double Fh = SQRT_2PI / 8.0 * x * sqrt(x) * (2.0 * i14.val + 2.0 * i34.val + k14 + k34);
    F = order == 1 ? Fh : 0.5 * Fm + x * Fh;
  }
  gsl_set_error_handler(old);
  /* a GSL failure (none seen over the domain): DC_ERANGE, output untouched */
  if (st || !isfinite(F)) return DC_ERANGE;
  *Fout = F;
  return DC_OK;
}
