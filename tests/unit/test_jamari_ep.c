/* Jamari-Schipper elastic-plastic law (dc/jamari_ep.h): the mpmath table
   (tests/reference/jamari_ep.csv: onsets, load-unload-reload paths, cycle
   energies, the review's Fig. 8), the elastic regime against
   dc_hertz_normal bit for bit, continuity and slopes at delta_n1 and
   delta_n2, delta_n1 == delta_n2, scale invariance down to tiny overlaps,
   the unloading branch's properties over random cycles, the parameter
   check, and the time per call. */
#include "check.h"
#include "dc/hertz_elliptic.h"
#include "dc/jamari_ep.h"
#include "dc/status.h"
#include <float.h>
#include <time.h>

static int same_contact(const dc_contact *x, const dc_contact *y)
{
  return x->F == y->F && x->kn == y->kn && x->area == y->area && x->a == y->a && x->b == y->b &&
         x->F_bound == y->F_bound && x->formed == y->formed;
}

static int contact_finite(const dc_contact *c)
{
  return isfinite(c->F) && isfinite(c->kn) && isfinite(c->area) && isfinite(c->a) && isfinite(c->b) &&
         isfinite(c->F_bound) && c->F >= 0.0 && c->area >= 0.0 && c->a >= c->b && c->b >= 0.0;
}

static double rel(double got, double want)
{
  if (want == 0.0) return got == 0.0 ? 0.0 : INFINITY;
  return fabs(got - want) / fabs(want);
}

/* ---------------------------------------------------------------- */
/* The committed table.                                               */

static void table(void)
{
  FILE *f = check_open_reference("jamari_ep.csv");
  if (!f) return;
  char tag[32];
  double v[10];
  int k, ncase = 0, npath = 0, nenergy = 0, nfig = 0;
  double err_F = 0, err_A = 0, err_a = 0, err_kn = 0, err_res = 0, err_lim = 0, err_E = 0, err_fig = 0;
  dc_hertz_geom g;
  dc_jamari_params p = {0, 0, 0, 0};
  double Estar = 0.0;
  dc_jamari_state h = {0, 0, 0, 0};
  int id = 0;
  while ((k = check_read_tagged_row(f, tag, sizeof tag, v, 10)) > 0) {
    if (!strcmp(tag, "case") && k == 8) {
      id = (int)v[0];
      CHECK(dc_hertz_geometry(v[1], v[2], &g) == DC_OK);
      Estar = v[3];
      p = (dc_jamari_params){v[4], v[5], v[6], v[7]};
      dc_param_error err;
      CHECK(dc_jamari_check(&p, &err) == DC_OK);
      memset(&h, 0, sizeof h);
      ncase++;
    } else if (!strcmp(tag, "limits") && k == 3) {
      CHECK((int)v[0] == id);
      double d1, d2;
      CHECK(dc_jamari_onsets(&g, Estar, &p, &d1, &d2) == DC_OK);
      err_lim = fmax(err_lim, fmax(rel(d1, v[1]), rel(d2, v[2])));
    } else if (!strcmp(tag, "path") && k == 7) {
      CHECK((int)v[0] == id);
      const double d = v[1];
      dc_contact c;
      if (!CHECK(dc_jamari_step(&g, Estar, &p, d, &h, &c) == DC_OK)) continue;
      char what[96];
      const double eF = rel(c.F, v[2]), eA = rel(c.area, v[3]), ea = rel(c.a, v[4]), ek = rel(c.kn, v[5]),
                   er = rel(h.delta_res, v[6]);
      snprintf(what, sizeof what, "case %d delta %.17g", id, d);
      if (!CHECK(eF <= 1e-12 && eA <= 1e-12 && ea <= 1e-12 && ek <= 1e-12 && er <= 1e-12))
        printf("  %s: F %.3g A %.3g a %.3g kn %.3g delta_res %.3g (%.17g vs %.17g)\n", what, eF, eA, ea, ek, er,
               h.delta_res, v[6]);
      CHECK(c.formed == (v[2] > 0.0) && c.F_bound == c.F && fabs(c.b - c.a * sqrt(g.m1)) <= 1e-15 * c.a);
      err_F = fmax(err_F, eF); err_A = fmax(err_A, eA); err_a = fmax(err_a, ea);
      err_kn = fmax(err_kn, ek); err_res = fmax(err_res, er);
      npath++;
    } else if (!strcmp(tag, "energy") && k == 3) {
      /* one cycle 0 -> delta_max -> 0: composite Simpson on the loading
         curve and on the branch, pieces split at delta_n1, delta_n2 */
      CHECK((int)v[0] == id);
      const double dm = v[1];
      double d1, d2;
      dc_jamari_onsets(&g, Estar, &p, &d1, &d2);
      dc_jamari_state hc = {0, 0, 0, 0};
      dc_contact c;
      dc_jamari_step(&g, Estar, &p, dm, &hc, &c);
      const double ends[2][2] = {{0.0, dm}, {hc.delta_res, dm}};
      double W[2] = {0.0, 0.0};
      for (int leg = 0; leg < 2; leg++) {
        double cut[4] = {ends[leg][0], 0, 0, 0};
        int nc = 1;
        if (d1 > ends[leg][0] && d1 < dm) cut[nc++] = d1;
        if (d2 > ends[leg][0] && d2 < dm && d2 > d1) cut[nc++] = d2;
        cut[nc++] = dm;
        for (int piece = 0; piece + 1 < nc; piece++) {
          const int n = 20000;
          const double a0 = cut[piece], hstep = (cut[piece + 1] - a0) / n;
          double s = 0.0;
          for (int i = 0; i <= n; i++) {
            /* right limits at the cuts: the force jumps at delta_n1 when delta_n1 == delta_n2 */
            const double x = i == n ? cut[piece + 1] : i == 0 && piece > 0 ? nextafter(a0, INFINITY) : a0 + i * hstep;
            dc_contact ci;
            dc_jamari_state hh = hc;
            if (leg == 0) dc_jamari_loading(&g, Estar, &p, x, &ci);
            else dc_jamari_step(&g, Estar, &p, fmin(x, nextafter(dm, 0.0)), &hh, &ci);
            s += (i == 0 || i == n ? 1.0 : i % 2 ? 4.0 : 2.0) * ci.F;
          }
          W[leg] += s * hstep / 3.0;
        }
      }
      const double D = W[0] - W[1];
      CHECK(D >= -1e-12 * W[0]);
      if (fabs(D - v[2]) / W[0] > 1e-9)
        printf("  energy case %d delta_max %.6g: C %.12g mpmath %.12g W_load %.6g\n", id, dm, D, v[2], W[0]);
      err_E = fmax(err_E, fabs(D - v[2]) / W[0]);
      nenergy++;
    } else if (!strcmp(tag, "fig8") && k == 2) {
      const double r = v[0];
      dc_hertz_geom gf;
      CHECK(dc_hertz_geometry(1.0, r, &gf) == DC_OK);
      const dc_jamari_params pf = {1e9, 0.5, 1.0, 108.0};
      double d1, d2;
      CHECK(dc_jamari_onsets(&gf, 1e11, &pf, &d1, &d2) == DC_OK);
      err_fig = fmax(err_fig, rel(d2 / (pf.c_A * d1), v[1]));
      /* the review's Fig. 8: nearly 0.5 for R_minor/R_major from 0.6 to 1 */
      if (r >= 0.6) CHECK(fabs(d2 / (pf.c_A * d1) - 0.5) < 0.002);
      nfig++;
    }
  }
  fclose(f);
  printf("table: %d cases, %d path rows, %d cycle energies, %d Fig. 8 ratios\n", ncase, npath, nenergy, nfig);
  printf("  max rel. error: onsets %.3g, F %.3g, area %.3g, a %.3g, kn %.3g, delta_res %.3g, Eq. 44 ratio %.3g\n",
         err_lim, err_F, err_A, err_a, err_kn, err_res, err_fig);
  printf("  cycle energy (Simpson on the C law) vs mpmath: max |dD|/W_load %.3g\n", err_E);
  CHECK(ncase == 6 && npath >= 300 && nenergy == 36 && nfig == 13);
  CHECK(err_lim <= 1e-14);
  CHECK(err_fig <= 1e-14);
  CHECK(err_E <= 1e-9);
}

