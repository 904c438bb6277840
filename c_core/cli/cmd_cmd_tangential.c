/* dclaw cmd_tangential: Cattaneo-Mindlin-Deresiewicz tangential force of a
   circular Hertz contact at constant normal force along a prescribed
   tangential displacement: the virgin curve 0 -> u*, unloading u* -> -u*,
   reloading -u* -> u* (the loop of review Eqs. 59, 67), or (--summary 1)
   one row with the no-slip stiffness, the slip displacement, the amplitude
   and the energy dissipated per cycle (the loop's area, trapezoid rule)
   beside review Eq. 69. With --sigma > 0 the contact is rough (the deck's
   gw_rough gwElliptic on with tangentialRoughness on): Fn held on the GW
   closed form, the summits' patch of dc/rough_tangential.h. --memory 1:
   the bounded-memory law (dc/cmd_turning_points.h, the deck's cmdMemory
   turningPoints) in place of the exact profile. */
#include "cli.h"
#include "dc/cmd_tangential.h"
#include "dc/cmd_turning_points.h"
#include "dc/gw_rough.h"
#include "dc/hertz_elliptic.h"
#include "dc/mindlin.h"
#include "dc/root_find.h"
#include "dc/rough_tangential.h"
#include "dc/status.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

/* The history of either law (p->memory). */
typedef union {
  dc_cmd_state profile;
  dc_cmdtp_state turning_points;
} history;

/* The contact moved from tangential displacement u0 to u1 along x in
   `steps` equal law steps; out holds the last step's; returns a dc_status. */
static int leg(const dc_cmd_params *p, int memory, const dc_mindlin_pair *m, const dc_patch *pa, double u0, double u1,
               int steps, history *h, dc_cmd_out *o)
{
  const double n[3] = {0.0, 0.0, 1.0};
  for (int i = 0; i < steps; i++) {
    const double du[3] = {(u1 - u0) / steps, 0.0, 0.0};
    const int st = memory ? dc_cmdtp_step(p, m, pa, n, du, 0.0, 1.0, &h->turning_points, o)
                             : dc_cmd_step(p, m, pa, n, du, 0.0, 1.0, &h->profile, o);
    if (st) return st;
  }
  return DC_OK;
}

/* The GW closed form's force less Fn at overlap x (the circle of radius R). */
typedef struct {
  dc_hertz_geom g;
  double Estar, n, sigma, Fn;
} rough_load;

static double rough_excess(double x, void *ctx, int slot)
{
  (void)slot;
  const rough_load *L = (const rough_load *)ctx;
  dc_gw_rough_state s;
  return dc_gw_rough_elliptic(&L->g, L->Estar, L->n, L->sigma, x, &s) == DC_OK ? s.F - L->Fn : NAN;
}

