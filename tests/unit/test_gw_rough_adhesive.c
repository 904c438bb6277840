/* GW rough contact with adhesive JKR summits (c_core/src/gw_rough_adhesive.c):
   the w -> 0 limit against the smooth-GW closed form, spheres and an
   ellipse (R_minor/R_major = 0.2) against the mpmath table of
   tests/reference/gen_gw_rough_adhesive.py (integrated over the summit's
   contact radius or eccentricity, no inversion of the summit law), the
   order and continuity of the two branches, kn = dF/d delta, sigma = 0,
   the error estimate and the domain. */
#include "check.h"
#include "dc/gw_rough.h"
#include "dc/gw_rough_adhesive.h"
#include "dc/jkr_elliptic.h"
#include "dc/status.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

static const double E_STAR = 1e9, SIGMA = 1e-7, N_ASP = 100.0;

/* (1) w -> 0 */
static void test_smooth_limit(void)
{
  const double radii[2][2] = {{1e-3, 1e-3}, {1e-3, 2e-4}};
  for (int c = 0; c < 2; c++) {
    /* w = 0: the closed form itself */
    dc_jkr_geom g0;
    CHECK(dc_jkr_geometry(radii[c][0], radii[c][1], E_STAR, 0.0, &g0) == DC_OK);
    for (double h = -4; h <= 6; h += 0.5)
      for (int b = 0; b < 2; b++) {
        dc_gw_adhesive_state s;
        dc_gw_rough_state r;
        CHECK(dc_gw_rough_adhesive(&g0, N_ASP, SIGMA, -h * SIGMA, b, &s) == DC_OK);
        CHECK(dc_gw_rough_elliptic(&g0.hertz, E_STAR, N_ASP, SIGMA, -h * SIGMA, &r) == DC_OK);
        CHECK(s.F == r.F && s.area == r.area && s.kn == r.kn && s.h == r.h);
      }
    /* w = 1e-40: the quadrature against the closed form; the adhesive parts
       (F, kn: O(w); area: O(w^1/2) ~ 1e-20) are below rounding, so this
       measures the quadrature alone (worst seen 2.6e-15) */
    dc_jkr_geom g;
    CHECK(dc_jkr_geometry(radii[c][0], radii[c][1], E_STAR, 1e-40, &g) == DC_OK);
    double ef = 0, ea = 0, ek = 0;
    for (double h = -8; h <= 12; h += 0.25)
      for (int b = 0; b < 2; b++) {
        dc_gw_adhesive_state s;
        dc_gw_rough_state r;
        CHECK(dc_gw_rough_adhesive(&g, N_ASP, SIGMA, -h * SIGMA, b, &s) == DC_OK);
        dc_gw_rough_elliptic(&g.hertz, E_STAR, N_ASP, SIGMA, -h * SIGMA, &r);
        ef = fmax(ef, fabs(s.F / r.F - 1));
        ea = fmax(ea, fabs(s.area / r.area - 1));
        ek = fmax(ek, fabs(s.kn / r.kn - 1));
      }
    CHECK_ABS(ef, 0.0, 1e-14, "w = 1e-40: force = closed form, h in [-8, 12]");
    CHECK_ABS(ea, 0.0, 1e-14, "w = 1e-40: area = closed form");
    CHECK_ABS(ek, 0.0, 1e-14, "w = 1e-40: kn = closed form");
    printf("w = 1e-40 (%s) vs closed form: F %.1e area %.1e kn %.1e\n", c ? "ellipse" : "sphere", ef, ea, ek);
    /* the rate of the limit: (F/F_0 - 1)/w and (A/A_0 - 1)/w^1/2 tend to
       constants (at w = 1e-7 and 1e-8 within 7e-4, measured) */
    for (double h = -2; h <= 2; h += 2) {
      double rf[2], ra[2];
      for (int k = 0; k < 2; k++) {
        const double w = k ? 1e-8 : 1e-7;
        dc_jkr_geometry(radii[c][0], radii[c][1], E_STAR, w, &g);
        dc_gw_adhesive_state s;
        dc_gw_rough_state r;
        dc_gw_rough_adhesive(&g, N_ASP, SIGMA, -h * SIGMA, DC_GW_UNLOADING, &s);
        dc_gw_rough_elliptic(&g.hertz, E_STAR, N_ASP, SIGMA, -h * SIGMA, &r);
        rf[k] = (s.F / r.F - 1) / w;
        ra[k] = (s.area / r.area - 1) / sqrt(w);
      }
      CHECK(rf[0] < 0 && ra[0] > 0);
      CHECK_REL(rf[0], rf[1], 5e-3, "adhesive part of F is O(w)");
      CHECK_REL(ra[0], ra[1], 5e-3, "adhesive part of the area is O(w^1/2)");
    }
  }
}

