/* Rolling contact (dc/rolling_kalker.h): ns per call of the creep-force
   law, its kinematics and the coefficient series, and the largest relative
   difference of the coefficients from the generator's held-out points
   (tests/reference/kalker.csv, a/b in [0.1, 10]). A benchmark, not a
   test: it prints figures. */
#include "dc/rolling_kalker.h"
#include "dc/status.h"
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#define N 4096
static volatile double sink;

static double now(void)
{
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

static double uniform(unsigned long long *x)
{
  *x ^= *x << 13; *x ^= *x >> 7; *x ^= *x << 17;
  return (double)(*x >> 11) * 0x1.0p-53;
}

static dc_rolling_kin kins[N];
static dc_patch patches[N];
static double gs[N];

/* best of 5 rounds over the N inputs, ns per call */
static double time_force(const dc_rolling_params *p, const dc_rolling_material *rm, int circle, int oblique)
{
  const double n[3] = {0.0, 0.0, 1.0};
  double best = 1e30;
  for (int r = 0; r < 5; r++) {
    double acc = 0.0;
    const double t0 = now();
    for (int rep = 0; rep < 50; rep++)
      for (int i = 0; i < N; i++) {
        dc_patch pa = patches[i];
        if (circle) { pa.b = pa.a; pa.axis[0] = pa.axis[1] = 0.0; }
        else if (!oblique) { pa.axis[0] = 1.0; pa.axis[1] = 0.0; }
        dc_rolling_out o;
        if (dc_rolling_force(p, rm, &pa, n, &kins[i], &o) == DC_OK) acc += o.Fx + o.Mz;
      }
    const double t = (now() - t0) / (50.0 * N) * 1e9;
    sink = acc;
    if (t < best) best = t;
  }
  return best;
}

/* best of 5, ns per call of the kinematics of one body on another (R_max
   < 0: dc_rolling_kinematics, else the capped form) */
static double time_kinematics(const dc_rolling_curvature *ci, const dc_rolling_curvature *cj, double R_max)
{
  const double n[3] = {0.0, 0.0, 1.0};
  double best = 1e30;
  for (int r = 0; r < 5; r++) {
    double acc = 0.0;
    const double t0 = now();
    for (int rep = 0; rep < 50; rep++)
      for (int i = 0; i < N; i++) {
        const double dv[3] = {kins[i].slip[0], kins[i].slip[1], 0.0}, dw[3] = {0.1, kins[i].V * 30.0, kins[i].spin};
        dc_rolling_kin k;
        const int st = R_max < 0.0 ? dc_rolling_kinematics(n, ci, cj, dv, dw, &k)
                                   : dc_rolling_kinematics_capped(n, ci, cj, dv, dw, R_max, &k);
        if (st == DC_OK) acc += k.V;
      }
    const double t = (now() - t0) / (50.0 * N) * 1e9;
    sink = acc;
    if (t < best) best = t;
  }
  return best;
}

int main(void)
{
  unsigned long long s = 99;
  for (int i = 0; i < N; i++) {
    const double a = 1e-3 * (1.0 + uniform(&s)), b = a * (0.1 + 0.9 * uniform(&s)), th = 6.283 * uniform(&s);
    patches[i] = (dc_patch){a, b, {cos(th), sin(th), 0.0}, 100.0, 100.0, 1.0};
    const double V = 0.5 + uniform(&s);
    kins[i] = (dc_rolling_kin){V, {1.0, 0.0, 0.0}, {V * 1e-3 * (uniform(&s) - 0.5), V * 1e-3 * (uniform(&s) - 0.5), 0.0},
                               V * 10.0 * (uniform(&s) - 0.5)};
    gs[i] = exp(2.3 * (2.0 * uniform(&s) - 1.0));
  }
  dc_mindlin_pair m;
  dc_rolling_material rm;
  dc_param_error err;
  dc_mindlin_pair_init(2e9 * 1.3, 0.3, 2e9 * 1.3, 0.3, &m);
  dc_rolling_material_init(&m, &rm, &err);
  const dc_rolling_params pk = {0.4, 1e-6, DC_ROLLING_KALKER, 0.0}, pv = {0.4, 1e-6, DC_ROLLING_VJ, 0.0};

  printf("dc_rolling_force, ns per call (best of 5, %d contacts, creepage up to 5e-4, spin):\n", N);
  printf("  circle (sphere), Kalker linear     %6.1f\n", time_force(&pk, &rm, 1, 0));
  printf("  circle (sphere), Vermeulen-Johnson %6.1f\n", time_force(&pv, &rm, 1, 0));
  printf("  ellipse along its axis, Kalker     %6.1f\n", time_force(&pk, &rm, 0, 0));
  printf("  ellipse along its axis, VJ         %6.1f\n", time_force(&pv, &rm, 0, 0));
  printf("  ellipse, oblique rolling, VJ       %6.1f\n", time_force(&pv, &rm, 0, 1));

  /* coefficient series alone */
  double best = 1e30;
  for (int r = 0; r < 5; r++) {
    double acc = 0.0;
    const double t0 = now();
    for (int rep = 0; rep < 50; rep++)
      for (int i = 0; i < N; i++) {
        dc_kalker_coef c;
        dc_kalker_coefficients(&rm, gs[i], &c);
        acc += c.c11 + c.c33;
      }
    const double t = (now() - t0) / (50.0 * N) * 1e9;
    sink = acc;
    if (t < best) best = t;
  }
  printf("dc_kalker_coefficients (a/b in [0.1, 10]): %.1f ns per call\n", best);

  /* kinematics */
  const dc_rolling_curvature ci = {50.0, 20.0, {0.6, 0.8, 0.0}}, cj = {0.0, 0.0, {0, 0, 0}};
  const dc_rolling_curvature si = {1000.0, 1000.0, {0, 0, 0}}, sj = {500.0, 500.0, {0, 0, 0}};
  const dc_rolling_curvature fi = {50.0, 0.0, {0.6, 0.8, 0.0}};
  printf("dc_rolling_kinematics (ellipsoid on a plane):                   %5.1f ns per call\n",
         time_kinematics(&ci, &cj, -1.0));
  printf("dc_rolling_kinematics_capped, no cap (spheres, the LIGGGHTS path): %5.1f ns per call\n",
         time_kinematics(&si, &sj, INFINITY));
  printf("dc_rolling_kinematics_capped, flat direction capped (superquadric face): %5.1f ns per call\n",
         time_kinematics(&fi, &cj, 0.1));

  /* error of the series against the generator's held-out points */
  FILE *f = fopen(DC_REFERENCE_DIR "/kalker.csv", "r");
  if (f) {
    char line[512];
    double worst[4] = {0, 0, 0, 0};
    int rows = 0;
    while (fgets(line, sizeof line, f)) {
      if (strncmp(line, "check,", 6)) continue;
      double v[6];
      if (sscanf(line + 6, "%lf,%lf,%lf,%lf,%lf,%lf", &v[0], &v[1], &v[2], &v[3], &v[4], &v[5]) != 6) continue;
      dc_kalker_coef c;
      if (dc_kalker_coefficients_nu(v[0], v[1], &c) != DC_OK) continue;
      const double got[4] = {c.c11, c.c22, c.c23, c.c33};
      for (int j = 0; j < 4; j++) worst[j] = fmax(worst[j], fabs(got[j] - v[2 + j]) / v[2 + j]);
      rows++;
    }
    fclose(f);
    printf("series vs generator at %d held-out points (a/b in [0.1, 10], nu in [0, 0.5]): max rel. error "
           "c11 %.1e, c22 %.1e, c23 %.1e, c33 %.1e\n", rows, worst[0], worst[1], worst[2], worst[3]);
  }
  return 0;
}
