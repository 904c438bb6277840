/* dclaw hertz_elliptic: relative radii (or two curvature pairs and the angle
   between their principal directions), E* and overlaps -> CSV. */
#include "cli.h"
#include "dc/curvature.h"
#include "dc/hertz_elliptic.h"
#include "dc/status.h"
#include <stdio.h>

int cmd_hertz_elliptic(int argc, char **argv)
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
    {"n", "number of overlaps in the range", 11, 0},
    {0, 0, 0, 0}};
  int st = dc_cli_parse(argc, argv, o,
      "(--R1 R --R2 R | --k1a k --k2a k --k1b k --k2b k --omega w) --Estar E (--delta d | --delta_min d --delta_max d --n N)");
  if (st) return st == 1 ? 0 : st;

  double R1 = dc_cli_get(o, "R1"), R2 = dc_cli_get(o, "R2");
  if (dc_cli_given(o, "k1a")) {
    st = dc_relative_radii(dc_cli_get(o, "k1a"), dc_cli_get(o, "k2a"), dc_cli_get(o, "k1b"),
                           dc_cli_get(o, "k2b"), dc_cli_get(o, "omega"), &R1, &R2);
    if (st) { fprintf(stderr, "dclaw hertz_elliptic: curvatures: %s (the smaller relative curvature must be > 0)\n", dc_status_str(st)); return 2; }
  }
  dc_hertz_geom g;
  st = dc_hertz_geometry(R1, R2, &g);
  if (st) {
    fprintf(stderr, "dclaw hertz_elliptic: R1, R2: %s (need R > 0 and R_minor/R_major >= %g)\n", dc_status_str(st), DC_HERTZ_RATIO_MIN);
    return 2;
  }
  int n = 1;
  double d0 = dc_cli_get(o, "delta"), d1 = d0;
  if (dc_cli_given(o, "delta_max")) {
    d0 = dc_cli_get(o, "delta_min"); d1 = dc_cli_get(o, "delta_max"); n = (int)dc_cli_get(o, "n");
    if (n < 1) { fprintf(stderr, "dclaw hertz_elliptic: --n must be >= 1\n"); return 2; }
  }
  printf("R_major,R_minor,Rc,e2,gamma,beta,delta,a,b,force,area,stiffness\n");
  for (int i = 0; i < n; i++) {
    const double d = n == 1 ? d0 : d0 + (d1 - d0) * i / (n - 1);
    dc_hertz_state s;
    st = dc_hertz_contact(&g, dc_cli_get(o, "Estar"), d, &s);
    if (st) { fprintf(stderr, "dclaw hertz_elliptic: Estar, delta: %s (need Estar > 0, delta >= 0)\n", dc_status_str(st)); return 2; }
    printf("%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n",
           g.R_major, g.R_minor, g.Rc, g.e2, g.gamma, g.beta, d, s.a, s.b, s.F, s.area, s.kn);
  }
  return 0;
}
