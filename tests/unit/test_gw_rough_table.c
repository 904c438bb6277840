/* Tabulated GW rough-sphere law (dc/gw_rough_table.h) against the full
   solver (dc/gw_solver.h, other m and domain than the generator's) at
   points off the table's nodes: random in the domain, the resting range
   alpha' = -2.4 .. -2.8, beyond the table; continuity of value and
   derivative across every cell boundary; monotone in delta; kn = dP/d
   delta; smooth in mu; status contract and a random never-NaN sweep;
   ns per call against the Feng law. */
#include "check.h"
#include "dc/feng_rough.h"
#include "dc/gw_rough.h"
#include "dc/gw_rough_table.h"
#include "dc/gw_solver.h"
#include "dc/status.h"
#include <float.h>
#include <time.h>

static dc_gw_solver S_small, S_mid, S_big;

/* P* = P/P_h(sigma) of the solver: domain 1.5 x Eq. 60 (the table: 2),
   m = 200 / 500 / 800 (the table: 400 / 600 / 1000) */
static double solver_pstar(double ap, double mu)
{
  dc_gw_solve_opts o = dc_gw_solve_default_opts();
  o.domain_scale = 1.5;
  dc_gw_solve_result r;
  const dc_gw_solver *S = ap <= 64 ? &S_small : ap <= 512 ? &S_mid : &S_big;
  if (dc_gw_solve(S, ap, mu, &o, &r) != DC_OK) return NAN;
  return r.Pstar_sigma;
}

static double table_pstar(const dc_gw_table_law *L, double ap)
{
  double P, dP;
  if (dc_gw_table_pstar(L, ap, &P, &dP) != DC_OK) return NAN;
  return P;
}

/* error of the table at (ap, mu): relative where the solver's P* >= 1e-6,
   absolute below; worst values kept per class */
typedef struct { double rel, rel_ap, rel_mu, abs, abs_ap, abs_mu; int n; } worst_err;

static void compare(worst_err *w, double ap, double mu)
{
  dc_gw_table_law L;
  dc_gw_table_init(mu, &L);
  const double ref = solver_pstar(ap, mu), got = table_pstar(&L, ap);
  w->n++;
  if (!(isfinite(ref) && isfinite(got))) {
    CHECK(!"solver and table finite");
    return;
  }
  if (ref >= 1e-6) {
    const double e = fabs(got / ref - 1);
    if (e > w->rel) { w->rel = e; w->rel_ap = ap; w->rel_mu = mu; }
  } else {
    const double e = fabs(got - ref);
    if (e > w->abs) { w->abs = e; w->abs_ap = ap; w->abs_mu = mu; }
  }
}

static void report(const char *what, const worst_err *w)
{
  printf("  %-34s %4d points:", what, w->n);
  if (w->rel_mu > 0) printf(" max rel.err %.2e (alpha' %.4g, mu %.4g)", w->rel, w->rel_ap, w->rel_mu);
  if (w->abs > 0) printf("%s max abs.err %.1e below 1e-6 (alpha' %.4g, mu %.4g)", w->rel_mu > 0 ? "," : "", w->abs, w->abs_ap, w->abs_mu);
  printf("\n");
  CHECK(w->rel <= DC_GW_TABLE_REL_ERR);
  CHECK(w->abs <= DC_GW_TABLE_ABS_ERR);
}

