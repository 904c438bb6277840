/* The summits' patch of the rough tangential law (dc_rough_tangential_axes,
   review Eqs. 80-84): semi-axes and Mindlin's no-slip stiffnesses
   (dc_cmd_stiffness) against the mpmath quadrature of Eq. 82
   (tests/reference/rough_tangential.csv, h from -3 to 6) within 1e-10;
   the smooth limit (the Hertz ellipse, bit for bit); before touch; the
   step of cmd_tangential on the patch; domain. */
#include "check.h"
#include "dc/cmd_tangential.h"
#include "dc/hertz_elliptic.h"
#include "dc/mindlin.h"
#include "dc/rough_tangential.h"
#include "dc/status.h"
#include <math.h>
#include <string.h>

int main(void)
{
  FILE *f = check_open_reference("rough_tangential.csv");
  double r[13], worst_a = 0.0, worst_k = 0.0;
  int rows = 0;
  if (f) {
    check_read_row(f, r, 13);   /* column names */
    while (check_read_row(f, r, 13) == 13) {
      dc_hertz_geom g;
      dc_mindlin_pair m;
      double a, b, km, kn;
      const double sigma = r[7], delta = -r[8] * sigma;
      CHECK(dc_hertz_geometry(r[0], r[1], &g) == DC_OK);
      CHECK(dc_mindlin_pair_init(r[2], r[3], r[4], r[5], &m) == DC_OK);
      CHECK(dc_rough_tangential_axes(&g, r[6], sigma, delta, &a, &b) == DC_OK);
      CHECK(dc_cmd_stiffness(&m, a, b, &km, &kn) == DC_OK);
      worst_a = fmax(worst_a, fmax(fabs(a / r[9] - 1), fabs(b / r[10] - 1)));
      worst_k = fmax(worst_k, fmax(fabs(km / r[11] - 1), fabs(kn / r[12] - 1)));
      rows++;
    }
    fclose(f);
  }
  printf("summits' patch against the quadrature of Eq. 82: %d rows, worst semi-axis %.3g, stiffness %.3g\n", rows,
         worst_a, worst_k);
  CHECK(rows == 148);
  CHECK(worst_a < 1e-10);
  CHECK(worst_k < 1e-10);

  /* smooth limit: sigma = 0 and sigma <= 1e-80 delta give dc_hertz_contact's
     ellipse bit for bit (n_asp = 1), n_asp times it otherwise; sigma = 1e-9
     delta within 1e-15 (sigma^1/2 F_1/2(h) = delta^1/2 (1 - sigma^2/(8 delta^2) + ...)) */
  const double radii[][2] = {{1e-3, 1e-3}, {2e-3, 5e-4}, {1.0, 1e-4}};
  for (int c = 0; c < 3; c++) {
    dc_hertz_geom g;
    dc_hertz_state hs;
    double a, b;
    CHECK(dc_hertz_geometry(radii[c][0], radii[c][1], &g) == DC_OK);
    const double delta = 1e-6 * radii[c][1];
    CHECK(dc_hertz_contact(&g, 1e9, delta, &hs) == DC_OK);
    CHECK(dc_rough_tangential_axes(&g, 1.0, 0.0, delta, &a, &b) == DC_OK);
    CHECK(a == hs.a && b == hs.b);
    CHECK(dc_rough_tangential_axes(&g, 1.0, 1e-81 * delta, delta, &a, &b) == DC_OK);
    CHECK(a == hs.a && b == hs.b);
    CHECK(dc_rough_tangential_axes(&g, 3.0, 0.0, delta, &a, &b) == DC_OK);
    CHECK_REL(a, 3.0 * hs.a, 1e-15, "sigma = 0: n_asp times the Hertz semi-axis");
    CHECK(dc_rough_tangential_axes(&g, 1.0, 1e-9 * delta, delta, &a, &b) == DC_OK);
    CHECK_REL(a, hs.a, 1e-15, "sigma -> 0: the Hertz semi-axis");
    CHECK_REL(b, hs.b, 1e-15, "sigma -> 0: the Hertz minor semi-axis");
    /* before touch the summits carry a patch; without roughness none */
    CHECK(dc_rough_tangential_axes(&g, 1.0, 1e-6 * radii[c][1], -delta, &a, &b) == DC_OK);
    CHECK(a > 0.0 && b > 0.0 && b <= a);
    CHECK(dc_rough_tangential_axes(&g, 1.0, 0.0, -delta, &a, &b) == DC_OK);
    CHECK(a == 0.0 && b == 0.0);
    CHECK(dc_rough_tangential_axes(&g, 1.0, 0.0, 0.0, &a, &b) == DC_OK);
    CHECK(a == 0.0 && b == 0.0);
    /* monotonic in delta; far apart (h = 50) F_1/2 underflows: no patch */
    double prev = 0.0;
    int mono = 1;
    for (int k = 0; k <= 400; k++) {
      const double s = 1e-6 * radii[c][1], d = s * (-12.0 + 0.1 * k);
      CHECK(dc_rough_tangential_axes(&g, 1.0, s, d, &a, &b) == DC_OK);
      mono &= a >= prev;
      prev = a;
    }
    CHECK(mono);
    CHECK(dc_rough_tangential_axes(&g, 1.0, 1e-9, -5e-8, &a, &b) == DC_OK && a == 0.0);
  }

  /* cmd_tangential on the summits' patch at sigma = 0 is cmd_tangential on
     the Hertz patch (the same patch); before touch it acts with the
     summits' stiffness: a small step's force is k_major du */
  {
    dc_hertz_geom g;
    dc_mindlin_pair m;
    double a, b, km, kn;
    CHECK(dc_hertz_geometry(1e-3, 1e-3, &g) == DC_OK);
    CHECK(dc_mindlin_pair_init(5e6, 0.3, 5e6, 0.3, &m) == DC_OK);
    CHECK(dc_rough_tangential_axes(&g, 1.0, 1e-6, -1e-6, &a, &b) == DC_OK);
    CHECK(dc_cmd_stiffness(&m, a, b, &km, &kn) == DC_OK);
    const dc_cmd_params p = {0.5, 0.0, 0, 0};
    const dc_patch pa = {a, b, {0.0, 0.0, 0.0}, 1e-5, 1e-5, 1.0};
    dc_cmd_state h;
    dc_cmd_out o;
    memset(&h, 0, sizeof h);
    const double n[3] = {0.0, 0.0, 1.0}, du[3] = {1e-12, 0.0, 0.0};
    CHECK(dc_cmd_step(&p, &m, &pa, n, du, 0.0, 1.0, &h, &o) == DC_OK);
    CHECK_REL(o.Ft[0], km * 1e-12, 1e-6, "before touch: the summits' no-slip stiffness");
  }

  /* domain and range */
  {
    dc_hertz_geom g;
    double a = 7.0, b = 7.0;
    dc_hertz_geometry(1e-3, 1e-3, &g);
    CHECK(dc_rough_tangential_axes(&g, 0.0, 1e-6, 1e-6, &a, &b) == DC_EDOM);
    CHECK(dc_rough_tangential_axes(&g, 1.0, -1e-6, 1e-6, &a, &b) == DC_EDOM);
    CHECK(dc_rough_tangential_axes(&g, 1.0, 1e-6, NAN, &a, &b) == DC_EDOM);
    CHECK(dc_rough_tangential_axes(&g, INFINITY, 1e-6, 1e-6, &a, &b) == DC_EDOM);
    CHECK(dc_rough_tangential_axes(&g, 1e300, 1e300, 1e300, &a, &b) == DC_ERANGE);
    CHECK(a == 7.0 && b == 7.0);
    /* an intermediate product beyond the doubles, the result inside */
    CHECK(dc_rough_tangential_axes(&g, 1e-200, 1e300, 1e300, &a, &b) == DC_OK && isfinite(a) && a > 0.0);
  }
  return check_summary("rough_tangential");
}
