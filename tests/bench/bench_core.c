/* c_core speed against error for the elliptic Hertz family: ns per call of
   each function over a sweep of its domain, and the largest difference from
   a second method. A benchmark, not a test: it prints figures. */
#include "../unit/check.h"
#include "dc/curvature.h"
#include "dc/elliptic_integrals.h"
#include "dc/hertz_elliptic.h"
#include <math.h>
#include <stdio.h>
#include <time.h>

#define N 4096
static double ratios[N], ms[N], m1s[N];
static volatile double sink;

static double now(void)
{
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

/* The arithmetic-geometric mean (A-S 17.6), the method dc_ellint used before
   its polynomials: a second method for the integrals and a timing baseline.
   D, B, C from the sum S of t_n = c_n/m; for m1 < 0.1, E and B from
   Legendre's relation with the complementary integrals. */
static void agm_ellint(double m, double m1, dc_ellint *out)
{
  double a = 0.5 * (1.0 + sqrt(m1)), b = sqrt(sqrt(m1)), t = 0.25 / a, w = 1.0, S = t * t;
  for (int n = 1; n < 40 && fabs(a - b) > 1e-15 * a; n++) {
    const double an = 0.5 * (a + b);
    b = sqrt(a * b);
    a = an;
    t = m * t * t / (4.0 * a);
    w *= 2.0;
    S += w * t * t;
  }
  const double K = M_PI / (a + b);
  out->K = K;
  out->D = K * (0.5 + m * S);
  out->B = K * (0.5 - m * S);
  out->C = 2.0 * K * S;
  out->E = K * (1.0 - m * (0.5 + m * S));
  if (m1 < 0.1) {
    dc_ellint c;
    agm_ellint(m1, m, &c);
    out->E = M_PI / (2.0 * c.K) + m1 * K * c.D / c.K;
    out->B = (out->E - m1 * K) / m;
  }
}

static double rel_diff(const dc_ellint *x, const dc_ellint *y)
{
  const double d[5] = {x->K / y->K, x->E / y->E, x->D / y->D, x->B / y->B, x->C / y->C};
  double w = 0.0;
  for (int j = 0; j < 5; j++) w = fmax(w, fabs(d[j] - 1.0));
  return w;
}

#define TIME(label, reps, ...)                                              \
  do {                                                                      \
    double best = 1e300;                                                    \
    for (int rep = 0; rep < 5; rep++) {                                     \
      double t0 = now();                                                    \
      for (int k = 0; k < (reps); k++)                                      \
        for (int i = 0; i < N; i++) { __VA_ARGS__; }                             \
      double dt = (now() - t0) / ((double)(reps) * N) * 1e9;                \
      if (dt < best) best = dt;                                             \
    }                                                                       \
    printf("%-52s %8.1f ns/call\n", label, best);                           \
  } while (0)

int main(void)
{
  for (int i = 0; i < N; i++) {
    ratios[i] = pow(10.0, -6.0 * (i + 0.5) / N);   /* R_minor/R_major in (1e-6, 1) */
    ms[i] = (i + 0.5) / N;
    m1s[i] = pow(10.0, -12.0 * (i + 0.5) / N);     /* 1 - m in (1e-12, 1) */
  }
  printf("c_core elliptic Hertz family (best of 5, %d inputs each)\n", N);
  TIME("dc_ellint_m (K, E, D, B, C), m in (0,1)", 20, { dc_ellint e; dc_ellint_m(ms[i], &e); sink = e.K + e.E; });
  TIME("dc_ellint_m1, m1 = 1 - m in (1e-12,1), log-spread", 20, { dc_ellint e; dc_ellint_m1(m1s[i], &e); sink = e.K + e.E; });
  TIME("  AGM (previous method), m in (0,1)", 20, { dc_ellint e; agm_ellint(ms[i], 1.0 - ms[i], &e); sink = e.K + e.E; });
  TIME("  AGM (previous method), m1 in (1e-12,1)", 20, { dc_ellint e; agm_ellint(1.0 - m1s[i], m1s[i], &e); sink = e.K + e.E; });
  TIME("dc_hertz_eccentricity (exact, Eq. 13), r in (1e-6,1)", 5, { double e2, m1; dc_hertz_eccentricity(ratios[i], &e2, &m1); sink = e2; });
  TIME("dc_hertz_eccentricity_approx (Eq. 14)", 20, { double e2; dc_hertz_eccentricity_approx(ratios[i], &e2); sink = e2; });
  TIME("dc_hertz_geometry (K, E, e, gamma, beta together)", 5, { dc_hertz_geom g; dc_hertz_geometry(1.0, ratios[i], &g); sink = g.gamma; });
  dc_hertz_geom g0;
  dc_hertz_geometry(1.0, 0.3, &g0);
  TIME("dc_hertz_contact (force, area, axes, stiffness)", 20, { dc_hertz_state s; dc_hertz_contact(&g0, 1e9, 1e-6 * (1 + ms[i]), &s); sink = s.F; });
  const double grad[3] = {0.3, -0.2, 0.9}, H[9] = {2, 0.1, 0, 0.1, 3, 0.2, 0, 0.2, 1.5};
  TIME("dc_tangent_basis + dc_curvature_form + principal", 20, {
    double n[3] = {0.3, -0.2 + 1e-9 * i, 0.9}, u[3], v[3], f[3], k1, k2;
    double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    n[0] /= l; n[1] /= l; n[2] /= l;
    dc_tangent_basis(n, u, v); dc_curvature_form(grad, H, u, v, f); dc_form_principal(f, &k1, &k2, 0); sink = k1 + k2; });

  double worst_agm = 0.0;
  for (int i = 0; i < N; i++) {
    dc_ellint p, q;
    dc_ellint_m(ms[i], &p);
    agm_ellint(ms[i], 1.0 - ms[i], &q);
    worst_agm = fmax(worst_agm, rel_diff(&p, &q));
    dc_ellint_m1(m1s[i], &p);
    agm_ellint(1.0 - m1s[i], m1s[i], &q);
    worst_agm = fmax(worst_agm, rel_diff(&p, &q));
  }
  printf("dc_ellint against the AGM: max rel. difference of K, E, D, B, C %.3g over both sweeps\n", worst_agm);

  /* error of the approximate eccentricity (Eq. 14) against the exact one */
  double worst_e = 0.0, worst_g = 0.0;
  for (int i = 0; i < N; i++) {
    double e2a, e2, m1;
    dc_hertz_eccentricity_approx(ratios[i], &e2a);
    dc_hertz_eccentricity(ratios[i], &e2, &m1);
    double ba = sqrt(1.0 - e2a), ba0 = sqrt(m1);
    if (fabs(ba / ba0 - 1) > worst_e) worst_e = fabs(ba / ba0 - 1);
    /* gamma from the approximate eccentricity (Eq. 11 with Eq. 14's e) */
    dc_ellint el;
    dc_ellint_m(e2a, &el);
    double ga = M_PI * M_SQRT2 * sqrt(el.E) / (2 * el.K * sqrt(el.K) * sqrt(1 - e2a));
    dc_hertz_geom g;
    dc_hertz_geometry(1.0, ratios[i], &g);
    if (fabs(ga / g.gamma - 1) > worst_g) worst_g = fabs(ga / g.gamma - 1);
  }
  printf("Eq. 14 instead of Eq. 13: max rel. error of b/a %.3g, of gamma (force) %.3g over r in (1e-6, 1)\n", worst_e, worst_g);

  /* dc_hertz_geometry against mpmath over r in [1e-12, 1] (ulps of the
     reference doubles, which are themselves within half an ulp) */
  FILE *f = check_open_reference("hertz_geometry_dense.csv");
  if (f) {
    static const char *const names[9] = {"e2", "m1", "K", "E", "D", "gamma", "beta", "R_force", "R_area"};
    double v[10], worst[9] = {0};
    int rows = 0;
    while (check_read_row(f, v, 10) == 10) {
      dc_hertz_geom g;
      dc_hertz_geometry(1.0, v[0], &g);
      const double got[9] = {g.e2, g.m1, g.K, g.E, g.D, g.gamma, g.beta, g.R_force, g.R_area};
      for (int k = 0; k < 9; k++) {
        int e;
        frexp(v[1 + k], &e);
        if (v[1 + k] > 0.0) worst[k] = fmax(worst[k], fabs(got[k] - v[1 + k]) / ldexp(1.0, e - 53));
      }
      rows++;
    }
    fclose(f);
    printf("dc_hertz_geometry vs mpmath (%d ratios in [1e-12, 1]), worst ulp:", rows);
    for (int k = 0; k < 9; k++) printf(" %s %.0f", names[k], worst[k]);
    printf("\n");
  }
  return 0;
}