/* (2), (3): the mpmath table. Columns: shape, R_major, R_minor, Estar, w,
   sigma, n_asp, theta, h, delta, branch, F, area, kn, Fabs. */
static void test_table(void)
{
  FILE *f = check_open_reference("gw_rough_adhesive.csv");
  if (!f) return;
  double v[15];
  check_read_row(f, v, 15);   /* header */
  int rows[2] = {0, 0};
  double worst[2][3] = {{0}}, ratio = 0;
  while (check_read_row(f, v, 15) == 15) {
    const int shape = (int)v[0], branch = (int)v[10];
    dc_jkr_geom g;
    CHECK(dc_jkr_geometry(v[1], v[2], v[3], v[4], &g) == DC_OK);
    CHECK(g.circular == (shape == 0));
    dc_gw_adhesive_state s;
    CHECK(dc_gw_rough_adhesive(&g, v[6], v[5], v[9], branch, &s) == DC_OK);
    const double Fabs = v[14];
    /* F against n_asp int |f| phi (F itself crosses zero); area relative;
       kn against |kn| + Fabs/sigma. sphere kn (worst seen 5.9e-13): from the
       contact radius, which cancels near the break; ellipse kn: the summit
       solver's kn is ~1e-9 (its Newton tolerance in e^2) */
    const double ef = fabs(s.F - v[11]) / Fabs;
    const double ea = fabs(s.area / v[12] - 1);
    const double ek = fabs(s.kn - v[13]) / (fabs(v[13]) + Fabs / v[5]);
    CHECK_ABS(ef, 0.0, 1e-14, shape ? "ellipse F vs mpmath" : "sphere F vs mpmath");
    CHECK_ABS(ea, 0.0, 1e-14, shape ? "ellipse area vs mpmath" : "sphere area vs mpmath");
    CHECK_ABS(ek, 0.0, shape ? 2e-8 : 1e-12, shape ? "ellipse kn vs mpmath" : "sphere kn vs mpmath");
    /* the error estimate covers the actual error */
    CHECK(fabs(s.F - v[11]) <= s.err);
    if (s.err > 0) ratio = fmax(ratio, fabs(s.F - v[11]) / s.err);
    worst[shape][0] = fmax(worst[shape][0], ef);
    worst[shape][1] = fmax(worst[shape][1], ea);
    worst[shape][2] = fmax(worst[shape][2], ek);
    rows[shape]++;
  }
  fclose(f);
  CHECK(rows[0] == 108 && rows[1] == 90);
  for (int c = 0; c < 2; c++)
    printf("%s vs mpmath (%d rows): F/Fabs %.1e, area %.1e, kn %.1e\n", c ? "ellipse" : "sphere", rows[c],
           worst[c][0], worst[c][1], worst[c][2]);
  printf("largest |error| / estimate: %.1e\n", ratio);
}