static int cmd_cmd_tangential(int argc, char **argv)
{
  dc_cli_option o[] = {
    {"R", "relative radius of the two spheres [m]", 1e-3, 0},
    {"E", "Young's modulus of both bodies [Pa] (deck: youngsModulus)", 7e10, 0},
    {"nu", "Poisson's ratio of both bodies (deck: poissonsRatio)", 0.3, 0},
    {"Fn", "normal force, held constant [N]", 10.0, 0},
    {"mu", "friction coefficient (deck: coefficientFriction)", 0.5, 0},
    {"r", "amplitude as the force reached on the virgin curve over mu Fn, in (0, 1]", 0.8, 0},
    {"u", "amplitude as the tangential displacement [m] (instead of --r)", 0, 0},
    {"n", DC_CLI_N_HELP " on each leg", 11, 0},
    {"steps", "law steps between printed rows (the step size of a DEM run)", 64, 0},
    {"summary", "1: print stiffness, slip displacement, amplitude and energy per cycle only", 0, 0},
    {"sigma", "rms summit height of the contact [m] (deck: surfaceRoughness); > 0: rough, Fn on the GW closed "
              "form and the summits' patch (tangentialRoughness on)", 0, 0},
    {"nasp", "summits n_asp of the GW closed form (deck: asperityCount), with --sigma", 1, 0},
    {"memory", "0: the exact spring profile; 1: the force with 4 remembered turning points (deck: cmdMemory "
               "profile | turningPoints)", 0, 0},
    {0, 0, 0, 0}};
  int st = dc_cli_parse(argc, argv, o, "--R R --E E --nu nu --Fn F --mu mu [--r r | --u u] [--n N] [--steps S] "
                        "[--summary 1] [--sigma S [--nasp N]] [--memory 0|1]");
  if (st) return st == 1 ? 0 : st;
  int n, steps;
  if (dc_cli_count(argv[0], o, "n", &n) || dc_cli_count(argv[0], o, "steps", &steps)) return 2;
  const double R = dc_cli_get(o, "R"), E = dc_cli_get(o, "E"), nu = dc_cli_get(o, "nu"), Fn = dc_cli_get(o, "Fn");
  const double mu = dc_cli_get(o, "mu");
  dc_mindlin_pair m;
  if (!(E > 0.0) || !(nu >= -1.0 && nu <= 0.5) || dc_mindlin_pair_init(E, nu, E, nu, &m) != DC_OK) {
    fprintf(stderr, "dclaw cmd_tangential: --E, --nu: need E > 0 and nu in [-1, 0.5] (got %g, %g)\n", E, nu);
    return 2;
  }
  if (!(R > 0.0) || !(Fn > 0.0)) {
    fprintf(stderr, "dclaw cmd_tangential: --R, --Fn: need R > 0 and Fn > 0 (got %g, %g)\n", R, Fn);
    return 2;
  }
  const double memory = dc_cli_get(o, "memory");
  const int mem = memory == 1.0;
  dc_cmd_params p = {mu, 0.0, 0, 0};
  dc_param_error err;
  if (memory != 0.0 && memory != 1.0) {
    fprintf(stderr, "dclaw cmd_tangential: --memory: %g is outside {0 (profile), 1 (turningPoints)}\n", memory);
    return 2;
  }
  if (dc_cmd_check(&p, &err) != DC_OK) {
    fprintf(stderr, "dclaw cmd_tangential: --mu: %s = %g is outside %s\n", err.name, err.value, err.range);
    return 2;
  }
  /* Hertz: a^3 = 3 Fn R / (4 E*), E* = E / (2 (1 - nu^2)); Mindlin: k0 = 8 G* a */
  const double Estar = E / (2.0 * (1.0 - nu * nu));
  double a = cbrt(3.0 * Fn * R / (4.0 * Estar)), delta = a * a / R;
  const double sigma = dc_cli_get(o, "sigma"), nasp = dc_cli_get(o, "nasp");
  if (!(sigma >= 0.0 && isfinite(sigma)) || !(nasp > 0.0 && isfinite(nasp))) {
    fprintf(stderr, "dclaw cmd_tangential: --sigma, --nasp: need sigma >= 0 and nasp > 0 (got %g, %g)\n", sigma, nasp);
    return 2;
  }
  if (sigma > 0.0) {
    /* the overlap holding Fn on the GW closed form: below the Hertz overlap
       of Fn / n_asp (the rough force is the larger at any overlap) */
    rough_load L = {{0}, Estar, nasp, sigma, Fn};
    dc_root_result res;
    const double hi = cbrt(3.0 * Fn / nasp * R / (4.0 * Estar));
    double b;
    if (dc_hertz_geometry(R, R, &L.g) != DC_OK ||
        dc_root_brent(rough_excess, &L, -40.0 * sigma, hi * hi / R, 1e-15, 0.0, 400, &res) != DC_OK ||
        dc_rough_tangential_axes(&L.g, nasp, sigma, res.x, &a, &b) != DC_OK) {
      fprintf(stderr, "dclaw cmd_tangential: --sigma, --nasp, --Fn: no overlap holds Fn on the GW closed form\n");
      return 2;
    }
    delta = res.x;
  }
  double k0, kminor;
  st = dc_cmd_stiffness(&m, a, a, &k0, &kminor);
  const double muF = mu * Fn, dL = 1.5 * muF / k0;   /* review Eq. 59: slip displacement 3 mu Fn / (2 k0) */
  if (st || !(isfinite(a) && a > 0.0 && isfinite(dL) && k0 > 0.0)) {
    fprintf(stderr, "dclaw cmd_tangential: --R, --E, --nu, --Fn: %s (contact radius %g m)\n",
            st ? dc_status_str(st) : "a result leaves the doubles", a);
    return 2;
  }
  double u;
  const char *amp = dc_cli_given(o, "u") ? "--u" : "--r";
  if (dc_cli_given(o, "u")) u = dc_cli_get(o, "u");
  else {
    const double r = dc_cli_get(o, "r");
    if (!(r > 0.0 && r <= 1.0)) {
      fprintf(stderr, "dclaw cmd_tangential: --r: %g is outside (0, 1]\n", r);
      return 2;
    }
    u = dL * (1.0 - cbrt((1.0 - r) * (1.0 - r)));   /* the virgin curve reaches r mu Fn */
  }
  if (!(u > 0.0 && isfinite(u) && u <= 1e6 * dL)) {
    fprintf(stderr, "dclaw cmd_tangential: %s: the amplitude %g m must be > 0 and at most 1e6 slip displacements\n", amp, u);
    return 2;
  }
  if (!(mu > 0.0)) {
    fprintf(stderr, "dclaw cmd_tangential: --mu: must be > 0 for a loop (got %g)\n", mu);
    return 2;
  }
  const dc_patch pa = {a, a, {0.0, 0.0, 0.0}, Fn, Fn, 1.0};
  history h;
  memset(&h, 0, sizeof h);
  dc_cmd_out out;
  memset(&out, 0, sizeof out);

  if (dc_cli_get(o, "summary") != 0.0) {
    /* one cycle +u -> -u -> +u after the virgin leg, trapezoid on the steps */
    if ((st = leg(&p, mem, &m, &pa, 0.0, u, steps * n, &h, &out))) goto fail;
    const double Fa = out.Ft[0];
    double W = 0.0, F0 = Fa;
    for (int s = 0; s < 2 && !st; s++) {
      const double from = s ? -u : u, to = s ? u : -u, du = (to - from) / (steps * n);
      for (int i = 0; i < steps * n && !st; i++) {
        st = leg(&p, mem, &m, &pa, 0.0, du, 1, &h, &out);
        W += 0.5 * (F0 + out.Ft[0]) * du;
        F0 = out.Ft[0];
      }
    }
    if (st) goto fail;
    /* review Eq. 69 for the loop between +-F*: E = 36 (mu Fn)^2 / (5 k0)
       (= 9 (mu Fn)^2 / (10 G* a), k0 = 8 G* a)
       [1 - (1 - r)^5/3 - 5 r/6 (1 + (1 - r)^2/3)], r = F* over mu Fn */
    const double rr = fmin(Fa / muF, 1.0), q = 1.0 - rr;
    const double W69 = 36.0 * muF * muF / (5.0 * k0) * (1.0 - pow(q, 5.0 / 3.0) - 5.0 * rr / 6.0 * (1.0 + cbrt(q * q)));
    const char *cols = "a,k0,mu_Fn,delta_slip,u_amp,F_amp,energy,energy_eq69,delta";
    printf("%s\n", cols);
    const double v[] = {a, k0, muF, dL, u, Fa, W, W69, delta};
    return dc_cli_row("cmd_tangential", o, cols, 9, v);
  }

  const char *cols = "leg,u,Ft,stick,kt";
  printf("%s\n", cols);
  double at = 0.0;
  for (int l = 0; l < 3; l++) {
    const double from = l == 0 ? 0.0 : l == 1 ? u : -u, to = l == 1 ? -u : u;
    for (int i = 0; i < n; i++) {
      const double target = dc_cli_range(from, to, i, n);
      if (target != at && (st = leg(&p, mem, &m, &pa, at, target, steps, &h, &out))) goto fail;
      at = target;
      const double v[] = {l, at, out.Ft[0], out.stick, out.kt};
      if (dc_cli_row("cmd_tangential", o, cols, 5, v)) return 2;
    }
  }
  return 0;
fail:
  fprintf(stderr, "dclaw cmd_tangential: %s, --Fn, --E: %s along the path\n", amp, dc_status_str(st));
  return 2;
}

DC_CLI_COMMAND(cmd_tangential, cmd_cmd_tangential,
               "Cattaneo-Mindlin-Deresiewicz, circle at constant Fn: displacement loop -> tangential force, stick "
               "fraction, stiffness; --summary 1: energy per cycle beside Eq. 69; --sigma: rough (summits' patch)");
