/* dclaw gw_rough: GW rough normal force of two bodies versus overlap, CSV:
   the elliptic closed form (review Eqs. 29-36, on the hertz_elliptic
   geometry) and, for the sphere-equivalent radius, the Feng et al. explicit
   law (Feng Eq. 75) in its table and fitted variants and the law tabulated
   from the full GW solver (dc/gw_rough_table.h); with --w > 0 also the
   GW force with adhesive JKR summits on loading and unloading
   (dc/gw_rough_adhesive.h); with --H > 0 also the GW force of
   elastic-plastic summits (dc/gw_rough_plastic.h, the deck's gwPlastic on). */
#include "cli.h"
#include "dc/feng_rough.h"
#include "dc/gw_rough.h"
#include "dc/gw_rough_adhesive.h"
#include "dc/gw_rough_plastic.h"
#include "dc/gw_rough_table.h"
#include "dc/hertz_elliptic.h"
#include "dc/status.h"
#include <math.h>
#include <stdio.h>

#define COLUMNS "delta,h,force_gw_elliptic,area_gw_elliptic,kn_gw_elliptic,force_feng_table,kn_feng_table,force_feng_fitted,kn_feng_fitted,force_gw_table,kn_gw_table"

/* Runs the subcommand; argv[0] is the law name. */
static int cmd_gw_rough(int argc, char **argv)
{
  dc_cli_option o[] = {
    {"R1", "relative principal radius 1 [m]", 1e-3, 0},
    {"R2", "relative principal radius 2 [m]", 1e-3, 0},
    {"Estar", "effective modulus [Pa]", 1e9, 0},
    {"sigma", "combined rms summit height [m]", 1e-6, 0},
    {"n_asp", "number of summits N A_n (elliptic closed form)", 1, 0},
    {"mu", "Feng roughness parameter mu = 8/3 sigma N sqrt(2 R beta), in [1, 50]", 4, 0},
    {"delta_min", "first overlap [m] (negative: separated)", -3e-6, 0},
    {"delta_max", "last overlap [m]", 1e-5, 0},
    {"n", DC_CLI_N_HELP, 14, 0},
    {"w", "work of adhesion [J/m^2]; > 0 adds the adhesive (JKR summit) GW force, loading and unloading", 0, 0},
    {"H", "hardness of the softer body [Pa]; > 0 adds the GW force of elastic-plastic summits (deck: gwPlastic on)", 0, 0},
    {"nu", "Poisson's ratio of the softer body, for the plastic summits' default plasticityKv", 0.3, 0},
    {0, 0, 0, 0}};
  int st = dc_cli_parse(argc, argv, o,
                        "--R1 R --R2 R --Estar E --sigma s --n_asp N --mu mu --delta_min d --delta_max d --n N [--w w] [--H H --nu nu]");
  if (st) return st == 1 ? 0 : st;
  int n;
  if (dc_cli_count(argv[0], o, "n", &n)) return 2;
  dc_hertz_geom g;
  if ((st = dc_hertz_geometry(dc_cli_get(o, "R1"), dc_cli_get(o, "R2"), &g))) {
    fprintf(stderr, "dclaw gw_rough: --R1, --R2: %s (need radii > 0 with ratio >= %g)\n", dc_status_str(st), DC_HERTZ_RATIO_MIN);
    return 2;
  }
  dc_feng_law Lt, Lf;
  dc_gw_table_law Lg;
  if (dc_feng_init(dc_cli_get(o, "mu"), DC_FENG_TABLE, &Lt) || dc_feng_init(dc_cli_get(o, "mu"), DC_FENG_FITTED, &Lf) ||
      dc_gw_table_init(dc_cli_get(o, "mu"), &Lg)) {
    fprintf(stderr, "dclaw gw_rough: --mu must lie in [%g, %g]\n", DC_FENG_MU_MIN, DC_FENG_MU_MAX);
    return 2;
  }
  const double E = dc_cli_get(o, "Estar"), s = dc_cli_get(o, "sigma"), N = dc_cli_get(o, "n_asp");
  const double d0 = dc_cli_get(o, "delta_min"), d1 = dc_cli_get(o, "delta_max");
  /* Feng's law is for spheres: use the radius of the Hertz force, Rc gamma^2 */
  const double R = g.R_force;
  const double w = dc_cli_get(o, "w");
  dc_jkr_geom jg;
  if (!(w >= 0) || (w > 0 && (st = dc_jkr_geometry(dc_cli_get(o, "R1"), dc_cli_get(o, "R2"), E, w, &jg)))) {
    fprintf(stderr, "dclaw gw_rough: --w, --R1, --R2, --Estar: %s (need w >= 0, ratio >= %g, Estar > 0)\n",
            dc_status_str(w >= 0 ? st : DC_EDOM), DC_JKR_RATIO_MIN);
    return 2;
  }
  const double H = dc_cli_get(o, "H");
  dc_gw_plastic_params pp = dc_gw_plastic_default_params(H, dc_cli_get(o, "nu"));
  dc_param_error perr;
  const double nu = dc_cli_get(o, "nu");
  if (H != 0.0 && !(nu >= -1.0 && nu <= 0.5)) {
    fprintf(stderr, "dclaw gw_rough: --nu: %g is outside [-1, 0.5]\n", nu);
    return 2;
  }
  if (H != 0.0 && dc_gw_plastic_check(&pp, &perr) != DC_OK) {
    fprintf(stderr, "dclaw gw_rough: --H, --nu: %s = %g is outside %s\n", perr.name, perr.value, perr.range);
    return 2;
  }
  char cols[512];
  snprintf(cols, sizeof cols, "%s%s%s", COLUMNS,
           w > 0 ? ",force_adhesive_loading,area_adhesive_loading,force_adhesive_unloading,area_adhesive_unloading" : "",
           H > 0 ? ",force_gw_plastic,area_gw_plastic,kn_gw_plastic" : "");
  printf("%s\n", cols);
  for (int i = 0; i < n; i++) {
    const double d = dc_cli_range(d0, d1, i, n);
    dc_gw_rough_state rs;
    dc_gw_adhesive_state al = {0}, au = {0};
    double pt, kt, pf, kf, pg, kg;
    if ((st = dc_gw_rough_elliptic(&g, E, N, s, d, &rs)) || (st = dc_feng_force(&Lt, E, R, s, d, &pt, &kt)) ||
        (st = dc_feng_force(&Lf, E, R, s, d, &pf, &kf)) || (st = dc_gw_table_force(&Lg, E, R, s, d, &pg, &kg)) ||
        (w > 0 && ((st = dc_gw_rough_adhesive(&jg, N, s, d, DC_GW_LOADING, &al)) ||
                   (st = dc_gw_rough_adhesive(&jg, N, s, d, DC_GW_UNLOADING, &au))))) {
      fprintf(stderr, "dclaw gw_rough: --Estar, --sigma, --n_asp, --delta_min, --delta_max%s: %s at delta %g (need Estar > 0, sigma >= 0, n_asp > 0)\n",
              w > 0 ? ", --w" : "", dc_status_str(st), d);
      return 2;
    }
    dc_gw_rough_state ps = {0};
    if (H > 0 && (st = dc_gw_rough_plastic(&g, E, &pp, N, s, d, &ps))) {
      fprintf(stderr, "dclaw gw_rough: --H, --Estar, --sigma, --n_asp: %s at delta %g\n", dc_status_str(st), d);
      return 2;
    }
    double v[18] = {d, rs.h, rs.F, rs.area, rs.kn, pt, kt, pf, kf, pg, kg};
    int nv = 11;
    if (w > 0) {
      v[nv++] = al.F; v[nv++] = al.area; v[nv++] = au.F; v[nv++] = au.area;
    }
    if (H > 0) {
      v[nv++] = ps.F; v[nv++] = ps.area; v[nv++] = ps.kn;
    }
    if (dc_cli_row("gw_rough", o, cols, nv, v)) return 2;
  }
  return 0;
}

DC_CLI_COMMAND(gw_rough, cmd_gw_rough,
               "GW rough contact: radii, E*, sigma, n_asp, mu, overlaps -> elliptic closed-form and Feng-law force, area, stiffness");
