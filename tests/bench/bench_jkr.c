/* Adhesive (JKR) contact: ns per call and max relative error of each
   evaluation path against the committed mpmath tables
   (tests/reference/gen_jkr_elliptic.py, gen_jkr_sphere_dense.py):
     - classical JKR for spheres, dc_jkr_sphere (the tabulated inverse of
       the JKR curve), vs jkr_sphere.csv and jkr_sphere_dense.csv, over
       w = 0.05 from the separation point up and along the Hertz
       trajectory of the bench scene (w = 1e-9), with its inline hot path
       and Hertz on the same overlaps;
     - elliptic JKR force for a given overlap, dc_jkr_contact, without a hint
       (cold start) and with the per-contact hint of a DEM time step (warm
       start), vs jkr_elliptic_force.csv;
     - dc_jkr_geometry (Hertz shape, separation and pull-off points), vs
       jkr_elliptic_extrema.csv.
   Errors are reported both raw and as a multiple of the condition-number
   bound eps (1 + |delta kn / F|) used by the unit test (rounding of delta is
   amplified by that factor near the separation point, where dF/d delta ->
   -oo). Timing loops: a load-unload sweep over the stable branch from the
   separation point to delta = 50 |delta_break| in 10^4 steps (warm: the hint
   carried from step to step, as in a DEM run; cold: the same overlaps with
   no hint), for R_minor/R_major = 0.5, 0.1, 0.01 and 0.001; dc_jkr_geometry
   best of 5 loops of 2000 calls. */
#include "../unit/check.h"
#include "dc/hertz_elliptic.h"
#include "dc/jkr_elliptic.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define EPS 2.220446049250313e-16