/* ---------------------------------------------------------------- */
/* Random geometries and materials (fixed seed).                      */

static unsigned long long rx = 0x2545F4914F6CDD1Dull;
static double U(void) { return check_uniform(&rx); }
static double LU(double lo, double hi) { return exp(log(lo) + (log(hi) - log(lo)) * U()); }

static void random_case(dc_hertz_geom *g, double *Estar, dc_jamari_params *p)
{
  const double R1 = LU(1e-5, 1.0);
  const double u = U();
  const double r = u < 0.2 ? 1.0 : u < 0.6 ? LU(0.1, 1.0) : LU(1e-12, 1.0);
  dc_hertz_geometry(R1, R1 * r, g);
  *Estar = LU(1e9, 3e11);
  const double nu = 0.5 * U();
  p->H = *Estar * LU(3e-4, 5e-2);
  p->K_v = U() < 0.7 ? dc_jamari_kv_default(nu) : LU(0.2, 1.5);
  p->c_h = U() < 0.6 ? fmax(1.0, 2.0 / 3.0 * p->K_v) : 2.0 / 3.0 * p->K_v * LU(1.0, 10.0);
  p->c_A = U() < 0.6 ? 108.0 : LU(2.0, 1000.0);
}

/* Elastic regime: dc_hertz_normal bit for bit (loading curve and step). */
static void elastic_limit(void)
{
  int bad = 0, n = 0;
  for (int k = 0; k < 20000; k++) {
    dc_hertz_geom g;
    dc_jamari_params p;
    double E, d1, d2;
    random_case(&g, &E, &p);
    dc_jamari_onsets(&g, E, &p, &d1, &d2);
    const double d = k % 10 == 0 ? (k % 20 ? d1 : -d1 * U()) : d1 * U();
    dc_contact cj, cs, ch;
    dc_jamari_state h = {0, 0, 0, 0};
    const int s1 = dc_jamari_loading(&g, E, &p, d, &cj), s2 = dc_jamari_step(&g, E, &p, d, &h, &cs),
              s3 = dc_hertz_normal(&g, E, d, &ch);
    if (!(s1 == DC_OK && s2 == DC_OK && s3 == DC_OK && same_contact(&cj, &ch) && same_contact(&cs, &ch) &&
          h.delta_max == 0.0 && h.delta_res == 0.0 && h.F_max == 0.0 && h.area_max == 0.0))
      bad++;
    n++;
  }
  printf("elastic regime (delta <= delta_n1, 0 and negative included): %d cases equal dc_hertz_normal bit for bit\n",
         n - bad);
  CHECK(bad == 0);
}

