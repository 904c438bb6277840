/* Maugis-Dugdale adhesion of spheres and the DMT limit
   (dc/maugis_dugdale.h): the contact branch and the pull-off force against
   an independent mpmath solution of the model's equations
   (tests/reference/maugis.csv, gen_maugis.py: lambda from 0.01 to 100)
   within 1e-10 and 1e-8; the published limits (JKR 3/2 pi w R as
   lambda -> inf, DMT 2 pi w R as lambda -> 0); the Tabor mapping; the
   zone-only states, the reach bound over lambda, the overlap-controlled loop
   (dc_md_step) against the reference along loading and unloading paths,
   spheres in SI units (dc_md_sphere) against the csv; domain. */
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
  /* the branch in s (the DEM path's variable) against the branch in abar: the same
     forces and overlaps, dDbar/ds against central differences, and its fold at the
     reference's separation overlap */
  {
    double worst_b = 0.0, worst_d = 0.0, worst_f = 0.0;
    int n = 0;
    const double lams[] = {0.01, 0.1, 0.5, 0.9, 1.0, 2.0, 10.0, 1000.0};
    for (int L = 0; L < 8; L++) {
      for (int k = 0; k <= 40; k++) {
        const double x = pow(10.0, -4.0 + 0.2 * k);
        double ab, Pb, Db, dD, m2, P2, D2;
        CHECK(dc_md_branch_s(lams[L], x, &ab, &Pb, &Db, &dD) == DC_OK);
        if (ab < 1e-20 || ab > 1e20) continue;
        CHECK(dc_md_state(lams[L], ab, &m2, &P2, &D2) == DC_OK);
        const double sc = ab * ab + 4.0 / 3.0 * lams[L] * ab * x;   /* MD3's terms */
        /* s itself to 1e-8 (the abar solve holds s to 4 DBL_EPSILON absolute, loose where MD1 is flat, s < 1e-2) */
        CHECK(fabs(sqrt((m2 - 1.0) * (m2 + 1.0)) / x - 1.0) < 1e-8);
        worst_b = fmax(worst_b, fmax(fabs(P2 - Pb) / (fabs(Pb) + ab * ab * ab), fabs(D2 - Db) / sc));
        double a1, P1, D1, d1, a3, P3, D3, d3;
        const double hs = 1e-5 * x;
        CHECK(dc_md_branch_s(lams[L], x - hs, &a1, &P1, &D1, &d1) == DC_OK);
        CHECK(dc_md_branch_s(lams[L], x + hs, &a3, &P3, &D3, &d3) == DC_OK);
        worst_d = fmax(worst_d, fabs((D3 - D1) / (2.0 * hs) - dD) * x / sc);
        n++;
      }
      /* the fold: the least Dbar over s against the reference's separation overlap */
      double Ds, as, Dmin = HUGE_VAL;
      CHECK(dc_md_separation(lams[L], &Ds, &as) == DC_OK);
      dc_md_contact h = {DC_MD_APART, 0.0, 0.0, lams[L], 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
      double P, a;
      CHECK(dc_md_step(5.0, &h, &P, &a) == DC_OK && h.phase == DC_MD_CONTACT);
      for (int k = 0; k <= 4000; k++) {
        double ab, Pb, Db, dD;
        if (dc_md_branch_s(lams[L], pow(10.0, -3.0 + 0.002 * k), &ab, &Pb, &Db, &dD) == DC_OK) Dmin = fmin(Dmin, Db);
      }
      worst_f = fmax(worst_f, fabs(h.Dsep - Ds));
      CHECK(h.Dsep <= Dmin + 1e-12);
      CHECK((as > 1e-6) == (h.sfold > 0.0));   /* the reference's golden section ends within 1e-8 of the end */
    }
    printf("  the branch in s: %d states against the branch in abar, worst %.3g; dDbar/ds against differences %.3g; "
           "separation overlaps from the fold %.3g from the reference\n", n, worst_b, worst_d, worst_f);
    CHECK(n > 250);
    CHECK(worst_b < 1e-12);
    CHECK(worst_d < 1e-8);
    CHECK(worst_f < 1e-10);
    double ab, Pb, Db, dD;
    CHECK(dc_md_branch_s(1.0, 0.0, &ab, &Pb, &Db, &dD) == DC_EDOM);
    CHECK(dc_md_branch_s(0.0, 1.0, &ab, &Pb, &Db, &dD) == DC_EDOM);
    CHECK(dc_md_branch_s(1.0, NAN, &ab, &Pb, &Db, &dD) == DC_EDOM);
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

  /* the zone-only states: they meet the branch's end (lambda below ~0.93) and fold at
     -c_z^2/2 - 2/(pi lambda); none where the end's cbar0 < c_z */
  {
    const double lz[] = {0.01, 0.1, 0.5, 0.9};
    for (int L = 0; L < 4; L++) {
      const double l = lz[L], cz = 8.0 * l / (3.0 * M_PI), Df = -0.5 * cz * cz - 2.0 / (M_PI * l);
      double cz0, Pz0, Dz0, cb, Pb;
      int zone;
      CHECK(dc_md_state_zero(l, &cz0, &Pz0, &Dz0) == DC_OK);
      CHECK(dc_md_zone(l, Dz0, &zone, &cb, &Pb) == DC_OK && zone == 1);
      CHECK_REL(cb, cz0, 1e-12, "zone at the branch's end: cbar0");
      CHECK_REL(Pb, Pz0, 1e-12, "zone at the branch's end: Pbar0");
      CHECK(dc_md_zone(l, Df * (1.0 - 1e-12), &zone, &cb, &Pb) == DC_OK && zone == 1);
      CHECK(cb >= cz && cb - cz <= 1.01 * sqrt(2e-12 * fabs(Df)));   /* the fold at c_z: cbar - c_z = (2 (Dbar - Df))^1/2 */
      CHECK(dc_md_zone(l, Df * (1.0 + 1e-12), &zone, &cb, &Pb) == DC_OK && zone == 0 && Pb == 0.0);
      CHECK(dc_md_zone(l, Dz0 + 1e-9, &zone, &cb, &Pb) == DC_OK && zone == 0);
    }
    double cb, Pb;
    int zone;
    CHECK(dc_md_zone(2.0, -0.5, &zone, &cb, &Pb) == DC_OK && zone == 0);
    CHECK(dc_md_zone(0.0, -0.5, &zone, &cb, &Pb) == DC_EDOM);
  }
  /* the reach bound over lambda: the branch's separation overlap lies in [-1, 0], the
     zone's fold within the bound where the zone is stable, and where the approach lands
     on the contact branch (cbar0 < 2 c_z) the branch is there (-2/(pi lambda) >= its
     separation overlap) */
  {
    int n = 0, ok = 1;
    double least = 0.0;
    for (int k = 0; k <= 60; k++) {
      const double l = k <= 20 ? pow(10.0, -3.0 + 0.1 * k) : k <= 40 ? 0.6 + 0.03 * (k - 20) : pow(10.0, 0.2 + 0.14 * (k - 40));
      double Ds, as, c0, P0, D0;
      CHECK(dc_md_separation(l, &Ds, &as) == DC_OK);
      dc_md_state_zero(l, &c0, &P0, &D0);
      const double cz = 8.0 * l / (3.0 * M_PI), Din = -2.0 / (M_PI * l), reach = dc_md_reach(l);
      least = fmin(least, Ds);
      ok &= Ds >= -1.0 && Ds <= 0.0 && reach >= 1.0 && reach >= -Din;
      if (c0 > cz) ok &= reach >= 0.5 * cz * cz + 2.0 / (M_PI * l);
      if (c0 < 2.0 * cz) ok &= Din >= Ds;
      n++;
    }
    printf("  reach bound over %d lambdas from 1e-3 to 1e3: holds %d; least separation overlap %.6f\n", n, ok, least);
    CHECK(ok && least > -1.0 && least < -0.99);
    CHECK(isnan(dc_md_reach(0.0)));
  }
  /* the overlap-controlled loop: loading from apart to Dbar 3 and back to apart, 4000 steps
     each way, against the reference (the stable branch from dc_md_at_overlap, the zone from
     dc_md_zone); the attraction begins at -2/(pi lambda) and ends at the lowest attached
     overlap (the branch's separation overlap or the zone's fold) */
  {
    const double lams[] = {0.01, 0.1, 0.5, 0.8, 0.9, 0.95, 1.0, 2.0, 10.0, 1000.0};
    double worst = 0.0, worst_in = 0.0, worst_out = 0.0;
    int n = 0, refs = 0;
    for (int L = 0; L < 10; L++) {
      const double l = lams[L], reach = dc_md_reach(l), Din = -2.0 / (M_PI * l);
      double Ds, as, c0, P0, D0;
      dc_md_separation(l, &Ds, &as);
      dc_md_state_zero(l, &c0, &P0, &D0);
      const double cz = 8.0 * l / (3.0 * M_PI);
      const double Dlo = c0 > cz ? -0.5 * cz * cz - 2.0 / (M_PI * l) : Ds;
      dc_md_contact h = {0.0, 0.0, 0.0, l, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
      const int steps = 4000;
      const double Dstart = -reach - 0.5, Dmax = 3.0, dD = (Dmax - Dstart) / steps;
      double first = NAN, last = NAN, prevD = NAN;
      int was = 0;
      for (int i = 0; i <= 2 * steps; i++) {
        const double D = i <= steps ? Dstart + dD * i : Dmax - dD * (i - steps);
        double P, a;
        CHECK(dc_md_step(D, &h, &P, &a) == DC_OK);
        const int att = h.phase != DC_MD_APART;
        if (att && !was && i <= steps) first = D;
        if (!att && was && i > steps) last = prevD;
        was = att;
        prevD = D;
        /* the reference state */
        double want = 0.0;
        if (h.phase == DC_MD_CONTACT) {
          int contact;
          double ar, mr, Pr;
          CHECK(dc_md_at_overlap(l, D, &contact, &ar, &mr, &Pr) == DC_OK && contact == 1);
          want = Pr;
          refs++;
          worst = fmax(worst, fabs(a / ar - 1.0));
        } else if (h.phase == DC_MD_ZONE) {
          int zone;
          double cb, Pb;
          CHECK(dc_md_zone(l, D, &zone, &cb, &Pb) == DC_OK && zone == 1);
          want = Pb;
        } else {
          CHECK(P == 0.0 && a == 0.0);
        }
        worst = fmax(worst, fabs(P - want) / (1.0 + fabs(want)));
        n++;
      }
      /* the first attached step is the first at or above Din; the last the last at or above Dlo */
      worst_in = fmax(worst_in, fabs(first - (Dstart + dD * ceil((Din - Dstart) / dD))) / dD);
      worst_out = fmax(worst_out, fabs(last - (Dmax - dD * floor((Dmax - Dlo) / dD))) / dD);
    }
    printf("  overlap-controlled loops: %d steps (%d in contact) against the reference, worst %.3g; attraction begins "
           "%.3g and ends %.3g steps from the model's overlaps\n", n, refs, worst, worst_in, worst_out);
    CHECK(worst < 1e-12);
    CHECK(worst_in < 1e-6 && worst_out < 1e-6);
    dc_md_contact h = {DC_MD_CONTACT, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    double P, a;
    CHECK(dc_md_step(1.0, &h, &P, &a) == DC_EDOM);
  }
  /* spheres in SI units: lambda = 1 at R (maugis.csv's overlap rows), the friction load
     F + 2 |F_c| with the pull-off force of the csv; the Tabor choice; parameters */
  {
    const double E = 2e9, w = 0.05, z0 = 4e-10;
    dc_md_sphere_pair p;
    dc_param_error err;
    CHECK(dc_md_sphere_pair_of(E, w, z0, &p, &err) == DC_OK);
    const double R = 1.0 / (p.Lam * p.Lam * p.Lam), K = 4.0 / 3.0 * E;
    const double sd = cbrt(M_PI * M_PI * w * w * R / (K * K)), sa = cbrt(M_PI * w * R * R / K), sF = M_PI * w * R;
    CHECK_REL(2.0 * 16.0 * w / (9.0 * sqrt(3.0) * z0) * cbrt(R / (M_PI * w * K * K)), 1.0, 1e-14, "lambda 1 at R");
    CHECK_REL(p.h0, 9.0 * sqrt(3.0) / 16.0 * z0, 1e-15, "h0 = w / sigma0");
    FILE *g = check_open_reference("maugis.csv");
    int rows = 0;
    while (g && check_read_tagged_row(g, tag, sizeof tag, v, 5) > 0) {
      if (v[0] != 1.0) continue;
      if (!strcmp(tag, "overlap") && v[1] > 0.0) {   /* jumps from apart straight onto the branch */
        dc_md_contact h = {0};
        double F, aa;
        CHECK(dc_md_sphere(&p, R, v[1] * sd, &h, &F, &aa) == DC_OK && h.phase == DC_MD_CONTACT);
        CHECK_REL(F, v[3] * sF, 1e-9, "dc_md_sphere: force at the csv's overlap");
        CHECK_REL(aa, v[2] * sa, 1e-9, "dc_md_sphere: contact radius at the csv's overlap");
        rows++;
      } else if (!strcmp(tag, "pulloff")) {
        dc_md_contact h = {DC_MD_CONTACT, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
        CHECK_REL(dc_md_friction_load(&h, 0.5), 0.5 - 2.0 * v[1], 1e-9, "friction load F + 2 |F_c|");
        rows++;
      }
    }
    if (g) fclose(g);
    CHECK(rows == 3);
    dc_md_contact h = {0};
    double F = 1.0, aa = 1.0;
    CHECK(dc_md_sphere(&p, R, -1.001 * p.h0, &h, &F, &aa) == DC_OK && F == 0.0 && aa == 0.0 && h.phase == DC_MD_APART);
    CHECK(dc_md_sphere(&p, R, -0.999 * p.h0, &h, &F, &aa) == DC_OK && F < 0.0 && h.phase == DC_MD_CONTACT);
    CHECK(dc_md_sphere(&p, -R, 0.0, &h, &F, &aa) == DC_EDOM);
    /* an ellipse of equal radii is the sphere (to rounding: its cube root is taken each step) */
    {
      dc_md_contact hs = {0}, he = {0};
      dc_hertz_geom gc, ge;
      double worst_e = 0.0;
      CHECK(dc_hertz_geometry(R, R, &gc) == DC_OK);
      for (int k = 0; k <= 400; k++) {
        const double d = (k <= 200 ? -1.0 + 0.02 * k : 3.0 - 0.025 * (k - 200)) * sd;
        double Fs, as_, Fe, ae;
        CHECK(dc_md_sphere(&p, R, d, &hs, &Fs, &as_) == DC_OK && dc_md_ellipse(&p, &gc, d, &he, &Fe, &ae) == DC_OK);
        CHECK(hs.phase == he.phase);
        worst_e = fmax(worst_e, fabs(Fe - Fs) / sF);
      }
      printf("  dc_md_ellipse with equal radii against dc_md_sphere along a cycle: worst %.3g of pi w R\n", worst_e);
      CHECK(worst_e < 1e-12);
      /* an ellipse: the sphere of its Hertz force radius, so that it carries elliptic Hertz's force as the load grows */
      dc_md_contact h2 = {0}, h3 = {0};
      double F2, a2, F3, a3;
      CHECK(dc_hertz_geometry(4.0 * R, 0.25 * R, &ge) == DC_OK);
      CHECK(dc_md_ellipse(&p, &ge, 0.5 * sd, &h2, &F2, &a2) == DC_OK);
      CHECK(dc_md_sphere(&p, ge.R_force, 0.5 * sd, &h3, &F3, &a3) == DC_OK);
      CHECK_REL(F2, F3, 1e-13, "dc_md_ellipse: the sphere of R_force");
      dc_hertz_state hz;
      dc_md_contact h4 = {0};
      double dbig = 1e4 * sd, Fb, ab;
      CHECK(dc_md_ellipse(&p, &ge, dbig, &h4, &Fb, &ab) == DC_OK);
      CHECK(dc_hertz_contact(&ge, E, dbig, &hz) == DC_OK);
      /* at 1e4 overlap scales: elliptic Hertz's force less the adhesion, which tends to pi w R_force (JKR: its
         Hertz force at the same overlap is F + pi w R to second order in the neck's overlap) and 2 pi w R_force (DMT) */
      CHECK(hz.F - Fb >= M_PI * w * ge.R_force && hz.F - Fb <= 2.0 * M_PI * w * ge.R_force);
      ge.R_force = 0.0;
      CHECK(dc_md_ellipse(&p, &ge, 0.0, &h2, &F2, &a2) == DC_EDOM);
    }
    /* Tabor: JKR above 5, DMT below 0.1 */
    CHECK_REL(p.Lam * cbrt(p.R_jkr), dc_md_lambda_of_tabor(5.0), 1e-14, "lambda at R_jkr: Tabor 5");
    CHECK_REL(p.Lam * cbrt(p.R_dmt), dc_md_lambda_of_tabor(0.1), 1e-14, "lambda at R_dmt: Tabor 0.1");
    CHECK(dc_md_tabor_law(&p, 1.01 * p.R_jkr) == DC_ADHESION_JKR && dc_md_tabor_law(&p, 0.99 * p.R_jkr) == DC_ADHESION_MD);
    CHECK(dc_md_tabor_law(&p, 1.01 * p.R_dmt) == DC_ADHESION_MD && dc_md_tabor_law(&p, 0.99 * p.R_dmt) == DC_ADHESION_DMT);
    CHECK(dc_md_sphere_pair_of(E, w, 0.0, &p, &err) == DC_EDOM && !strcmp(err.name, "equilibriumSeparation"));
    CHECK(dc_md_sphere_pair_of(E, 0.0, z0, &p, &err) == DC_EDOM && !strcmp(err.name, "workOfAdhesion"));
    CHECK(dc_md_sphere_pair_of(NAN, w, z0, &p, &err) == DC_EDOM);
  }

  /* domain */
  CHECK(dc_md_state(0.0, 1.0, &m, &P, &D) == DC_EDOM);
  CHECK(dc_md_state(1.0, 0.0, &m, &P, &D) == DC_EDOM);
  CHECK(dc_md_state(NAN, 1.0, &m, &P, &D) == DC_EDOM);
  CHECK(dc_md_pulloff(-1.0, &P, &a) == DC_EDOM);
  CHECK(dc_md_state_zero(INFINITY, &c, &P0, &D0) == DC_EDOM);
  return check_summary("maugis_dugdale");
}