static double now(void)
{
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

static volatile double sink;

static double cond(const dc_jkr_state *s)
{
  double c = fabs(s->delta * s->kn / s->F);
  return c < 1e12 ? c : 1e12;
}

/* best = the best of 5 loops over i < N of the body, in ns per call. */
#define TIME_BEST(best, N, ...)                                             \
  do {                                                                      \
    best = 1e300;                                                           \
    for (int rep_ = 0; rep_ < 5; rep_++) {                                  \
      const double t0_ = now();                                             \
      for (int i = 0; i < (N); i++) { __VA_ARGS__; }                        \
      best = fmin(best, (now() - t0_) / (N) * 1e9);                        \
    }                                                                       \
  } while (0)

static void bench_sphere(void)
{
  double emax = 0, eunits = 0, v[8];
  FILE *f = check_open_reference("jkr_sphere.csv");
  if (f) {
    check_read_row(f, v, 6);
    while (check_read_row(f, v, 6) == 6) {
      dc_jkr_state s;
      dc_jkr_sphere(v[0], v[1], v[2], v[3], &s);
      const double e = fabs(s.F / v[4] - 1);
      emax = fmax(emax, e);
      eunits = fmax(eunits, e / (EPS * (1 + cond(&s))));
    }
    fclose(f);
  }
  /* the whole stable branch of four materials (gen_jkr_sphere_dense.py):
     F relative where its condition number |delta dF/d delta / F| < 10 */
  double edense = 0;
  f = check_open_reference("jkr_sphere_dense.csv");
  if (f) {
    check_read_row(f, v, 8);
    while (check_read_row(f, v, 8) == 8) {
      dc_jkr_state s;
      dc_jkr_sphere(v[0], v[1], v[2], v[3], &s);
      if (fabs(v[3] * v[6]) < 10 * fabs(v[4])) edense = fmax(edense, fabs(s.F / v[4] - 1));
    }
    fclose(f);
  }
  printf("path                                         ns/call   max rel.err   in units of eps(1+cond)\n");
  /* w = 0.05: from the separation point to 50 |delta_break| */
  const double R = 1e-3, E = 1e9, w = 0.05;
  const double db = dc_jkr_sphere_delta_break(R, E, w);
  const int N = 200000;
  double acc = 0;
  dc_jkr_state st;
  double t_w, t_j, t_i, t_h;
  TIME_BEST(t_w, N, { dc_jkr_sphere(R, E, w, db + (50.0 * fabs(db) - db) * (double)i / N, &st); acc += st.F; });
  printf("classical JKR, dc_jkr_sphere               %8.1f     %.2e      %.1f\n", t_w, emax, eunits);
  printf("  (w = 0.05, delta from delta_break to 50 |delta_break|; vs jkr_sphere_dense.csv, 1384 states\n"
         "   of four materials, F within %.2g where its condition number is below 10)\n", edense);
  /* the Hertz trajectory of tests/bench/bench_scenes.sh (sj0): spheres of
     r = 1.5 mm (R = 0.75 mm), E* = 5 MPa/(2 (1 - 0.3^2)), w = 1e-9 J/m^2,
     settling overlaps 0.1 .. 5 um; Hertz on the same overlaps */
  const double Rs = 7.5e-4, Es = 5e6 / (2 * (1 - 0.09)), ws = 1e-9;
  TIME_BEST(t_j, N, { dc_jkr_sphere(Rs, Es, ws, 1e-7 + 5e-6 * (double)i / N, &st); acc += st.F; });
  const dc_jkr_sphere_pair pr = dc_jkr_sphere_pair_of(Es, ws);
  TIME_BEST(t_i, N, {
    double a = 0.0, F;
    if (!dc_jkr_sphere_near_hertz(&pr, Rs, 1e-7 + 5e-6 * (double)i / N, &a, &F)) F = -1.0;
    acc += F + a;
  });
  TIME_BEST(t_h, N, {
    double kn, S;
    const double d = 1e-7 + 5e-6 * (double)i / N, root = dc_hertz_stiffness(Es, Rs, d, &kn, &S);
    acc += kn * d + root;
  });
  sink = acc;
  printf("Hertz trajectory (w = 1e-9, R = 0.75 mm, E* = 2.75 MPa, delta 0.1..5 um):\n");
  printf("  dc_jkr_sphere %.1f ns, inline dc_jkr_sphere_near_hertz (a, F) %.1f ns, Hertz (dc_hertz_stiffness) %.1f ns\n",
         t_j, t_i, t_h);
}

static void bench_elliptic(void)
{
  /* accuracy vs the mpmath table, cold and warm */
  double ecold = 0, ewarm = 0, ucold = 0, uwarm = 0, egeo = 0, v[12];
  int rows = 0;
  FILE *f = check_open_reference("jkr_elliptic_force.csv");
  if (f) {
    check_read_row(f, v, 11);
    while (check_read_row(f, v, 11) == 11) {
      dc_jkr_geom G;
      dc_jkr_geometry(v[1], v[2], v[3], v[4], &G);
      dc_jkr_state s, t;
      dc_jkr_contact(&G, v[6], NULL, &s);
      /* warm: hint from the state one small step earlier */
      dc_jkr_hint hint = {0};
      dc_jkr_contact(&G, v[6] - 1e-3 * fabs(G.delta_break), &hint, &t);
      dc_jkr_contact(&G, v[6], &hint, &t);
      const double e1 = fabs(s.F / v[7] - 1), e2 = fabs(t.F / v[7] - 1);
      ecold = fmax(ecold, e1);
      ewarm = fmax(ewarm, e2);
      ucold = fmax(ucold, e1 / (EPS * (1 + cond(&s))));
      uwarm = fmax(uwarm, e2 / (EPS * (1 + cond(&t))));
      rows++;
    }
    fclose(f);
  }
  f = check_open_reference("jkr_elliptic_extrema.csv");
  if (f) {
    check_read_row(f, v, 12);
    while (check_read_row(f, v, 12) == 12) {
      dc_jkr_geom G;
      dc_jkr_geometry(v[1], v[2], v[3], v[4], &G);
      egeo = fmax(egeo, fabs(G.F_pull / v[11] - 1));
      egeo = fmax(egeo, fabs(G.delta_break / v[7] - 1));
      egeo = fmax(egeo, fabs(G.e2_hertz / v[5] - 1));
    }
    fclose(f);
  }
  const double ratios[] = {0.5, 0.1, 0.01, 0.001};
  const int N = 10000, REP = 40;
  double tcold = 0, twarm = 0, tgeo = 0, s = 0;
  for (int k = 0; k < 4; k++) {
    dc_jkr_geom G;
    TIME_BEST(tgeo, 2000, { dc_jkr_geometry(1e-3, 1e-3 * ratios[k], 1e9, 0.05 + 1e-6 * i, &G); s += G.F_pull; });
    dc_jkr_geometry(1e-3, 1e-3 * ratios[k], 1e9, 0.05, &G);
    const double db = G.delta_break, span = 50.0 * fabs(db) - db;
    dc_jkr_state st;
    double t1 = now();
    for (int r = 0; r < REP; r++) {
      dc_jkr_hint hint = {0};
      for (int i = 0; i < N; i++) {
        /* load then unload: a DEM contact's path */
        const int j = i < N / 2 ? i : N - i;
        dc_jkr_contact(&G, db + span * (double)j / (N / 2), &hint, &st);
        s += st.F;
      }
    }
    double t2 = now();
    for (int r = 0; r < REP / 4; r++) {
      for (int i = 0; i < N; i++) {
        const int j = i < N / 2 ? i : N - i;
        dc_jkr_contact(&G, db + span * (double)j / (N / 2), NULL, &st);
        s += st.F;
      }
    }
    double t3 = now();
    twarm += (t2 - t1) / ((double)REP * N);
    tcold += (t3 - t2) / ((double)(REP / 4) * N);
    printf("  R_minor/R_major = %-6g  warm %6.1f ns, cold %6.1f ns, dc_jkr_geometry %6.0f ns\n", ratios[k],
           1e9 * (t2 - t1) / ((double)REP * N), 1e9 * (t3 - t2) / ((double)(REP / 4) * N), tgeo);
  }
  sink = s;
  printf("elliptic JKR F(delta), warm-start hint     %8.1f     %.2e      %.1f   (%d states)\n", 1e9 * twarm / 4,
         ewarm, uwarm, rows);
  printf("elliptic JKR F(delta), no hint             %8.1f     %.2e      %.1f\n", 1e9 * tcold / 4, ecold, ucold);
  printf("dc_jkr_geometry (e2_hertz, delta_break, F_pull)   see above   %.2e\n", egeo);
}

int main(void)
{
  bench_sphere();
  bench_elliptic();
  return 0;
}