/* Eq. 41: both printed forms, from this geometry's gamma, beta, K, E. */
static void eq41_forms(void)
{
  double worst = 0.0;
  for (int k = 0; k <= 2000; k++) {
    dc_hertz_geom g;
    dc_hertz_geometry(1.0, pow(10.0, -12.0 * k / 2000.0), &g);
    const dc_jamari_params p = {2e9, 0.58, 1.0, 108.0};
    double d1, d2;
    dc_jamari_onsets(&g, 1e11, &p, &d1, &d2);
    const double x = p.K_v * p.H / 1e11;
    const double form1 = M_PI * M_PI / 4.0 * g.Rc * (g.beta / g.gamma) * (g.beta / g.gamma) * x * x;
    worst = fmax(worst, rel(d1, form1));
  }
  printf("Eq. 41: first printed form vs the second (used) over R_minor/R_major in [1e-12, 1]: %.3g\n", worst);
  CHECK(worst < 2e-14);
  /* sphere: delta_n1 = (pi K_v H/(2 E*))^2 R, delta_n2 = c_A/2 delta_n1 */
  dc_hertz_geom g;
  dc_hertz_geometry(1e-3, 1e-3, &g);
  const dc_jamari_params p = {2e9, 0.577, 1.0, 108.0};
  double d1, d2;
  dc_jamari_onsets(&g, 1.15e11, &p, &d1, &d2);
  const double want = pow(M_PI * 0.577 * 2e9 / (2.0 * 1.15e11), 2) * 1e-3;
  CHECK_REL(d1, want, 1e-15, "sphere delta_n1 (two orders of the operations)");
  CHECK_REL(d2, 54.0 * d1, 4e-16, "sphere delta_n2 = 54 delta_n1 (c_A = 108)");
}

/* Continuity at delta_n1 and delta_n2 (one ulp apart) and the slopes
   against the header's closed forms. */