static void against_solver(void)
{
  unsigned long long s = 0x9e3779b97f4a7c15ull;
  const double lmu = log(DC_GW_TABLE_MU_MAX);
  printf("table vs solver at points off the nodes (relative where P* >= 1e-6, absolute in P* below):\n");
  worst_err w = {0};
  for (int k = 0; k < 120; k++)   /* alpha' uniform in (-6, 1) */
    compare(&w, -6.0 + 7.0 * check_uniform(&s), exp(lmu * check_uniform(&s)));
  report("alpha' in (-6, 1), random", &w);
  worst_err wr = {0};
  for (int k = 0; k < 60; k++)    /* the resting range */
    compare(&wr, -2.8 + 0.4 * check_uniform(&s), exp(lmu * check_uniform(&s)));
  report("alpha' in (-2.8, -2.4), random", &wr);
  worst_err wg = {0};
  for (int k = 0; k < 80; k++)    /* alpha' log-uniform in (1, 512) */
    compare(&wg, exp(log(512.0) * check_uniform(&s)), exp(lmu * check_uniform(&s)));
  report("alpha' in (1, 512), log-random", &wg);
  worst_err wb = {0};
  for (int k = 0; k < 6; k++)     /* alpha' in (512, 4096) */
    compare(&wb, 512.0 * exp(log(8.0) * check_uniform(&s)), exp(lmu * check_uniform(&s)));
  report("alpha' in (512, 4096), log-random", &wb);
  worst_err wa = {0};
  const double beyond[] = {5000.0, 9900.0}, mus[] = {1.0, 6.3, 50.0};   /* the solver's domain ends at 1e4 */
  for (int i = 0; i < 2; i++)
    for (int j = 0; j < 3; j++) compare(&wa, beyond[i], mus[j]);
  report("alpha' = 5000, 9900 (asymptote)", &wa);
  worst_err wt = {0};
  for (int k = 0; k < 20; k++)    /* the cut at -6 and the first cells */
    compare(&wt, -6.5 + 1.0 * check_uniform(&s), k < 10 ? 50.0 : exp(lmu * check_uniform(&s)));
  report("alpha' in (-6.5, -5.5), the cut", &wt);
  worst_err wc = {0};
  for (int i = 0; i < 16; i++)    /* cell midpoints, uniform part, the worst place for the spline */
    compare(&wc, -5.0 + (7 * i + 0.5) / 16.0, 1.0 + 49.0 * check_uniform(&s));
  report("cell midpoints (-5 .. 1)", &wc);
}

/* value and derivative continuous across every cell boundary, C1 at
   -6 (zero) and 4096 (asymptote) */
static void continuity(void)
{
  const double mus[] = {1.0, 2.7, 13.0, 50.0};
  double wv = 0, wd = 0;
  for (int j = 0; j < 4; j++) {
    dc_gw_table_law L;
    CHECK(dc_gw_table_init(mus[j], &L) == DC_OK);
    for (int i = 0; i < DC_GW_TABLE_NNODE; i++) {
      const double x = dc_gw_table_node(i), xm = nextafter(x, -INFINITY);
      double P0, d0, P1, d1;
      CHECK(dc_gw_table_pstar(&L, xm, &P0, &d0) == DC_OK);
      CHECK(dc_gw_table_pstar(&L, x, &P1, &d1) == DC_OK);
      /* allowance: the function's own change over one ulp of x */
      const double slack = fabs(d1) * (x - xm) * 2 + 1e-300;
      const double ev = fabs(P1 - P0) / fmax(fabs(P1), 1e-300);
      const double ed = fabs(d1 - d0) / fmax(fabs(d1), 1e-300);
      if (i > 0) wv = fmax(wv, (fabs(P1 - P0) - slack) / fmax(fabs(P1), 1e-300));
      if (i > 0) wd = fmax(wd, ed);
      if (i == 0) CHECK(P0 == 0.0 && d0 == 0.0 && P1 == 0.0 && d1 == 0.0);
      else {
        CHECK(ev <= 1e-13 || fabs(P1 - P0) <= slack + 1e-13 * fabs(P1));
        CHECK(ed <= 1e-9);
      }
    }
    /* the first cell leaves -6 with slope 0 */
    double P, d;
    dc_gw_table_pstar(&L, DC_GW_TABLE_X_LO + 1e-9, &P, &d);
    CHECK(P >= 0.0 && P < 1e-20 && d >= 0.0 && d < 1e-10);
  }
  printf("cell boundaries (209 nodes, mu = 1, 2.7, 13, 50): max relative jump in value %.1e, in "
         "dP*/dalpha' %.1e\n", fmax(wv, 0.0), wd);
}

