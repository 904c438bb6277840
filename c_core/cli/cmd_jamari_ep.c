/* dclaw jamari_ep: Jamari-Schipper elastic-plastic elliptic contact ->
   CSV along a load-unload-reload cycle (0 -> peak -> 0 -> peak), or
   (--summary 1) one row with the onsets, the slope jump at delta_n1, the
   residual overlap and the energy dissipated by the cycle. */
#include "cli.h"
#include "dc/jamari_ep.h"
#include "dc/status.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

/* The CLI key of a deck property named by dc_jamari_check. */
static const char *key_of(const char *property)
{
  static const char *map[4][2] = {{"hardness", "--H"}, {"plasticityKv", "--Kv"}, {"plasticityCh", "--ch"},
                                  {"plasticityCa", "--cA"}};
  for (int i = 0; i < 4; i++)
    if (!strcmp(property, map[i][0])) return map[i][1];
  return property;
}

/* Runs the subcommand; argv[0] is the law name. */
static int cmd_jamari_ep(int argc, char **argv)
{
  dc_cli_option o[] = {
    {"R1", "relative principal radius 1 [m]", 1e-3, 0},
    {"R2", "relative principal radius 2 [m]", 1e-3, 0},
    {"Estar", "effective modulus 1/sum((1-nu^2)/E) [Pa]", 1.15e11, 0},
    {"H", "hardness of the softer body [Pa] (deck: hardness)", 2e9, 0},
    {"nu", "Poisson's ratio of the softer body, for the default Kv", 0.3, 0},
    {"Kv", "maximum pressure at first yield over H (deck: plasticityKv; default 0.454 + 0.41 nu)", 0, 0},
    {"ch", "mean pressure at full plasticity over H (deck: plasticityCh)", DC_JAMARI_CH_DEFAULT, 0},
    {"cA", "truncation area at delta_n2 over Hertz area at delta_n1 (deck: plasticityCa)", DC_JAMARI_CA_DEFAULT, 0},
    {"peak", "largest overlap of the cycle in units of delta_n1", 20, 0},
    {"delta_peak", "largest overlap of the cycle [m] (instead of --peak)", 0, 0},
    {"n", DC_CLI_N_HELP " on each leg", 11, 0},
    {"summary", "1: print onsets, residual overlap and dissipated energy only", 0, 0},
    {0, 0, 0, 0}};
  int st = dc_cli_parse(argc, argv, o,
      "--R1 R --R2 R --Estar E --H H [--nu nu | --Kv K] [--ch c] [--cA c] [--peak p | --delta_peak d] [--n N] [--summary 1]");
  if (st) return st == 1 ? 0 : st;
  int n;
  if (dc_cli_count(argv[0], o, "n", &n)) return 2;
  dc_hertz_geom g;
  st = dc_hertz_geometry(dc_cli_get(o, "R1"), dc_cli_get(o, "R2"), &g);
  if (st) {
    fprintf(stderr, "dclaw jamari_ep: --R1, --R2: %s (need R > 0 and R_minor/R_major >= %g)\n", dc_status_str(st),
            DC_HERTZ_RATIO_MIN);
    return 2;
  }
  dc_jamari_params p = dc_jamari_defaults(dc_cli_get(o, "H"), dc_cli_get(o, "nu"));
  if (dc_cli_given(o, "Kv")) p.K_v = dc_cli_get(o, "Kv");
  p.c_h = dc_cli_get(o, "ch");
  p.c_A = dc_cli_get(o, "cA");
  dc_param_error err;
  if (dc_jamari_check(&p, &err) != DC_OK) {
    fprintf(stderr, "dclaw jamari_ep: %s%s: %s = %g is outside %s\n", key_of(err.name),
            !strcmp(err.name, "plasticityKv") && !dc_cli_given(o, "Kv") ? " (from --nu)" : "", err.name, err.value,
            err.range);
    return 2;
  }
  const double E = dc_cli_get(o, "Estar");
  double d1, d2;
  st = dc_jamari_onsets(&g, E, &p, &d1, &d2);
  if (st) {
    fprintf(stderr, "dclaw jamari_ep: --Estar, --H, --Kv, --R1, --R2: %s (need Estar > 0; delta_n1 = 2 Rc E K (Kv H/Estar)^2 in range)\n",
            dc_status_str(st));
    return 2;
  }
  const int given_peak = dc_cli_given(o, "delta_peak");
  const double top = given_peak ? dc_cli_get(o, "delta_peak") : dc_cli_get(o, "peak") * d1;
  const char *peak_keys = given_peak ? "--delta_peak" : "--peak";
  if (!(top > 0.0 && top <= 1e300)) {
    fprintf(stderr, "dclaw jamari_ep: %s: the largest overlap %g must be > 0 and finite\n", peak_keys, top);
    return 2;
  }
  dc_jamari_state h = {0, 0, 0, 0};
  dc_contact c;

  if (dc_cli_get(o, "summary") != 0.0) {
    /* the cycle 0 -> top -> 0 by the trapezoid rule on 2 x 100000 steps */
    const int m = 100000;
    double W = 0.0, F = 0.0, res = 0.0;
    for (int leg = 0; leg < 2 && st == DC_OK; leg++)
      for (int i = 1; i <= m && st == DC_OK; i++) {
        const double x0 = leg ? top * (m - i + 1) / m : top * (i - 1) / m, x = leg ? top * (m - i) / m : top * i / m;
        st = dc_jamari_step(&g, E, &p, x, &h, &c);
        W += 0.5 * (F + c.F) * (x - x0);
        F = c.F;
        if (leg == 0 && i == m) res = h.delta_res;
      }
    if (st) {
      fprintf(stderr, "dclaw jamari_ep: %s, --Estar, --H: %s along the cycle\n", peak_keys, dc_status_str(st));
      return 2;
    }
    dc_contact c1;
    dc_jamari_loading(&g, E, &p, d1, &c1);
    const double kappa = d2 > d1 ? (p.c_h - 2.0 / 3.0 * p.K_v) / (2.0 / 3.0 * p.K_v * log(d2 / d1)) : 0.0;
    const char *cols = "R_major,R_minor,Kv,delta_n1,delta_n2,ratio_eq44,kappa,F_n1,delta_peak,delta_res,energy";
    printf("%s\n", cols);
    const double v[] = {g.R_major, g.R_minor, p.K_v, d1, d2, d2 / (p.c_A * d1), kappa, c1.F, top, res, W};
    return dc_cli_row("jamari_ep", o, cols, 11, v);
  }

  const char *cols = "leg,delta,force,area,a,b,stiffness,delta_max,delta_res";
  printf("%s\n", cols);
  for (int leg = 0; leg < 3; leg++)
    for (int i = 0; i < n; i++) {
      const double d = dc_cli_range(leg == 1 ? top : 0.0, leg == 1 ? 0.0 : top, i, n);
      st = dc_jamari_step(&g, E, &p, d, &h, &c);
      if (st) {
        fprintf(stderr, "dclaw jamari_ep: %s, --Estar, --H: %s at delta %g\n", peak_keys, dc_status_str(st), d);
        return 2;
      }
      const double v[] = {leg, d, c.F, c.area, c.a, c.b, c.kn, h.delta_max, h.delta_res};
      if (dc_cli_row("jamari_ep", o, cols, 9, v)) return 2;
    }
  return 0;
}

DC_CLI_COMMAND(jamari_ep, cmd_jamari_ep,
               "Jamari-Schipper elastic-plastic elliptic contact: load-unload-reload cycle -> force, area, semi-axes, residual overlap; --summary 1: onsets, energy");
