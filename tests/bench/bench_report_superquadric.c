/* Speed-versus-error report, family "superquadric": the normal force of
   superquadric contacts from one-radius Hertz laws (stock LIGGGHTS `hertz`
   with its three radii, see below) and from elliptic Hertz with the
   approximate eccentricity (review Eq. 14), against exact elliptic Hertz
   (hertz_elliptic: review Eqs. 1, 11, 13 on the relative principal radii of
   both surfaces' curvatures).

   Scene: pairs of superquadrics with semi-axes 1.5, 2.5, 3.5 mm, each of
   blockiness 2, 3 or 4 (n1 = n2, drawn per body), touching at a random
   point of each surface, in random orientations (the second body turned so
   that its normal there is opposite to the first's). Contacts whose larger
   relative radius exceeds 100 volume-equivalent effective radii are drawn
   again (near-flat pairs: both codes cap radii there, hertz_elliptic with
   maxRadiusFactor, stock hertz with curvatureLimitFactor; the report's
   LIGGGHTS scene sets both to 100). Every law's force is proportional to
   delta^3/2, so its relative error does not depend on the overlap.

   Kernel call: from both bodies' shape-function gradient and Hessian at the
   contact point (world frame) and the contact normal to the force, as the
   plugin evaluates it per contact and step. Prints CSV (report_common.h). */
#include "dc/curvature.h"
#include "dc/elliptic_integrals.h"
#include "dc/hertz_elliptic.h"
#include "dc/status.h"
#include "report_common.h"

#define NCONTACT 20000   /* contacts sampled for the error */
#define NTIME 4096       /* of which timed */
#define RADIUS_CAP 100.0 /* maxRadiusFactor = curvatureLimitFactor */

static const double AXES[3] = {1.5e-3, 2.5e-3, 3.5e-3};
static const double ESTAR = 2.75e6, DELTA = 1e-5;

typedef struct {
  double gi[3], Hi[9], gj[3], Hj[9]; /* world-frame gradient and Hessian of each body */
  double n[3];                       /* contact normal */
  double r_vol;                      /* volume-equivalent effective radius */
} contact;

static contact C[NCONTACT];

/* Superquadric f = (|x/a|^n2 + |y/b|^n2)^(n1/n2) + |z/c|^n1 - 1 (LIGGGHTS'
   shape function), gradient and Hessian at p in the body frame. */
static void sq_derivatives(const double ax[3], double n1, double n2, const double p[3], double g[3],
                           double H[9])
{
  const double X = p[0] / ax[0], Y = p[1] / ax[1], Z = p[2] / ax[2], q = n1 / n2;
  const double u = pow(fabs(X), n2) + pow(fabs(Y), n2);
  const double ux = n2 * pow(fabs(X), n2 - 1) * copysign(1.0, X) / ax[0];
  const double uy = n2 * pow(fabs(Y), n2 - 1) * copysign(1.0, Y) / ax[1];
  const double uxx = n2 * (n2 - 1) * pow(fabs(X), n2 - 2) / (ax[0] * ax[0]);
  const double uyy = n2 * (n2 - 1) * pow(fabs(Y), n2 - 2) / (ax[1] * ax[1]);
  const double d1 = q * pow(u, q - 1), d2 = q * (q - 1) * pow(u, q - 2);
  g[0] = d1 * ux;
  g[1] = d1 * uy;
  g[2] = n1 * pow(fabs(Z), n1 - 1) * copysign(1.0, Z) / ax[2];
  for (int k = 0; k < 9; k++) H[k] = 0.0;
  H[0] = d2 * ux * ux + d1 * uxx;
  H[4] = d2 * uy * uy + d1 * uyy;
  H[1] = H[3] = d2 * ux * uy;
  H[8] = n1 * (n1 - 1) * pow(fabs(Z), n1 - 2) / (ax[2] * ax[2]);
}

static double sq_f(const double ax[3], double n1, double n2, const double p[3])
{
  return pow(pow(fabs(p[0] / ax[0]), n2) + pow(fabs(p[1] / ax[1]), n2), n1 / n2) + pow(fabs(p[2] / ax[2]), n1) - 1.0;
}

