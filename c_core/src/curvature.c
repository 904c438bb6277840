/* Principal curvatures of implicit surfaces and relative radii of contact
   (review Eqs. 3-10); see dc/curvature.h. */
#include "dc/curvature.h"
#include "dc/status.h"
#include <math.h>

void dc_tangent_basis(const double n[3], double u[3], double v[3])
{
  /* Frisvad / Duff et al. 2017 branchless orthonormal basis */
  const double s = copysign(1.0, n[2]);
  const double a = -1.0 / (s + n[2]);
  const double b = n[0] * n[1] * a;
  u[0] = 1.0 + s * n[0] * n[0] * a; u[1] = s * b; u[2] = -s * n[0];
  v[0] = b; v[1] = s + n[1] * n[1] * a; v[2] = -n[1];
}

static void matvec(const double H[9], const double x[3], double y[3])
{
  for (int i = 0; i < 3; i++) y[i] = H[3 * i] * x[0] + H[3 * i + 1] * x[1] + H[3 * i + 2] * x[2];
}

static double dot(const double a[3], const double b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

int dc_curvature_form(const double grad[3], const double hess[9],
                      const double u[3], const double v[3], double form[3])
{
  const double g = sqrt(dot(grad, grad));
  if (!(g > 0.0) || !isfinite(g)) return DC_EDOM;
  double Hu[3], Hv[3];
  matvec(hess, u, Hu);
  matvec(hess, v, Hv);
  const double inv_g = 1.0 / g;
  form[0] = dot(u, Hu) * inv_g;
  form[1] = 0.5 * (dot(u, Hv) + dot(v, Hu)) * inv_g;
  form[2] = dot(v, Hv) * inv_g;
  return DC_OK;
}

void dc_form_principal(const double form[3], double *k1, double *k2, double *theta)
{
  const double mean = 0.5 * (form[0] + form[2]);
  const double half = 0.5 * (form[0] - form[2]);
  const double r = sqrt(half * half + form[1] * form[1]);   /* curvatures: no overflow concern */
  *k1 = mean + r;
  *k2 = mean - r;
  if (theta) *theta = 0.5 * atan2(form[1], half);
}

static int radii_from_curvatures(double k_big, double k_small, double *R_major, double *R_minor)
{
  if (!(k_small > 0.0) || !isfinite(k_big)) return DC_EDOM;
  *R_major = 1.0 / k_small;
  *R_minor = 1.0 / k_big;
  return DC_OK;
}

int dc_form_relative_radii(const double form[3], double *R_major, double *R_minor)
{
  double k1, k2;
  dc_form_principal(form, &k1, &k2, 0);
  return radii_from_curvatures(k1, k2, R_major, R_minor);
}

int dc_relative_radii(double k1I, double k2I, double k1II, double k2II,
                      double omega, double *R_major, double *R_minor)
{
  const double sum = k1I + k2I + k1II + k2II;
  const double dI = k1I - k2I, dII = k1II - k2II;
  const double root = sqrt(fmax(0.0, dI * dI + dII * dII + 2.0 * dI * dII * cos(2.0 * omega)));
  /* Eq. 3: 1/R_i = (sum - root)/2, Eq. 4: 1/R_j = (sum + root)/2 */
  return radii_from_curvatures(0.5 * (sum + root), 0.5 * (sum - root), R_major, R_minor);
}

void dc_form_major_axis(const double form[3], const double u[3], const double v[3], double axis[3])
{
  double k1, k2;
  dc_form_principal(form, &k1, &k2, 0);
  /* (form - k2 I) x = 0: the two rows give (form1, k2 - form0) and
     (k2 - form2, form1); the longer is the better conditioned */
  double x = form[1], y = k2 - form[0];
  const double x2 = k2 - form[2], y2 = form[1];
  if (x2 * x2 + y2 * y2 > x * x + y * y) { x = x2; y = y2; }
  const double n = sqrt(x * x + y * y);
  if (!(n > 1e-12 * (fabs(k1) + fabs(k2))) || !isfinite(n)) {
    axis[0] = axis[1] = axis[2] = 0.0;
    return;
  }
  for (int k = 0; k < 3; k++) axis[k] = (x * u[k] + y * v[k]) / n;
}
