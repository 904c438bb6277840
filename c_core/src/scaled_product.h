/* A product of several factors without overflow or underflow before the
   end, for the laws' out-of-range fallbacks (private to c_core/src). */
#ifndef DC_SCALED_PRODUCT_H
#define DC_SCALED_PRODUCT_H

#include <math.h>

/* x[0] x[1] ... x[n-1]: mantissas multiplied, exponents summed, one
   scaling (rounded as the plain product would be when that stays in
   range). */
static inline double dc_scaled_product(int n, const double *x)
{
  double m = 1.0;
  int e = 0;
  for (int i = 0; i < n; i++) {
    int k;
    m *= frexp(x[i], &k);
    e += k;
    m = frexp(m, &k);
    e += k;
  }
  return ldexp(m, e);
}

/* The rough-sphere laws' scales: P = 4/3 E* R^1/2 L^3/2 Pu and
   kn = 4/3 E* R^1/2 L^1/2 knu, from a reduced force Pu and stiffness knu
   in units of the length L, without intermediate overflow. */
static inline void dc_rough_sphere_scale(double Estar, double R, double L, double Pu, double knu, double *P,
                                         double *kn)
{
  const double sR = sqrt(R), sL = sqrt(L);
  *P = dc_scaled_product(6, (const double[]){4.0 / 3.0, Estar, sR, L, sL, Pu});
  *kn = dc_scaled_product(5, (const double[]){4.0 / 3.0, Estar, sR, sL, knu});
}

/* Hertz force and dF/d delta of a sphere of effective radius R at overlap
   delta (0 for delta <= 0), the rough-sphere laws' sigma = 0 limit: plain
   products, scaled where they leave the doubles. */
static inline void dc_rough_sphere_hertz(double Estar, double R, double delta, double *P, double *kn)
{
  const double c = 4.0 / 3.0 * Estar * sqrt(R), sd = delta > 0.0 ? sqrt(delta) : 0.0;
  *P = c * fmax(delta, 0.0) * sd;
  *kn = 1.5 * c * sd;
  if (!(isfinite(*P) && isfinite(*kn))) {
    *P = dc_scaled_product(5, (const double[]){4.0 / 3.0, Estar, sqrt(R), fmax(delta, 0.0), sd});
    *kn = dc_scaled_product(4, (const double[]){2.0, Estar, sqrt(R), sd});
  }
}

#endif
