/* dclaw classical_tangential: a classical tangential law of the lecture
   notes (dc/classical_tangential.h) on a circular Hertz contact at constant
   normal force, along a prescribed tangential displacement cycled between
   +-u (0 -> u -> -u -> u ...) at a constant speed: the force along the
   cycles, or (--summary 1) one row with the force at the amplitude and the
   energy dissipated in the last cycle. */
#include "cli.h"
#include "dc/classical_tangential.h"
#include "dc/status.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

static int cmd_classical_tangential(int argc, char **argv)
{
  dc_cli_option o[] = {
    {"law", "0 coulomb, 1 viscous, 2 viscousSliding, 3 springSliding, 4 springDashpotSliding, 5 diRenzo, "
            "6 langston, 7 zheng, 8 tsuji, 9 incremental (deck: classicalTangential)", 3, 0},
    {"stiffness", "0 given (--kt), 1 ratio, 2 mindlin (deck: classicalTangentialStiffness)", 2, 0},
    {"damping", "0 none, 1 given (--gammat), 2 restitution (--e_t), 3 normal (deck: classicalTangentialDamping)", 0, 0},
    {"mu", "friction coefficient (deck: coefficientFriction)", 0.5, 0},
    {"kt", "tangential stiffness [N/m] (--stiffness 0; deck: kt)", 1e5, 0},
    {"gammat", "tangential damping [N s/m] (deck: gammat)", 0, 0},
    {"e_t", "tangential restitution in [0, 1] (deck: coefficientRestitutionTangential)", 0.5, 0},
    {"eta_l", "Langston damping [-] (deck: langstonDamping)", 0, 0},
    {"A_t", "tangential viscoelastic time [s] (deck: tangentialViscoelasticTime)", 0, 0},
    {"R", "relative radius of the two spheres [m]", 1e-3, 0},
    {"E", "Young's modulus of both bodies [Pa] (deck: youngsModulus)", 7e10, 0},
    {"nu", "Poisson's ratio of both bodies (deck: poissonsRatio)", 0.3, 0},
    {"Fn", "normal force, held constant [N]", 1.0, 0},
    {"meff", "effective mass [kg] (restitution damping, langston)", 1e-5, 0},
    {"u", "displacement amplitude [m]", 5e-6, 0},
    {"speed", "displacement speed [m/s] (the viscous laws' velocity)", 1e-3, 0},
    {"cycles", "cycles after the first loading (an integer from 1 to 1000000)", 3, 0},
    {"n", DC_CLI_N_HELP " on each leg", 11, 0},
    {"steps", "law steps between printed rows", 100, 0},
    {"summary", "1: print the force at the amplitude and the energy of the last cycle only", 0, 0},
    {0, 0, 0, 0}};
  int st = dc_cli_parse(argc, argv, o,
                        "--law L [--stiffness S] [--damping D] --mu mu [--kt k] [--gammat g] [--e_t e] [--eta_l e] "
                        "[--A_t A] --R R --E E --nu nu --Fn F [--meff m] --u u [--speed v] [--cycles C] [--n N] "
                        "[--steps S] [--summary 1]");
  if (st) return st == 1 ? 0 : st;
  int n, steps, cycles;
  if (dc_cli_count(argv[0], o, "n", &n) || dc_cli_count(argv[0], o, "steps", &steps) ||
      dc_cli_count(argv[0], o, "cycles", &cycles))
    return 2;
  const char *const ints[] = {"law", "stiffness", "damping"};
  if (dc_cli_whole(argv[0], o, ints, 3)) return 2;
  const double R = dc_cli_get(o, "R"), E = dc_cli_get(o, "E"), nu = dc_cli_get(o, "nu"), Fn = dc_cli_get(o, "Fn");
  const double me = dc_cli_get(o, "meff"), u = dc_cli_get(o, "u"), speed = dc_cli_get(o, "speed");
  if (!(E > 0.0 && isfinite(E)) || !(nu >= -1.0 && nu <= 0.5)) {
    fprintf(stderr, "dclaw classical_tangential: --E, --nu: need E > 0 and nu in [-1, 0.5] (got %g, %g)\n", E, nu);
    return 2;
  }
  if (!(R > 0.0 && Fn > 0.0 && me > 0.0 && u > 0.0 && speed > 0.0 && isfinite(u / speed))) {
    fprintf(stderr, "dclaw classical_tangential: --R, --Fn, --meff, --u, --speed: need all > 0 (got %g, %g, %g, %g, %g)\n",
            R, Fn, me, u, speed);
    return 2;
  }
  /* Hertz: a^3 = 3 Fn R / (4 E*); k_n = 2 E* a; G* = 1 / sum (2 - nu)/G */
  const double G = E / (2.0 * (1.0 + nu)), Estar = E / (2.0 * (1.0 - nu * nu)), Gstar = G / (2.0 * (2.0 - nu));
  const double a = cbrt(3.0 * Fn * R / (4.0 * Estar));
  dc_classical_tangential_params p = {(int)dc_cli_get(o, "law"), (int)dc_cli_get(o, "stiffness"),
                                      (int)dc_cli_get(o, "damping"), dc_cli_get(o, "mu"), dc_cli_get(o, "kt"),
                                      dc_cli_get(o, "gammat"), dc_cli_get(o, "e_t"), Gstar, Estar,
                                      dc_cli_get(o, "eta_l"), dc_cli_get(o, "A_t")};
  dc_classical_tangential m;
  dc_param_error err;
  if (dc_classical_tangential_init(&p, &m, &err) != DC_OK) {
    fprintf(stderr, "dclaw classical_tangential: %s = %g is outside %s\n", err.name, err.value, err.range);
    return 2;
  }
  const dc_patch pa = {a, a, {0.0, 0.0, 0.0}, Fn, Fn, 1.0};
  const dc_classical_tangential_contact c = {me, 2.0 * Estar * a, 0.0};
  const double nz[3] = {0.0, 0.0, 1.0};
  dc_classical_tangential_state h;
  memset(&h, 0, sizeof h);
  dc_classical_tangential_out out;
  memset(&out, 0, sizeof out);
  const int summary = dc_cli_get(o, "summary") != 0.0;
  const char *cols = "leg,u,Ft,kt,sliding";
  if (!summary) printf("%s\n", cols);
  /* legs: 0 -> u, then -u and u in turn; the force on body j along x, as
     the tangential force of the contact's motion u */
  double at = 0.0, W = 0.0, F0 = 0.0, Famp = 0.0;
  const int legs = 1 + 2 * cycles;
  for (int l = 0; l < legs; l++) {
    const double to = l % 2 ? -u : u, from = at;
    if (l == legs - 2) W = 0.0;   /* the last cycle: its two legs */
    for (int i = 0; i < n * steps; i++) {
      const double du = (to - from) / (n * steps);
      const double d3[3] = {du, 0.0, 0.0}, vt[3] = {du > 0 ? speed : -speed, 0.0, 0.0};
      st = dc_classical_tangential_step(&m, &pa, &c, nz, d3, vt, fabs(du) / speed, &h, &out);
      if (st) {
        fprintf(stderr, "dclaw classical_tangential: --u, --Fn, --kt: %s along the path\n", dc_status_str(st));
        return 2;
      }
      at += du;
      W += 0.5 * (F0 + out.Ft[0]) * du;
      F0 = out.Ft[0];
      if (!summary && (i + 1) % steps == 0) {
        const double v[] = {l, at, out.Ft[0], out.kt, out.sliding};
        if (dc_cli_row("classical_tangential", o, cols, 5, v)) return 2;
      }
    }
    Famp = out.Ft[0];
  }
  if (summary) {
    const char *scols = "a,mu_Fn,u_amp,F_amp,energy_last_cycle";
    printf("%s\n", scols);
    const double v[] = {a, p.mu * Fn, u, Famp, W};
    return dc_cli_row("classical_tangential", o, scols, 5, v);
  }
  return 0;
}

DC_CLI_COMMAND(classical_tangential, cmd_classical_tangential,
               "classical tangential laws (coulomb .. incremental): displacement cycles at constant Fn -> tangential "
               "force; --summary 1: force at the amplitude, energy of the last cycle");
