/* Tabulated adhesive part of the rough contact with circular JKR summits
   (dc/gw_rough_adhesive_table.h) against the exact c_core law
   (dc_gw_rough_adhesive minus dc_gw_rough_elliptic) at random points off
   the table's nodes, continuity, branches and hysteresis, pull-off force,
   w = 0, magnitudes at the edges of the doubles, and a random never-NaN
   sweep; prints ns per call. */
#include "check.h"
#include "dc/gw_rough.h"
#include "dc/gw_rough_adhesive.h"
#include "dc/gw_rough_adhesive_table.h"
#include "dc/jkr_elliptic.h"
#include "dc/status.h"
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <stdlib.h>
#include <time.h>

static double now(void)
{
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

/* exact adhesive part and its kn */
static int exact(const dc_jkr_geom *g, double n, double sigma, double delta, int b, double *F, double *kn)
{
  dc_gw_adhesive_state s;
  dc_gw_rough_state e;
  if (dc_gw_rough_adhesive(g, n, sigma, delta, b, &s) != DC_OK) return 1;
  if (dc_gw_rough_elliptic(&g->hertz, g->Estar, n, sigma, delta, &e) != DC_OK) return 1;
  *F = s.F - e.F;
  *kn = s.kn - e.kn;
  return 0;
}

static void test_constant(void)
{
  dc_jkr_geom g;
  CHECK(dc_jkr_geometry(1.0, 1.0, 1.0, 1.0, &g) == DC_OK);
  dc_gwa_table_pair p;
  CHECK(dc_gwa_table_pair_init(1.0, 1.0, 1.0, 1.0, &p) == DC_OK);
  CHECK_REL(p.ub, g.delta_break / g.delta_scale, 1e-14, "delta_break/delta_c");
  CHECK_REL(p.dc_coef, g.delta_scale, 1e-14, "delta_c");
}

/* random (R, sigma, w, E*, delta) in the table's theta range, both branches */
static void test_random_vs_exact(void)
{
  unsigned long long rs = 0x9e3779b97f4a7c15ULL;
  double worst_rel[2] = {0, 0}, worst_abs[2] = {0, 0}, worst_kn[2] = {0, 0};
  int n_rel = 0;
  for (int k = 0; k < 1500; k++) {
    const double R = 1e-5 * pow(1e3, check_uniform(&rs));
    const double E = 1e7 * pow(1e4, check_uniform(&rs));
    const double w = 1e-3 * pow(1e3, check_uniform(&rs));
    const double n = 10.0 + 1000.0 * check_uniform(&rs);
    /* sigma from eta uniform in the table's range */
    dc_gwa_table_pair p0;
    dc_gwa_table_pair_init(E, w, 1.0, n, &p0);
    const double eta = DC_GWA_TABLE_ETA_LO + (8.0 - DC_GWA_TABLE_ETA_LO) * check_uniform(&rs);
    const double sigma = exp(eta) * p0.dc_coef * cbrt(R);
    dc_gwa_table_pair p;
    CHECK(dc_gwa_table_pair_init(E, w, sigma, n, &p) == DC_OK);
    dc_jkr_geom g;
    CHECK(dc_jkr_geometry(R, R, E, w, &g) == DC_OK);
    const int b = k & 1;
    /* x uniform in [-12, 7] most of the time, deep [-2000, -8] else */
    double x = -12.0 + 19.0 * check_uniform(&rs);
    if (k % 5 == 4) x = -8.0 * pow(250.0, check_uniform(&rs));
    const double D = -g.delta_break / sigma;
    const double h = b ? x + D : x;
    const double delta = -h * sigma;
    double Fe, ke, Ft, kt;
    if (exact(&g, n, sigma, delta, b, &Fe, &ke)) { CHECK(0); continue; }
    CHECK(dc_gwa_table_force(&p, R, b, delta, &Ft, &kt) == DC_OK);
    const double scale = n * 8.0 * w * R;   /* n_asp F_s */
    if (fabs(Fe) >= 1e-6 * scale) {
      if (fabs(Ft / Fe - 1) > 1e-4 && getenv("GWA_DEBUG")) printf("  b %d x %.4g eta %.3g rel %.2e\n", b, x, eta, fabs(Ft / Fe - 1));
      worst_rel[b] = fmax(worst_rel[b], fabs(Ft / Fe - 1));
      worst_kn[b] = fmax(worst_kn[b], fabs(kt - ke) / (fabs(ke) + fabs(Fe) / sigma));
      n_rel++;
    } else {
      worst_abs[b] = fmax(worst_abs[b], fabs(Ft - Fe) / scale);
    }
  }
  for (int b = 0; b < 2; b++) {
    printf("%s: max rel. error %.2e where |F| >= 1e-6 n_asp 8 w R, abs. %.2e (units n_asp 8 w R) below; kn %.2e\n",
           b ? "unloading" : "loading", worst_rel[b], worst_abs[b], worst_kn[b]);
    /* measured: loading 1.5e-6 (the deep continuation, x < -255), kn 5.4e-7;
       unloading 1.8e-5, kn 6.8e-6 */
    CHECK_ABS(worst_rel[b], 0.0, b ? 3e-5 : 2e-6, "relative error where the force matters");
    CHECK_ABS(worst_abs[b], 0.0, 1e-10, "absolute error below");
    CHECK_ABS(worst_kn[b], 0.0, b ? 1e-5 : 1e-6, "kn error");
  }
  CHECK(n_rel > 1000);
}

/* G_b and dG/dx against the exact law inside every cell of the table
   (eta in [-4.5, 8], x in [-400, 10]), 4 points per eta cell and 60 per x
   band; relative where |G| >= 1e-6 */
static void test_dense_vs_exact(void)
{
  dc_jkr_geom g;
  CHECK(dc_jkr_geometry(1.0, 1.0, 1.0, 1.0, &g) == DC_OK);
  const double xb[] = {-400, -256, -64, -16, -8, -6.5, -4.5, -2, 0, 2, 8, 10};
  double worst[2] = {0, 0}, worst_kn[2] = {0, 0};
  for (int b = 0; b < 2; b++)
    for (double e0 = DC_GWA_TABLE_ETA_LO; e0 < 8.0; e0 += 0.5)
      for (int q = 0; q < 11; q++)
        for (int i = 0; i < 60; i++) {
          const double f = (i + 0.37) / 60;
          const double x = xb[q] < -10 ? -exp(log(-xb[q]) + f * (log(-xb[q + 1]) - log(-xb[q])))
                                       : xb[q] + f * (xb[q + 1] - xb[q]);
          for (int r = 0; r < 4; r++) {
            const double eta = e0 + (r + 0.5 + 0.21 * (i % 3)) * 0.125;
            const double tau = exp(eta), sigma = tau * g.delta_scale;
            const double h = b ? x - g.delta_break / sigma : x;
            double F, kn, G, Gx;
            if (exact(&g, 1.0, sigma, -h * sigma, b, &F, &kn)) { CHECK(0); continue; }
            CHECK(dc_gwa_table_reduced(b, x, eta, &G, &Gx) == DC_OK);
            const double Ge = F / g.F_scale, Gex = -sigma * kn / g.F_scale;
            if (fabs(Ge) < 1e-6) continue;
            worst[b] = fmax(worst[b], fabs(G / Ge - 1));
            worst_kn[b] = fmax(worst_kn[b], fabs(Gx - Gex) / (fabs(Gex) + fabs(Ge)));
          }
        }
  for (int b = 0; b < 2; b++)
    printf("%s, dense: max rel. error %.2e, dG/dx %.2e\n", b ? "unloading" : "loading", worst[b], worst_kn[b]);
  /* measured: loading 3.1e-7, dG/dx 6.7e-7; unloading 2.3e-5, dG/dx 2.9e-5
     (moderate tau, 0.2 < tau < 1, x in -5..-2: the summits' Hertz kink
     crossing the near region) */
  CHECK_ABS(worst[0], 0.0, 5e-7, "loading: dense relative error");
  CHECK_ABS(worst_kn[0], 0.0, 1e-6, "loading: dense dG/dx error");
  CHECK_ABS(worst[1], 0.0, 3e-5, "unloading: dense relative error");
  CHECK_ABS(worst_kn[1], 0.0, 4e-5, "unloading: dense dG/dx error");
}

/* C1 at the seams of the table (the deep continuation, the near/deep
   blend, the kink term's mask, the linear continuation beyond X_HI): G
   and dG/dx from both sides */
static void test_seams(void)
{
  const double xs[] = {dc_gwa_table_x_deep(DC_GWA_TABLE_K_END), DC_GWA_TABLE_BLEND_LO, DC_GWA_TABLE_BLEND_HI,
                       DC_GWA_KINK_W_LO, DC_GWA_KINK_W_HI, DC_GWA_TABLE_X_HI};
  double jump = 0, kink = 0;
  for (int b = 0; b < 2; b++)
    for (double eta = DC_GWA_TABLE_ETA_LO; eta <= 8.0; eta += 0.0731)
      for (int k = 0; k < 6; k++) {
        const double e = 1e-7 * fmax(1.0, fabs(xs[k]));
        double G[4], Gx[4];
        for (int m = 0; m < 4; m++) {
          const double off[4] = {-3, -1, 1, 3};
          CHECK(dc_gwa_table_reduced(b, xs[k] + off[m] * e, eta, &G[m], &Gx[m]) == DC_OK);
        }
        /* the value across the seam against the trapezoid of the slopes; the
           slope at the seam extrapolated from either side */
        jump = fmax(jump, fabs(G[2] - G[1] - (Gx[1] + Gx[2]) * e) / fabs(G[1]));
        const double left = 1.5 * Gx[1] - 0.5 * Gx[0], right = 1.5 * Gx[2] - 0.5 * Gx[3];
        kink = fmax(kink, fabs(right - left) / (fabs(Gx[1]) + fabs(G[1])));
      }
  printf("seams: worst jump in G %.1e, in dG/dx %.1e\n", jump, kink);
  /* measured: 5e-11 and 9e-8 (the deep continuation's slope) */
  CHECK_ABS(jump, 0.0, 1e-9, "seams: G continuous");
  CHECK_ABS(kink, 0.0, 1e-6, "seams: dG/dx continuous");
}

/* continuity of F and kn in delta across cells and zones: secant slope vs kn */
static void test_continuity(void)
{
  dc_gwa_table_pair p;
  const double R = 1e-3, sigma = 1e-7;
  const double ws[] = {2.0, 0.1, 1e-3, 1e-5};
  for (int k = 0; k < 4; k++) {
    dc_gwa_table_pair_init(1e9, ws[k], sigma, 100.0, &p);
    for (int b = 0; b < 2; b++) {
      double Fp = 0, kp = 0, worst = 0, jump = 0;
      const double D = b ? -p.ub * p.dc_coef * cbrt(R) / sigma : 0.0;
      const int N = 40000;
      for (int i = 0; i <= N; i++) {
        const double x = -400.0 + 420.0 * i / N;   /* crosses -256, -8, 8 */
        const double delta = -(x + D) * sigma, dd = 420.0 / N * sigma;
        double F, kn;
        CHECK(dc_gwa_table_force(&p, R, b, delta, &F, &kn) == DC_OK);
        if (i > 0) {
          const double slope = (Fp - F) / dd;
          const double lo = fmin(kn, kp), hi = fmax(kn, kp), sl = 1e-3 * (fabs(kn) + fabs(F) / sigma) + 1e-30;
          if (slope < lo - sl || slope > hi + sl) worst = fmax(worst, fmin(fabs(slope - lo), fabs(slope - hi)) / sl * 1e-3);
          jump = fmax(jump, fabs(F - Fp) / (100.0 * 8.0 * ws[k] * R));
        }
        Fp = F; kp = kn;
      }
      CHECK_ABS(worst, 0.0, 1e-3, "secant slope within the end kn (C1)");
      CHECK_ABS(jump, 0.0, 0.02, "no jump in F (step 0.0105 sigma)");
    }
  }
}

/* branches: loading then unloading of one contact, hysteresis, pull-off */
static void test_branches(void)
{
  const double R = 1e-3, sigma = 1e-7, E = 1e9, n = 100.0;
  const double ws[] = {0.5, 0.02};
  for (int k = 0; k < 2; k++) {
    dc_gwa_table_pair p;
    dc_gwa_table_pair_init(E, ws[k], sigma, n, &p);
    dc_jkr_geom g;
    dc_jkr_geometry(R, R, E, ws[k], &g);
    double hist[2] = {0, 0};
    dc_gwa_table_out o;
    /* approach from h = 6 to h = -3: loading branch, equal to the exact law */
    for (double h = 6; h >= -3; h -= 0.25) {
      CHECK(dc_gwa_table_step(&p, R, -h * sigma, hist, &o) == DC_OK);
      double Fe, ke;
      exact(&g, n, sigma, -h * sigma, DC_GW_LOADING, &Fe, &ke);
      CHECK(o.weight == 0.0);
      CHECK_REL(o.F, Fe, 1e-4, "approach: loading branch");
    }
    CHECK(hist[0] == 1.0 && hist[1] == 3 * sigma);
    /* retract: unloading once delta <= delta_max + delta_break; the pull
       is larger than on loading (hysteresis); the largest pull (pull-off)
       against the exact law's */
    double pull_t = 0, pull_e = 0, pull_l = 0, Fprev = 0;
    int hyst = 1, reset = 0;
    for (int i = 1; i < 4000; i++) {
      const double delta = 3 * sigma - i * 0.01 * sigma;
      double Fe, ke, Fl, kl;
      CHECK(dc_gwa_table_step(&p, R, delta, hist, &o) == DC_OK);
      if (hist[0] == 0.0) { reset = 1; break; }
      if (delta <= 3 * sigma + g.delta_break) {
        CHECK(o.weight == 1.0);
        exact(&g, n, sigma, delta, DC_GW_UNLOADING, &Fe, &ke);
        exact(&g, n, sigma, delta, DC_GW_LOADING, &Fl, &kl);
        if (fabs(Fe) > 1e-6 * n * 8 * ws[k] * R && fabs(o.F / Fe - 1) > 1e-4) CHECK_REL(o.F, Fe, 1e-4, "unloading branch");
        if (Fl > -1e-6 * n * 8 * ws[k] * R && !(o.F <= Fl)) hyst = 0;
        if (Fl < -1e-6 * n * 8 * ws[k] * R && !(o.F < Fl)) hyst = 0;
        /* pull-off: the largest pull of the total force (elastic + adhesive) */
        dc_gw_rough_state el;
        dc_gw_rough_elliptic(&g.hertz, E, n, sigma, delta, &el);
        pull_t = fmin(pull_t, o.F + el.F);
        pull_e = fmin(pull_e, Fe + el.F);
        pull_l = fmin(pull_l, Fl + el.F);
      }
      Fprev = o.F;
    }
    (void)Fprev;
    CHECK(hyst);
    CHECK(reset);
    printf("w = %g: pull-off (largest pull, unloading) table %.6e N, exact %.6e N (rel %.1e); loading %.6e N\n",
           ws[k], -pull_t, -pull_e, fabs(pull_t / pull_e - 1), -pull_l);
    CHECK_REL(pull_t, pull_e, 1e-5, "pull-off force");
    CHECK(pull_e < pull_l);
  }
}

/* The partly attached band against its exact force: a contact pressed to
   h_min = -delta_max/sigma and back at h in (h_min, h_min + D) holds the
   summits that touched and are stretched less than |delta_break|, so
   F = F_L(h) + n_asp int_{h_min}^{h} f(sigma (s - h)) phi(s) ds, with f
   the JKR summit's tensile force (dc_jkr_sphere, itself checked against
   mpmath) and F_L the exact loading branch; the integral by composite
   Simpson (4000 intervals). The error in units of the band's scale
   |F_U - F_L|, for the table's weight and for the smoothstep weight it
   replaced (3 xi^2 - 2 xi^3). */
static void test_band(void)
{
  const double R = 1e-3, E = 1e9, w = 0.05, n = 100.0;
  const double sigmas[] = {1e-9, 1.27e-8, 6.3e-8, 4.6e-7};   /* tau 0.08, 1, 5, 36 */
  const double hmins[] = {-3.0, -1.0, 0.0, 1.0, 3.0};
  const double xis[] = {0.01, 0.1, 0.3, 0.6, 0.9, 1.0};
  double worst = 0.0, worst_old = 0.0, closure = 0.0, kn_worst = 0.0;
  for (int k = 0; k < 4; k++) {
    const double sigma = sigmas[k];
    dc_gwa_table_pair p;
    CHECK(dc_gwa_table_pair_init(E, w, sigma, n, &p) == DC_OK);
    dc_jkr_geom g;
    CHECK(dc_jkr_geometry(R, R, E, w, &g) == DC_OK);
    const double D = -g.delta_break / sigma;
    double wk = 0.0, wk_old = 0.0;
    for (int i = 0; i < 5; i++)
      for (int j = 0; j < 6; j++) {
        /* xi = 1: the whole band attached, where the construction must
           give the exact unloading branch (its check) */
        const double hmin = hmins[i], h = hmin + (j == 5 ? 1.0 - 1e-9 : xis[j]) * D, delta = -h * sigma;
        double hist[2] = {1.0, -hmin * sigma};
        dc_gwa_table_out o;
        CHECK(dc_gwa_table_step(&p, R, delta, hist, &o) == DC_OK);
        CHECK(o.weight > 0.0 && o.weight <= 1.0);
        if (j < 5) {
          /* kn = dF/d delta in the band (the weight's slope included): central
             difference at the same largest overlap */
          const double e = 1e-5 * xis[j] * D * sigma;
          dc_gwa_table_out o1, o2;
          double h1[2] = {1.0, -hmin * sigma}, h2[2] = {1.0, -hmin * sigma};
          CHECK(dc_gwa_table_step(&p, R, delta + e, h1, &o1) == DC_OK);
          CHECK(dc_gwa_table_step(&p, R, delta - e, h2, &o2) == DC_OK);
          const double fd = (o1.F - o2.F) / (2.0 * e);
          kn_worst = fmax(kn_worst, fabs(fd - o.kn) / (fabs(o.kn) + fabs(o.F) / sigma));
        }
        double FL, FU, k1, k2;
        CHECK(exact(&g, n, sigma, delta, DC_GW_LOADING, &FL, &k1) == 0);
        CHECK(exact(&g, n, sigma, delta, DC_GW_UNLOADING, &FU, &k2) == 0);
        const int M = 4000;
        double T = 0.0;
        for (int m = 0; m <= M; m++) {
          const double sm = hmin + (h - hmin) * m / M;
          dc_jkr_state st;
          CHECK(dc_jkr_sphere(R, E, w, sigma * (sm - h), &st) == DC_OK && st.contact);
          const double c = (m == 0 || m == M) ? 1.0 : (m % 2 ? 4.0 : 2.0);
          T += c * st.F * exp(-0.5 * sm * sm);
        }
        T *= n * (h - hmin) / (3.0 * M) / sqrt(2.0 * M_PI);
        const double truth = FL + T, scale = fabs(FU - FL);
        if (j == 5) {
          closure = fmax(closure, fabs(truth - FU) / scale);
          continue;
        }
        double tL, tU, kk;
        CHECK(dc_gwa_table_force(&p, R, DC_GW_LOADING, delta, &tL, &kk) == DC_OK);
        CHECK(dc_gwa_table_force(&p, R, DC_GW_UNLOADING, delta, &tU, &kk) == DC_OK);
        const double xi = xis[j], old = tL + xi * xi * (3.0 - 2.0 * xi) * (tU - tL);
        wk = fmax(wk, fabs(o.F - truth) / scale);
        wk_old = fmax(wk_old, fabs(old - truth) / scale);
      }
    printf("band, tau %.2g (D %.3g): worst error %.3f of |F_U - F_L| (the smoothstep weight: %.3f)\n",
           sigma / g.delta_scale, D, wk, wk_old);
    worst = fmax(worst, wk);
    worst_old = fmax(worst_old, wk_old);
  }
  printf("band: F_L + the attached summits' integral at xi = 1 against the exact unloading branch: %.1e of "
         "|F_U - F_L|\n", closure);
  CHECK(closure < 1e-3);
  printf("band: kn against the central difference of F: %.1e of |kn| + |F|/sigma\n", kn_worst);
  CHECK(kn_worst < 1e-5);
  /* measured: 0.055 at most (tau 1), the smoothstep 0.97 */
  CHECK(worst < 0.1);
  CHECK(worst < 0.5 * worst_old);
}

/* P(a < S < b) for a standard normal S, a < b, in long double from the
   tail away from 0 (the reference for the band weight) */
static long double normal_mass_l(long double a, long double b)
{
  const long double r = 0.70710678118654752440L;
  if (a >= 0) return 0.5L * (erfcl(a * r) - erfcl(b * r));
  if (b <= 0) return 0.5L * (erfcl(-b * r) - erfcl(-a * r));
  return 1.0L - 0.5L * (erfcl(b * r) + erfcl(-a * r));
}

/* The band's weight w = P(h_min < S < h)/P(h - D < S < h) (header) against
   long-double erfc, in the step's own h and h_min, over both of its ways:
   J's series where (|h| + 3) D < 1/2 (its truncation bound: 4e-7 relative
   on J) and erfc elsewhere; h from -11 to 11, D from 0.02 to 3. Measured
   2.6e-10 and 4.4e-12. */
static void test_band_weight(void)
{
  const double R = 1e-3, E = 1e9, w = 0.05;
  unsigned long long x = 2718281828ull;
  double worst[2] = {0.0, 0.0};
  int series = 0, erfc_way = 0;
  for (int k = 0; k < 8; k++) {
    const double sigma = 2e-9 * pow(2.0, k);   /* D from ~3 down to ~0.02 */
    dc_gwa_table_pair p;
    dc_gwa_table_radius r;
    CHECK(dc_gwa_table_pair_init(E, w, sigma, 1.0, &p) == DC_OK && dc_gwa_table_radius_init(&p, R, &r) == DC_OK);
    for (int m = 0; m < 4000; m++) {
      const double h = -11.0 + 22.0 * check_uniform(&x), xi = 0.001 + 0.998 * check_uniform(&x);
      const double delta = -h * sigma, dmax = delta + xi * r.db;
      double hist[2] = {1.0, dmax};
      dc_gwa_table_out o;
      CHECK(dc_gwa_table_step(&p, R, delta, hist, &o) == DC_OK);
      const double hc = -delta * p.inv_sigma, hmin = -dmax * p.inv_sigma, c = (fabs(hc) + 3.0) * r.D;
      if (!(o.weight > 0.0 && o.weight < 1.0)) continue;   /* clamped at 1 by rounding */
      const long double ref = normal_mass_l(hmin, hc) / normal_mass_l(hc - r.D, hc);
      const int way = c >= 0.5;
      worst[way] = fmax(worst[way], (double)fabsl((o.weight - ref) / ref));
      series += way == 0;
      erfc_way += way == 1;
    }
  }
  printf("band weight against long-double erfc, worst relative: the series %.2e (%d points), erfc %.2e (%d)\n",
         worst[0], series, worst[1], erfc_way);
  CHECK(series > 1000 && erfc_way > 1000);
  CHECK_ABS(worst[0], 0.0, 1e-8, "band weight, the series");
  CHECK_ABS(worst[1], 0.0, 1e-10, "band weight, erfc");
}

/* The cut (dc_gwa_table_apart): an untouched contact more than X_CUT = 8
   sigma apart feels nothing and stays untouched; just inside, the force
   is below the stated 3.3e-16 n_asp 8 w R, and so is the exact law's
   adhesive part at the cut (3.26e-16 as tau -> 0, smaller above); after a
   touch the cut no longer applies. */
static void test_cut(void)
{
  const double R = 1e-3, E = 1e9, n = 100.0, cut = DC_GWA_TABLE_X_CUT;
  CHECK(cut == 8.0);
  const double sigmas[] = {1e-10, 1e-9, 1e-7, 1e-5};
  for (int k = 0; k < 4; k++) {
    const double sigma = sigmas[k], w = 0.05, Fs = n * 8 * w * R;
    dc_gwa_table_pair p;
    CHECK(dc_gwa_table_pair_init(E, w, sigma, n, &p) == DC_OK);
    dc_jkr_geom g;
    CHECK(dc_jkr_geometry(R, R, E, w, &g) == DC_OK);
    double hist[2] = {0, 0};
    dc_gwa_table_out o;
    CHECK(dc_gwa_table_step(&p, R, -(cut + 0.001) * sigma, hist, &o) == DC_OK);
    CHECK(o.F == 0.0 && o.kn == 0.0 && o.weight == 0.0 && hist[0] == 0.0 && hist[1] == 0.0);
    CHECK(dc_gwa_table_step(&p, R, -(cut - 0.001) * sigma, hist, &o) == DC_OK);
    CHECK(o.F < 0.0 && -o.F < 3.3e-16 * Fs && hist[0] == 1.0);
    double Fe, ke;
    CHECK(exact(&g, n, sigma, -cut * sigma, DC_GW_LOADING, &Fe, &ke) == 0);
    CHECK(Fe < 0.0 && -Fe < 3.3e-16 * Fs);
    printf("cut at h = %g (sigma %g): F just inside %.3e n_asp 8 w R, exact law at the cut %.3e\n", cut, sigma,
           -o.F / Fs, -Fe / Fs);
    /* touched: no cut (a force acts) */
    CHECK(dc_gwa_table_step(&p, R, -(cut + 0.5) * sigma, hist, &o) == DC_OK);
    CHECK(o.F < 0.0);
  }
}

/* Magnitudes at the edges of the doubles (cases of test_fuzz.c). */
static void test_extremes(void)
{
  dc_gwa_table_pair p;
  double G, Gx, F, kn;
  /* deep compression where tau x leaves the doubles: the limit G = -pi/8
     (was DC_ERANGE), continuous with x = -1e300 */
  CHECK(dc_gwa_table_reduced(DC_GW_LOADING, -1.7e308, 2.5, &G, &Gx) == DC_OK && G == -M_PI / 8.0 && Gx == 0.0);
  CHECK(dc_gwa_table_reduced(DC_GW_UNLOADING, -1e300, 2.5, &G, &Gx) == DC_OK && fabs(G + M_PI / 8.0) < 1e-15);
  /* unloading with h = -delta/sigma and D = |delta_break|/sigma both
     beyond the doubles: h - D was inf - inf, a NaN cell index (a read
     outside the table); every summit is attached, -pi/8 F_s each */
  CHECK(dc_gwa_table_pair_init(1e-200, 1.0, 1e-300, 1.0, &p) == DC_OK);
  CHECK(dc_gwa_table_force(&p, 1e200, DC_GW_UNLOADING, -1e100, &F, &kn) == DC_OK);
  CHECK_REL(F, -8.0 * 1e200 * M_PI / 8.0, 1e-15, "unloading, h and D beyond the doubles");
  CHECK(kn == 0.0);
  /* w = 0 with 1/sigma beyond the doubles: DC_ERANGE (was DC_OK with an
     infinite inv_sigma) */
  CHECK(dc_gwa_table_pair_init(1e6, 0.0, DBL_TRUE_MIN, 1e3, &p) == DC_ERANGE);
  /* 8 w / (pi E*) beyond the doubles, delta_c's coefficient not: was DC_ERANGE */
  CHECK(dc_gwa_table_pair_init(1e-310, 1.0, 1e-6, 1.0, &p) == DC_OK);
  CHECK_REL(p.dc_coef, 0.5 * exp(2.0 / 3.0 * (log(8.0 / M_PI) - log(1e-310))), 1e-13, "delta_c coefficient, E* = 1e-310");
  /* 8 w beyond the doubles, 8 w n_asp not: was DC_ERANGE */
  CHECK(dc_gwa_table_pair_init(1e5, DBL_MAX, 1e-6, 1e-3, &p) == DC_OK);
  CHECK_REL(p.F_coef, 8.0 * (DBL_MAX * 1e-3), 1e-15, "8 w n_asp, w = DBL_MAX");
}

static void test_w_zero_and_domain(void)
{
  dc_gwa_table_pair p;
  CHECK(dc_gwa_table_pair_init(1e9, 0.0, 1e-7, 100.0, &p) == DC_OK);
  double hist[2] = {0, 0};
  dc_gwa_table_out o;
  for (double d = -1e-5; d <= 1e-5; d += 1e-7) {
    CHECK(dc_gwa_table_step(&p, 1e-3, d, hist, &o) == DC_OK);
    if (!(o.F == 0.0 && o.kn == 0.0)) CHECK(0);
    double F, kn;
    CHECK(dc_gwa_table_force(&p, 1e-3, 1, d, &F, &kn) == DC_OK && F == 0.0 && kn == 0.0);
  }
  dc_gwa_table_pair q;
  memset(&q, 0x5a, sizeof q);
  const dc_gwa_table_pair ref = q;
  CHECK(dc_gwa_table_pair_init(1e9, -1.0, 1e-7, 100.0, &q) == DC_EDOM);
  CHECK(dc_gwa_table_pair_init(1e9, 0.1, 0.0, 100.0, &q) == DC_EDOM);
  CHECK(dc_gwa_table_pair_init(NAN, 0.1, 1e-7, 100.0, &q) == DC_EDOM);
  CHECK(dc_gwa_table_pair_init(1e9, 0.1, 1e-7, INFINITY, &q) == DC_EDOM);
  CHECK(memcmp(&q, &ref, sizeof q) == 0);
  dc_param_error e;
  CHECK(dc_gwa_table_check(1e9, -1.0, 1e-7, 1.0, &e) == DC_EDOM && strcmp(e.name, "workOfAdhesion") == 0);
  CHECK(dc_gwa_table_pair_init(1e9, 0.1, 1e-7, 100.0, &p) == DC_OK);
  double F = 7, kn = 7;
  CHECK(dc_gwa_table_force(&p, 1e-3, 0, NAN, &F, &kn) == DC_EDOM && F == 7 && kn == 7);
  CHECK(dc_gwa_table_force(&p, -1e-3, 0, 0.0, &F, &kn) == DC_EDOM);
  CHECK(dc_gwa_table_force(&p, 1e-3, 2, 0.0, &F, &kn) == DC_EDOM);
  double h2[2] = {1.0, 1e-7};
  CHECK(dc_gwa_table_step(&p, 1e-3, INFINITY, h2, &o) == DC_EDOM && h2[0] == 1.0 && h2[1] == 1e-7);
  CHECK(dc_gwa_table_reduced(0, NAN, 0.0, &F, &kn) == DC_EDOM);
  /* the radius kept: the same bits as setting it up at each step */
  dc_gwa_table_radius r, r0;
  memset(&r, 0x5a, sizeof r);
  r0 = r;
  CHECK(dc_gwa_table_radius_init(&p, -1e-3, &r) == DC_EDOM && memcmp(&r, &r0, sizeof r) == 0);
  CHECK(dc_gwa_table_radius_init(&p, INFINITY, &r) == DC_EDOM && memcmp(&r, &r0, sizeof r) == 0);
  CHECK(dc_gwa_table_radius_init(&p, 1e-3, &r) == DC_OK);
  CHECK(r.reach == dc_gwa_table_reach(&p, 1e-3));
  double ha[2] = {0, 0}, hb[2] = {0, 0};
  int same = 1;
  for (int i = 0; i < 3000; i++) {
    const double d = 1e-7 * (-9.0 + 12.0 * fabs(sin(0.01 * i)));
    dc_gwa_table_out oa, ob;
    CHECK(dc_gwa_table_step(&p, 1e-3, d, ha, &oa) == DC_OK);
    CHECK(dc_gwa_table_step_radius(&p, &r, d, hb, &ob) == DC_OK);
    if (memcmp(&oa, &ob, sizeof oa) != 0 || memcmp(ha, hb, sizeof ha) != 0) same = 0;
  }
  CHECK(same);
}

/* never NaN: random and edge inputs, any eta (clamped), any x */
static void test_never_nan(void)
{
  unsigned long long rs = 12345;
  int bad = 0;
  const double xs[] = {-1e300, -1e10, -256.0000001, -256, -8, 8, 8.0000001, 40, 1e3, 1e300, 0.0, -0.0};
  for (int k = 0; k < 200000; k++) {
    const int b = k & 1;
    double x = (check_uniform(&rs) - 0.5) * pow(10.0, 12 * check_uniform(&rs));
    double eta = (check_uniform(&rs) - 0.5) * 60.0;
    if (k < 12 * 12) { x = xs[k % 12]; eta = (k / 12 - 6) * 5.0; }
    double G, Gx;
    const int r = dc_gwa_table_reduced(b, x, eta, &G, &Gx);
    if (r != DC_OK || !isfinite(G) || !isfinite(Gx) || G > 0.0) bad++;
  }
  for (int k = 0; k < 20000; k++) {
    dc_gwa_table_pair p;
    const double E = pow(10.0, 3 + 9 * check_uniform(&rs)), w = pow(10.0, -8 + 9 * check_uniform(&rs));
    const double sigma = pow(10.0, -12 + 9 * check_uniform(&rs)), R = pow(10.0, -9 + 9 * check_uniform(&rs));
    if (dc_gwa_table_pair_init(E, w, sigma, 100.0, &p) != DC_OK) { bad++; continue; }
    double hist[2] = {0, 0};
    dc_gwa_table_out o;
    for (int s = 0; s < 5; s++) {
      const double delta = (check_uniform(&rs) - 0.7) * sigma * pow(10.0, 4 * check_uniform(&rs));
      const int r = dc_gwa_table_step(&p, R, delta, hist, &o);
      if (r != DC_OK || !isfinite(o.F) || !isfinite(o.kn) || o.F > 0.0) bad++;
    }
  }
  printf("never-NaN sweep: %d bad\n", bad);
  CHECK(bad == 0);
}

/* ns per step along a press-and-release cycle (-6 to 1.5 sigma), the
   radius set up once as a DEM wrapper keeps it */
static double bench_steps(double E, double w, double sigma, double R, double *eta, double *sum)
{
  dc_gwa_table_pair p;
  dc_gwa_table_pair_init(E, w, sigma, 100.0, &p);
  dc_gwa_table_radius r;
  dc_gwa_table_radius_init(&p, R, &r);
  *eta = r.cell.eta;
  const int N = 400000;
  double hist[2] = {0, 0};
  dc_gwa_table_out o;
  const double t0 = now();
  for (int i = 0; i < N; i++) {
    const double ph = (i % 2000) / 2000.0;
    dc_gwa_table_step_radius(&p, &r, sigma * (-6.0 + 7.5 * (ph < 0.5 ? 2 * ph : 2 - 2 * ph)), hist, &o);
    *sum += o.F;
  }
  return (now() - t0) / N * 1e9;
}

/* ns per step of a settled contact (the overlap wandering by 1e-4 sigma
   about 0.5 sigma after one press to 1 sigma: the unloading branch, one
   cell) with the radius set up once (contact 0) or with the contact's
   record (contact 1: the cell kept) */
static double bench_settled(double E, double w, double sigma, double R, int contact, double *sum)
{
  dc_gwa_table_pair p;
  dc_gwa_table_pair_init(E, w, sigma, 100.0, &p);
  dc_gwa_table_radius r;
  dc_gwa_table_radius_init(&p, R, &r);
  dc_gwa_table_contact c;
  dc_gwa_table_contact_init(&p, R, &c);
  const int N = 400000;
  double hist[2] = {1.0, sigma};
  dc_gwa_table_out o;
  const double t0 = now();
  for (int i = 0; i < N; i++) {
    const double d = sigma * (0.5 + 1e-4 * (int)((7919LL * i) % 1000) / 1000.0);
    if (contact) dc_gwa_table_step_contact(&p, &c, d, hist, &o);
    else dc_gwa_table_step_radius(&p, &r, d, hist, &o);
    *sum += o.F;
  }
  return (now() - t0) / N * 1e9;
}

static void bench(void)
{
  const double R = 1e-3, sigma = 1e-7, E = 1e9, w = 0.1, n = 100.0;
  double s = 0, eta_a, eta_b;
  /* tau ~ 37: no kink term; tau ~ 5: the kink term on unloading */
  const double t_a = bench_steps(E, 0.05 * w, sigma, R, &eta_a, &s);
  const double t_b = bench_steps(E, w, sigma, R, &eta_b, &s);
  dc_gwa_table_pair p;
  dc_gwa_table_pair_init(E, w, sigma, n, &p);
  dc_jkr_geom g;
  dc_jkr_geometry(R, R, E, w, &g);
  const int N = 400000;
  double hist[2] = {0, 0};
  dc_gwa_table_out o;
  double t0 = now();
  for (int i = 0; i < N; i++) {
    dc_gwa_table_step(&p, R, (-3.0 + 6.0 * (int)((7919LL * i) % N) / N) * sigma, hist, &o);
    s += o.F;
  }
  const double t_tab = (now() - t0) / N * 1e9;
  dc_gw_rough_state rs;
  t0 = now();
  for (int i = 0; i < N; i++) {
    dc_gw_rough_elliptic(&g.hertz, E, n, sigma, (-3.0 + 6.0 * i / N) * sigma, &rs);
    s += rs.F;
  }
  const double t_el = (now() - t0) / N * 1e9;
  const int M = 2000;
  dc_gw_adhesive_state as;
  t0 = now();
  for (int i = 0; i < M; i++) {
    dc_gw_rough_adhesive(&g, n, sigma, (-3.0 + 6.0 * i / M) * sigma, i & 1, &as);
    s += as.F;
  }
  const double t_ex = (now() - t0) / M * 1e9;
  const double t_s0 = bench_settled(E, 0.05 * w, sigma, R, 0, &s), t_s1 = bench_settled(E, 0.05 * w, sigma, R, 1, &s);
  printf("ns per call, a settled contact (eta %.2f): radius kept %.0f, contact's record (cell kept) %.0f\n", eta_a, t_s0,
         t_s1);
  printf("ns per call: table step with the radius kept %.0f (eta %.2f), %.0f (eta %.2f, kink term); with the radius "
         "set up each call %.0f; elastic gw_rough_elliptic %.0f; exact gw_rough_adhesive %.0f (checksum %g)\n",
         t_a, eta_a, t_b, eta_b, t_tab, t_el, t_ex, s);
}

/* dc_gwa_table_step_contact: the bits of dc_gwa_table_step_radius (and
   the same history) along random contacts, each with its own radius and
   record: settled stretches (small wanders inside one cell: the kept cell
   read), walks across cells and jumps (a new cell formed: the kept one
   replaced), both branches and the band, the blend, the deep region and
   beyond it, the kink term (small tau), tau clamped at both ends, w = 0;
   a record carried over as a restart would (copied) and re-set-up when R
   changes; every path counted so that none goes untested. */
static void test_contact(void)
{
  const double E = 2.7e6;
  const double ws[] = {0.05, 5e-4, 50.0, 0.0, 5e-9, 5e5};
  unsigned long long x = 88172645463325252ull;
  int same = 1, calls = 0, hits = 0, misses = 0, band = 0, unl = 0, kink = 0, deep = 0, beyond = 0, reinit = 0;
  for (int k = 0; k < 6; k++) {
    const double sigma = k == 4 ? 2.1e-8 : 2.1e-5;
    dc_gwa_table_pair p;
    CHECK(dc_gwa_table_pair_init(E, ws[k], sigma, k == 2 ? 7.0 : 1.0, &p) == DC_OK);
    for (int q = 0; q < 40; q++) {
      double R = 1e-5 * exp(6.0 * check_uniform(&x));   /* 1e-5 to 4e-3 m */
      dc_gwa_table_radius r;
      CHECK(dc_gwa_table_radius_init(&p, R, &r) == DC_OK);
      dc_gwa_table_contact c;
      memset(&c, 0, sizeof c);   /* a new contact: history values start at 0 */
      double h0[2] = {0, 0}, h1[2] = {0, 0};
      const double scale = sigma + r.db;
      double delta = -scale * 3.0 * check_uniform(&x);
      for (int i = 0; i < 3000; i++) {
        const double u = check_uniform(&x), v = check_uniform(&x);
        if (u < 0.02) delta = -scale * 300.0 * v;                  /* deep apart, beyond */
        else if (u < 0.04) delta = scale * 300.0 * v;              /* pressed deep, and beyond x_end */
        else if (u < 0.10) delta = scale * (-9.0 + 12.0 * v);      /* a jump */
        else if (u < 0.40) delta += scale * 0.3 * (v - 0.5);       /* a walk */
        else delta += scale * 1e-4 * (v - 0.5);                    /* settled */
        if (i == 1500) {
          /* a restart: the record travels as history values */
          double buf[DC_GWA_TABLE_CONTACT_NFIELDS];
          memcpy(buf, &c, sizeof buf);
          memcpy(&c, buf, sizeof c);
        }
        if (i == 2000 && q % 4 == 0) {   /* the contact's radius changes (another contact in its slot) */
          R *= 1.0 + 1e-15 * (1 + q);
          CHECK(dc_gwa_table_radius_init(&p, R, &r) == DC_OK);
        }
        if (c.R != R) {
          CHECK(dc_gwa_table_contact_init(&p, R, &c) == DC_OK);
          CHECK(c.cell[0] == 0.0);
          reinit++;
        }
        const double key = c.cell[0];
        dc_gwa_table_out o0, o1;
        memset(&o0, 0, sizeof o0);
        memset(&o1, 0, sizeof o1);
        const int s0 = dc_gwa_table_step_radius(&p, &r, delta, h0, &o0);
        const int s1 = dc_gwa_table_step_contact(&p, &c, delta, h1, &o1);
        if (!(s0 == s1 && memcmp(&o0, &o1, sizeof o0) == 0 && memcmp(h0, h1, sizeof h0) == 0)) same = 0;
        if (!(dc_gwa_table_contact_reach(&p, &c) == r.reach || p.w == 0.0)) same = 0;
        calls++;
        if (key != 0.0 && c.cell[0] == key) hits++;
        else if (c.cell[0] != key) misses++;
        if (o0.weight > 0.0 && o0.weight < 1.0) band++;
        if (o0.weight == 1.0) unl++;
        const double xl = -delta / sigma;
        if (o0.weight > 0.0 && r.cell.eta < DC_GWA_KINK_K_HI && xl - r.D < DC_GWA_KINK_W_HI) kink++;
        if (xl < DC_GWA_TABLE_BLEND_HI && xl > dc_gwa_table_x_deep(DC_GWA_TABLE_K_END)) deep++;
        if (xl < dc_gwa_table_x_deep(DC_GWA_TABLE_K_END) || xl - (o0.weight > 0.0 ? r.D : 0.0) > DC_GWA_TABLE_X_HI)
          beyond++;
      }
    }
  }
  /* errors: as dc_gwa_table_radius_init, the record untouched */
  dc_gwa_table_pair p;
  CHECK(dc_gwa_table_pair_init(E, 0.05, 2.1e-5, 1.0, &p) == DC_OK);
  dc_gwa_table_contact c, c0;
  memset(&c, 0x5a, sizeof c);
  c0 = c;
  CHECK(dc_gwa_table_contact_init(&p, 0.0, &c) == DC_EDOM);
  CHECK(dc_gwa_table_contact_init(&p, -1e-3, &c) == DC_EDOM);
  CHECK(dc_gwa_table_contact_init(&p, NAN, &c) == DC_EDOM);
  CHECK(dc_gwa_table_contact_init(&p, INFINITY, &c) == DC_EDOM);
  CHECK(memcmp(&c, &c0, sizeof c) == 0);
  CHECK(sizeof(dc_gwa_table_contact) == DC_GWA_TABLE_CONTACT_NFIELDS * sizeof(double));
  CHECK(same);
  CHECK(hits > calls / 4 && misses > calls / 10 && band > 1000 && unl > 1000 && kink > 1000 && deep > 1000 &&
        beyond > 1000);
  printf("contact: %d steps (cell kept %d, formed %d; band %d, unloading %d, kink %d, deep %d, beyond %d; %d set-ups), "
         "the same bits as dc_gwa_table_step_radius: %s\n",
         calls, hits, misses, band, unl, kink, deep, beyond, reinit, same ? "yes" : "no");
}

int main(void)
{
  test_contact();
  test_constant();
  test_random_vs_exact();
  test_dense_vs_exact();
  test_seams();
  test_continuity();
  test_branches();
  test_band();
  test_band_weight();
  test_cut();
  test_w_zero_and_domain();
  test_extremes();
  test_never_nan();
  bench();
  return check_summary("gw_rough_adhesive_table");
}
