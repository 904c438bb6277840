/* dclaw jkr_elliptic: adhesive elliptic contact (Johnson-Greenwood JKR,
   classical JKR for R1 = R2) -> CSV of the stable branch for a range of
   overlaps, or (--summary 1) one row with the pull-off force and the
   separation overlap. */
#include "cli.h"
#include "dc/jkr_elliptic.h"
#include "dc/status.h"
#include <stdio.h>

/* Runs the subcommand; argv[0] is the law name. */
static int cmd_jkr_elliptic(int argc, char **argv)
{
  dc_cli_option o[] = {
    {"R1", "relative principal radius 1 [m]", 1e-3, 0},
    {"R2", "relative principal radius 2 [m]", 1e-3, 0},
    {"Estar", "effective modulus 1/sum((1-nu^2)/E) [Pa]", 1e9, 0},
    {"w", "work of adhesion [J/m^2]", 0.05, 0},
    {"delta_min", "first overlap [m] (default: the separation overlap)", 0, 0},
    {"delta_max", "last overlap [m] (default: -10 x the separation overlap)", 0, 0},
    {"n", DC_CLI_N_HELP, 21, 0},
    {"summary", "1: print pull-off force and separation overlap only", 0, 0},
    {0, 0, 0, 0}};
  int st = dc_cli_parse(argc, argv, o,
      "--R1 R --R2 R --Estar E --w W [--delta_min d --delta_max d --n N] [--summary 1]");
  if (st) return st == 1 ? 0 : st;
  int n;
  if (dc_cli_count(argv[0], o, "n", &n)) return 2;
  dc_jkr_geom g;
  st = dc_jkr_geometry(dc_cli_get(o, "R1"), dc_cli_get(o, "R2"), dc_cli_get(o, "Estar"),
                       dc_cli_get(o, "w"), &g);
  if (st) {
    fprintf(stderr, "dclaw jkr_elliptic: --R1, --R2, --Estar, --w: %s (need R > 0, R_minor/R_major >= %g, Estar > 0, w >= 0)\n",
            dc_status_str(st), DC_JKR_RATIO_MIN);
    return 2;
  }
  if (dc_cli_get(o, "summary") != 0.0) {
    const char *cols = "R_major,R_minor,Rhat,e2_hertz,pulloff_force,delta_pull,e2_pull,F_break,delta_break,e2_break";
    printf("%s\n", cols);
    const double v[] = {g.R_major, g.R_minor, g.Rhat, g.e2_hertz, -g.F_pull, g.delta_pull, g.e2_pull,
                        g.F_break, g.delta_break, g.e2_break};
    return dc_cli_row("jkr_elliptic", o, cols, 10, v);
  }
  const double d0 = dc_cli_given(o, "delta_min") ? dc_cli_get(o, "delta_min") : g.delta_break;
  const double d1 = dc_cli_given(o, "delta_max") ? dc_cli_get(o, "delta_max")
                    : (g.delta_break < 0.0 ? -10.0 * g.delta_break : 1e-6 * g.Rhat);
  const char *cols = "delta,contact,force,area,a,b,e2,stiffness";
  printf("%s\n", cols);
  dc_jkr_hint hint = {0};
  for (int i = 0; i < n; i++) {
    const double d = dc_cli_range(d0, d1, i, n);
    dc_jkr_state s;
    st = dc_jkr_contact(&g, d, &hint, &s);
    if (st) {
      fprintf(stderr, "dclaw jkr_elliptic: --delta_min, --delta_max, --R1, --R2, --Estar, --w: %s at delta %g\n", dc_status_str(st), d);
      return 2;
    }
    const double v[] = {d, s.contact, s.F, s.area, s.a, s.b, s.e2, s.kn};
    if (dc_cli_row("jkr_elliptic", o, cols, 8, v)) return 2;
  }
  return 0;
}

DC_CLI_COMMAND(jkr_elliptic, cmd_jkr_elliptic,
               "adhesive elliptic JKR (Johnson-Greenwood; classical JKR for R1 = R2): overlaps -> force, area, semi-axes; --summary 1: pull-off force, separation overlap");
