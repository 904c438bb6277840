/* Elliptic GW rough contact (review Eqs. 29-36) and the rough tangential
   stiffness (Eqs. 78-84): smooth limits against elliptic Hertz / Mindlin,
   reference values from the mpmath table, stiffness = dF/d delta, domain. */
#include "check.h"
#include "dc/gw_rough.h"
#include "dc/hertz_elliptic.h"
#include "dc/rough_tangential.h"
#include "dc/status.h"
#include <stdlib.h>
#include <string.h>

/* F_n(h) from tests/reference/gw_integrals.csv (mpmath quadrature) */
static double ref_F(double n, double h)
{
  FILE *f = check_open_reference("gw_integrals.csv");
  if (!f) return NAN;
  double v = NAN, row[3];
  check_read_row(f, row, 3);   /* column names */
  while (check_read_row(f, row, 3) == 3)
    if (row[0] == n && row[1] == h) { v = row[2]; break; }
  fclose(f);
  return v;
}

int main(void)
{
  const double Estar = 7e10, sigma = 1e-7;
  const double radii[][2] = {{1e-3, 1e-3}, {2e-3, 5e-4}, {1.0, 1e-4}};
  for (int c = 0; c < 3; c++) {
    dc_hertz_geom g;
    CHECK(dc_hertz_geometry(radii[c][0], radii[c][1], &g) == DC_OK);
    dc_hertz_state hs;
    dc_gw_rough_state rs;
    /* sigma -> 0: smooth elliptic Hertz, exactly at sigma = 0, and before
       with the next terms of F_3/2(h) = |h|^3/2 (1 + 3/(8h^2) + 27/(384h^4))
       (binomial series of E[(Z + |h|)^3/2]) */
    const double delta = 1e-5;
    dc_hertz_contact(&g, Estar, delta, &hs);
    CHECK(dc_gw_rough_elliptic(&g, Estar, 1.0, 0.0, delta, &rs) == DC_OK);
    CHECK_REL(rs.F, hs.F, 2e-16, "sigma = 0: force = Hertz");
    CHECK_REL(rs.area, hs.area, 2e-16, "sigma = 0: area = Hertz");
    CHECK_REL(rs.kn, hs.kn, 2e-16, "sigma = 0: stiffness = Hertz");
    const double sig[] = {1e-8, 1e-10, 1e-12, 1e-14};  /* x^6 term < 1e-19 */
    for (int k = 0; k < 4; k++) {
      CHECK(dc_gw_rough_elliptic(&g, Estar, 1.0, sig[k], delta, &rs) == DC_OK);
      const double x = sig[k] / delta;
      CHECK_REL(rs.F, hs.F * (1 + 0.375 * x * x + 27.0 / 384 * x * x * x * x), 4e-15, "sigma -> 0: force -> Hertz");
      CHECK_REL(rs.area, hs.area, 4e-15, "sigma -> 0: area -> Hertz");
    }
    /* reference values: h = -2 and h = +1 from the quadrature table */
    const double hs_[] = {-2.0, 1.0};
    for (int k = 0; k < 2; k++) {
      const double d = -hs_[k] * sigma;
      CHECK(dc_gw_rough_elliptic(&g, Estar, 250.0, sigma, d, &rs) == DC_OK);
      const double Fw = 250.0 * 4.0 / 3.0 * Estar * sqrt(g.Rc) * pow(sigma, 1.5) * g.gamma * ref_F(1.5, hs_[k]);
      const double Aw = 250.0 * M_PI * g.Rc * sigma * g.beta * ref_F(1.0, hs_[k]);
      CHECK_REL(rs.F, Fw, 2e-15, "rough force vs table F_3/2");
      CHECK_REL(rs.area, Aw, 2e-15, "rough area vs table F_1");
      /* stiffness = dF/d delta (central difference, step 1e-4 sigma) */
      dc_gw_rough_state p, m;
      dc_gw_rough_elliptic(&g, Estar, 250.0, sigma, d + 1e-4 * sigma, &p);
      dc_gw_rough_elliptic(&g, Estar, 250.0, sigma, d - 1e-4 * sigma, &m);
      CHECK_REL(rs.kn, (p.F - m.F) / (2e-4 * sigma), 1e-8, "kn = dF/d delta");
    }
    /* separated far beyond the summits: zero force, finite */
    CHECK(dc_gw_rough_elliptic(&g, Estar, 1.0, sigma, -100 * sigma, &rs) == DC_OK);
    CHECK(rs.F == 0.0 && rs.area == 0.0);
  }
  /* domain */
  dc_hertz_geom g;
  dc_hertz_geometry(1e-3, 1e-3, &g);
  dc_gw_rough_state rs;
  CHECK(dc_gw_rough_elliptic(&g, -1, 1, 1e-7, 1e-6, &rs) == DC_EDOM);
  CHECK(dc_gw_rough_elliptic(&g, 1e9, 0, 1e-7, 1e-6, &rs) == DC_EDOM);
  CHECK(dc_gw_rough_elliptic(&g, 1e9, 1, -1e-7, 1e-6, &rs) == DC_EDOM);
  CHECK(dc_gw_rough_elliptic(&g, 1e9, 1, 1e-7, NAN, &rs) == DC_EDOM);

  /* tangential: circle chi = 4/(pi (2 - nu)); sigma -> 0 gives Mindlin
     k_t = 8 G a/(2 - nu) with a = sqrt(R delta) */
  const double nu = 0.3, G = 3e10, R = 1e-3, delta = 1e-6;
  double chi, kt;
  CHECK(dc_mindlin_chi(&g, nu, 0.7, &chi) == DC_OK);
  CHECK_REL(chi, 4.0 / (M_PI * (2 - nu)), 1e-15, "chi, circle");
  CHECK(dc_rough_tangential_stiffness(G, chi, 1.0, R, 0.0, delta, &kt) == DC_OK);
  CHECK_REL(kt, 8 * G * sqrt(R * delta) / (2 - nu), 1e-15, "sigma = 0: Mindlin");
  CHECK(dc_rough_tangential_stiffness(G, chi, 1.0, R, 1e-6 * delta, delta, &kt) == DC_OK);
  /* F_1/2(h) = |h|^1/2 (1 - 1/(8 h^2) + ...) */
  CHECK_REL(kt, 8 * G * sqrt(R * delta) / (2 - nu) * (1 - 0.125e-12), 1e-15, "sigma -> 0: Mindlin");
  CHECK(dc_rough_tangential_stiffness(G, chi, 40.0, R, 1e-7, 1e-7, &kt) == DC_OK);
  CHECK_REL(kt, 2 * M_PI * 40 * G * chi * sqrt(R * 1e-7) * ref_F(0.5, -1.0), 2e-15, "k_t vs table F_1/2(-1)");
  CHECK(dc_rough_tangential_stiffness(G, chi, 1.0, R, 0.0, -1e-6, &kt) == DC_OK && kt == 0.0);
  CHECK(dc_rough_tangential_stiffness(G, chi, 1.0, -R, 1e-7, 1e-6, &kt) == DC_EDOM);
  CHECK(dc_mindlin_chi(&g, 0.6, 0.0, &chi) == DC_EDOM);
  /* random elliptic GW contacts (fixed seed): radii 1e-6 .. 1 m, ratio down
     to 1e-6, sigma 1e-9 .. 1e-3 R, n_asp 1e-2 .. 1e6, delta in [-4, 10] sigma */
  unsigned long long x = 88172645463325252ull;
  int bad = 0;
  for (int k = 0; k < 200000; k++) {
    const double R1 = pow(10.0, -6.0 + 6.0 * check_uniform(&x)), R2 = R1 * pow(10.0, -6.0 * check_uniform(&x));
    const double E = pow(10.0, 5.0 + 7.0 * check_uniform(&x)), sig = R1 * pow(10.0, -9.0 + 6.0 * check_uniform(&x));
    const double n = pow(10.0, -2.0 + 8.0 * check_uniform(&x)), d = sig * (-4.0 + 14.0 * check_uniform(&x));
    if (dc_hertz_geometry(R1, R2, &g) != DC_OK || dc_gw_rough_elliptic(&g, E, n, sig, d, &rs) != DC_OK ||
        !(isfinite(rs.F) && isfinite(rs.kn) && isfinite(rs.area) && rs.F >= 0.0 && rs.kn >= 0.0)) {
      if (bad < 5) printf("random GW: R1 %g R2 %g sigma %g delta %g: F %g\n", R1, R2, sig, d, rs.F);
      bad++;
    }
  }
  CHECK(bad == 0);

  /* dc_gw_bound_force against dc_gw_rough_elliptic: within the pieces of
     dc_gw_F32_F12 (h in [-10, 3)) to its accuracy, elsewhere the same bits;
     the same status; the init's domain */
  double worst_F = 0.0, worst_k = 0.0;
  for (int c = 0; c < 3; c++) {
    const double Rs[][2] = {{7.5e-4, 7.5e-4}, {1e-3, 2e-4}, {1.0, 1.0}};
    CHECK(dc_hertz_geometry(Rs[c][0], Rs[c][1], &g) == DC_OK);
    dc_gw_bound b;
    CHECK(dc_gw_bound_init(&g, 2.7e6, 3.0, 2.1e-5, &b) == DC_OK);
    for (int k = 0; k <= 20000; k++) {
      const double h = -12.0 + 17.0 * k / 20000.0, d = -h * 2.1e-5;
      double F = 0.0, kn = 0.0;
      CHECK(dc_gw_bound_force(&b, d, &F, &kn) == DC_OK);
      CHECK(dc_gw_rough_elliptic(&g, 2.7e6, 3.0, 2.1e-5, d, &rs) == DC_OK);
      if (h >= DC_GW_F32P_LO && h < DC_GW_F32P_HI) {
        worst_F = fmax(worst_F, fabs(F / rs.F - 1));
        worst_k = fmax(worst_k, fabs(kn / rs.kn - 1));
      } else if (!(fabs(-d * b.inv_sigma - h) < 1e-12 && (-d * b.inv_sigma < DC_GW_F32P_LO) != (h < DC_GW_F32P_LO))) {
        CHECK(F == rs.F && kn == rs.kn);
      }
    }
    double F = 1.0, kn = 1.0;
    CHECK(dc_gw_bound_force(&b, NAN, &F, &kn) == DC_EDOM && F == 1.0 && kn == 1.0);
  }
  printf("dc_gw_bound_force vs dc_gw_rough_elliptic, h in [-10, 3): F %.2e, kn %.2e\n", worst_F, worst_k);
  /* measured 2.4e-15 and 2.0e-15: h = -delta (1/sigma) rounds twice, h =
     -delta/sigma once, and F_3/2 near h = 3 amplifies an ulp of h ~13 fold */
  CHECK_ABS(worst_F, 0.0, 4e-15, "bound closed form: force");
  CHECK_ABS(worst_k, 0.0, 4e-15, "bound closed form: stiffness");
  /* dc_gw_bound_bind: the bits of dc_gw_bound_init for each new geometry
     (circles of random radius, as polydisperse spheres bind them, and
     ellipses); where the products overflow, the checked form */
  {
    dc_gw_bound m, bi;
    CHECK(dc_gw_bound_material(2.7e6, 3.0, 2.1e-5, &m) == DC_OK);
    unsigned long long y = 7;
    int differ = 0;
    for (int k = 0; k < 2000; k++) {
      const double R = pow(10.0, -6.0 + 6.0 * check_uniform(&y)), r = k % 2 ? 1.0 : check_uniform(&y);
      if (k % 2) dc_hertz_geometry_circle(R, &g);
      else CHECK(dc_hertz_geometry(R, R * fmax(r, 1e-3), &g) == DC_OK);
      CHECK(dc_gw_bound_bind(&m, &g) == DC_OK && dc_gw_bound_init(&g, 2.7e6, 3.0, 2.1e-5, &bi) == DC_OK);
      differ += memcmp(&m.g, &bi.g, sizeof g) != 0 || m.cF != bi.cF || m.ck != bi.ck || m.inv_sigma != bi.inv_sigma;
    }
    CHECK(differ == 0);
    CHECK(dc_gw_bound_material(1e300, 1e300, 1e-7, &m) == DC_OK);
    dc_hertz_geometry_circle(1.0, &g);
    CHECK(dc_gw_bound_bind(&m, &g) == DC_ERANGE && m.cF == HUGE_VAL && m.ck == HUGE_VAL);
    for (int k = 0; k <= 40; k++) {
      const double d = 1e-7 * (-30.0 + 1.5 * k);
      double F = 0.0, kn = 0.0;
      const int sb = dc_gw_bound_force(&m, d, &F, &kn), se = dc_gw_rough_elliptic(&g, 1e300, 1e300, 1e-7, d, &rs);
      CHECK(sb == se && (se != DC_OK || (F == rs.F && kn == rs.kn)));
    }
  }
  dc_gw_bound b0, b1;
  memset(&b0, 0, sizeof b0);
  b1 = b0;
  CHECK(dc_gw_bound_init(&g, 1e9, 1.0, 0.0, &b1) == DC_EDOM);
  CHECK(dc_gw_bound_init(&g, 1e9, -1.0, 1e-7, &b1) == DC_EDOM);
  CHECK(dc_gw_bound_init(&g, NAN, 1.0, 1e-7, &b1) == DC_EDOM);
  CHECK(dc_gw_bound_init(&g, 1e9, 1.0, 1e-320, &b1) == DC_ERANGE);
  CHECK(dc_gw_bound_init(&g, 1e300, 1e300, 1e-7, &b1) == DC_ERANGE);
  CHECK(memcmp(&b0, &b1, sizeof b0) == 0);
  CHECK(dc_gw_bound_material(1e9, 1.0, 0.0, &b1) == DC_EDOM && dc_gw_bound_material(1e9, 1.0, 1e-320, &b1) == DC_ERANGE);
  CHECK(memcmp(&b0, &b1, sizeof b0) == 0);
  return check_summary("gw_rough");
}