static void continuity(void)
{
  double jF1 = 0, jA1 = 0, ja1 = 0, jF2 = 0, jA2 = 0, ja2 = 0, es1 = 0, es2 = 0, es0 = 0;
  int n = 0;
  for (int k = 0; k < 20000; k++) {
    dc_hertz_geom g;
    dc_jamari_params p;
    double E, d1, d2;
    random_case(&g, &E, &p);
    dc_jamari_onsets(&g, E, &p, &d1, &d2);
    if (!(d2 > d1 * (1.0 + 1e-9))) continue;
    dc_contact c0, c1, c2, c3;
    const double d1p = nextafter(d1, INFINITY), d2m = nextafter(d2, 0.0);
    int ok = dc_jamari_loading(&g, E, &p, d1, &c0) == DC_OK && dc_jamari_loading(&g, E, &p, d1p, &c1) == DC_OK &&
             dc_jamari_loading(&g, E, &p, d2m, &c2) == DC_OK && dc_jamari_loading(&g, E, &p, d2, &c3) == DC_OK;
    if (!CHECK(ok)) continue;
    /* the jump less what the slope gives over that ulp (steep where
       delta_n2 is close to delta_n1) */
    jF1 = fmax(jF1, fabs(c1.F - c0.F - c1.kn * (d1p - d1)) / c0.F);
    jA1 = fmax(jA1, rel(c1.area, c0.area)); ja1 = fmax(ja1, rel(c1.a, c0.a));
    jF2 = fmax(jF2, fabs(c3.F - c2.F - c2.kn * (d2 - d2m)) / c3.F);
    jA2 = fmax(jA2, rel(c2.area, c3.area)); ja2 = fmax(ja2, rel(c2.a, c3.a));
    /* slopes: Hertz 3/2 F/delta below, (1 + kappa) F/delta above delta_n1;
       (1 + (c_h - 2/3 K_v)/(c_h ln(d2/d1))) F/delta below delta_n2, F/delta above */
    const double L = log(d2 / d1), p1 = 2.0 / 3.0 * p.K_v;
    const double kappa = (p.c_h - p1) / (p1 * L);
    es0 = fmax(es0, rel(c0.kn, 1.5 * c0.F / d1));
    /* one ulp inside, the area blend adds ~ 6 (Ap/Ae - 1) ulp/(q - 1)^2 to the slope: q >= 1.1 here */
    if (d2 >= 1.1 * d1) {
      es1 = fmax(es1, rel(c1.kn, (1.0 + kappa) * c1.F / d1p));
      es2 = fmax(es2, rel(c2.kn, (1.0 + (p.c_h - p1) / (p.c_h * L)) * c2.F / d2m));
    }
    CHECK(rel(c3.kn, c3.F / d2) < 1e-15);
    n++;
  }
  printf("continuity over %d random cases, one ulp apart (relative jumps, F less slope x ulp):\n"
         "  delta_n1: F %.3g, area %.3g, a %.3g;  delta_n2: F %.3g, area %.3g, a %.3g\n"
         "  slopes vs closed forms: Hertz at delta_n1 %.3g, (1 + kappa) F/delta above it %.3g, below delta_n2 %.3g\n",
         n, jF1, jA1, ja1, jF2, jA2, ja2, es0, es1, es2);
  CHECK(n > 15000);
  CHECK(jF1 < 2e-15 && jA1 < 2e-15 && ja1 < 2e-15 && jF2 < 2e-15 && jA2 < 2e-15 && ja2 < 2e-15);
  CHECK(es0 < 1e-15 && es1 < 1e-12 && es2 < 1e-12);

  /* delta_n1 == delta_n2: a circle with c_A = 2 (Eq. 44: delta_n2 = delta_n1);
     an ellipse with c_A = 2 (Eq. 44 below delta_n1, raised to it) */
  for (int e = 0; e < 2; e++) {
    dc_hertz_geom g;
    dc_hertz_geometry(2e-3, e ? 5e-4 : 2e-3, &g);
    const dc_jamari_params p = {3e9, 0.6, 1.2, 2.0};
    double d1, d2;
    CHECK(dc_jamari_onsets(&g, 1e11, &p, &d1, &d2) == DC_OK && d1 == d2);
    dc_contact c0, c1, c2;
    dc_jamari_loading(&g, 1e11, &p, d1, &c0);
    dc_jamari_loading(&g, 1e11, &p, nextafter(d1, INFINITY), &c1);
    dc_jamari_loading(&g, 1e11, &p, 1.5 * d1, &c2);
    dc_contact ch;
    dc_hertz_normal(&g, 1e11, d1, &ch);
    CHECK(same_contact(&c0, &ch));
    /* beyond: fully plastic, Eqs. 42-43 */
    const double Ap = 2.0 * M_PI * sqrt(g.R_major * g.R_minor);
    CHECK_REL(c1.F, p.c_h * p.H * Ap * nextafter(d1, INFINITY), 1e-15, "delta_n1 == delta_n2: plastic force");
    CHECK_REL(c2.area, Ap * 1.5 * d1, 1e-15, "delta_n1 == delta_n2: plastic area");
    CHECK(contact_finite(&c1) && contact_finite(&c2));
    printf("delta_n1 == delta_n2 (%s): force jumps by %.4g at delta_n1 (c_h H Ap / (2/3 K_v H Ae) = %.4g)\n",
           e ? "ellipse, Eq. 44 raised" : "circle, Eq. 44 exact", c1.F / c0.F,
           p.c_h * Ap / (2.0 / 3.0 * p.K_v * M_PI * g.R_area));
  }
}

/* Homogeneity: radii and overlaps scaled by lambda scale F and area by
   lambda^2; checks the logarithms and thresholds at tiny and huge overlaps. */
static void scaling(void)
{
  double worst = 0.0;
  const double lam[] = {1e-120, 1e-60, 1e60, 1e120};   /* F stays normal */
  for (int k = 0; k < 4000; k++) {
    dc_hertz_geom g, gs;
    dc_jamari_params p;
    double E, d1, d2;
    random_case(&g, &E, &p);
    dc_jamari_onsets(&g, E, &p, &d1, &d2);
    const double L = lam[k % 4];
    if (dc_hertz_geometry(g.R_major * L, g.R_minor * L, &gs) != DC_OK) continue;
    const double d = d1 * LU(0.5, 5.0) * (d2 / d1 > 1.0 ? LU(1.0, d2 / d1 * 3.0) : 1.0);
    dc_contact c, cs;
    dc_jamari_state h = {0, 0, 0, 0}, hs = {0, 0, 0, 0};
    if (!CHECK(dc_jamari_step(&g, E, &p, d, &h, &c) == DC_OK && dc_jamari_step(&gs, E, &p, d * L, &hs, &cs) == DC_OK))
      continue;
    /* unload halfway */
    dc_contact cu, cus;
    const double du = 0.5 * (d + h.delta_res);
    dc_jamari_step(&g, E, &p, du, &h, &cu);
    dc_jamari_step(&gs, E, &p, du * L, &hs, &cus);
    const double e = fmax(fmax(rel(cs.F / (L * L), c.F), rel(cs.area / (L * L), c.area)),
                          fmax(rel(cus.F / (L * L), cu.F), rel(hs.delta_res / L, h.delta_res)));
    worst = fmax(worst, e);
  }
  printf("scale invariance (radii, overlaps x 1e-120 .. 1e120; F, area x lambda^2): worst %.3g\n", worst);
  CHECK(worst < 1e-13);
}

/* ---------------------------------------------------------------- */
/* The unloading branch.                                              */