/* monotone (P* and its slope >= 0) on a dense sweep; kn = dP/d delta */
static void monotone_and_stiffness(void)
{
  int bad = 0;
  double wk = 0;
  for (double mu = 1.0; mu <= 50.0; mu *= 1.21) {
    dc_gw_table_law L;
    dc_gw_table_init(mu, &L);
    double prev = -1.0;
    for (double x = -6.5; x < 2e4; x += x < 2 ? 1.0 / 1024 : x / 2048) {
      double P, d;
      dc_gw_table_pstar(&L, x, &P, &d);
      if (!(P >= prev && d >= 0.0 && P >= 0.0)) {
        if (bad < 5) printf("  not monotone: mu %g alpha' %.17g: P* %g (before %g), slope %g\n", mu, x, P, prev, d);
        bad++;
      }
      prev = P;
    }
    /* kn against a central difference of P (step 1e-6 sigma; 1e-6 relative beyond 1) */
    dc_gw_table_pair p;
    const double sigma = 1e-6, sqrtR = sqrt(1e-3);
    dc_gw_table_pair_init(&L, 1e9, sigma, &p);
    for (double x = -5.3; x < 1e4; x = x < 1 ? x + 0.37 : x * 1.9) {
      double P, kn, Pp, Pm, k2;
      const double h = 1e-6 * fmax(1.0, fabs(x)) * sigma;
      dc_gw_table_pair_force(&p, sqrtR, x * sigma, &P, &kn);
      dc_gw_table_pair_force(&p, sqrtR, x * sigma + h, &Pp, &k2);
      dc_gw_table_pair_force(&p, sqrtR, x * sigma - h, &Pm, &k2);
      const double fd = (Pp - Pm) / (2 * h);
      wk = fmax(wk, fabs(kn - fd) / fabs(kn));
      CHECK_REL(kn, fd, 1e-6, "kn = dP/d delta");
    }
  }
  CHECK(bad == 0);
  printf("monotone in delta on a dense sweep (alpha' -6.5 .. 2e4, 21 mu): %s; kn vs central difference: "
         "max rel. diff %.1e\n", bad ? "NO" : "yes", wk);
}

/* smooth in mu: P* and the central-difference slope in ln mu change
   smoothly (second difference at step h and h/2 in the h^2 ratio) */
static void smooth_in_mu(void)
{
  const double xs[] = {-4.7, -2.63, -0.41, 0.77, 13.3, 900.0};
  double worst = 0, gmax = 0;
  for (int i = 0; i < 6; i++)
    for (double mu = 1.3; mu < 50; mu *= 2.3) {
      double v[5];
      const double h = 0.01;
      for (int k = 0; k < 5; k++) {
        dc_gw_table_law L;
        dc_gw_table_init(mu * exp((k - 2) * h), &L);
        v[k] = table_pstar(&L, xs[i]);
      }
      /* second differences at steps 2h and h: ratio 4 for a C2 function */
      const double d2h = (v[4] - 2 * v[2] + v[0]), d1h = (v[3] - 2 * v[2] + v[1]);
      if (fabs(d1h) > 1e-12 * v[2]) {
        const double r = d2h / d1h;
        worst = fmax(worst, fabs(r - 4.0));
        CHECK(fabs(r - 4.0) < 0.05);
      }
      /* first differences: 0 <= d ln P* / d ln mu <= 1 (P* proportional to mu
         where the summits barely deform the bulk, less where they do) */
      const double g = (v[3] - v[1]) / (2 * h * v[2]);
      gmax = fmax(gmax, g);
      CHECK(g >= 0.0 && g <= 1.0 + 1e-3);
    }
  printf("smooth in mu: second differences in ln mu at steps 0.02 and 0.01 in ratio 4 within %.1e; "
         "max d ln P*/d ln mu %.3f\n", worst, gmax);
}

