/* GW rough contact: ns per call and max relative error of each evaluation
   path (F_3/2 fast / closed form; rough force closed form, Feng explicit law
   in both variants, full solver m = 5, 10, 20; GW with adhesive JKR
   summits), then the error map of the explicit law against the solver
   (tests/reference/gw_feng_error_map.txt is this program's output with
   the argument "map"). */
#include "dc/feng_rough.h"
#include "dc/gw_integrals.h"
#include "dc/gw_rough.h"
#include "dc/gw_rough_adhesive.h"
#include "dc/gw_solver.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double now(void)
{
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

static volatile double sink;

static void bench_F32(void)
{
  /* reference: the committed mpmath table, located from this file's path */
  char path[1024];
  snprintf(path, sizeof path, "%s", __FILE__);
  char *sl = strrchr(path, '/');
  if (sl) *sl = 0;
  strncat(path, "/../reference/gw_integrals.csv", sizeof path - strlen(path) - 1);
  FILE *f = fopen(path, "r");
  double efast = 0, eclosed = 0;
  if (f) {
    char line[256];
    while (fgets(line, sizeof line, f)) {
      if (line[0] == '#' || line[0] == 'n') continue;
      double n = atof(strtok(line, ",")), h = atof(strtok(0, ",")), want = atof(strtok(0, ",\n"));
      if (n != 1.5 || want < 1e-300) continue;
      double a, b;
      dc_gw_F(3, h, &a);
      dc_gw_F_closed(3, h, &b);
      efast = fmax(efast, fabs(a / want - 1));
      if (h <= 10) eclosed = fmax(eclosed, fabs(b / want - 1));
    }
    fclose(f);
  }
  const int N = 2000000;
  double t0 = now(), s = 0, v;
  for (int i = 0; i < N; i++) { dc_gw_F(3, -10.0 + 25.0 * i / N, &v); s += v; }
  double t1 = now();
  for (int i = 0; i < N / 10; i++) { dc_gw_F_closed(3, -10.0 + 25.0 * i / (N / 10), &v); s += v; }
  double t2 = now();
  sink = s;
  printf("F_3/2(h), h in [-10, 15]           ns/call   max rel.err (vs mpmath table)\n");
  printf("  Chebyshev/asymptotic (fast)    %8.1f   %.2e (all h in [-40, 37])\n", 1e9 * (t1 - t0) / N, efast);
  printf("  Bessel closed form (GSL)       %8.1f   %.2e (h <= 10)\n", 1e9 * (t2 - t1) / (N / 10), eclosed);
}

static void bench_force(void)
{
  dc_hertz_geom g;
  dc_hertz_geometry(2e-3, 5e-4, &g);
  dc_feng_law Lt, Lf;
  dc_feng_init(4.0, DC_FENG_TABLE, &Lt);
  dc_feng_init(4.0, DC_FENG_FITTED, &Lf);
  const int N = 2000000;
  const double sigma = 1e-6;
  double s = 0, t0 = now();
  dc_gw_rough_state rs;
  for (int i = 0; i < N; i++) { dc_gw_rough_elliptic(&g, 1e9, 100.0, sigma, (-3.0 + 13.0 * i / N) * sigma, &rs); s += rs.F; }
  double t1 = now();
  double p, k;
  for (int i = 0; i < N; i++) { dc_feng_force(&Lt, 1e9, 1e-3, sigma, (-3.0 + 13.0 * i / N) * sigma, &p, &k); s += p; }
  double t2 = now();
  for (int i = 0; i < N; i++) { dc_feng_force(&Lf, 1e9, 1e-3, sigma, (-3.0 + 13.0 * i / N) * sigma, &p, &k); s += p; }
  double t3 = now();
  dc_feng_pair pt;   /* the hot path: bound to E*, sigma once, inline kernel */
  dc_feng_pair_init(&Lt, 1e9, sigma, &pt);
  const double sqrtR = sqrt(1e-3);
  for (int i = 0; i < N; i++) { dc_feng_pair_force(&pt, sqrtR, (-3.0 + 13.0 * i / N) * sigma, &p, &k); s += p; }
  double t4 = now();
  sink = s;
  printf("\nrough normal force                  ns/call\n");
  printf("  elliptic GW closed form (Eq. 33) %8.1f   (F_3/2 fast path; exact to ~1e-15)\n", 1e9 * (t1 - t0) / N);
  printf("  Feng law, table variant           %8.1f   (checked dc_feng_force)\n", 1e9 * (t2 - t1) / N);
  printf("  Feng law, fitted variant          %8.1f   (checked dc_feng_force)\n", 1e9 * (t3 - t2) / N);
  printf("  Feng law, bound pair (hot path)   %8.1f   (dc_feng_pair_force, as in the plugin)\n", 1e9 * (t4 - t3) / N);
  /* solver: error against m = 200 (domain 1.5 x Eq. 60) over alpha' grid, mu = 4 */
  dc_gw_solver ref;
  dc_gw_solver_init(&ref, 200);
  dc_gw_solve_opts o = dc_gw_solve_default_opts();
  o.domain_scale = 1.5;
  const double aps[] = {-2.5, -1.0, 0.0, 0.5, 1.0, 2.0, 5.0, 10.0, 100.0};
  double Pref[9];
  for (int i = 0; i < 9; i++) { dc_gw_solve_result r; dc_gw_solve(&ref, aps[i], 4.0, &o, &r); Pref[i] = r.Pstar_sigma; }
  dc_gw_solver_free(&ref);
  const int ms[] = {5, 10, 20};
  for (int k = 0; k < 3; k++) {
    dc_gw_solver S;
    dc_gw_solver_init(&S, ms[k]);
    double e = 0;
    const double ta = now();
    for (int i = 0; i < 9; i++) {
      dc_gw_solve_result r;
      dc_gw_solve(&S, aps[i], 4.0, &o, &r);
      e = fmax(e, fabs(r.Pstar_sigma / Pref[i] - 1));
    }
    const double tb = now();
    printf("  full solver m = %3d             %8.0f   max rel.err %.1e vs m = 200 (mu = 4, alpha' in [-2.5, 100])\n",
           ms[k], 1e9 * (tb - ta) / 9, e);
    dc_gw_solver_free(&S);
  }
}

/* GW with JKR summits: h in [-3, 5], both branches alternating, for a sphere
   and an ellipse (R_minor/R_major = 0.2), at w = 0.1 and 1e-5 (sigma = 1e-7,
   R_major = 1e-3, E* = 1e9; Fuller-Tabor theta printed). Accuracy: unit
   test. */
static void bench_adhesive(void)
{
  printf("\nGW with adhesive JKR summits (Eq. 29)     ns/call   summit evaluations per call\n");
  const double ratios[] = {1.0, 0.2}, ws[] = {0.1, 1e-5};
  for (int c = 0; c < 2; c++)
    for (int k = 0; k < 2; k++) {
      dc_jkr_geom g;
      dc_jkr_geometry(1e-3, 1e-3 * ratios[c], 1e9, ws[k], &g);
      const double theta = 1e9 * pow(1e-7, 1.5) / (ws[k] * sqrt(g.Rhat));
      const int N = c ? 4000 : 10000;
      long ne = 0;
      double s = 0, t0 = now();
      for (int i = 0; i < N; i++) {
        dc_gw_adhesive_state st;
        dc_gw_rough_adhesive(&g, 100.0, 1e-7, (3.0 - 8.0 * i / N) * 1e-7, i & 1, &st);
        s += st.F;
        ne += st.n_eval;
      }
      const double t1 = now();
      sink = s;
      printf("  %-7s theta = %-8.2g              %8.0f   %.0f\n", c ? "ellipse" : "sphere", theta,
             1e9 * (t1 - t0) / N, (double)ne / N);
    }
}

static void error_map(void)
{
  const double mus[] = {1, 2, 4, 7, 10, 20, 35, 50};
  const int nmu = 8;
  dc_gw_solver S;
  dc_gw_solver_init(&S, 60);
  dc_gw_solve_opts o = dc_gw_solve_default_opts();
  o.domain_scale = 1.5;
  printf("\nError map of the Feng explicit law against the full solver (m = 60, domain 1.5 x Eq. 60,\n"
         "exact F_3/2, force integrated to infinity). Cell: (law - solver)/solver in %%, law variant\n"
         "table | fitted. Rows: Case I in alpha = sigma/delta (P* = P/P_h(delta)), Cases II-III in\n"
         "alpha' = delta/sigma (P* = P/P_h(sigma)). '*' marks P*_solver < 0.02 (relative error of a\n"
         "near-zero force).\n");
  printf("%9s", "");
  for (int j = 0; j < nmu; j++) printf(" %15s%-4g", "mu=", mus[j]);
  printf("\n");
  double worst[2][3] = {{0}};
  for (int row = 0; row < 29; row++) {
    double ap, a = 0;
    int cs;
    if (row < 10) { a = 0.1 * (row + 1) - 0.05 * (row == 0); ap = 1.0 / a; cs = 0; }   /* alpha 0.05 .. 1 */
    else if (row < 14) { ap = 0.25 * (17 - row) - 0.25 * 0 ; ap = 1.0 - 0.25 * (row - 9); cs = 1; } /* 0.75 .. 0 */
    else { ap = -0.2 * (row - 13); cs = 2; }                                          /* -0.2 .. -3 */
    if (cs == 0) printf("alpha=%-4.2f", a); else printf("a'=%-7.2f", ap);
    for (int j = 0; j < nmu; j++) {
      dc_gw_solve_result r;
      dc_gw_solve(&S, ap, mus[j], &o, &r);
      double e[2];
      for (int v = 0; v < 2; v++) {
        dc_feng_law L;
        dc_feng_init(mus[j], v, &L);
        const double law = dc_feng_pstar_sigma(&L, ap);
        e[v] = 100 * (law / r.Pstar_sigma - 1);
        if (r.Pstar_sigma >= 0.02) worst[v][cs] = fmax(worst[v][cs], fabs(e[v]));
      }
      printf(" %7.2f|%7.2f%c", e[0], e[1], r.Pstar_sigma < 0.02 ? '*' : ' ');
    }
    printf("\n");
  }
  printf("\nworst |error| where P*_solver >= 0.02:   Case I    Case II   Case III\n");
  for (int v = 0; v < 2; v++)
    printf("  %-8s                              %6.2f%%  %6.2f%%  %6.2f%%\n", v ? "fitted" : "table",
           worst[v][0], worst[v][1], worst[v][2]);
  dc_gw_solver_free(&S);
}

int main(int argc, char **argv)
{
  if (argc > 1 && !strcmp(argv[1], "map")) { error_map(); return 0; }
  bench_F32();
  bench_force();
  bench_adhesive();
  error_map();
  return 0;
}