static void unloading(void)
{
  double cont = 0.0, min_res_ratio = INFINITY, worst_dom = 0.0, worst_W = 0.0;
  int retrace_bad = 0, res_bad = 0, zero_bad = 0, n = 0, ncap = 0;
  for (int k = 0; k < 3000; k++) {
    dc_hertz_geom g;
    dc_jamari_params p;
    double E, d1, d2;
    random_case(&g, &E, &p);
    dc_jamari_onsets(&g, E, &p, &d1, &d2);
    const double dmax = d1 * (k % 5 == 0 ? 1.0 + LU(1e-6, 1e-2) : LU(1.0 + 1e-6, fmax(3.0, 4.0 * d2 / d1)));
    dc_jamari_state h = {0, 0, 0, 0};
    dc_contact cm, c;
    if (!CHECK(dc_jamari_step(&g, E, &p, dmax, &h, &cm) == DC_OK)) continue;
    n++;
    /* continuity at delta_max, and delta_res > 0 */
    dc_jamari_state h0 = h;
    dc_jamari_step(&g, E, &p, nextafter(dmax, 0.0), &h, &c);
    cont = fmax(cont, fabs(cm.F - c.F - c.kn * (dmax - nextafter(dmax, 0.0))) / cm.F);
    if (!(h.delta_res > 0.0 && h.delta_res < dmax && memcmp(&h, &h0, sizeof h) == 0)) {
      if (res_bad < 5)
        printf("  delta_res %.17g delta_max %.17g delta_n1 %.17g delta_n2 %.17g, history changed %d\n", h.delta_res,
               dmax, d1, d2, memcmp(&h, &h0, sizeof h) != 0);
      res_bad++;
    }
    min_res_ratio = fmin(min_res_ratio, h.delta_res / dmax);
    /* zero force at and below delta_res */
    dc_jamari_step(&g, E, &p, h.delta_res, &h, &c);
    if (!(c.F == 0.0 && c.formed == 0 && c.area == 0.0)) zero_bad++;
    /* along the branch: never above the loading curve; reloading retraces
       bit for bit */
    double xs[64];
    dc_contact cs[64];
    for (int i = 0; i < 64; i++) {
      xs[i] = h.delta_res + (dmax - h.delta_res) * (i + 0.5) / 64.0;
      dc_contact cl;
      dc_jamari_step(&g, E, &p, xs[i], &h, &cs[i]);
      dc_jamari_loading(&g, E, &p, xs[i], &cl);
      worst_dom = fmax(worst_dom, (cs[i].F - cl.F) / cm.F);
      ncap += cs[i].F == cl.F;
      CHECK(contact_finite(&cs[i]));
    }
    for (int i = 63; i >= 0; i--) {
      dc_jamari_step(&g, E, &p, xs[i], &h, &c);
      if (!same_contact(&c, &cs[i])) retrace_bad++;
    }
    /* one more load step past delta_max continues the loading curve */
    dc_contact cl, cn;
    dc_jamari_step(&g, E, &p, dmax * 1.01, &h, &cn);
    dc_jamari_loading(&g, E, &p, dmax * 1.01, &cl);
    CHECK(same_contact(&cn, &cl) && h.delta_max == dmax * 1.01);

    /* random cycles from a fresh contact, ending apart, over the nodes of a
       fixed grid: trapezoid sums over the same nodes cancel exactly where a
       leg retraces a branch, so the work done (the dissipated energy) is
       >= 0 up to the rounding of the sum, not the quadrature's error */
    if (k % 4 == 0) {
      dc_jamari_state hr = {0, 0, 0, 0};
      const int nodes = 4000;
      const double dx = 3.0 * dmax / nodes;
      int j = 0;
      double F = 0.0, W = 0.0, scaleW = 0.0;
      for (int leg = 0; leg < 12; leg++) {
        const int target = leg == 11 ? -1 : (int)(U() * nodes);
        while (j != target) {
          const int jn = j + (target > j ? 1 : -1);
          dc_jamari_step(&g, E, &p, jn * dx, &hr, &c);
          W += 0.5 * (F + c.F) * (jn - j) * dx;
          scaleW = fmax(scaleW, c.F * fabs(jn * dx));
          j = jn;
          F = c.F;
        }
      }
      worst_W = fmin(worst_W, W / scaleW);
    }
  }
  printf("unloading over %d random contacts: F continuity at delta_max (one ulp below, less slope x ulp) %.3g;\n"
         "  min delta_res/delta_max %.3g (delta_max/delta_n1 - 1 >= 1e-6); branch above the loading curve by at\n"
         "  most %.3g F_max (%d of %d branch states on the cap); retrace mismatches %d; work of random cycles\n"
         "  ending apart, min W/(F delta) %.3g\n",
         n, cont, min_res_ratio, worst_dom, ncap, 64 * n, retrace_bad, worst_W);
  CHECK(n == 3000 && cont < 2e-15 && res_bad == 0 && zero_bad == 0 && retrace_bad == 0);
  CHECK(worst_dom <= 0.0);
  CHECK(worst_W > -1e-13);

  /* limits: delta_max <= delta_n1 leaves no memory; sphere branch = Thornton &
     Ning with a_p from the law's area: R_p = 4 E* a_p^3/(3 F), delta_p =
     delta_max - a_p^2/R_p */
  dc_hertz_geom g;
  dc_hertz_geometry(1e-3, 1e-3, &g);
  const dc_jamari_params p = dc_jamari_defaults(2e9, 0.3);
  double d1, d2;
  dc_jamari_onsets(&g, 1.15e11, &p, &d1, &d2);
  dc_jamari_state h = {0, 0, 0, 0};
  dc_contact c;
  dc_jamari_step(&g, 1.15e11, &p, d1, &h, &c);
  CHECK(h.delta_max == 0.0 && h.delta_res == 0.0);
  dc_jamari_step(&g, 1.15e11, &p, 0.5 * d1, &h, &c);
  dc_contact ch;
  dc_hertz_normal(&g, 1.15e11, 0.5 * d1, &ch);
  CHECK(same_contact(&c, &ch));
  for (int i = 0; i < 3; i++) {
    const double dm = (double[]){5.0, 30.0, 300.0}[i] * d1;
    memset(&h, 0, sizeof h);
    dc_jamari_step(&g, 1.15e11, &p, dm, &h, &c);
    const double ap = sqrt(c.area / M_PI), Rp = 4.0 * 1.15e11 * ap * ap * ap / (3.0 * c.F);
    CHECK_REL(h.delta_res, dm - ap * ap / Rp, 1e-13, "sphere: Thornton-Ning residual overlap");
    /* fully plastic: delta_res/delta_max grows towards 1 */
    printf("sphere, defaults, nu = 0.3: delta_max = %g delta_n1: delta_res/delta_max = %.4f, R_p/R = %.4g\n",
           dm / d1, h.delta_res / dm, Rp / 1e-3);
  }
}