static void limits_and_status(void)
{
  dc_gw_table_law L;
  CHECK(dc_gw_table_init(0.999, &L) == DC_EDOM);
  CHECK(dc_gw_table_init(50.001, &L) == DC_EDOM);
  CHECK(dc_gw_table_init(NAN, &L) == DC_EDOM);
  CHECK(dc_gw_table_init(1.0, &L) == DC_OK);
  CHECK(dc_gw_table_init(50.0, &L) == DC_OK);
  dc_param_error err;
  CHECK(dc_gw_table_check(51.0, &err) == DC_EDOM && !strcmp(err.name, "roughnessMu"));
  CHECK(dc_gw_table_check(7.0, &err) == DC_OK);
  /* sigma = 0: Hertz; sigma -> 0 at fixed delta: P/P_h(delta) -> 1 */
  dc_gw_table_init(4.0, &L);
  double P, kn;
  const double Es = 1e9, R = 1e-3, c = 4.0 / 3 * Es * sqrt(R);
  CHECK(dc_gw_table_force(&L, Es, R, 0.0, 1e-6, &P, &kn) == DC_OK);
  CHECK_REL(P, c * 1e-9, 1e-15, "sigma = 0: Hertz");
  CHECK(dc_gw_table_force(&L, Es, R, 0.0, -1e-6, &P, &kn) == DC_OK && P == 0.0 && kn == 0.0);
  const double sig[] = {1e-12, 1e-15, 1e-20, 1e-40};
  for (int k = 0; k < 4; k++) {
    CHECK(dc_gw_table_force(&L, Es, R, sig[k], 1e-6, &P, &kn) == DC_OK);
    CHECK_REL(P, c * 1e-9, 0.2 * pow(sig[k] / 1e-6 * 4096, 2.0 / 3.0) + 1e-15, "sigma -> 0: Hertz");
    CHECK_REL(kn, 1.5 * c * 1e-3, 0.2 * pow(sig[k] / 1e-6 * 4096, 2.0 / 3.0) + 1e-15, "sigma -> 0: Hertz kn");
  }
  /* at and below -6 sigma: zero */
  CHECK(dc_gw_table_force(&L, Es, R, 1e-6, -6e-6, &P, &kn) == DC_OK && P == 0.0 && kn == 0.0);
  CHECK(dc_gw_table_force(&L, Es, R, 1e-6, -1.0, &P, &kn) == DC_OK && P == 0.0 && kn == 0.0);
  /* domain: outputs untouched */
  P = kn = 123.0;
  CHECK(dc_gw_table_force(&L, -1.0, R, 1e-6, 1e-6, &P, &kn) == DC_EDOM);
  CHECK(dc_gw_table_force(&L, Es, 0.0, 1e-6, 1e-6, &P, &kn) == DC_EDOM);
  CHECK(dc_gw_table_force(&L, Es, R, -1e-6, 1e-6, &P, &kn) == DC_EDOM);
  CHECK(dc_gw_table_force(&L, Es, R, 1e-6, NAN, &P, &kn) == DC_EDOM);
  CHECK(dc_gw_table_force(&L, Es, R, 1e-6, INFINITY, &P, &kn) == DC_EDOM);
  CHECK(dc_gw_table_force(&L, INFINITY, R, 1e-6, 1e-6, &P, &kn) == DC_EDOM);
  CHECK(P == 123.0 && kn == 123.0);
  double dP;
  CHECK(dc_gw_table_pstar(&L, NAN, &P, &dP) == DC_EDOM && P == 123.0);
  CHECK(dc_gw_table_pstar(&L, 1e300, &P, &dP) == DC_ERANGE && P == 123.0);
  CHECK(dc_gw_table_force(&L, 1e300, 1e300, 1e-6, 1e300, &P, &kn) == DC_ERANGE && P == 123.0);
  /* pair: domain, range, and the same numbers as the checked form */
  dc_gw_table_pair p;
  CHECK(dc_gw_table_pair_init(&L, Es, 0.0, &p) == DC_EDOM);
  CHECK(dc_gw_table_pair_init(&L, Es, 1e-320, &p) == DC_ERANGE);
  CHECK(dc_gw_table_pair_init(&L, Es, 1e-6, &p) == DC_OK);
  const double ds[] = {-7e-6, -5.99e-6, -2.7e-6, -1e-7, 0.0, 3e-7, 1e-6, 2.5e-5, 3e-4, 4.095e-3, 4.096e-3, 1e-2, 10.0};
  for (int k = 0; k < 13; k++) {
    double P2, k2;
    CHECK(dc_gw_table_force(&L, Es, R, 1e-6, ds[k], &P, &kn) == DC_OK);
    dc_gw_table_pair_force(&p, sqrt(R), ds[k], &P2, &k2);
    CHECK(P == P2 && kn == k2);
  }
  /* out-of-range constants: the scaled path gives the same law */
  CHECK(dc_gw_table_force(&L, 1e-300, 1e-300, 1e-200, 2.7e-200, &P, &kn) == DC_OK);
  double Pu, du;
  dc_gw_table_pstar(&L, 2.7, &Pu, &du);
  CHECK_REL(P, 4.0 / 3 * 1e-300 * 1e-150 * 1e-300 * Pu, 1e-13, "scaled path, tiny scales");
  CHECK(dc_gw_table_force(&L, 1e300, 1e10, 1e-300, 1e-250, &P, &kn) == DC_OK);
  CHECK_REL(P, 4.0 / 3 * 1e-70, 1e-13, "scaled path, asymptote: Hertz (4/3 E* R^1/2 delta^3/2)");
}

/* random inputs, including extreme ones: DC_OK with finite outputs, or an
   error with outputs untouched; the hot path is finite wherever the pair
   could be bound and P_h(delta) is finite */
