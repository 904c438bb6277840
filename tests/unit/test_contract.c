/* The law contract's shared pieces (dc/contract.h), the damping laws
   (dc/damping.h), the contact's major axis (dc_form_major_axis) and the
   contract outputs of the normal laws (dc_hertz_normal, dc_gw_rough_normal). */
#include "check.h"
#include "dc/contract.h"
#include "dc/curvature.h"
#include "dc/damping.h"
#include "dc/gw_rough.h"
#include "dc/hertz_elliptic.h"
#include "dc/status.h"

int main(void)
{
  /* parameter checks: open and closed ends, non-finite values */
  dc_param_error err = {0, 0, 0};
  CHECK(dc_param_check("w", 0.0, 0.0, 0, HUGE_VAL, 1, "[0, inf)", &err) == DC_OK && err.name == 0);
  CHECK(dc_param_check("w", -1e-300, 0.0, 0, HUGE_VAL, 1, "[0, inf)", &err) == DC_EDOM && !strcmp(err.name, "w"));
  CHECK(dc_param_check("n", 0.0, 0.0, 1, HUGE_VAL, 1, "(0, inf)", &err) == DC_EDOM);
  CHECK(dc_param_check("mu", 50.0, 1.0, 0, 50.0, 0, "[1, 50]", &err) == DC_OK);
  CHECK(dc_param_check("mu", NAN, 1.0, 0, 50.0, 0, "[1, 50]", &err) == DC_EDOM);
  CHECK(dc_param_check("w", HUGE_VAL, 0.0, 0, HUGE_VAL, 0, "[0, inf]", &err) == DC_EDOM);
  char msg[128];
  dc_param_check("roughnessMu", 60.0, 1.0, 0, 50.0, 0, "[1, 50]", &err);
  dc_param_error_format(&err, 1, 2, msg, sizeof msg);
  CHECK(!strcmp(msg, "roughnessMu = 60 for types 1 and 2 is outside [1, 50]"));

  /* circular patch of a stock law; the history table has unique names */
  dc_patch p;
  dc_patch_circular(0.5e-3, 2e-6, 3.0, &p);
  CHECK_REL(p.a, sqrt(1e-9), 1e-15, "circular patch a = (R delta)^1/2");
  CHECK(p.a == p.b && p.axis[0] == 0 && p.F_bound == 3.0 && p.formed == 1.0);
  dc_patch_circular(0.5e-3, -1e-6, 0.0, &p);
  CHECK(p.a == 0.0 && p.formed == 0.0);
  CHECK(sizeof(dc_patch) == DC_PATCH_NFIELDS * sizeof(double));
  for (int i = 0; i < DC_PATCH_NFIELDS; i++)
    for (int j = i + 1; j < DC_PATCH_NFIELDS; j++) CHECK(strcmp(dc_patch_history[i].name, dc_patch_history[j].name));

  /* damping: beta of LIGGGHTS' hertz, punch stiffness (K(3/4) from mpmath) */
  double beta = 1;
  CHECK(dc_damping_beta(1.0, &beta) == DC_OK && beta == 0.0);
  CHECK(dc_damping_beta(0.5, &beta) == DC_OK);
  CHECK_REL(beta, log(0.5) / sqrt(log(0.5) * log(0.5) + M_PI * M_PI), 1e-15, "beta(e = 0.5)");
  CHECK(dc_damping_beta(0.0, &beta) == DC_EDOM && dc_damping_beta(1.5, &beta) == DC_EDOM);
  double k;
  CHECK(dc_punch_stiffness(2e9, 1e-4, 1e-4, &k) == DC_OK);
  CHECK_REL(k, 4e5, 1e-15, "punch stiffness of a circle 2 E* a");
  CHECK(dc_punch_stiffness(2e9, 1e-4, 0.5e-4, &k) == DC_OK);
  CHECK_REL(k, M_PI * 2e9 * 1e-4 / 2.1565156474996432354, 1e-14, "punch stiffness pi E* a / K(3/4)");
  CHECK(dc_punch_stiffness(2e9, 0.5e-4, 1e-4, &k) == DC_EDOM);
  CHECK_REL(dc_damping_restitution(-0.2, 100.0, 0.01), 2.0 * sqrt(5.0 / 6.0) * 0.2 * 1.0, 1e-15,
            "restitution damping -2 sqrt(5/6) beta (S m)^1/2");

  /* major axis: along the smaller curvature, zero for a circle */
  const double u[3] = {1, 0, 0}, v[3] = {0, 1, 0};
  double ax[3];
  const double f1[3] = {3.0, 0.0, 1.0};
  dc_form_major_axis(f1, u, v, ax);
  CHECK(fabs(ax[0]) < 1e-15 && fabs(fabs(ax[1]) - 1.0) < 1e-15);
  const double f2[3] = {2.0, 0.0, 2.0};
  dc_form_major_axis(f2, u, v, ax);
  CHECK(ax[0] == 0.0 && ax[1] == 0.0 && ax[2] == 0.0);
  /* the form diag(1, 3) turned by 30 degrees: smaller curvature at 30 degrees */
  const double c = cos(M_PI / 6), s = sin(M_PI / 6);
  const double f3[3] = {c * c + 3 * s * s, (1 - 3) * c * s, s * s + 3 * c * c};
  dc_form_major_axis(f3, u, v, ax);
  CHECK_REL(fabs(ax[0] * c + ax[1] * s), 1.0, 1e-15, "rotated form: major axis at 30 degrees");

  /* contract outputs */
  dc_hertz_geom g;
  CHECK(dc_hertz_geometry(2e-3, 0.5e-3, &g) == DC_OK);
  dc_hertz_state hs;
  dc_contact out;
  CHECK(dc_hertz_contact(&g, 1e9, 1e-6, &hs) == DC_OK && dc_hertz_normal(&g, 1e9, 1e-6, &out) == DC_OK);
  CHECK(out.F == hs.F && out.kn == hs.kn && out.a == hs.a && out.b == hs.b && out.area == hs.area);
  CHECK(out.F_bound == out.F && out.formed == 1 && out.a > out.b);
  CHECK(dc_hertz_normal(&g, 1e9, -1e-6, &out) == DC_OK && out.formed == 0 && out.F == 0.0 && out.a == 0.0);
  dc_contact keep = out;
  CHECK(dc_hertz_normal(&g, 1e9, NAN, &out) == DC_EDOM && !memcmp(&keep, &out, sizeof out));
  CHECK(dc_gw_rough_normal(&g, 1e9, -1e-7, 0.01, 5e3, &out) == DC_OK);
  CHECK(out.formed == 1 && out.F == 0.01 && out.a == 0.0 && out.F_bound == 0.01);
  CHECK(dc_gw_rough_normal(&g, 1e9, 1e-6, 2.0, 5e3, &out) == DC_OK && out.a == hs.a && out.F == 2.0);
  return check_summary("test_contract");
}
