/* K, E, D, B, C against the mpmath table (tests/reference/ellint.csv). */
#include "check.h"
#include "dc/elliptic_integrals.h"
#include "dc/status.h"
#include <string.h>

int main(void)
{
  FILE *f = check_open_reference("ellint.csv");
  if (!f) return check_summary("elliptic_integrals");
  char line[512];
  int rows = 0;
  while (fgets(line, sizeof line, f)) {
    if (line[0] == '#') continue;
    char kind[4];
    double x, K, E, D, B, C;
    if (sscanf(line, "%3[^,],%lf,%lf,%lf,%lf,%lf,%lf", kind, &x, &K, &E, &D, &B, &C) != 7) continue;
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
