/* Maugis-Dugdale adhesion of spheres and the DMT limit
   (dc/maugis_dugdale.h): the contact branch and the pull-off force against
   an independent mpmath solution of the model's equations
   (tests/reference/maugis.csv, gen_maugis.py: lambda from 0.01 to 100)
   within 1e-10 and 1e-8; the published limits (JKR 3/2 pi w R as
   lambda -> inf, DMT 2 pi w R as lambda -> 0); the Tabor mapping; domain. */
#include "check.h"
#include "dc/maugis_dugdale.h"
#include "dc/status.h"
#include <math.h>
#include <string.h>

int main(void)
{
  FILE *f = check_open_reference("maugis.csv");
  char tag[32];
  double v[5], worst_s = 0.0, worst_p = 0.0, worst_d = 0.0, worst_o = 0.0;
  int ns = 0, np = 0, nd = 0, no = 0;
  while (f && check_read_tagged_row(f, tag, sizeof tag, v, 5) > 0) {
    if (!strcmp(tag, "state")) {
      double m, P, D;
      CHECK(dc_md_state(v[0], v[1], &m, &P, &D) == DC_OK);
      worst_s = fmax(worst_s, fmax(fabs(m / v[2] - 1), fmax(fabs(P - v[3]), fabs(D - v[4])) / fmax(1.0, fabs(v[3]))));
      ns++;
    } else if (!strcmp(tag, "pulloff")) {
      double P, a;
      CHECK(dc_md_pulloff(v[0], &P, &a) == DC_OK);
      worst_p = fmax(worst_p, fabs(P / v[1] - 1));
      CHECK_ABS(a, v[2], 1e-4, "abar at pull-off");
      np++;
    } else if (!strcmp(tag, "separation")) {
      double D, a;
      CHECK(dc_md_separation(v[0], &D, &a) == DC_OK);
      worst_d = fmax(worst_d, fabs(D / v[1] - 1));
      CHECK_ABS(a, v[2], 1e-4, "abar at separation");
      nd++;
    } else if (!strcmp(tag, "overlap")) {
      double a, m, P;
      int contact;
      CHECK(dc_md_at_overlap(v[0], v[1], &contact, &a, &m, &P) == DC_OK && contact == 1);
      worst_o = fmax(worst_o, fmax(fabs(a / v[2] - 1), fabs(P - v[3]) / fmax(1.0, fabs(v[3]))));
      no++;
    }
  }
  if (f) fclose(f);
  printf("Maugis-Dugdale against the mpmath solution: %d states (m, P, D) worst %.3g, %d pull-off forces worst %.3g\n",
         ns, worst_s, np, worst_p);
  printf("  %d separation overlaps worst %.3g, %d stable-branch states at given overlaps worst %.3g\n", nd, worst_d, no,
         worst_o);
  CHECK(ns == 84 && np == 14 && nd == 14 && no == 56);
  CHECK(worst_s < 1e-10);
  CHECK(worst_p < 1e-8);
  CHECK(worst_d < 1e-8);
  CHECK(worst_o < 1e-8);
  /* below the separation overlap: no contact; JKR's separation (lambda 1e4): -3 6^-2/3 at 6^-1/3 */
  {
    double D, a, m, P;
    int contact;
    CHECK(dc_md_separation(2.0, &D, &a) == DC_OK);
    CHECK(dc_md_at_overlap(2.0, D - 1e-9, &contact, &a, &m, &P) == DC_OK && contact == 0 && P == 0.0);
    CHECK(dc_md_separation(1e4, &D, &a) == DC_OK);
    CHECK_REL(D, -3.0 * pow(6.0, -2.0 / 3.0), 1e-3, "lambda 1e4: JKR's separation overlap");
    CHECK_REL(a, pow(6.0, -1.0 / 3.0), 2e-3, "lambda 1e4: JKR's contact radius at separation");
  }

  /* limits: JKR (lambda -> inf: the approach goes as 1/lambda), DMT (lambda -> 0) */
  double P, a, m, D;
  CHECK(dc_md_pulloff(1e4, &P, &a) == DC_OK);
  CHECK_REL(P, -1.5, 2e-6, "lambda 1e4: JKR pull-off 3/2 pi w R");
  CHECK_REL(a, cbrt(1.5), 1e-3, "lambda 1e4: JKR's contact radius at pull-off (3/2)^1/3");
  CHECK(dc_md_state(1e4, 2.0, &m, &P, &D) == DC_OK);
  CHECK_REL(P, 8.0 - sqrt(6.0 * 8.0), 1e-3, "lambda 1e4: JKR force a^3 - (6 a^3)^1/2");
  CHECK_REL(D, 4.0 - 2.0 / 3.0 * sqrt(6.0 * 2.0), 1e-3, "lambda 1e4: JKR overlap a^2 - 2/3 (6 a)^1/2");
  CHECK(dc_md_pulloff(1e-6, &P, &a) == DC_OK);
  CHECK_REL(P, -2.0, 1e-5, "lambda 1e-6: DMT pull-off 2 pi w R");
  /* the overlap approaches Hertz's as lambda^1/2 (the zone's radius goes as lambda^-1/2) */
  CHECK(dc_md_state(1e-10, 1.5, &m, &P, &D) == DC_OK);
  CHECK_REL(P, 1.5 * 1.5 * 1.5 - 2.0, 1e-4, "lambda 1e-10: DMT force a^3 - 2 (Hertz less 2 pi w R)");
  CHECK_REL(D, 2.25, 1e-4, "lambda 1e-10: DMT overlap a^2 (Hertz)");
  /* Newton from a nearby state (a DEM contact's previous step) against the reference
     evaluation along an unloading path from Dbar 4 to 1 % of the separation overlap above it
     (at the fold itself Newton may stop: DC_ENOCONV), 2000 steps, for lambda 0.1, 1, 10 */
  {
    double worst_n = 0.0;
    int fails = 0, n = 0;
    const double lams[] = {0.1, 1.0, 10.0};
    for (int L = 0; L < 3; L++) {
      double Ds, as, a, s, P, m, ar, Pr;
      int contact;
      CHECK(dc_md_separation(lams[L], &Ds, &as) == DC_OK);
      CHECK(dc_md_at_overlap(lams[L], 4.0, &contact, &a, &m, &P) == DC_OK);
      s = sqrt(m * m - 1.0);
      for (int k = 1; k <= 2000; k++) {
        const double D = 4.0 + (Ds - 0.01 * Ds - 4.0) * k / 2000.0;
        if (dc_md_at_overlap_near(lams[L], D, a, s, &a, &s, &P) != DC_OK) { fails++; break; }
        if (k % 97 == 0 || k == 2000) {
          CHECK(dc_md_at_overlap(lams[L], D, &contact, &ar, &m, &Pr) == DC_OK && contact == 1);
          worst_n = fmax(worst_n, fmax(fabs(a / ar - 1), fabs(P - Pr) / fmax(1.0, fabs(Pr))));
          n++;
        }
      }
    }
    printf("  Newton from the previous step along unloading paths: %d compared, worst %.3g, %d failures\n", n, worst_n,
           fails);
    CHECK(fails == 0 && n == 63);
    CHECK(worst_n < 1e-12);
    double a, s, P;
    CHECK(dc_md_at_overlap_near(1.0, 1.0, 0.0, 1.0, &a, &s, &P) == DC_EDOM);
    CHECK(dc_md_at_overlap_near(1.0, NAN, 1.0, 1.0, &a, &s, &P) == DC_EDOM);
  }
  /* the pull-off force is monotonic in lambda between the limits */
  double prev = -2.0;
  int mono = 1;
  for (int k = 0; k <= 40; k++) {
    CHECK(dc_md_pulloff(pow(10.0, -3.0 + 0.15 * k), &P, &a) == DC_OK);
    mono &= P >= prev - 1e-12 && P <= -1.5;
    prev = P;
  }
  CHECK(mono);
  /* the abar -> 0 end is the limit of the branch */
  double c, P0, D0;
  CHECK(dc_md_state_zero(0.7, &c, &P0, &D0) == DC_OK);
  CHECK(dc_md_state(0.7, 1e-7, &m, &P, &D) == DC_OK);
  CHECK_REL(P, P0, 1e-6, "abar -> 0: force");
  CHECK_REL(D, D0, 1e-6, "abar -> 0: overlap");
  CHECK_REL(1e-7 * m, c, 1e-6, "abar -> 0: zone radius");

  /* Tabor: lambda = 1.1570 mu_T (sigma0 = 16 w/(9 3^1/2 z0) of Lennard-Jones) */
  CHECK_REL(dc_md_lambda_of_tabor(1.0), 1.1570, 1e-4, "lambda / mu_T");
  CHECK_REL(dc_md_lambda_of_tabor(2.0), 2.0 * 32.0 / (9.0 * sqrt(3.0)) * cbrt(9.0 / (16.0 * M_PI)), 1e-15, "exact form");

  /* DMT pull-off: 2 pi w R for spheres, 2 pi w (R1 R2)^1/2 for ellipses */
  CHECK_REL(dc_dmt_pulloff(1e-3, 1e-3, 0.05), 2.0 * M_PI * 0.05 * 1e-3, 1e-15, "DMT, sphere");
  CHECK_REL(dc_dmt_pulloff(4e-3, 1e-3, 0.05), 2.0 * M_PI * 0.05 * 2e-3, 1e-15, "DMT, ellipse");
  CHECK(isnan(dc_dmt_pulloff(-1.0, 1.0, 0.05)) && isnan(dc_dmt_pulloff(1.0, 1.0, NAN)));

  /* the DMT contact: Hertz less 2 pi w (R_major R_minor)^1/2 while delta > 0 */
  {
    dc_hertz_geom g;
    dc_hertz_state hs;
    dc_contact cd;
    CHECK(dc_hertz_geometry(4e-3, 1e-3, &g) == DC_OK);
    CHECK(dc_hertz_contact(&g, 2e9, 1e-6, &hs) == DC_OK);
    CHECK(dc_dmt_contact(&g, 2e9, 0.05, 1e-6, &cd) == DC_OK && cd.formed == 1);
    CHECK_REL(cd.F, hs.F - 2.0 * M_PI * 0.05 * 2e-3, 1e-15, "DMT force, ellipse");
    CHECK_REL(cd.F_bound, hs.F + 2.0 * M_PI * 0.05 * 2e-3, 1e-15, "DMT friction load F + 2 F_po");
    CHECK(cd.kn == hs.kn && cd.a == hs.a && cd.b == hs.b);
    CHECK(dc_dmt_contact(&g, 2e9, 0.05, -1e-9, &cd) == DC_OK && cd.formed == 0 && cd.F == 0.0);
    CHECK(dc_dmt_contact(&g, 2e9, -0.05, 1e-6, &cd) == DC_EDOM);
    /* the sphere hot path: dc_dmt_contact's F and kn to the bit over random spheres */
    unsigned long long x = 123456789ull;
    int same = 1, n = 0;
    for (int k = 0; k < 100000; k++) {
      const double R = pow(10.0, -6.0 + 6.0 * check_uniform(&x)), E = pow(10.0, 5.0 + 7.0 * check_uniform(&x));
      const double w = pow(10.0, -4.0 + 4.0 * check_uniform(&x)), d = R * pow(10.0, -9.0 + 8.0 * check_uniform(&x));
      double F, kn, root;
      dc_hertz_geometry_circle(R, &g);
      if (dc_dmt_contact(&g, E, w, d, &cd) != DC_OK || !dc_dmt_sphere(R, E, w, d, &F, &kn, &root)) continue;
      same &= F == cd.F && kn == cd.kn && root == sqrt(g.R_area * d);
      n++;
    }
    CHECK(n == 100000 && same);
  }

  /* domain */
  CHECK(dc_md_state(0.0, 1.0, &m, &P, &D) == DC_EDOM);
  CHECK(dc_md_state(1.0, 0.0, &m, &P, &D) == DC_EDOM);
  CHECK(dc_md_state(NAN, 1.0, &m, &P, &D) == DC_EDOM);
  CHECK(dc_md_pulloff(-1.0, &P, &a) == DC_EDOM);
  CHECK(dc_md_state_zero(INFINITY, &c, &P0, &D0) == DC_EDOM);
  return check_summary("maugis_dugdale");
}