static void never_nan(void)
{
  unsigned long long s = 1234567ull;
  int bad = 0, ok = 0;
  dc_gw_table_law laws[8];
  for (int i = 0; i < 8; i++) dc_gw_table_init(1.0 + 49.0 * i / 7.0, &laws[i]);
  const double specials[] = {0.0, -0.0, DBL_MIN, DBL_TRUE_MIN, DBL_MAX, -DBL_MAX, INFINITY, -INFINITY, NAN, 1.0, -6.0, 4096.0};
  for (int k = 0; k < 200000; k++) {
    const dc_gw_table_law *L = &laws[k & 7];
    double v[4];
    for (int j = 0; j < 4; j++) {
      const double u = check_uniform(&s);
      if (u < 0.05) v[j] = specials[(int)(check_uniform(&s) * 12)];
      else v[j] = (check_uniform(&s) < 0.2 ? -1 : 1) * pow(10.0, -320 + 628 * check_uniform(&s));
    }
    if (k % 3 == 0) v[3] = v[2] * (-7.0 + 20.0 * check_uniform(&s));   /* delta ~ sigma */
    double P = 7.0, kn = 7.0;
    const int st = dc_gw_table_force(L, v[0], v[1], v[2], v[3], &P, &kn);
    if (st == DC_OK) { ok++; if (!(isfinite(P) && isfinite(kn) && P >= 0.0 && kn >= 0.0)) bad++; }
    else if (!(P == 7.0 && kn == 7.0 && (st == DC_EDOM || st == DC_ERANGE))) bad++;
    double dP;
    P = 7.0;
    const int sp = dc_gw_table_pstar(L, v[3], &P, &dP);
    if (sp == DC_OK ? !(isfinite(P) && isfinite(dP) && P >= 0.0 && dP >= 0.0) : P != 7.0) bad++;
    dc_gw_table_pair p;
    if (dc_gw_table_pair_init(L, fabs(v[0]), fabs(v[2]), &p) == DC_OK && isfinite(v[3]) && fabs(v[3]) < 1e100) {
      const double sR = 1e-3;
      dc_gw_table_pair_force(&p, sR, v[3], &P, &kn);
      const double Ph = p.c * sR * fabs(v[3]) * sqrt(fabs(v[3]));
      if (isfinite(Ph) && isfinite(p.c * sR * sqrt(fabs(v[3]))) && !(isfinite(P) && isfinite(kn) && P >= 0 && kn >= 0)) {
        if (bad < 5) printf("  pair: E %g sigma %g delta %g: P %g kn %g\n", fabs(v[0]), fabs(v[2]), v[3], P, kn);
        bad++;
      }
    }
  }
  printf("random sweep: 200000 inputs (%d DC_OK), never NaN or Inf, errors leave outputs untouched: %s\n", ok,
         bad ? "NO" : "yes");
  CHECK(bad == 0);
}

/* gw_rough's sphere-law setting: each law through the switch gives its own
   kernel's numbers bit for bit */
static void sphere_switch(void)
{
  static dc_gw_sphere_pair sf, st, sx;
  const double Es = 2e9, sigma = 3e-7, sqrtR = sqrt(2e-3);
  CHECK(dc_gw_sphere_pair_init(DC_GW_SPHERE_FENG, DC_FENG_FITTED, 7.0, Es, sigma, &sf) == DC_OK);
  CHECK(dc_gw_sphere_pair_init(DC_GW_SPHERE_TABULATED, DC_FENG_FITTED, 7.0, Es, sigma, &st) == DC_OK);
  sx.law = 99;
  CHECK(dc_gw_sphere_pair_init(2, DC_FENG_TABLE, 7.0, Es, sigma, &sx) == DC_EDOM && sx.law == 99);
  CHECK(dc_gw_sphere_pair_init(DC_GW_SPHERE_TABULATED, DC_FENG_TABLE, 0.5, Es, sigma, &sx) == DC_EDOM && sx.law == 99);
  CHECK(dc_gw_sphere_pair_init(DC_GW_SPHERE_FENG, DC_FENG_TABLE, 7.0, Es, 0.0, &sx) == DC_EDOM && sx.law == 99);
  CHECK(dc_gw_sphere_pair_init(DC_GW_SPHERE_TABULATED, DC_FENG_TABLE, 7.0, Es, 1e-320, &sx) == DC_ERANGE && sx.law == 99);
  CHECK(dc_gw_sphere_reach(DC_GW_SPHERE_FENG) == -3.0 && dc_gw_sphere_reach(DC_GW_SPHERE_TABULATED) == -6.0);
  dc_feng_law F;
  dc_feng_pair fp;
  dc_feng_init(7.0, DC_FENG_FITTED, &F);
  dc_feng_pair_init(&F, Es, sigma, &fp);
  static dc_gw_table_pair tp;
  dc_gw_table_law T;
  dc_gw_table_init(7.0, &T);
  dc_gw_table_pair_init(&T, Es, sigma, &tp);
  int same = 1;
  for (double x = -7.0; x < 5000.0; x = x < 2 ? x + 0.013 : x * 1.01) {
    double P1, k1, P2, k2;
    dc_gw_sphere_pair_force(&sf, sqrtR, x * sigma, &P1, &k1);
    dc_feng_pair_force(&fp, sqrtR, x * sigma, &P2, &k2);
    same &= P1 == P2 && k1 == k2;
    dc_gw_sphere_pair_force(&st, sqrtR, x * sigma, &P1, &k1);
    dc_gw_table_pair_force(&tp, sqrtR, x * sigma, &P2, &k2);
    same &= P1 == P2 && k1 == k2;
  }
  CHECK(same);
}

