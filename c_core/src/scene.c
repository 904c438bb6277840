/* Scene measures (dc/scene.h). */
#include "dc/scene.h"
#include "dc/curvature.h"
#include "dc/status.h"
#include <float.h>
#include <math.h>

/* (prod x_i^p_i)^(1/r), x_i > 0 finite, p_i small integers, r 1 to 3:
   mantissas and binary exponents apart, so that no partial product leaves
   the doubles (the result to a few ulps wherever it is a normal number) */
static double monomial_root(int n, const double *x, const int *p, int r)
{
  double m = 1.0;
  long e = 0;
  for (int i = 0; i < n; i++) {
    int k, kn;
    const double f = frexp(x[i], &k);
    for (int j = 0; j < (p[i] > 0 ? p[i] : -p[i]); j++) {
      m = p[i] > 0 ? m * f : m / f;
      e += p[i] > 0 ? k : -k;
      m = frexp(m, &kn);
      e += kn;
    }
  }
  /* e = r q + s, 0 <= s < r: the root of m 2^s times 2^q */
  long q = e / r, sft = e % r;
  if (sft < 0) { sft += r; q--; }
  const double ms = ldexp(m, (int)sft);
  const double root = r == 1 ? ms : r == 2 ? sqrt(ms) : cbrt(ms);
  return ldexp(root, q < -2000 ? -2000 : q > 2000 ? 2000 : (int)q);
}

static int normal_out(double v, double *out)
{
  if (!(v >= DBL_MIN && v <= DBL_MAX)) return DC_ERANGE;
  *out = v;
  return DC_OK;
}

int dc_scene_rayleigh_time(double R, double rho, double E, double nu, double *T)
{
  if (!(R > 0.0 && R <= DBL_MAX && rho > 0.0 && rho <= DBL_MAX && E > 0.0 && E <= DBL_MAX && nu >= 0.0 && nu <= 0.5))
    return DC_EDOM;
  /* T_R^2 = pi^2 R^2 rho 2 (1 + nu) / (E (0.1631 nu + 0.8766)^2), G = E / (2 (1 + nu)) */
  const double c = M_PI / (0.1631 * nu + 0.8766);
  const double x[5] = {c, R, rho, 2.0 * (1.0 + nu), E};
  const int p[5] = {2, 2, 1, 1, -1};
  return normal_out(monomial_root(5, x, p, 2), T);
}

int dc_scene_tabor(double R, double w, double Estar, double z0, double *mu)
{
  if (!(R > 0.0 && R <= DBL_MAX && w >= 0.0 && w <= DBL_MAX && Estar > 0.0 && Estar <= DBL_MAX && z0 > 0.0 &&
        z0 <= DBL_MAX))
    return DC_EDOM;
  if (w == 0.0) {
    *mu = 0.0;
    return DC_OK;
  }
  const double x[4] = {R, w, Estar, z0};
  const int p[4] = {1, 2, -2, -3};
  return normal_out(monomial_root(4, x, p, 3), mu);
}

int dc_scene_hertz_overlap(const dc_hertz_geom *g, double Estar, double F, double *delta)
{
  if (!(F >= 0.0 && F <= DBL_MAX && Estar > 0.0 && Estar <= DBL_MAX && g->R_force > 0.0 && g->R_force <= DBL_MAX))
    return DC_EDOM;
  if (F == 0.0) {
    *delta = 0.0;
    return DC_OK;
  }
  /* review Eq. 1, F = 4/3 E* R_force^1/2 delta^3/2, for delta:
     delta^3 = (3/4)^2 F^2 / (E*^2 R_force) */
  const double x[4] = {0.75, F, Estar, g->R_force};
  const int p[4] = {2, 2, -2, -1};
  return normal_out(monomial_root(4, x, p, 3), delta);
}

static int shape_ok(const double shape[3], const double blockiness[2])
{
  for (int i = 0; i < 3; i++)
    if (!(shape[i] > 0.0 && shape[i] <= DBL_MAX)) return 0;
  return blockiness[0] >= 2.0 && blockiness[0] <= 1e3 && blockiness[1] >= 2.0 && blockiness[1] <= 1e3;
}

/* Beta function B(x, y) for x, y > 0 */
static double beta_fn(double x, double y)
{
  return exp(lgamma(x) + lgamma(y) - lgamma(x + y));
}

int dc_scene_superquadric_radius(const double shape[3], const double blockiness[2], double *R_eq)
{
  if (!shape_ok(shape, blockiness)) return DC_EDOM;
  const double e1 = 2.0 / blockiness[0], e2 = 2.0 / blockiness[1];
  /* V / (a b c), then R_eq = (3 V / (4 pi))^1/3 with the cube root of
     each length apart */
  const double v = 2.0 * e1 * e2 * beta_fn(0.5 * e1 + 1.0, e1) * beta_fn(0.5 * e2, 0.5 * e2);
  const double R = cbrt(shape[0]) * cbrt(shape[1]) * cbrt(shape[2]) * cbrt(0.75 * v / M_PI);
  if (!(R >= DBL_MIN && R <= DBL_MAX)) return DC_ERANGE;
  *R_eq = R;
  return DC_OK;
}