/* (4) F(unloading) <= F(loading); both continuous in h with slope kn */
static void test_branches(void)
{
  const double radii[2][2] = {{1e-3, 1e-3}, {1e-3, 2e-4}};
  const double ws[] = {2.0, 0.1, 1e-3};
  for (int c = 0; c < 2; c++)
    for (int k = 0; k < 3; k++) {
      dc_jkr_geom g;
      dc_jkr_geometry(radii[c][0], radii[c][1], E_STAR, ws[k], &g);
      int order = 1, cont[2] = {1, 1};
      dc_gw_adhesive_state prev[2];
      /* h from -12 to 12, step 0.01: crosses the switch of the first
         panel (s0 = -sqrt 90) and s0 = 0 on both branches */
      for (int i = 0; i <= 2400; i++) {
        const double h = -12.0 + 0.01 * i;
        dc_gw_adhesive_state s[2];
        for (int b = 0; b < 2; b++) dc_gw_rough_adhesive(&g, N_ASP, SIGMA, -h * SIGMA, b, &s[b]);
        /* the extra summits of the unloading branch weigh ~phi(h): at
           h < -5 their pull is near the rounding of F (and below the cut
           of phi at h < -9.5), so there only F_unload <= F_load up to it */
        if (!(s[1].F <= s[0].F + 1e-14 * fabs(s[0].F))) order = 0;
        if (h > -5 && !(s[1].F < s[0].F)) order = 0;   /* phi(5) = 1.5e-6 */
        if (i > 0)
          for (int b = 0; b < 2; b++) {
            /* secant slope dF/d delta within the end slopes, 1% slack */
            const double slope = (s[b].F - prev[b].F) / (-0.01 * SIGMA);
            const double slack = 0.01 * fmax(fabs(s[b].kn), fabs(prev[b].kn)) + 1e-12 * fabs(s[b].F) / (0.01 * SIGMA);
            if (!(slope >= fmin(s[b].kn, prev[b].kn) - slack && slope <= fmax(s[b].kn, prev[b].kn) + slack)) cont[b] = 0;
          }
        prev[0] = s[0];
        prev[1] = s[1];
      }
      CHECK(order);
      CHECK(cont[0]);
      CHECK(cont[1]);
      /* kn against a central difference (step 1e-4 sigma) */
      for (double h = -2; h <= 2; h += 1)
        for (int b = 0; b < 2; b++) {
          dc_gw_adhesive_state s, p, m;
          const double d = -h * SIGMA, e = 1e-4 * SIGMA;
          dc_gw_rough_adhesive(&g, N_ASP, SIGMA, d, b, &s);
          dc_gw_rough_adhesive(&g, N_ASP, SIGMA, d + e, b, &p);
          dc_gw_rough_adhesive(&g, N_ASP, SIGMA, d - e, b, &m);
          CHECK_ABS((p.F - m.F) / (2 * e) - s.kn, 0.0, 1e-7 * (fabs(s.kn) + fabs(s.F) / SIGMA), "kn = dF/d delta");
        }
    }
}

static void test_special(void)
{
  dc_jkr_geom g;
  dc_jkr_geometry(1e-3, 2e-4, E_STAR, 0.1, &g);
  dc_gw_adhesive_state s;
  dc_jkr_state j;
  /* sigma = 0: n_asp summits at delta, attached as the branch says */
  const double d = 0.5 * g.delta_break;
  CHECK(dc_gw_rough_adhesive(&g, N_ASP, 0.0, d, DC_GW_LOADING, &s) == DC_OK);
  CHECK(s.F == 0.0 && s.area == 0.0);
  CHECK(dc_gw_rough_adhesive(&g, N_ASP, 0.0, d, DC_GW_UNLOADING, &s) == DC_OK);
  dc_jkr_contact(&g, d, NULL, &j);
  CHECK(j.F < 0 && s.F == N_ASP * j.F && s.area == N_ASP * j.area);
  /* sigma << delta: the summit law at delta, F = n f(delta) (1 + O((sigma/delta)^2)) */
  CHECK(dc_gw_rough_adhesive(&g, N_ASP, 1e-14, 1e-6, DC_GW_LOADING, &s) == DC_OK);
  dc_jkr_contact(&g, 1e-6, NULL, &j);
  CHECK_REL(s.F, N_ASP * j.F, 1e-13, "sigma -> 0: n_asp f(delta)");
  CHECK(dc_gw_rough_adhesive(&g, N_ASP, 1e-320, 1e-6, DC_GW_LOADING, &s) == DC_OK);   /* s0 overflows */
  CHECK(s.F == N_ASP * j.F && s.h == -1e300);
  /* far apart: exactly zero */
  CHECK(dc_gw_rough_adhesive(&g, N_ASP, SIGMA, -60 * SIGMA, DC_GW_UNLOADING, &s) == DC_OK);
  CHECK(s.F == 0.0 && s.area == 0.0 && s.kn == 0.0);
  /* domain */
  memset(&s, 0x5a, sizeof s);
  const dc_gw_adhesive_state ref = s;
  CHECK(dc_gw_rough_adhesive(&g, 0.0, SIGMA, 0.0, 0, &s) == DC_EDOM);
  CHECK(dc_gw_rough_adhesive(&g, N_ASP, -SIGMA, 0.0, 0, &s) == DC_EDOM);
  CHECK(dc_gw_rough_adhesive(&g, N_ASP, SIGMA, NAN, 0, &s) == DC_EDOM);
  CHECK(dc_gw_rough_adhesive(&g, N_ASP, INFINITY, 0.0, 0, &s) == DC_EDOM);
  CHECK(dc_gw_rough_adhesive(&g, N_ASP, SIGMA, 0.0, 2, &s) == DC_EDOM);
  CHECK(memcmp(&s, &ref, sizeof s) == 0);
}

int main(void)
{
  test_smooth_limit();
  test_table();
  test_branches();
  test_special();
  return check_summary("gw_rough_adhesive");
}