/* Whether the cap acts on some branch from delta_max in (delta_n1, 1e4
   delta_n1] (nd values of delta_max, nb points on each branch). */
static int cap_acts(const dc_hertz_geom *g, const dc_jamari_params *p, int nd, int nb)
{
  double d1, d2;
  dc_jamari_onsets(g, 1e11, p, &d1, &d2);
  for (int k = 0; k < nd; k++) {
    const double dm = d1 * pow(10.0, 4.0 * (k + 0.5) / nd);
    dc_jamari_state h = {0, 0, 0, 0};
    dc_contact c, cl;
    dc_jamari_step(g, 1e11, p, dm, &h, &c);
    for (int i = 1; i < nb; i++) {
      const double x = h.delta_res + (dm - h.delta_res) * i / nb;
      dc_jamari_step(g, 1e11, p, x, &h, &c);
      dc_jamari_loading(g, 1e11, p, x, &cl);
      if (c.F == cl.F) return 1;
    }
  }
  return 0;
}

/* Where the cap acts with the default parameters (the header quotes this):
   the largest nu on a 0.005 grid, per axis ratio; none for nu >= 0.2 down
   to R_minor/R_major = 1e-4 (finer scan), always for nu = 0. */
static void cap_with_defaults(void)
{
  const double rs[] = {1.0, 0.1, 1e-4, 1e-6, 1e-9};
  printf("cap with the defaults acts (coarse scan) up to nu =");
  for (int ir = 0; ir < 5; ir++) {
    dc_hertz_geom g;
    dc_hertz_geometry(1e-3, 1e-3 * rs[ir], &g);
    double found = -1.0;
    for (int inu = 100; inu >= 0 && found < 0.0; inu--)
      if (cap_acts(&g, &(dc_jamari_params){2e9, dc_jamari_kv_default(0.005 * inu), 1.0, 108.0}, 60, 200))
        found = 0.005 * inu;
    printf(" %.3f (R_minor/R_major %g)%s", found, rs[ir], ir < 4 ? "," : "\n");
    CHECK(cap_acts(&g, &(dc_jamari_params){2e9, dc_jamari_kv_default(0.0), 1.0, 108.0}, 60, 200));
    if (rs[ir] >= 1e-4)
      for (int inu = 0; inu < 4; inu++) {
        const dc_jamari_params p = dc_jamari_defaults(2e9, 0.2 + 0.1 * inu);
        CHECK(!cap_acts(&g, &p, 200, 400));
      }
  }
}

/* ---------------------------------------------------------------- */
/* Parameter check, domain, statuses.                                 */