/* The point of the octant at parametric angles eta (from the xy plane)
   and omega (from x), and the unit outward normal there. */
static void octant_point(const double shape[3], const double blockiness[2], double eta, double omega, double p[3],
                         double nrm[3])
{
  const double n1 = blockiness[0], n2 = blockiness[1];
  const double ce = pow(cos(eta), 2.0 / n1), se = pow(sin(eta), 2.0 / n1);
  const double co = pow(cos(omega), 2.0 / n2), so = pow(sin(omega), 2.0 / n2);
  p[0] = shape[0] * ce * co;
  p[1] = shape[1] * ce * so;
  p[2] = shape[2] * se;
  /* grad f / n1 = (S^(n1/n2 - 1) X^(n2-1) / a, S^(n1/n2 - 1) Y^(n2-1) / b, Z^(n1-1) / c),
     X = x/a, S = X^n2 + Y^n2 = cos(eta)^(2 n2/n1) */
  const double X = ce * co, Y = ce * so, Z = se, S = pow(cos(eta), 2.0 * n2 / n1);
  const double P = pow(S, n1 / n2 - 1.0);
  nrm[0] = P * pow(X, n2 - 1.0) / shape[0];
  nrm[1] = P * pow(Y, n2 - 1.0) / shape[1];
  nrm[2] = pow(Z, n1 - 1.0) / shape[2];
  const double l = sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
  for (int i = 0; i < 3; i++) nrm[i] /= l;
}

enum { SHAPE_M_MAX = 64 };

int dc_scene_shape_error(const double shape[3], const double blockiness[2], int m, double cap, dc_scene_shape *s)
{
  if (!shape_ok(shape, blockiness) || m < 2 || m > SHAPE_M_MAX || !(cap >= 1.0 && cap <= 1e6)) return DC_EDOM;
  /* lengths in units of the largest semi-axis (the errors are ratios) */
  const double L = fmax(shape[0], fmax(shape[1], shape[2]));
  const double sh[3] = {shape[0] / L, shape[1] / L, shape[2] / L};
  double R_eq;
  if (dc_scene_superquadric_radius(sh, blockiness, &R_eq) != DC_OK) return DC_ERANGE;
  const double k_min = 1.0 / (cap * R_eq);
  static const int n_omega = 5;
  double k1[SHAPE_M_MAX * SHAPE_M_MAX], k2[SHAPE_M_MAX * SHAPE_M_MAX];
  dc_scene_shape r = {0};
  r.R_body_min = HUGE_VAL;
  double sw = 0.0, sp = 0.0;
  long nw = 0, np = 0;
  for (int i = 0; i < m; i++)
    for (int j = 0; j < m; j++) {
      double p[3], nrm[3], u[3], v[3], form[3], th;
      octant_point(sh, blockiness, (i + 0.5) / m * M_PI_2, (j + 0.5) / m * M_PI_2, p, nrm);
      dc_tangent_basis(nrm, u, v);
      if (dc_superquadric_form(sh, blockiness, p, u, v, form) != DC_OK) return DC_ERANGE;
      double a1, a2;
      dc_form_principal(form, &a1, &a2, &th);
      /* the cap: a radius beyond cap R_eq counts as cap R_eq */
      a1 = fmax(a1, k_min);
      a2 = fmax(a2, k_min);
      const int q = i * m + j;
      k1[q] = a1;
      k2[q] = a2;
      r.R_body_min = fmin(r.R_body_min, 1.0 / a1);
      r.R_body_max = fmax(r.R_body_max, 1.0 / a2);
      /* against a wall: the body's own radii */
      dc_hertz_geom g;
      if (dc_hertz_geometry(1.0 / a2, 1.0 / a1, &g) != DC_OK) return DC_ERANGE;
      const double e = fabs(sqrt(R_eq / g.R_force) - 1.0);
      r.err_wall_max = fmax(r.err_wall_max, e);
      sw += e * e;
      nw++;
    }
  for (int q1 = 0; q1 < m * m; q1++)
    for (int q2 = q1; q2 < m * m; q2++)
      for (int w = 0; w < n_omega; w++) {
        double Rmaj, Rmin;
        dc_hertz_geom g;
        if (dc_relative_radii(k1[q1], k2[q1], k1[q2], k2[q2], w * M_PI_2 / (n_omega - 1), &Rmaj, &Rmin) != DC_OK ||
            dc_hertz_geometry(Rmaj, Rmin, &g) != DC_OK)
          return DC_ERANGE;
        const double e = fabs(sqrt(0.5 * R_eq / g.R_force) - 1.0);
        r.err_pair_max = fmax(r.err_pair_max, e);
        sp += e * e;
        np++;
      }
  r.R_eq = R_eq * L;
  r.R_body_min *= L;
  r.R_body_max *= L;
  /* (the sums' rounding may lift a mean of equal terms above their max) */
  r.err_wall_rms = fmin(sqrt(sw / nw), r.err_wall_max);
  r.err_pair_rms = fmin(sqrt(sp / np), r.err_pair_max);
  if (!(r.R_eq <= DBL_MAX && r.R_body_max <= DBL_MAX && r.R_body_min >= DBL_MIN)) return DC_ERANGE;
  *s = r;
  return DC_OK;
}
