/* GW integrals F_n(h): both evaluation paths against the committed mpmath
   quadrature table (tests/reference/gw_integrals.csv, gen_gw_integrals.py),
   the identities F_n' = -n F_{n-1} and F_{n+1} = n F_{n-1} - h F_n, the
   h -> 0 and large-|h| behaviour, and the domain. */
#include "check.h"
#include "dc/gw_integrals.h"
#include "dc/status.h"
#include <float.h>
#include <stdlib.h>
#include <string.h>

static void table(void)
{
  FILE *f = check_open_reference("gw_integrals.csv");
  if (!f) return;
  int rows = 0, seen_zero = 0, seen_1em3 = 0;
  double worst_fast = 0, worst_closed = 0;
  double row[3];
  check_read_row(f, row, 3);   /* column names */
  while (check_read_row(f, row, 3) == 3) {
    const double n = row[0], h = row[1], want = row[2];
    const int order = (int)(2 * n + 0.5);
    rows++;
    if (h == 0.0) seen_zero = 1;
    if (h == 1e-3) seen_1em3 = 1;
    double got, gotc, Fa[4];
    CHECK(dc_gw_F(order, h, &got) == DC_OK);
    CHECK(dc_gw_F_all(h, Fa) == DC_OK);
    CHECK(Fa[order] == got);
    char what[96];
    snprintf(what, sizeof what, "fast F_%g(%g)", n, h);
    if (want >= DBL_MIN) {
      /* fast path: near machine precision over the whole range. Budget:
         coefficients 1 ulp, Clenshaw 2 ulp, exp and scaling 1-2 ulp */
      CHECK_REL(got, want, 8e-16, what);
      worst_fast = fmax(worst_fast, fabs(got / want - 1));
    } else {
      CHECK_ABS(got, want, 1e-300, what);  /* gradual underflow, no garbage */
      CHECK(got >= 0);
    }
    CHECK(dc_gw_F_closed(order, h, &gotc) == DC_OK);
    snprintf(what, sizeof what, "closed F_%g(%g)", n, h);
    if (want >= DBL_MIN && h <= 10) {
      /* closed forms: GSL's erfc, K_nu, I_nu (a few 1e-15) amplified, for
         h > 0, by the cancellation of F_1 (~h^2, with erfc's own error
         growing with h) and F_3/2 (~2h^4/3); see gw_integrals.h */
      const double hp = fmax(h, 0.0);
      const double tol = 5e-15 * (1 + hp * hp * hp * hp) + (h < 0 ? 5e-14 : 0);
      CHECK_REL(gotc, want, tol, what);
      worst_closed = fmax(worst_closed, fabs(gotc / want - 1));
    }
    if (want < DBL_MIN) CHECK(gotc >= 0 && gotc < 1e-290);
  }
  fclose(f);
  CHECK(rows >= 4 * 70);
  CHECK(seen_zero && seen_1em3);
  printf("table: %d rows, worst rel.err fast %.2e, closed (h <= 10) %.2e\n", rows, worst_fast, worst_closed);
}

static double F(int o, double h)
{
  double v;
  dc_gw_F(o, h, &v);
  return v;
}

static void identities(void)
{
  double worst_rec = 0, worst_der = 0;
  for (double h = -12.0; h <= 25.0; h += 0.173) {
    /* derivative identities by central differences of the fast path, with a
       step small against the scale 1/|h| on which F varies: truncation
       (eps h)^2/6 ~ 2e-9, rounding ~ 1e-16/(eps h) ~ 1e-12 (relative).
       With F_-1/2 = -2 F_1/2' the n = 1/2 recurrence reads
       F_3/2 = -F_1/2' - h F_1/2. */
    const double eps = 1e-4 / fmax(1.0, fabs(h));
    const double d32 = (F(3, h + eps) - F(3, h - eps)) / (2 * eps);
    const double d1 = (F(2, h + eps) - F(2, h - eps)) / (2 * eps);
    const double d12 = (F(1, h + eps) - F(1, h - eps)) / (2 * eps);
    if (F(1, h) > 1e-250) {
      CHECK_REL(d32, -1.5 * F(1, h), 1e-8, "F_3/2' = -3/2 F_1/2");
      CHECK_REL(d1, -F(0, h), 1e-8, "F_1' = -F_0");
      worst_der = fmax(worst_der, fabs(d32 / (-1.5 * F(1, h)) - 1));
      const double rhs = -d12 - h * F(1, h);
      /* for h > 0 the right side cancels to O(1/h^2): scale the tolerance */
      CHECK_REL(F(3, h), rhs, 1e-8 * (1 + h * h), "F_3/2 = 1/2 F_-1/2 - h F_1/2");
    }
    if (h < 8) {
      /* recurrence n = 0 exactly: F_1 = phi(h) - h F_0 (no cancellation for h < 0) */
      const double phi = exp(-0.5 * h * h) / sqrt(2 * M_PI);
      const double rhs = phi - h * F(0, h);
      /* both sides carry a few ulp; for h > 0 the right side's phi has the
         h*h rounding (~h^2 eps) and then cancels by ~h^2 */
      CHECK_REL(F(2, h), rhs, 1e-15 * (1 + h * h * h * h), "F_1 = phi - h F_0");
      worst_rec = fmax(worst_rec, fabs(F(2, h) / rhs - 1));
    }
  }
  printf("identities: worst F_3/2' rel.err %.2e (finite differences), F_1 = phi - h F_0 %.2e\n",
         worst_der, worst_rec);
}