static void check_params(void)
{
  dc_param_error err;
  dc_jamari_params p = dc_jamari_defaults(2e9, 0.3);
  CHECK(dc_jamari_check(&p, &err) == DC_OK);
  CHECK(p.K_v == 0.454 + 0.41 * 0.3 && p.c_h == 1.0 && p.c_A == 108.0);
  struct { dc_jamari_params p; const char *name; } bad[] = {
    {{0.0, 0.5, 1.0, 108.0}, "hardness"},
    {{-1.0, 0.5, 1.0, 108.0}, "hardness"},
    {{INFINITY, 0.5, 1.0, 108.0}, "hardness"},
    {{NAN, 0.5, 1.0, 108.0}, "hardness"},
    {{1e9, 0.0, 1.0, 108.0}, "plasticityKv"},
    {{1e9, NAN, 1.0, 108.0}, "plasticityKv"},
    {{1e9, 0.6, 0.39, 108.0}, "plasticityCh"},
    {{1e9, 0.6, INFINITY, 108.0}, "plasticityCh"},
    {{1e9, 0.6, 1.0, 1.99}, "plasticityCa"},
    {{1e9, 0.6, 1.0, NAN}, "plasticityCa"},
    /* the yield pressures K_v H, c_h H beyond the doubles */
    {{1e300, 1e9, 1e9, 108.0}, "hardness"},
    {{1e308, 0.6, 2.0, 108.0}, "hardness"},
  };
  for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
    memset(&err, 0, sizeof err);
    const int st = dc_jamari_check(&bad[i].p, &err);
    char what[96];
    snprintf(what, sizeof what, "check names %s", bad[i].name);
    if (!CHECK(st == DC_EDOM && err.name && !strcmp(err.name, bad[i].name) && err.range))
      printf("  %s: got %s\n", what, err.name ? err.name : "(null)");
  }
  /* the largest hardness that keeps c_h H a double is inside */
  p = (dc_jamari_params){DBL_MAX / 2.0, 0.6, 2.0, 108.0};
  CHECK(dc_jamari_check(&p, &err) == DC_OK);
  /* c_h = 2/3 K_v and c_A = 2 are inside */
  p = (dc_jamari_params){1e9, 0.6, 2.0 / 3.0 * 0.6, 2.0};
  CHECK(dc_jamari_check(&p, &err) == DC_OK);
  char buf[128];
  dc_jamari_params q = {1e9, 0.6, 0.1, 108.0};
  dc_jamari_check(&q, &err);
  dc_param_error_format(&err, 1, 2, buf, sizeof buf);
  printf("check message: %s\n", buf);
  CHECK(strstr(buf, "plasticityCh") != NULL);
  /* history field names are unique and prefixed */
  for (int i = 0; i < DC_JAMARI_HISTORY_NFIELDS; i++) {
    CHECK(!strncmp(dc_jamari_history[i].name, "jamari_", 7) && dc_jamari_history[i].flips == 0);
    for (int j = 0; j < i; j++) CHECK(strcmp(dc_jamari_history[i].name, dc_jamari_history[j].name));
  }
  CHECK(DC_JAMARI_HISTORY_NFIELDS == 4);

  /* domain: statuses, untouched outputs */
  dc_hertz_geom g;
  dc_hertz_geometry(1e-3, 5e-4, &g);
  p = dc_jamari_defaults(2e9, 0.3);
  dc_contact c, c0;
  memset(&c, 0x5A, sizeof c);
  c0 = c;
  dc_jamari_state h = {0, 0, 0, 0}, h0;
  CHECK(dc_jamari_step(&g, 1e11, &p, NAN, &h, &c) == DC_EDOM);
  CHECK(dc_jamari_step(&g, INFINITY, &p, 1e-6, &h, &c) == DC_EDOM);
  CHECK(dc_jamari_step(&g, 0.0, &p, 1e-6, &h, &c) == DC_EDOM);
  h.F_max = NAN;
  CHECK(dc_jamari_step(&g, 1e11, &p, 1e-6, &h, &c) == DC_EDOM);
  q = (dc_jamari_params){1e9, 0.6, 0.1, 108.0};
  memset(&h, 0, sizeof h);
  CHECK(dc_jamari_step(&g, 1e11, &q, 1e-6, &h, &c) == DC_EDOM);
  CHECK(dc_jamari_loading(&g, 1e11, &q, 1e-6, &c) == DC_EDOM);
  CHECK(memcmp(&c, &c0, sizeof c) == 0);
  /* any finite history is safe */
  int bad_hist = 0;
  for (int k = 0; k < 200000; k++) {
    h = (dc_jamari_state){LU(1e-12, 1e-3) * (U() < 0.1 ? -1 : 1), LU(1e-14, 1e-3) * (U() < 0.1 ? -1 : 1),
                          LU(1e-6, 1e6) * (U() < 0.1 ? -1 : 1), LU(1e-16, 1e-4)};
    if (U() < 0.1) h.delta_res = 0.0;
    const double d = LU(1e-12, 2e-3) * (U() < 0.1 ? -1 : 1);
    h0 = h;
    const int st = dc_jamari_step(&g, 1e11, &p, d, &h, &c);
    if (!(st == DC_OK && contact_finite(&c) && isfinite(h.delta_max) && isfinite(h.delta_res) &&
          isfinite(h.F_max) && isfinite(h.area_max)))
      bad_hist++;
    (void)h0;
  }
  CHECK(bad_hist == 0);
  printf("random finite histories: %d of 200000 steps not DC_OK and finite\n", bad_hist);
}

/* ---------------------------------------------------------------- */
/* Time per call.                                                     */

