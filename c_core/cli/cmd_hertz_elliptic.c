/* dclaw hertz_elliptic: relative radii (or two curvature pairs and the angle
   between their principal directions), E* and overlaps -> CSV. */
#include "cli.h"
#include "dc/curvature.h"
#include "dc/hertz_elliptic.h"
#include "dc/status.h"
#include <stdio.h>

/* Runs the subcommand; argv[0] is the law name. */
static int cmd_hertz_elliptic(int argc, char **argv)
{
  dc_cli_option o[] = {
    {"R1", "relative principal radius 1 [m]", 0, 0},
    {"R2", "relative principal radius 2 [m]", 0, 0},
    {"k1a", "body I principal curvature 1 [1/m] (instead of R1, R2)", 0, 0},
    {"k2a", "body I principal curvature 2 [1/m]", 0, 0},
    {"k1b", "body II principal curvature 1 [1/m]", 0, 0},
    {"k2b", "body II principal curvature 2 [1/m]", 0, 0},
    {"omega", "angle between the k1 directions [rad]", 0, 0},
    {"Estar", "effective modulus 1/sum((1-nu^2)/E) [Pa]", 1e9, 0},
    {"delta", "overlap [m] (or a range with delta_min, delta_max, n)", 0, 0},
    {"delta_min", "first overlap of a range [m]", 0, 0},
    {"delta_max", "last overlap of a range [m]", 0, 0},
    {"n", DC_CLI_N_HELP " in the range", 11, 0},
    {0, 0, 0, 0}};
  int st = dc_cli_parse(argc, argv, o,
      "(--R1 R --R2 R | --k1a k --k2a k --k1b k --k2b k --omega w) --Estar E (--delta d | --delta_min d --delta_max d --n N)");
  if (st) return st == 1 ? 0 : st;
  int n;
  if (dc_cli_count(argv[0], o, "n", &n)) return 2;

  const int curv = dc_cli_given(o, "k1a");
  const char *radii = curv ? "--k1a, --k2a, --k1b, --k2b, --omega" : "--R1, --R2";
  double R1 = dc_cli_get(o, "R1"), R2 = dc_cli_get(o, "R2");
  if (curv) {
    st = dc_relative_radii(dc_cli_get(o, "k1a"), dc_cli_get(o, "k2a"), dc_cli_get(o, "k1b"),
                           dc_cli_get(o, "k2b"), dc_cli_get(o, "omega"), &R1, &R2);
    if (st) { fprintf(stderr, "dclaw hertz_elliptic: %s: %s (the smaller relative curvature must be > 0)\n", radii, dc_status_str(st)); return 2; }
  }
  dc_hertz_geom g;
  st = dc_hertz_geometry(R1, R2, &g);
  if (st) {
    fprintf(stderr, "dclaw hertz_elliptic: %s: %s (need R > 0 and R_minor/R_major >= %g)\n", radii, dc_status_str(st), DC_HERTZ_RATIO_MIN);
    return 2;
  }
  const int range = dc_cli_given(o, "delta_max");
  const double d0 = dc_cli_get(o, range ? "delta_min" : "delta"), d1 = range ? dc_cli_get(o, "delta_max") : d0;
  if (!range) n = 1;
  const char *cols = "R_major,R_minor,Rc,e2,gamma,beta,delta,a,b,force,area,stiffness";
  printf("%s\n", cols);
  for (int i = 0; i < n; i++) {
    const double d = dc_cli_range(d0, d1, i, n);
    dc_hertz_state s;
    st = dc_hertz_contact(&g, dc_cli_get(o, "Estar"), d, &s);
    if (st) {
      fprintf(stderr, "dclaw hertz_elliptic: --Estar, %s: %s at delta %g (need Estar > 0, delta >= 0)\n",
              range ? "--delta_min, --delta_max" : "--delta", dc_status_str(st), d);
      return 2;
    }
    const double v[] = {g.R_major, g.R_minor, g.Rc, g.e2, g.gamma, g.beta, d, s.a, s.b, s.F, s.area, s.kn};
    if (dc_cli_row("hertz_elliptic", o, cols, 12, v)) return 2;
  }
  return 0;
}

DC_CLI_COMMAND(hertz_elliptic, cmd_hertz_elliptic,
               "elliptic Hertz: radii or curvatures, E*, overlaps -> e^2, gamma, beta, semi-axes, force, area, stiffness");