static void limits(void)
{
  /* continuity across the piece boundaries of the fast path */
  const double edges[] = {-10.0, -3.0, 0.0, 1.0, 19.0, 20.0};
  for (size_t i = 0; i < sizeof edges / sizeof edges[0]; i++) {
    const double e = edges[i];
    /* one ulp step in h changes F by |d ln F/dh| ulp <= (|h| + 3) ulp */
    const double em = nextafter(e, -INFINITY), tol = 1e-15 + 1.5 * (fabs(e) + 3) * (e - em);
    for (int o = 0; o < 4; o++)
      CHECK_REL(F(o, em), F(o, e), tol, "continuity at a piece edge");
  }
  /* h -> -inf: F_n -> |h|^n (smooth limit, review Eq. 33 -> Hertz) */
  CHECK_REL(F(3, -1e6), 1e9 * (1 + 3.0 / 8 * 1e-12), 1e-15, "F_3/2(-1e6)");
  CHECK_REL(F(1, -1e80), 1e40, 1e-15, "F_1/2(-1e80)");
  CHECK_REL(F(2, -1e100), 1e100, 1e-15, "F_1(-1e100)");
  /* huge h: zero, not garbage */
  CHECK(F(3, 50.0) == 0.0 && F(0, 1e300) == 0.0);
  double v;
  CHECK(dc_gw_F(3, NAN, &v) == DC_EDOM);
  CHECK(dc_gw_F(3, INFINITY, &v) == DC_EDOM);
  CHECK(dc_gw_F(3, -1e101, &v) == DC_EDOM);
  CHECK(dc_gw_F(4, 0.0, &v) == DC_EDOM);
  CHECK(dc_gw_F_all(NAN, (double[4]){0}) == DC_EDOM);
}

/* dc_gw_F32_F12: the degree-9 pieces against the mpmath table (every row
   in their range) and against dc_gw_F_all densely (every piece, its ends
   and 40 points inside), dc_gw_F_all outside, the domain. */
static void f32_pieces(void)
{
  double worst_table = 0, worst_dense[2] = {0, 0};
  FILE *f = check_open_reference("gw_integrals.csv");
  if (f) {
    double row[3];
    int rows = 0;
    check_read_row(f, row, 3);
    while (check_read_row(f, row, 3) == 3) {
      const int order = (int)(2 * row[0] + 0.5);
      const double h = row[1];
      if (!(order == 1 || order == 3) || !(h >= DC_GW_F32P_LO && h < DC_GW_F32P_HI)) continue;
      double a, b;
      CHECK(dc_gw_F32_F12(h, &a, &b) == DC_OK);
      worst_table = fmax(worst_table, fabs((order == 3 ? a : b) / row[2] - 1));
      rows++;
    }
    fclose(f);
    CHECK(rows >= 60);
  }
  for (int p = 0; p < 104; p++)
    for (int k = 0; k <= 41; k++) {
      double h = DC_GW_F32P_LO + (p + k / 41.0) / 8.0;
      if (k == 41) h = nextafter(h, -INFINITY);   /* the piece's last double */
      if (h >= DC_GW_F32P_HI) continue;
      double a, b, Fa[4];
      CHECK(dc_gw_F32_F12(h, &a, &b) == DC_OK);
      CHECK(dc_gw_F_all(h, Fa) == DC_OK);
      worst_dense[0] = fmax(worst_dense[0], fabs(a / Fa[DC_GW_F32] - 1));
      worst_dense[1] = fmax(worst_dense[1], fabs(b / Fa[DC_GW_F12] - 1));
    }
  printf("dc_gw_F32_F12 on [%g, %g): vs mpmath %.2e; vs dc_gw_F_all F_3/2 %.2e, F_1/2 %.2e\n",
         DC_GW_F32P_LO, DC_GW_F32P_HI, worst_table, worst_dense[0], worst_dense[1]);
  /* coefficients 1.2e-16 (gen_gw_F32_poly.py) plus the evaluation's rounding;
     dc_gw_F_all is itself within 8e-16 of mpmath */
  CHECK_ABS(worst_table, 0.0, 4e-16, "dc_gw_F32_F12 vs mpmath");
  CHECK_ABS(worst_dense[0], 0.0, 1e-15, "dc_gw_F32_F12 F_3/2 vs dc_gw_F_all");
  CHECK_ABS(worst_dense[1], 0.0, 1e-15, "dc_gw_F32_F12 F_1/2 vs dc_gw_F_all");
  /* outside the pieces: dc_gw_F_all's bits; the domain */
  const double out[] = {-1e100, -10.000000000000002, 3.0, 7.5, 50.0};
  for (int k = 0; k < 5; k++) {
    double a, b, Fa[4];
    CHECK(dc_gw_F32_F12(out[k], &a, &b) == DC_OK && dc_gw_F_all(out[k], Fa) == DC_OK);
    CHECK(a == Fa[DC_GW_F32] && b == Fa[DC_GW_F12]);
  }
  double a = 7.0, b = 7.0;
  CHECK(dc_gw_F32_F12(NAN, &a, &b) == DC_EDOM && dc_gw_F32_F12(-1e101, &a, &b) == DC_EDOM && a == 7.0 && b == 7.0);
}

int main(void)
{
  table();
  f32_pieces();
  identities();
  limits();
  return check_summary("gw_integrals");
}
