/* dclaw gw_adhesion: the rough contact with adhesive (JKR) summits of the
   LIGGGHTS model `gw_rough gwElliptic on` + `cohesion gw_adhesion` along an
   approach-retraction path, as a DEM contact steps through it: the elastic
   GW closed form (dc/gw_rough.h) plus the tabulated adhesive part with its
   loading and unloading branches kept in the contact's history
   (dc/gw_rough_adhesive_table.h); circular summits of the relative radius
   R. Beside it the exact law (dc/gw_rough_adhesive.h, from the summits'
   JKR solutions) on the branch the table is on, where it is wholly on one. */
#include "cli.h"
#include "dc/gw_rough.h"
#include "dc/gw_rough_adhesive.h"
#include "dc/gw_rough_adhesive_table.h"
#include "dc/hertz_elliptic.h"
#include "dc/jkr_elliptic.h"
#include "dc/status.h"
#include <math.h>
#include <stdio.h>

static int cmd_gw_adhesion(int argc, char **argv)
{
  dc_cli_option o[] = {
    {"R", "relative radius of the contact [m] (circular summits)", 1e-3, 0},
    {"Estar", "effective modulus [Pa]", 1e9, 0},
    {"sigma", "combined rms summit height [m] (deck: surfaceRoughness)", 1e-7, 0},
    {"n_asp", "number of summits N A_n (deck: asperityCount)", 1e4, 0},
    {"w", "work of adhesion [J/m^2] (deck: workOfAdhesion)", 0.05, 0},
    {"delta_min", "overlap at the start and the end of the path [m] (negative: apart)", -1e-6, 0},
    {"delta_max", "deepest overlap of the path [m]", 5e-7, 0},
    {"n", DC_CLI_N_HELP " on each leg (approach, retraction)", 21, 0},
    {"steps", "table steps between printed rows (a DEM run's steps)", 10, 0},
    {0, 0, 0, 0}};
  int st = dc_cli_parse(argc, argv, o, "--R R --Estar E --sigma s --n_asp N --w w --delta_min d --delta_max d [--n N] [--steps S]");
  if (st) return st == 1 ? 0 : st;
  int n, steps;
  if (dc_cli_count(argv[0], o, "n", &n) || dc_cli_count(argv[0], o, "steps", &steps)) return 2;
  const double R = dc_cli_get(o, "R"), E = dc_cli_get(o, "Estar"), s = dc_cli_get(o, "sigma");
  const double N = dc_cli_get(o, "n_asp"), w = dc_cli_get(o, "w");
  const double d0 = dc_cli_get(o, "delta_min"), d1 = dc_cli_get(o, "delta_max");
  dc_param_error err;
  dc_gwa_table_pair p;
  if (dc_gwa_table_check(E, w, s, N, &err) != DC_OK || dc_gwa_table_pair_init(E, w, s, N, &p) != DC_OK) {
    fprintf(stderr, "dclaw gw_adhesion: --Estar, --w, --sigma, --n_asp: %s = %g is outside %s\n", err.name, err.value,
            err.range);
    return 2;
  }
  dc_hertz_geom g;
  dc_jkr_geom jg;
  if (!(R > 0.0) || dc_hertz_geometry(R, R, &g) != DC_OK || dc_jkr_geometry(R, R, E, w, &jg) != DC_OK) {
    fprintf(stderr, "dclaw gw_adhesion: --R: need R > 0 (got %g)\n", R);
    return 2;
  }
  if (!(d0 < d1)) {
    fprintf(stderr, "dclaw gw_adhesion: --delta_min, --delta_max: need delta_min < delta_max (got %g, %g)\n", d0, d1);
    return 2;
  }
  const char *cols = "leg,delta,force,force_adhesive,weight,force_exact,exact_branch";
  printf("%s\n", cols);
  double hist[2] = {0.0, 0.0}, at = d0;
  for (int leg = 0; leg < 2; leg++)
    for (int i = 0; i < n; i++) {
      const double target = dc_cli_range(leg ? d1 : d0, leg ? d0 : d1, i, n);
      dc_gwa_table_out a = {0.0, 0.0, 0.0};
      const int m = target == at ? 1 : steps;   /* the first row: one step at the start */
      st = DC_OK;
      for (int k = 1; k <= m && st == DC_OK; k++) st = dc_gwa_table_step(&p, R, at + (target - at) * k / m, hist, &a);
      if (st) {
        fprintf(stderr, "dclaw gw_adhesion: --delta_min, --delta_max, --R: %s at overlap %g\n", dc_status_str(st), target);
        return 2;
      }
      at = target;
      dc_gw_rough_state el;
      if ((st = dc_gw_rough_elliptic(&g, E, N, s, at, &el))) {
        fprintf(stderr, "dclaw gw_adhesion: --delta_min, --delta_max: %s at overlap %g\n", dc_status_str(st), at);
        return 2;
      }
      /* the exact law where the table is wholly on one branch (exact_branch
         0 loading, 1 unloading; -1 in the blend between them: force_exact 0) */
      double exact = 0.0;
      int has_exact = 0;
      if (a.weight == 0.0 || a.weight == 1.0) {
        dc_gw_adhesive_state ex;
        if (dc_gw_rough_adhesive(&jg, N, s, at, a.weight == 0.0 ? DC_GW_LOADING : DC_GW_UNLOADING, &ex) == DC_OK) {
          exact = ex.F;
          has_exact = 1;
        }
      }
      const double v[] = {leg, at, el.F + a.F, a.F, a.weight, exact, has_exact ? a.weight : -1.0};
      if (dc_cli_row("gw_adhesion", o, cols, 7, v)) return 2;
    }
  return 0;
}

DC_CLI_COMMAND(gw_adhesion, cmd_gw_adhesion,
               "rough contact with adhesive JKR summits (gw_rough + gw_adhesion): approach-retraction path -> force, "
               "adhesive part, branch weight, the exact law beside");
