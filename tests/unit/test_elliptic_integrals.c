/* K, E, D, B, C against the mpmath tables (tests/reference/ellint.csv, and
   ellint_dense.csv: m over [0, 1), m1 down to 1e-300, both sides of every
   polynomial piece edge), and Legendre's relation on a dense sweep. */
#include "check.h"
#include "dc/elliptic_integrals.h"
#include "dc/status.h"
#include <string.h>

int main(void)
{
  FILE *f = check_open_reference("ellint.csv");
  if (!f) return check_summary("elliptic_integrals");
  int rows = 0;
  char kind[4];
  double row[6];
  while (check_read_tagged_row(f, kind, sizeof kind, row, 6) == 6) {
    const double x = row[0], K = row[1], E = row[2], D = row[3], B = row[4], C = row[5];
    dc_ellint el;
    int st = strcmp(kind, "m") == 0 ? dc_ellint_m(x, &el) : dc_ellint_m1(x, &el);
    CHECK(st == DC_OK);
    char what[64];
    /* ~10 ulp */
    snprintf(what, sizeof what, "K(%s=%g)", kind, x); CHECK_REL(el.K, K, 2e-15, what);
    snprintf(what, sizeof what, "E(%s=%g)", kind, x); CHECK_REL(el.E, E, 2e-15, what);
    snprintf(what, sizeof what, "D(%s=%g)", kind, x); CHECK_REL(el.D, D, 2e-15, what);
    snprintf(what, sizeof what, "B(%s=%g)", kind, x); CHECK_REL(el.B, B, 2e-15, what);
    snprintf(what, sizeof what, "C(%s=%g)", kind, x); CHECK_REL(el.C, C, 2e-15, what);
    rows++;
  }
  fclose(f);
  CHECK(rows >= 20);

  /* dense table: same tolerance, worst error of each integral printed */
  f = check_open_reference("ellint_dense.csv");
  if (!f) return check_summary("elliptic_integrals");
  const char *names[5] = {"K", "E", "D", "B", "C"};
  double worst[5] = {0, 0, 0, 0, 0};
  int dense = 0;
  while (check_read_tagged_row(f, kind, sizeof kind, row, 6) == 6) {
    const double x = row[0], *want = row + 1;
    dc_ellint el;
    CHECK((strcmp(kind, "m") == 0 ? dc_ellint_m(x, &el) : dc_ellint_m1(x, &el)) == DC_OK);
    const double got[5] = {el.K, el.E, el.D, el.B, el.C};
    for (int j = 0; j < 5; j++) {
      char what[64];
      snprintf(what, sizeof what, "%s(%s=%.17g)", names[j], kind, x);
      CHECK_REL(got[j], want[j], 2e-15, what);
      const double err = fabs(got[j] - want[j]) / want[j];
      if (!(err <= worst[j])) worst[j] = err;
    }
    dense++;
  }
  fclose(f);
  CHECK(dense >= 400);
  printf("dense table (%d rows): worst rel. error K %.3g E %.3g D %.3g B %.3g C %.3g\n",
         dense, worst[0], worst[1], worst[2], worst[3], worst[4]);

  /* Legendre's relation E K' + E' K - K K' = pi/2 (A-S 17.3.13), with primes
     at parameter 1 - m. By K = B + D, E - (1 - m) K = m B it reads
     E B' + m B D' = pi/2, a sum of positive terms. dc_ellint_m1(m) gives the
     primed integrals at exactly 1 - m, so this covers both entries. */
  double worst_leg = 0.0;
  for (int i = 0; i <= 20000; i++) {
    const double m = i < 10000 ? (i + 0.5) / 10000.0 : pow(10.0, -300.0 * (i - 9999) / 10001.0);
    dc_ellint a, b;
    dc_ellint_m(m, &a);
    dc_ellint_m1(m, &b);
    const double err = fabs((a.E * b.B + m * a.B * b.D) / (0.5 * M_PI) - 1.0);
    if (!(err <= worst_leg)) worst_leg = err;
  }
  printf("Legendre's relation over m in (0, 1) and m down to 1e-300: worst rel. error %.3g\n", worst_leg);
  CHECK(worst_leg < 1e-15);

  /* domain edges: a status, never NaN */
  dc_ellint el;
  CHECK(dc_ellint_m(1.0, &el) == DC_EDOM);
  CHECK(dc_ellint_m(-1e-300, &el) == DC_EDOM);
  CHECK(dc_ellint_m(0.0 / 0.0, &el) == DC_EDOM);
  CHECK(dc_ellint_m1(0.0, &el) == DC_EDOM);
  CHECK(dc_ellint_m1(1.5, &el) == DC_EDOM);
  /* finite everywhere on a dense sweep of the domain */
  int finite = 1;
  for (int i = 0; i <= 2000; i++) {
    dc_ellint a, b;
    dc_ellint_m(i / 2001.0, &a);
    dc_ellint_m1(pow(10.0, -300.0 * i / 2000.0), &b);
    finite &= isfinite(a.K) && isfinite(a.E) && isfinite(a.D) && isfinite(a.B) && isfinite(a.C);
    finite &= isfinite(b.K) && isfinite(b.E) && isfinite(b.D) && isfinite(b.B) && isfinite(b.C);
  }
  CHECK(finite);
  return check_summary("elliptic_integrals");
}