/* CPU time of this thread: the machine may be shared */
static double now(void)
{
  struct timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static void timing(void)
{
  dc_hertz_geom gs, ge;
  dc_hertz_geometry(1e-3, 1e-3, &gs);
  dc_hertz_geometry(2e-3, 5e-4, &ge);
  const dc_jamari_params p = dc_jamari_defaults(2e9, 0.3);
  const double E = 1.15e11;
  double d1, d2;
  dc_jamari_onsets(&gs, E, &p, &d1, &d2);
  enum { N = 2000000 };
  volatile double sink = 0.0;
  const char *names[] = {"hertz_normal (reference)", "elastic", "elastic-plastic loading", "fully plastic loading",
                         "unloading branch", "unloading, ellipse"};
  for (int m = 0; m < 6; m++) {
    double best = INFINITY;
    for (int rep = 0; rep < 3; rep++) {
      dc_jamari_state h = {0, 0, 0, 0};
      const dc_hertz_geom *g = m == 5 ? &ge : &gs;
      if (m >= 4) {
        dc_contact c;
        dc_jamari_step(g, E, &p, 10.0 * d1, &h, &c);
      }
      const double lo = m == 1 || m == 0 ? 0.1 * d1 : m == 2 ? 1.5 * d1 : m == 3 ? 60.0 * d1 : 0.5 * h.delta_res + 0.5 * 10.0 * d1;
      const double hi = m == 1 || m == 0 ? 0.9 * d1 : m == 2 ? 50.0 * d1 : m == 3 ? 90.0 * d1 : 9.9 * d1;
      const double t0 = now();
      for (int i = 0; i < N; i++) {
        const double d = lo + (hi - lo) * (double)(i & 1023) / 1023.0;
        dc_contact c;
        if (m == 0) dc_hertz_normal(g, E, d, &c);
        else {
          if (m == 2 || m == 3) h.delta_max = 0.0;   /* stay on the loading curve */
          dc_jamari_step(g, E, &p, d, &h, &c);
        }
        sink += c.F;
      }
      best = fmin(best, (now() - t0) / N * 1e9);
    }
    printf("time per call, %-26s %6.1f ns\n", names[m], best);
  }
  (void)sink;
}

/* Reproductions of the fuzz's findings (tests/unit/test_fuzz.c), in the
   domain of dc_jamari_check and dc_jamari_onsets:
   - dc_jamari_onsets formed K_v (H/E*) with H/E* subnormal and K_v (H/E*)
     normal, so it lost digits (23 % here: H/E* is 4.5 subnormal steps);
     now such an intermediate takes the scaled path too;
   - dc_jamari_circle_yield_ratio formed pi/2 K_v first: +inf for
     K_v = DBL_MAX with a ratio of 4e197, 62 % off for a subnormal K_v,
     2.7e-5 off for a subnormal pi/2 K_v H (E* subnormal). */
static void extreme_onsets(void)
{
  dc_hertz_geom g;
  dc_hertz_geometry(1e-3, 1e-3, &g);
  /* onsets: H/E* = 2.2e-323 */
  {
    const dc_jamari_params p = {DBL_MIN, 1e250, 1e250, 108.0};
    const double E = 1e15;
    CHECK(dc_jamari_check(&p, &(dc_param_error){0}) == DC_OK);
    double d1 = -1.0, d2 = -1.0;
    CHECK(dc_jamari_onsets(&g, E, &p, &d1, &d2) == DC_OK);
    const double want = pow(M_PI / 2.0 * (p.K_v * p.H) / E, 2) * 1e-3;
    CHECK_REL(d1, want, 1e-14, "delta_n1 with H/E* subnormal");
    CHECK_REL(d2, 54.0 * d1, 1e-15, "delta_n2 with H/E* subnormal");
    CHECK_REL(dc_jamari_circle_yield_ratio(E, &p) * 1e-3, d1, 1e-14, "circle yield ratio, H/E* subnormal");
  }
  /* the circle's yield ratio: inputs in the domain, each against the
     value in long double (wider exponent range than double's on the
     targets, x86-64 and aarch64) and against delta_n1 / R */
  const struct { double E, H, K_v, c_h; } c[] = {
    {4632154569.6028948, 1e-200, DBL_MAX, DBL_MAX},      /* gave +inf, is 3.8e197 */
    {24986776346.723164, 1e300, DBL_TRUE_MIN, 1.0},      /* gave 1.58e-69, is 9.73e-70 */
    {DBL_TRUE_MIN, 37792509.572018519, 9.82548349884487e-320, 1.0},   /* 2.7e-5 off */
    {2e11, 2e9, 0.577, 1.0},                             /* ordinary */
  };
  for (size_t i = 0; i < sizeof c / sizeof c[0]; i++) {
    const dc_jamari_params p = {c[i].H, c[i].K_v, c[i].c_h, 108.0};
    CHECK(dc_jamari_check(&p, &(dc_param_error){0}) == DC_OK);
    const double q = dc_jamari_circle_yield_ratio(c[i].E, &p);
    const long double w = 1.5707963267948966192L * c[i].K_v * c[i].H / c[i].E;   /* long double: no overflow here */
    const double want = (double)(w * w);
    if (!CHECK_REL(q, want, 1e-14, "circle yield ratio"))
      printf("  E* %.17g H %.17g K_v %.17g\n", c[i].E, c[i].H, c[i].K_v);
    double d1, d2;
    if (dc_jamari_onsets(&g, c[i].E, &p, &d1, &d2) == DC_OK) CHECK_REL(q * 1e-3, d1, 1e-14, "circle yield ratio vs delta_n1");
  }
}

int main(void)
{
  table();
  elastic_limit();
  eq41_forms();
  continuity();
  scaling();
  unloading();
  cap_with_defaults();
  check_params();
  extreme_onsets();
  timing();
  return check_summary("jamari_ep");
}