/* Volume 2 a b c e1 e2 B(e1/2 + 1, e1) B(e2/2, e2/2), e = 2/n (Jaklic et al.). */
static double sq_volume(const double ax[3], double n1, double n2)
{
  const double e1 = 2.0 / n1, e2 = 2.0 / n2;
  const double B1 = exp(lgamma(e1 / 2 + 1) + lgamma(e1) - lgamma(1.5 * e1 + 1));
  const double B2 = exp(2 * lgamma(e2 / 2) - lgamma(e2));
  return 2.0 * ax[0] * ax[1] * ax[2] * e1 * e2 * B1 * B2;
}

static void unit_vector(unsigned long long *s, double d[3])
{
  const double z = 2.0 * report_uniform(s) - 1.0, phi = 2.0 * M_PI * report_uniform(s), r = sqrt(1.0 - z * z);
  d[0] = r * cos(phi);
  d[1] = r * sin(phi);
  d[2] = z;
}

/* The surface point in direction d (f is homogeneous of degree n1 in p). */
static void sq_surface_point(const double ax[3], double n1, double n2, const double d[3], double p[3])
{
  const double t = pow(sq_f(ax, n1, n2, d) + 1.0, -1.0 / n1);
  for (int k = 0; k < 3; k++) p[k] = t * d[k];
}

