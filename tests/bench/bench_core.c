/* c_core speed against error for the elliptic Hertz family: ns per call of
   each function over a sweep of its domain, and the largest difference from
   a second method. A benchmark, not a test: it prints figures. */
#include "dc/curvature.h"
#include "dc/elliptic_integrals.h"
#include "dc/hertz_elliptic.h"
#include <math.h>
#include <stdio.h>
#include <time.h>

#define N 4096
static double ratios[N], ms[N];
static volatile double sink;

static double now(void)
{
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
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
  }
  printf("c_core elliptic Hertz family (best of 5, %d inputs each)\n", N);
  TIME("dc_ellint_m (K, E, D, B, C), m in (0,1)", 20, { dc_ellint e; dc_ellint_m(ms[i], &e); sink = e.K + e.E; });
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
  return 0;
}
