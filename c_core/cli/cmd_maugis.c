/* dclaw maugis: the Maugis-Dugdale contact branch of two spheres
   (dc/maugis_dugdale.h) over the contact radius, in the deck's units
   (contact radius a, force F, overlap delta) and Johnson-Greenwood's
   (abar, Pbar, Dbar, m = c/a); (--overlap 1) the stable branch over the
   overlap from the separation overlap to --D_max, as an overlap-controlled
   DEM contact follows it; or (--summary 1) the pull-off force under load
   control and the separation overlap beside the JKR and DMT limits.
   lambda from --lambda or from the Tabor parameter of --z0 (Lennard-Jones
   equilibrium separation). */
#include "cli.h"
#include "dc/maugis_dugdale.h"
#include "dc/status.h"
#include <math.h>
#include <stdio.h>

static int cmd_maugis(int argc, char **argv)
{
  dc_cli_option o[] = {
    {"R", "effective radius R1 R2 / (R1 + R2) [m]", 1e-3, 0},
    {"Estar", "effective modulus E* = 1 / sum (1 - nu_i^2) / E_i [Pa]", 1e9, 0},
    {"w", "work of adhesion [J/m^2] (deck: workOfAdhesion)", 0.05, 0},
    {"lambda", "Maugis' parameter lambda = 2 sigma0 (R / (pi w K^2))^1/3, K = 4 E*/3", 1, 0},
    {"z0", "Lennard-Jones equilibrium separation [m]: lambda = 1.1570 mu_T (instead of --lambda)", 0, 0},
    {"a_min", "first non-dimensional contact radius abar", 0.05, 0},
    {"a_max", "last abar", 3, 0},
    {"n", DC_CLI_N_HELP, 31, 0},
    {"overlap", "1: rows over the overlap Dbar from the separation overlap to --D_max (the stable branch)", 0, 0},
    {"D_max", "last non-dimensional overlap Dbar, with --overlap 1", 4, 0},
    {"summary", "1: print lambda, the Tabor parameter, the pull-off force and the separation overlap only", 0, 0},
    {0, 0, 0, 0}};
  int st = dc_cli_parse(argc, argv, o, "--R R --Estar E --w w [--lambda L | --z0 z] [--a_min a] [--a_max a] [--n N] "
                        "[--overlap 1 [--D_max D]] [--summary 1]");
  if (st) return st == 1 ? 0 : st;
  int n;
  if (dc_cli_count(argv[0], o, "n", &n)) return 2;
  const double R = dc_cli_get(o, "R"), Es = dc_cli_get(o, "Estar"), w = dc_cli_get(o, "w");
  if (!(R > 0.0 && isfinite(R) && Es > 0.0 && isfinite(Es) && w > 0.0 && isfinite(w))) {
    fprintf(stderr, "dclaw maugis: --R, --Estar, --w: need R > 0, E* > 0, w > 0 (got %g, %g, %g)\n", R, Es, w);
    return 2;
  }
  double lambda = dc_cli_get(o, "lambda"), muT = NAN;
  if (dc_cli_given(o, "z0")) {
    const double z0 = dc_cli_get(o, "z0");
    muT = cbrt(R * w * w / (Es * Es * z0 * z0 * z0));
    lambda = dc_md_lambda_of_tabor(muT);
  }
  /* Johnson-Greenwood's scales */
  const double K = 4.0 / 3.0 * Es, sa = cbrt(M_PI * w * R * R / K), sF = M_PI * w * R;
  const double sd = cbrt(M_PI * M_PI * w * w * R / (K * K));
  if (!isfinite(muT)) muT = lambda / dc_md_lambda_of_tabor(1.0);
  /* the separation overlap (the --overlap rows start there); its status is lambda's domain */
  double Ds, as;
  if ((st = dc_md_separation(lambda, &Ds, &as))) {
    fprintf(stderr, "dclaw maugis: --lambda, --z0: %s (lambda %g must lie in [1e-10, 1e10])\n", dc_status_str(st),
            lambda);
    return 2;
  }
  if (dc_cli_get(o, "summary") != 0.0) {
    double Pc, ac;
    dc_md_pulloff(lambda, &Pc, &ac);
    const char *cols = "lambda,tabor,Pbar_pulloff,abar_pulloff,F_pulloff,F_jkr,F_dmt,Dbar_sep,delta_sep";
    printf("%s\n", cols);
    const double v[] = {lambda, muT, Pc, ac, -Pc * sF, 1.5 * sF, dc_dmt_pulloff(R, R, w), Ds, Ds * sd};
    return dc_cli_row("maugis", o, cols, 9, v);
  }
  if (dc_cli_get(o, "overlap") != 0.0) {
    const char *cols = "Dbar,abar,Pbar,delta,a,F";
    printf("%s\n", cols);
    for (int i = 0; i < n; i++) {
      const double D = dc_cli_range(Ds, dc_cli_get(o, "D_max"), i, n);
      double ab, m, P;
      int contact;
      if ((st = dc_md_at_overlap(lambda, D, &contact, &ab, &m, &P))) {
        fprintf(stderr, "dclaw maugis: --D_max: %s at Dbar %g\n", dc_status_str(st), D);
        return 2;
      }
      const double v[] = {D, ab, P, D * sd, ab * sa, P * sF};
      if (dc_cli_row("maugis", o, cols, 6, v)) return 2;
    }
    return 0;
  }
  const char *cols = "abar,m,Pbar,Dbar,a,F,delta";
  printf("%s\n", cols);
  for (int i = 0; i < n; i++) {
    const double ab = dc_cli_range(dc_cli_get(o, "a_min"), dc_cli_get(o, "a_max"), i, n);
    double m, P, D;
    if ((st = dc_md_state(lambda, ab, &m, &P, &D))) {
      fprintf(stderr, "dclaw maugis: --lambda, --a_min, --a_max: %s (lambda in [1e-10, 1e10], abar in [1e-20, "
                      "1e20]; got lambda %g, abar %g)\n", dc_status_str(st), lambda, ab);
      return 2;
    }
    const double v[] = {ab, m, P, D, ab * sa, P * sF, D * sd};
    if (dc_cli_row("maugis", o, cols, 7, v)) return 2;
  }
  return 0;
}

DC_CLI_COMMAND(maugis, cmd_maugis,
               "Maugis-Dugdale adhesion of spheres (JKR to DMT by lambda or the Tabor parameter): contact branch "
               "over the contact radius or (--overlap 1) the overlap; --summary 1: pull-off force beside JKR's and "
               "DMT's");
