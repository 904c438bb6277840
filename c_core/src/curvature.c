/* Principal curvatures of implicit surfaces and relative radii of contact
   (review Eqs. 3-10); see dc/curvature.h. */
#include "dc/curvature.h"
#include "dc/status.h"
#include <float.h>
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

/* Binary exponent e of the largest |x_i| (max |x_i| = m 2^e, m in [1/2, 1));
   0 when all are zero. Scaling by 2^-e is exact. */
static int max_exponent(const double *x, int n)
{
  double m = 0.0;
  for (int i = 0; i < n; i++) m = fmax(m, fabs(x[i]));
  int e = 0;
  frexp(m, &e);
  return e;
}

static int all_finite(const double *x, int n)
{
  for (int i = 0; i < n; i++)
    if (!isfinite(x[i])) return 0;
  return 1;
}

/* The form on scaled copies (H 2^-eH, u 2^-eu, v 2^-ev, grad 2^-eg), where
   no product leaves the range of doubles, scaled back at the end. */
static void curvature_form_scaled(const double grad[3], const double hess[9], const double u[3],
                                  const double v[3], double form[3])
{
  const int eg = max_exponent(grad, 3), eH = max_exponent(hess, 9);
  const int eu = max_exponent(u, 3), ev = max_exponent(v, 3);
  double gs[3], Hs[9], us[3], vs[3], Hu[3], Hv[3];
  for (int i = 0; i < 3; i++) {
    gs[i] = ldexp(grad[i], -eg);
    us[i] = ldexp(u[i], -eu);
    vs[i] = ldexp(v[i], -ev);
  }
  for (int i = 0; i < 9; i++) Hs[i] = ldexp(hess[i], -eH);
  matvec(Hs, us, Hu);
  matvec(Hs, vs, Hv);
  const double inv_g = 1.0 / sqrt(dot(gs, gs));
  form[0] = ldexp(dot(us, Hu) * inv_g, eH + 2 * eu - eg);
  form[1] = ldexp(0.5 * (dot(us, Hv) + dot(vs, Hu)) * inv_g, eH + eu + ev - eg);
  form[2] = ldexp(dot(vs, Hv) * inv_g, eH + 2 * ev - eg);
}

int dc_curvature_form(const double grad[3], const double hess[9],
                      const double u[3], const double v[3], double out[3])
{
  /* common case first: |grad f|^2 normal and finite (so is grad), u and v
     finite, a finite form. A non-finite entry of hess cannot give one (it
     reaches every form entry through a product, inf * 0 = NaN), so the
     full checks below are needed only when this path fails */
  const double g2f = dot(grad, grad);
  if (g2f >= DBL_MIN && g2f <= DBL_MAX) {
    double Hu[3], Hv[3];
    matvec(hess, u, Hu);
    matvec(hess, v, Hv);
    const double inv_g = 1.0 / sqrt(g2f);
    const double f0 = dot(u, Hu) * inv_g, f1 = 0.5 * (dot(u, Hv) + dot(v, Hu)) * inv_g, f2 = dot(v, Hv) * inv_g;
    /* one test: a non-finite entry makes the sum non-finite (a sum that
       overflows only sends a finite form to the general path), and a
       non-finite u or v makes f0 or f2 so (each squared entry meets a
       diagonal Hessian entry: inf or, against a 0, NaN) */
    if (isfinite(f0 + f1 + f2)) {
      out[0] = f0;
      out[1] = f1;
      out[2] = f2;
      return DC_OK;
    }
  }
  if (!(all_finite(grad, 3) && all_finite(hess, 9) && all_finite(u, 3) && all_finite(v, 3))) return DC_EDOM;
  if (grad[0] == 0.0 && grad[1] == 0.0 && grad[2] == 0.0) return DC_EDOM;
  const double g2 = dot(grad, grad);
  double form[3];
  if (g2 >= DBL_MIN && g2 <= DBL_MAX) {
    const double g = sqrt(g2);
    double Hu[3], Hv[3];
    matvec(hess, u, Hu);
    matvec(hess, v, Hv);
    const double inv_g = 1.0 / g;
    form[0] = dot(u, Hu) * inv_g;
    form[1] = 0.5 * (dot(u, Hv) + dot(v, Hu)) * inv_g;
    form[2] = dot(v, Hv) * inv_g;
    if (!all_finite(form, 3)) curvature_form_scaled(grad, hess, u, v, form);
  } else {
    /* |grad f|^2 overflows or underflows although |grad f| need not */
    curvature_form_scaled(grad, hess, u, v, form);
  }
  if (!all_finite(form, 3)) return DC_ERANGE;
  out[0] = form[0];
  out[1] = form[1];
  out[2] = form[2];
  return DC_OK;
}

