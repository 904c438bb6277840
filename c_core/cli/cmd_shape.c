/* dclaw shape: the force error of the one-radius (volume-equivalent
   sphere) Hertz model on a superquadric against elliptic Hertz, sampled
   over its surface (dc_scene_shape_error, dc/scene.h). One CSV row. */
#include "cli.h"
#include "dc/scene.h"
#include "dc/status.h"
#include <stdio.h>

static int cmd_shape(int argc, char **argv)
{
  dc_cli_option o[] = {
    {"a", "semi-axis along x [m] (deck: shape)", 1e-3, 0},
    {"b", "semi-axis along y [m]", 1e-3, 0},
    {"c", "semi-axis along z [m]", 1e-3, 0},
    {"n1", "blockiness n1 in [2, 1000] (deck: blockiness)", 2, 0},
    {"n2", "blockiness n2 in [2, 1000]", 2, 0},
    {"m", "sample grid m x m on an octant, an integer from 2 to 64", 12, 0},
    {"cap", "principal radii capped at cap x R_eq, in [1, 1e6] (LIGGGHTS: curvatureLimitFactor)", 100, 0},
    {0, 0, 0, 0}};
  int st = dc_cli_parse(argc, argv, o, "--a a --b b --c c --n1 n --n2 n [--m M] [--cap C]");
  if (st) return st == 1 ? 0 : st;
  const char *const ints[] = {"m"};
  if (dc_cli_whole(argv[0], o, ints, 1)) return 2;
  const double shape[3] = {dc_cli_get(o, "a"), dc_cli_get(o, "b"), dc_cli_get(o, "c")};
  const double bl[2] = {dc_cli_get(o, "n1"), dc_cli_get(o, "n2")};
  dc_scene_shape s;
  st = dc_scene_shape_error(shape, bl, (int)dc_cli_get(o, "m"), dc_cli_get(o, "cap"), &s);
  if (st) {
    fprintf(stderr, "dclaw shape: --a, --b, --c, --n1, --n2, --m, --cap: %s (semi-axes > 0, blockiness in [2, 1000], "
                    "m from 2 to 64, cap in [1, 1e6])\n", dc_status_str(st));
    return 2;
  }
  const char *cols = "R_eq,err_pair_max,err_pair_rms,err_wall_max,err_wall_rms,R_body_min,R_body_max";
  printf("%s\n", cols);
  const double row[] = {s.R_eq, s.err_pair_max, s.err_pair_rms, s.err_wall_max, s.err_wall_rms, s.R_body_min,
                        s.R_body_max};
  return dc_cli_row("shape", o, cols, 7, row);
}

DC_CLI_COMMAND(shape, cmd_shape,
               "superquadric: force error of the volume-equivalent-sphere Hertz model against elliptic Hertz over "
               "its surface, pairs and on a wall");