/* CPU time of this thread: a loaded machine does not count against the law */
static double now(void)
{
  struct timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

static volatile double sink;
static dc_gw_table_pair tpair;
static dc_feng_pair fpair;

static double loop_table(const double *d, int n, double sqrtR)
{
  double acc = 0, P, kn;
  for (int i = 0; i < n; i++) { dc_gw_table_pair_force(&tpair, sqrtR, d[i], &P, &kn); acc += P + kn; }
  return acc;
}

static double loop_feng(const double *d, int n, double sqrtR)
{
  double acc = 0, P, kn;
  for (int i = 0; i < n; i++) { dc_feng_pair_force(&fpair, sqrtR, d[i], &P, &kn); acc += P + kn; }
  return acc;
}

/* ns per call of the bound pairs (the hot path; the loop's own load and
   sum included), best of 7: a sweep alpha' -3 .. 10, a random order over
   -6 .. 100 and the resting range -2.8 .. -2.4. Prints, does not assert. */
static void timing(void)
{
  dc_gw_table_law L;
  dc_gw_table_init(4.0, &L);
  const double sigma = 1e-6, sqrtR = sqrt(1e-3);
  dc_gw_table_pair_init(&L, 1e9, sigma, &tpair);
  dc_feng_law F;
  dc_feng_init(4.0, DC_FENG_TABLE, &F);
  dc_feng_pair_init(&F, 1e9, sigma, &fpair);
  enum { N = 4096, REP = 1000 };
  static double d[3][N];
  unsigned long long s = 42;
  for (int i = 0; i < N; i++) {
    d[0][i] = (-3.0 + 13.0 * i / N) * sigma;
    d[1][i] = (-6.0 + 106.0 * check_uniform(&s) * check_uniform(&s)) * sigma;
    d[2][i] = (-2.8 + 0.4 * check_uniform(&s)) * sigma;
  }
  const char *name[3] = {"sweep alpha' -3 .. 10", "random alpha' in (-6, 100)", "random alpha' in (-2.8, -2.4)"};
  for (int k = 0; k < 3; k++) {
    double best[2] = {1e9, 1e9};
    for (int rep = 0; rep < 7; rep++) {
      const double t0 = now();
      for (int r = 0; r < REP; r++) sink = loop_table(d[k], N, sqrtR);
      const double t1 = now();
      for (int r = 0; r < REP; r++) sink = loop_feng(d[k], N, sqrtR);
      const double t2 = now();
      best[0] = fmin(best[0], 1e9 * (t1 - t0) / (N * REP));
      best[1] = fmin(best[1], 1e9 * (t2 - t1) / (N * REP));
    }
    printf("ns per call (thread CPU time, best of 7, %s): table %.2f, Feng %.2f\n", name[k], best[0], best[1]);
  }
}

int main(void)
{
  dc_gw_solver_init(&S_small, 200);
  dc_gw_solver_init(&S_mid, 500);
  dc_gw_solver_init(&S_big, 800);
  limits_and_status();
  continuity();
  monotone_and_stiffness();
  smooth_in_mu();
  never_nan();
  sphere_switch();
  against_solver();
  timing();
  dc_gw_solver_free(&S_small);
  dc_gw_solver_free(&S_mid);
  dc_gw_solver_free(&S_big);
  return check_summary("gw_rough_table");
}