/* |x|^k for an integer k in [0, 14] */
static inline double pow_abs_int(double x, int k)
{
  const double a = fabs(x), a2 = a * a;
  switch (k) {
  case 0: return 1.0;
  case 1: return a;
  case 2: return a2;
  case 3: return a2 * a;
  case 4: return a2 * a2;
  default: {
    double r = a2 * a2;
    for (int i = 4; i < k; i++) r *= a;
    return r;
  }
  }
}

int dc_superquadric_form(const double shape[3], const double blockiness[2], const double p[3],
                         const double u[3], const double v[3], double out[3])
{
  const double n1 = blockiness[0], n2 = blockiness[1];
  if (!(shape[0] > 0.0 && shape[1] > 0.0 && shape[2] > 0.0 && shape[0] <= DBL_MAX && shape[1] <= DBL_MAX &&
        shape[2] <= DBL_MAX && n1 >= 2.0 && n1 <= 1e3 && n2 >= 2.0 && n2 <= 1e3))
    return DC_EDOM;
  const double ia = 1.0 / shape[0], ib = 1.0 / shape[1], ic = 1.0 / shape[2];
  const double xa = p[0] * ia, yb = p[1] * ib, zc = p[2] * ic;
  /* |x/a|^(n2-2), |y/b|^(n2-2), |z/c|^(n1-2), then one power higher */
  double X2, Y2, Z2;
  const int k1 = (int)n1, k2 = (int)n2;
  if (k1 == n1 && k2 == n2 && k1 <= 16 && k2 <= 16) {   /* exponents k - 2 <= 14 */
    X2 = pow_abs_int(xa, k2 - 2);
    Y2 = pow_abs_int(yb, k2 - 2);
    Z2 = pow_abs_int(zc, k1 - 2);
  } else {
    X2 = pow(fabs(xa), n2 - 2.0);
    Y2 = pow(fabs(yb), n2 - 2.0);
    Z2 = pow(fabs(zc), n1 - 2.0);
  }
  const double X1 = X2 * fabs(xa), Y1 = Y2 * fabs(yb), Z1 = Z2 * fabs(zc);
  /* S = |x/a|^n2 + |y/b|^n2; P1 = S^(n1/n2 - 1), P2 = (n1 - n2) S^(n1/n2 - 2) */
  double P1 = 1.0, P2 = 0.0;
  if (n1 != n2) {
    const double S = X1 * fabs(xa) + Y1 * fabs(yb);
    const double Sp = pow(S, n1 / n2 - 2.0);
    P1 = Sp * S;
    P2 = (n1 - n2) * Sp;
  }
  /* grad f and its Hessian (nonzero: xx, yy, zz, xy), both over n1, which
     cancels in Hessian / |grad f| */
  const double sx = copysign(X1, xa) * ia, sy = copysign(Y1, yb) * ib;
  const double g[3] = {sx * P1, sy * P1, copysign(Z1, zc) * ic};
  const double Hxx = ((n2 - 1.0) * X2 * P1) * ia * ia + P2 * sx * sx;
  const double Hyy = ((n2 - 1.0) * Y2 * P1) * ib * ib + P2 * sy * sy;
  const double Hzz = (n1 - 1.0) * Z2 * ic * ic;
  const double Hxy = P2 * sx * sy;
  const double g2 = dot(g, g);
  if (g2 >= DBL_MIN && g2 <= DBL_MAX) {
    const double inv_g = 1.0 / sqrt(g2);
    const double f0 = (Hxx * u[0] * u[0] + Hyy * u[1] * u[1] + Hzz * u[2] * u[2] + 2.0 * Hxy * u[0] * u[1]) * inv_g;
    const double f1 = (Hxx * u[0] * v[0] + Hyy * u[1] * v[1] + Hzz * u[2] * v[2] + Hxy * (u[0] * v[1] + u[1] * v[0])) * inv_g;
    const double f2 = (Hxx * v[0] * v[0] + Hyy * v[1] * v[1] + Hzz * v[2] * v[2] + 2.0 * Hxy * v[0] * v[1]) * inv_g;
    if (isfinite(f0) && isfinite(f1) && isfinite(f2) && all_finite(u, 3) && all_finite(v, 3)) {
      out[0] = f0;
      out[1] = f1;
      out[2] = f2;
      return DC_OK;
    }
  }
  /* the general path decides: rescaling, or the status */
  const double H[9] = {Hxx, Hxy, 0.0, Hxy, Hyy, 0.0, 0.0, 0.0, Hzz};
  return dc_curvature_form(g, H, u, v, out);
}

