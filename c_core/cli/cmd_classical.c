/* dclaw classical: one head-on collision under a classical normal law
   (the lecture notes' LSD, Hertz and the hysteretic HLS laws,
   dc/classical_normal.h), integrated step by step as a DEM code does
   (velocity Verlet, the force from the half-step velocity): the overlap and
   force along the collision, or (--summary 1) one row with its duration,
   largest overlap and force, residual overlap and restitution, beside the
   closed forms of the law where it has them. */
#include "cli.h"
#include "dc/classical_normal.h"
#include "dc/damping.h"
#include "dc/status.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

static int cmd_classical(int argc, char **argv)
{
  dc_cli_option o[] = {
    {"law", "0 lsd, 1 hertz, 2 hlsConstant, 3 hlsVariable (deck: classicalNormal)", 0, 0},
    {"stiffness", "0 given (--kn), 1 duration, 2 overlap, 3 energy (deck: classicalStiffness; lsd, hls)", 0, 0},
    {"damping", "hertz: 0 restitution, 1 viscoelastic, 2 kuwabaraKono, 3 tsuji, 4 none (deck: damping)", 4, 0},
    {"limit", "1: the total force clipped at 0 (deck: limitForce on)", 0, 0},
    {"Estar", "effective modulus [Pa] (hertz; matched stiffness)", 3e10, 0},
    {"kn", "stiffness K or K_L [N/m] (--stiffness 0)", 1e6, 0},
    {"vchar", "characteristic velocity [m/s] (matched stiffness; deck: characteristicVelocity)", 1.0, 0},
    {"e", "coefficient of restitution, in (0, 1] (deck: coefficientRestitution)", 0.5, 0},
    {"A", "viscoelastic time [s] (--damping 1; deck: viscoelasticTime)", 0, 0},
    {"eta", "Kuwabara-Kono damping [N s m^-3/2] (--damping 2; deck: kuwabaraKonoDamping)", 0, 0},
    {"S", "unloading stiffness slope [1/m] (hlsVariable; deck: unloadingStiffnessSlope)", 0, 0},
    {"R", "effective radius [m]", 5e-4, 0},
    {"meff", "effective mass [kg]", 5e-6, 0},
    {"v0", "impact speed [m/s]", 1.0, 0},
    {"steps", "time steps per elastic collision duration (sets dt)", 20000, 0},
    {"n", DC_CLI_N_HELP " (printed rows along the collision)", 21, 0},
    {"summary", "1: print duration, largest overlap and force, residual overlap, restitution only", 0, 0},
    {0, 0, 0, 0}};
  int st = dc_cli_parse(argc, argv, o,
                        "--law L [--stiffness S] [--damping D] [--limit 1] [--Estar E] [--kn K] [--vchar v] [--e e] "
                        "[--A A] [--eta eta] [--S S] --R R --meff m --v0 v [--steps N] [--n N] [--summary 1]");
  if (st) return st == 1 ? 0 : st;
  int n, steps;
  if (dc_cli_count(argv[0], o, "n", &n) || dc_cli_count(argv[0], o, "steps", &steps)) return 2;
  dc_classical_normal_params p;
  memset(&p, 0, sizeof p);
  p.law = (int)dc_cli_get(o, "law");
  p.stiffness = (int)dc_cli_get(o, "stiffness");
  p.damping = p.law == DC_CLASSICAL_HERTZ ? (int)dc_cli_get(o, "damping") : DC_DAMPING_NONE;
  p.limit = (int)dc_cli_get(o, "limit");
  p.Estar = dc_cli_get(o, "Estar");
  p.kn = dc_cli_get(o, "kn");
  p.v_char = dc_cli_get(o, "vchar");
  p.e = dc_cli_get(o, "e");
  p.A = dc_cli_get(o, "A");
  p.eta_kk = dc_cli_get(o, "eta");
  p.S = dc_cli_get(o, "S");
  const char *const ints[] = {"law", "stiffness", "damping", "limit"};
  if (dc_cli_whole(argv[0], o, ints, 4)) return 2;
  if (p.law == DC_CLASSICAL_HERTZ && (p.damping == DC_DAMPING_RESTITUTION || p.damping == DC_DAMPING_TSUJI)) {
    /* the damping law's coefficient from e, as the LIGGGHTS wrapper forms it */
    if (!(p.e > 0.0 && p.e <= 1.0)) {
      fprintf(stderr, "dclaw classical: --e: %g is outside (0, 1]\n", p.e);
      return 2;
    }
    if (p.damping == DC_DAMPING_TSUJI) dc_damping_tsuji_alpha(p.e, &p.A);
    else dc_damping_beta(p.e, &p.A);
    p.eta_kk = p.A;
  }
  dc_classical_normal m;
  dc_param_error err;
  if (dc_classical_normal_init(&p, &m, &err) != DC_OK) {
    fprintf(stderr, "dclaw classical: %s = %g is outside %s (law %d)\n", err.name, err.value, err.range, p.law);
    return 2;
  }
  const double R = dc_cli_get(o, "R"), me = dc_cli_get(o, "meff"), v0 = dc_cli_get(o, "v0");
  double K;
  if (!(R > 0.0 && me > 0.0 && v0 > 0.0) || dc_classical_normal_stiffness(&m, R, me, &K) != DC_OK) {
    fprintf(stderr, "dclaw classical: --R, --meff, --v0: need R, meff, v0 > 0 and a finite stiffness (got %g, %g, %g)\n",
            R, me, v0);
    return 2;
  }
  /* the elastic duration: pi (m/K)^1/2 (linear), c_T (m^2/(K^2 v0))^1/5 (Hertz) */
  const double Tel = p.law == DC_CLASSICAL_HERTZ ? DC_CLASSICAL_HERTZ_TC * pow(me * me / (K * K * v0), 0.2)
                                                 : M_PI * sqrt(me / K);
  const double dt = Tel / steps;
  if (!(dt > 0.0 && isfinite(dt))) {
    fprintf(stderr, "dclaw classical: --meff, --kn, --Estar, --v0: the collision duration %g s is not finite\n", Tel);
    return 2;
  }
  /* the collision: delta from 0 at approach speed v0 until the surfaces part
     (delta < 0 again) or 100 elastic durations pass; a first pass finds its
     duration, a second prints n rows evenly over it */
  const int summary = dc_cli_get(o, "summary") != 0.0;
  const char *cols = "t,delta,force,rate";
  dc_classical_normal_out out;
  double delta, v, F, t, dmax, Fmax, dres, gamma, tc = 0.0;
  int touched;
  const long nmax = 100L * steps;
  for (int pass = 0; pass < (summary ? 1 : 2); pass++) {
    dc_classical_normal_state h = {0.0};
    delta = 0.0, v = v0, F = 0.0, t = 0.0, dmax = 0.0, Fmax = 0.0, dres = 0.0, gamma = 0.0;
    touched = 0;
    long printed = 0;
    if (pass == 1) printf("%s\n", cols);
    for (long i = 0; i < nmax; i++) {
      const double vh = v - 0.5 * dt * F / me;   /* F pushes the bodies apart: delta'' = -F/m */
      delta += dt * vh;
      t += dt;
      st = dc_classical_normal_step(&m, R, me, delta, vh, &h, &out);
      if (st) {
        fprintf(stderr, "dclaw classical: --v0, --meff, --kn: %s at overlap %g\n", dc_status_str(st), delta);
        return 2;
      }
      F = out.F;
      v = vh - 0.5 * dt * F / me;
      if (delta > 0.0) {
        touched = 1;
        gamma = out.gamma;   /* the law's damping coefficient in contact */
      }
      if (delta > dmax) dmax = delta;
      if (F > Fmax) Fmax = F;
      if (out.c.F == 0.0 && vh < 0.0 && delta > 0.0 && dres == 0.0) dres = delta;   /* hls: parted at delta_res */
      if (pass == 1 && printed < n && t >= printed * tc / (n > 1 ? n - 1 : 1)) {
        const double row[] = {t, delta, F, vh};
        if (dc_cli_row("classical", o, cols, 4, row)) return 2;
        printed++;
      }
      if (touched && delta <= 0.0) break;
    }
    tc = t;
  }
  if (summary) {
    dc_classical_collision c;
    int sc = DC_EDOM;
    if (p.law == DC_CLASSICAL_LSD) sc = dc_classical_lsd_collision(K, gamma, me, v0, p.limit, &c);
    else if (p.law == DC_CLASSICAL_HERTZ && p.damping == DC_DAMPING_NONE) sc = dc_classical_hertz_collision(K, me, v0, &c);
    else if (p.law != DC_CLASSICAL_HERTZ) sc = dc_classical_hls_collision(p.law, K, p.law == DC_CLASSICAL_HLS_CONSTANT ? p.e : p.S, me, v0, &c);
    if (sc != DC_OK) memset(&c, 0, sizeof c);   /* no closed form: zeros */
    const char *scols = "K,dt,Tc,delta_max,F_max,delta_res,e,Tc_closed,delta_max_closed,e_closed,parted";
    printf("%s\n", scols);
    const double row[] = {K, dt, t, dmax, Fmax, dres, fabs(v) / v0, c.Tc, c.dmax, c.e, touched && delta <= 0.0};
    return dc_cli_row("classical", o, scols, 11, row);
  }
  return 0;
}

DC_CLI_COMMAND(classical, cmd_classical,
               "classical normal laws (lsd, hertz, hlsConstant, hlsVariable): one head-on collision integrated -> "
               "overlap, force; --summary 1: duration, largest overlap and force, restitution beside the closed forms");
