/* dclaw kalker: Kalker's creep force and spin moment of a rolling contact
   (review Eqs. 86-88, with the Vermeulen-Johnson saturation of Eqs. 92-93
   or Kalker's linear law bounded by mu F_b): longitudinal creepages from
   --xi_min to --xi_max at the given lateral and spin creepages -> force
   along and across the rolling direction, spin moment, saturation and the
   coefficients c_ij used. */
#include "cli.h"
#include "dc/mindlin.h"
#include "dc/rolling_kalker.h"
#include "dc/status.h"
#include <math.h>
#include <stdio.h>

static int cmd_kalker(int argc, char **argv)
{
  dc_cli_option o[] = {
    {"a", "patch semi-axis a (the major one) [m]", 1e-3, 0},
    {"b", "patch semi-axis b <= a [m]", 1e-3, 0},
    {"alpha", "angle of the rolling direction from the major axis [deg]", 0, 0},
    {"E", "Young's modulus of both bodies [Pa] (deck: youngsModulus)", 2.1e11, 0},
    {"nu", "Poisson's ratio of both bodies, in [0, 0.5] (deck: poissonsRatio)", 0.3, 0},
    {"mu", "friction coefficient (deck: coefficientFriction)", 0.3, 0},
    {"Fb", "friction load (the normal force) [N]", 1e4, 0},
    {"V", "rolling speed [m/s]", 1.0, 0},
    {"xi_min", "smallest longitudinal creepage [-]", 0, 0},
    {"xi_max", "largest longitudinal creepage [-]", 0.01, 0},
    {"eta", "lateral creepage [-]", 0, 0},
    {"phi", "spin creepage [1/m]", 0, 0},
    {"model", "0: Kalker's linear law bounded by mu Fb; 1: Vermeulen-Johnson (deck: rollingCreepModel)", 1, 0},
    {"n", DC_CLI_N_HELP " (creepages)", 11, 0},
    {0, 0, 0, 0}};
  int st = dc_cli_parse(argc, argv, o,
                        "--a a --b b [--alpha deg] --E E --nu nu --mu mu --Fb F [--V V] --xi_min x --xi_max x [--eta e] "
                        "[--phi p] [--model 0|1] [--n N]");
  if (st) return st == 1 ? 0 : st;
  int n;
  if (dc_cli_count(argv[0], o, "n", &n)) return 2;
  const double E = dc_cli_get(o, "E"), nu = dc_cli_get(o, "nu"), a = dc_cli_get(o, "a"), b = dc_cli_get(o, "b");
  const double model = dc_cli_get(o, "model");
  dc_rolling_params p = {dc_cli_get(o, "mu"), 1e-300, model == 0.0 ? DC_ROLLING_KALKER : DC_ROLLING_VJ, 0.0};
  if (model != 0.0 && model != 1.0) {
    fprintf(stderr, "dclaw kalker: --model: %g is not 0 (Kalker) or 1 (Vermeulen-Johnson)\n", model);
    return 2;
  }
  dc_param_error err;
  if (dc_rolling_check(&p, &err) != DC_OK) {
    fprintf(stderr, "dclaw kalker: --mu: %s = %g is outside %s\n", err.name, err.value, err.range);
    return 2;
  }
  dc_mindlin_pair m;
  dc_rolling_material rm;
  if (!(E > 0.0) || dc_mindlin_pair_init(E, nu, E, nu, &m) != DC_OK || dc_rolling_material_init(&m, &rm, &err) != DC_OK) {
    fprintf(stderr, "dclaw kalker: --E, --nu: need E > 0 and nu in [0, 0.5] (got %g, %g)\n", E, nu);
    return 2;
  }
  if (!(a >= b && b > 0.0 && b >= 1e-150 * a)) {
    fprintf(stderr, "dclaw kalker: --a, --b: need a >= b > 0, b >= 1e-150 a (got %g, %g)\n", a, b);
    return 2;
  }
  const double V = dc_cli_get(o, "V"), Fb = dc_cli_get(o, "Fb"), al = dc_cli_get(o, "alpha") * M_PI / 180.0;
  if (!(V > 0.0) || !(Fb >= 0.0)) {
    fprintf(stderr, "dclaw kalker: --V, --Fb: need V > 0 and Fb >= 0 (got %g, %g)\n", V, Fb);
    return 2;
  }
  /* the plane z = 0, rolling along x; the major axis at alpha from it */
  const double nz[3] = {0.0, 0.0, 1.0};
  const dc_patch pa = {a, b, {cos(al), -sin(al), 0.0}, Fb, Fb, 1.0};
  const char *cols = "xi,eta,phi,Fx,Fy,Mz,saturation,c11,c22,c23,c33";
  printf("%s\n", cols);
  for (int i = 0; i < n; i++) {
    const double xi = dc_cli_range(dc_cli_get(o, "xi_min"), dc_cli_get(o, "xi_max"), i, n);
    const double eta = dc_cli_get(o, "eta"), phi = dc_cli_get(o, "phi");
    const dc_rolling_kin k = {V, {1.0, 0.0, 0.0}, {xi * V, eta * V, 0.0}, phi * V};
    dc_rolling_out out;
    st = dc_rolling_force(&p, &rm, &pa, nz, &k, &out);
    if (st) {
      fprintf(stderr, "dclaw kalker: --xi_min, --xi_max, --eta, --phi, --a, --b: %s at xi %g\n", dc_status_str(st), xi);
      return 2;
    }
    const double v[] = {xi, eta, phi, out.Fx, out.Fy, out.Mz, out.saturation, out.c.c11, out.c.c22, out.c.c23, out.c.c33};
    if (dc_cli_row("kalker", o, cols, 11, v)) return 2;
  }
  return 0;
}

DC_CLI_COMMAND(kalker, cmd_kalker,
               "Kalker rolling contact (linear or Vermeulen-Johnson): creepages -> creep forces, spin moment, "
               "saturation, coefficients");