static void cross(const double a[3], const double b[3], double c[3])
{
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

static void normalize(double a[3])
{
  const double l = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  for (int k = 0; k < 3; k++) a[k] /= l;
}

/* Rotation Q (row-major) taking the body-frame unit vector b to the world
   unit vector w, turned by angle psi about w. */
static void rotation_to(const double b[3], const double w[3], double psi, double Q[9])
{
  double b2[3], b3[3], w2[3], w3[3], t[3] = {1, 0, 0};
  if (fabs(b[0]) > 0.9) t[0] = 0, t[1] = 1;
  cross(b, t, b2), normalize(b2), cross(b, b2, b3);
  t[0] = 1, t[1] = t[2] = 0;
  if (fabs(w[0]) > 0.9) t[0] = 0, t[1] = 1;
  double s2[3], s3[3];
  cross(w, t, s2), normalize(s2), cross(w, s2, s3);
  for (int k = 0; k < 3; k++) {
    w2[k] = cos(psi) * s2[k] + sin(psi) * s3[k];
    w3[k] = -sin(psi) * s2[k] + cos(psi) * s3[k];
  }
  for (int r = 0; r < 3; r++)
    for (int c = 0; c < 3; c++) Q[3 * r + c] = w[r] * b[c] + w2[r] * b2[c] + w3[r] * b3[c];
}

/* World-frame gradient Q g and Hessian Q H Q^T. */
static void to_world(const double Q[9], const double g[3], const double H[9], double gw[3], double Hw[9])
{
  double QH[9];
  for (int r = 0; r < 3; r++) {
    gw[r] = Q[3 * r] * g[0] + Q[3 * r + 1] * g[1] + Q[3 * r + 2] * g[2];
    for (int c = 0; c < 3; c++) QH[3 * r + c] = Q[3 * r] * H[c] + Q[3 * r + 1] * H[3 + c] + Q[3 * r + 2] * H[6 + c];
  }
  for (int r = 0; r < 3; r++)
    for (int c = 0; c < 3; c++)
      Hw[3 * r + c] = QH[3 * r] * Q[3 * c] + QH[3 * r + 1] * Q[3 * c + 1] + QH[3 * r + 2] * Q[3 * c + 2];
}

/* The analytic derivatives against central differences at random surface
   points of every shape; exits on a mismatch (the scene would be wrong). */
static void check_derivatives(void)
{
  unsigned long long s = 99;
  for (int k = 0; k < 300; k++) {
    const double n = 2.0 + (k % 3), h = 1e-7;
    double d[3], p[3], g[3], H[9], gp[3], gm[3], Hd[9];
    unit_vector(&s, d);
    sq_surface_point(AXES, n, n, d, p);
    sq_derivatives(AXES, n, n, p, g, H);
    double gnorm = 0, Hnorm = 0, gerr = 0, Herr = 0;
    for (int a = 0; a < 3; a++) {
      double pp[3] = {p[0], p[1], p[2]}, pm[3] = {p[0], p[1], p[2]};
      pp[a] += h, pm[a] -= h;
      gerr = fmax(gerr, fabs((sq_f(AXES, n, n, pp) - sq_f(AXES, n, n, pm)) / (2 * h) - g[a]));
      gnorm = fmax(gnorm, fabs(g[a]));
      sq_derivatives(AXES, n, n, pp, gp, Hd);
      sq_derivatives(AXES, n, n, pm, gm, Hd);
      for (int b = 0; b < 3; b++) {
        Herr = fmax(Herr, fabs((gp[b] - gm[b]) / (2 * h) - H[3 * a + b]));
        Hnorm = fmax(Hnorm, fabs(H[3 * a + b]));
      }
    }
    if (gerr > 1e-5 * gnorm || Herr > 1e-4 * Hnorm) {
      fprintf(stderr, "bench_report_superquadric: shape derivatives wrong at n = %g (%.3g, %.3g)\n", n,
              gerr / gnorm, Herr / Hnorm);
      exit(1);
    }
  }
}

/* Relative curvature form of a contact on the basis (u, v) of its normal. */
static int relative_form(const contact *c, double u[3], double v[3], double fi[3], double fj[3])
{
  dc_tangent_basis(c->n, u, v);
  return dc_curvature_form(c->gi, c->Hi, u, v, fi) | dc_curvature_form(c->gj, c->Hj, u, v, fj);
}

static double hertz_force(double R)
{
  double kn, S;
  dc_hertz_stiffness(ESTAR, R, DELTA, &kn, &S);
  return kn * DELTA;
}

/* hertz_elliptic (the reference): exact eccentricity. */
static double force_exact(const contact *c)
{
  double u[3], v[3], fi[3], fj[3], R1, R2;
  relative_form(c, u, v, fi, fj);
  const double f[3] = {fi[0] + fj[0], fi[1] + fj[1], fi[2] + fj[2]};
  dc_form_relative_radii(f, &R1, &R2);
  dc_hertz_geom g;
  dc_hertz_geometry(R1, R2, &g);
  return hertz_force(g.R_force);
}

/* Elliptic Hertz with e^2 of review Eq. 14, gamma by Eq. 11 at that e^2. */
static double force_eq14(const contact *c)
{
  double u[3], v[3], fi[3], fj[3], R1, R2, e2;
  relative_form(c, u, v, fi, fj);
  const double f[3] = {fi[0] + fj[0], fi[1] + fj[1], fi[2] + fj[2]};
  dc_form_relative_radii(f, &R1, &R2);
  dc_hertz_eccentricity_approx(R2 / R1, &e2);
  dc_ellint el;
  dc_ellint_m(e2, &el);
  const double gamma = M_PI * M_SQRT2 * sqrt(el.E) / (2.0 * el.K * sqrt(el.K) * sqrt(1.0 - e2));
  return hertz_force(R1 * R2 / (R1 + R2) * gamma * gamma);
}

/* Stock hertz: one radius, LIGGGHTS' surface superquadric default (the
   volume-equivalent spheres) or its curvature options, whose radius is
   1/(k_i + k_j) with k the mean curvature (meanCurvature yes) or the square
   root of the Gaussian curvature (gaussianCurvature yes) of each body at
   its contact point, capped at curvatureLimitFactor volume-equivalent radii
   (superquadric.cpp calc_curvature_coefficient, get_effective_radius). */
static double force_volume(const contact *c) { return hertz_force(c->r_vol); }

static double capped(double keff, double r_vol)
{
  const double rmax = RADIUS_CAP * r_vol;
  return keff < 1.0 / rmax ? rmax : 1.0 / keff;
}

static double force_mean(const contact *c)
{
  double u[3], v[3], fi[3], fj[3];
  relative_form(c, u, v, fi, fj);
  return hertz_force(capped(0.5 * (fabs(fi[0] + fi[2]) + fabs(fj[0] + fj[2])), c->r_vol));
}

static double force_gauss(const contact *c)
{
  double u[3], v[3], fi[3], fj[3];
  relative_form(c, u, v, fi, fj);
  const double Ki = fi[0] * fi[2] - fi[1] * fi[1], Kj = fj[0] * fj[2] - fj[1] * fj[1];
  return hertz_force(capped(sqrt(fabs(Ki)) + sqrt(fabs(Kj)), c->r_vol));
}

/* Draws the scene; returns the number of draws rejected as near-flat. */
static long sample_contacts(void)
{
  unsigned long long s = 20260101;
  long rejected = 0;
  for (int k = 0; k < NCONTACT;) {
    contact *c = &C[k];
    const double ni = 2.0 + floor(3.0 * report_uniform(&s)), nj = 2.0 + floor(3.0 * report_uniform(&s));
    double di[3], dj[3], pi[3], pj[3], g[3], H[9], Qi[9], Qj[9], nb[3], minus_n[3];
    unit_vector(&s, di);
    unit_vector(&s, dj);
    sq_surface_point(AXES, ni, ni, di, pi);
    sq_surface_point(AXES, nj, nj, dj, pj);
    /* body i: a random orientation (a random unit vector taken to a random
       one, turned by a random angle); body j: its normal at pj opposite */
    double a[3], b[3];
    unit_vector(&s, a);
    unit_vector(&s, b);
    rotation_to(a, b, 2.0 * M_PI * report_uniform(&s), Qi);
    sq_derivatives(AXES, ni, ni, pi, g, H);
    to_world(Qi, g, H, c->gi, c->Hi);
    for (int m = 0; m < 3; m++) c->n[m] = c->gi[m];
    normalize(c->n);
    sq_derivatives(AXES, nj, nj, pj, g, H);
    for (int m = 0; m < 3; m++) nb[m] = g[m], minus_n[m] = -c->n[m];
    normalize(nb);
    rotation_to(nb, minus_n, 2.0 * M_PI * report_uniform(&s), Qj);
    to_world(Qj, g, H, c->gj, c->Hj);
    const double ri = cbrt(0.75 * sq_volume(AXES, ni, ni) / M_PI), rj = cbrt(0.75 * sq_volume(AXES, nj, nj) / M_PI);
    c->r_vol = ri * rj / (ri + rj);
    double u[3], v[3], fi[3], fj[3], R1, R2;
    const int st = relative_form(c, u, v, fi, fj);
    const double f[3] = {fi[0] + fj[0], fi[1] + fj[1], fi[2] + fj[2]};
    if (st != DC_OK || dc_form_relative_radii(f, &R1, &R2) != DC_OK || R1 > RADIUS_CAP * c->r_vol ||
        R2 / R1 < DC_HERTZ_RATIO_MIN) {
      rejected++;
      continue;
    }
    k++;
  }
  return rejected;
}

int main(void)
{
  check_derivatives();
  const long rejected = sample_contacts();
  struct {
    const char *law;
    double (*force)(const contact *);
  } laws[] = {
      {"hertz_elliptic (exact)", force_exact},
      {"elliptic Hertz with Eq. 14 eccentricity", force_eq14},
      {"stock hertz: volume-equivalent radius", force_volume},
      {"stock hertz: mean-curvature radius", force_mean},
      {"stock hertz: Gaussian-curvature radius", force_gauss},
  };
  char note[160];
  snprintf(note, sizeof note, "%d contacts; %ld near-flat draws redrawn", NCONTACT, rejected);
  report_header();
  for (size_t L = 0; L < sizeof laws / sizeof laws[0]; L++) {
    report_err e = {0};
    for (int k = 0; k < NCONTACT; k++)
      report_err_add(&e, L == 0 ? 0.0 : laws[L].force(&C[k]) / force_exact(&C[k]) - 1.0);
    double ns = 0.0;   /* each law called directly: no indirect call in the timed loop */
    switch (L) {
    case 0: REPORT_TIME(ns, NTIME, acc += force_exact(&C[i])); break;
    case 1: REPORT_TIME(ns, NTIME, acc += force_eq14(&C[i])); break;
    case 2: REPORT_TIME(ns, NTIME, acc += force_volume(&C[i])); break;
    case 3: REPORT_TIME(ns, NTIME, acc += force_mean(&C[i])); break;
    case 4: REPORT_TIME(ns, NTIME, acc += force_gauss(&C[i])); break;
    }
    report_row("superquadric", "superquadric pairs 1.5:2.5:3.5 mm blockiness 2-4", laws[L].law, L == 0, ns, &e,
               "relative force error (max; rms)", note);
  }
  return 0;
}