void dc_form_principal(const double form[3], double *k1, double *k2, double *theta)
{
  const int e = max_exponent(form, 3);
  if (e < -900 && isfinite(form[0]) && isfinite(form[1]) && isfinite(form[2])) {
    /* subnormal entries lose the smaller eigenvalue to rounding: the same
       on the form scaled by 2^-e (exact), scaled back */
    const double fs[3] = {ldexp(form[0], -e), ldexp(form[1], -e), ldexp(form[2], -e)};
    dc_form_principal(fs, k1, k2, theta);
    *k1 = ldexp(*k1, e);
    *k2 = ldexp(*k2, e);
    return;
  }
  double mean = 0.5 * (form[0] + form[2]);
  double half = 0.5 * (form[0] - form[2]);
  if (!(isfinite(mean) && isfinite(half))) {   /* the sum overflows, the halves need not */
    mean = 0.5 * form[0] + 0.5 * form[2];
    half = 0.5 * form[0] - 0.5 * form[2];
  }
  const double r2 = half * half + form[1] * form[1];
  double r = sqrt(r2);
  if (!(r2 >= DBL_MIN && r2 <= DBL_MAX) && (half != 0.0 || form[1] != 0.0))
    r = hypot(half, form[1]);                  /* the squares overflow or underflow */
  *k1 = mean + r;
  *k2 = mean - r;
  if (theta) *theta = 0.5 * atan2(form[1], half);
}

/* From the relative principal curvatures of finite inputs (+inf: overflowed). */
static int radii_from_curvatures(double k_big, double k_small, double *R_major, double *R_minor)
{
  if (!(k_small > 0.0)) return DC_EDOM;
  const double Rmaj = 1.0 / k_small, Rmin = 1.0 / k_big;
  /* 1/k_small overflows for a subnormal k_small; 1/k_big underflows to 0
     when k_big overflowed */
  if (!(isfinite(Rmaj) && Rmin > 0.0)) return DC_ERANGE;
  *R_major = Rmaj;
  *R_minor = Rmin;
  return DC_OK;
}

int dc_form_relative_radii(const double form[3], double *R_major, double *R_minor)
{
  if (!all_finite(form, 3)) return DC_EDOM;
  double k1, k2;
  dc_form_principal(form, &k1, &k2, 0);
  return radii_from_curvatures(k1, k2, R_major, R_minor);
}

int dc_relative_radii(double k1I, double k2I, double k1II, double k2II,
                      double omega, double *R_major, double *R_minor)
{
  const double k[4] = {k1I, k2I, k1II, k2II};
  if (!(all_finite(k, 4) && isfinite(omega))) return DC_EDOM;
  const double c2 = cos(2.0 * omega);
  double sum = k1I + k2I + k1II + k2II;
  double dI = k1I - k2I, dII = k1II - k2II;
  double root2 = dI * dI + dII * dII + 2.0 * dI * dII * c2;
  int e = 0;
  if (!(isfinite(sum) && isfinite(root2)) || (root2 < DBL_MIN && (dI != 0.0 || dII != 0.0))) {
    /* the squares overflow or underflow: the same on curvatures scaled by
       2^-e (exact), scaled back below */
    e = max_exponent(k, 4);
    const double s1I = ldexp(k1I, -e), s2I = ldexp(k2I, -e), s1II = ldexp(k1II, -e), s2II = ldexp(k2II, -e);
    sum = s1I + s2I + s1II + s2II;
    dI = s1I - s2I;
    dII = s1II - s2II;
    root2 = dI * dI + dII * dII + 2.0 * dI * dII * c2;
  }
  const double root = sqrt(fmax(0.0, root2));
  /* Eq. 3: 1/R_i = (sum - root)/2, Eq. 4: 1/R_j = (sum + root)/2 */
  return radii_from_curvatures(ldexp(0.5 * (sum + root), e), ldexp(0.5 * (sum - root), e), R_major, R_minor);
}

void dc_form_major_axis(const double form[3], const double u[3], const double v[3], double axis[3])
{
  if (!all_finite(form, 3)) {
    axis[0] = axis[1] = axis[2] = 0.0;
    return;
  }
  const int e = max_exponent(form, 3);
  if (e != 0) {
    /* the squares below may overflow or underflow (those of a nearly
       circular form's differences are far below its entries'): the same
       direction from the form scaled by 2^-e (exact; in the normal range
       the same bits) */
    const double fs[3] = {ldexp(form[0], -e), ldexp(form[1], -e), ldexp(form[2], -e)};
    dc_form_major_axis(fs, u, v, axis);
    return;
  }
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
