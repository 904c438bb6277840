/* Speed-versus-error report, family "rough": the normal force of rough
   spheres (Greenwood-Williamson summits, Feng et al. 2016) from each of the
   project's rough-sphere laws, against the full GW solver at m = 200
   Gauss points (dc/gw_solver.h; domain 1.5 x Feng Eq. 60, the pressure
   beyond it included, exact F_3/2).

   Scene: P* = P/P_h(sigma) (P_h(sigma) = 4/3 E* R^1/2 sigma^3/2: sigma, R
   and E* scale out exactly, dc/gw_rough_table.h) on the grid alpha' =
   delta/sigma in {-2.5 .. 100} times mu in {1, 4, 10, 50} (Feng's
   roughness parameter, Eq. 22). Laws: Feng's explicit law with either
   coefficient variant, the law tabulated from the solver (gw_rough's
   default), the GW closed form (review Eq. 33 with n_asp = 1: P* =
   F_3/2(-alpha'), Hertz in the smooth limit; it has no mu), and the solver
   itself at m = 5, 10, 20. Kernel call: the force at one overlap, the
   pair's constants bound beforehand as in the plugin (the solver: its
   influence tables built beforehand). Prints CSV (report_common.h). */
#include "dc/feng_rough.h"
#include "dc/gw_rough.h"
#include "dc/gw_rough_table.h"
#include "dc/gw_solver.h"
#include "dc/status.h"
#include "report_common.h"

static const double ALPHA[] = {-2.5, -2.0, -1.5, -1.0, -0.5, 0.0, 0.25, 0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0};
static const double MU[] = {1.0, 4.0, 10.0, 50.0};
enum { NA = sizeof ALPHA / sizeof ALPHA[0], NMU = sizeof MU / sizeof MU[0], NS = NA * NMU };
#define M_REF 200
/* sigma = 1, R = 1, E* = 3/4: P = P* (P_h(sigma) = 1) */
static const double ESTAR = 0.75, SIGMA = 1.0;

static double Pref[NS];

static dc_gw_solve_opts solver_opts(void)
{
  dc_gw_solve_opts o = dc_gw_solve_default_opts();
  o.domain_scale = 1.5;
  return o;
}

/* P* over the scene from the solver at m points; ns per solve. */
static void solve_scene(int m, double *P, double *ns)
{
  dc_gw_solver S;
  if (dc_gw_solver_init(&S, m) != DC_OK) exit(1);
  const dc_gw_solve_opts o = solver_opts();
  dc_gw_solve_result r;
  for (int k = 0; k < NS; k++) P[k] = dc_gw_solve(&S, ALPHA[k % NA], MU[k / NA], &o, &r) == DC_OK ? r.Pstar_sigma : NAN;
  REPORT_TIME(*ns, NS, { dc_gw_solve(&S, ALPHA[i % NA], MU[i / NA], &o, &r); acc += r.Pstar_sigma; });
  dc_gw_solver_free(&S);
}

static void row(const char *law, int exact, double ns, const double *P, const char *note)
{
  report_err e = {0};
  for (int k = 0; k < NS; k++) report_err_add(&e, P[k] / Pref[k] - 1.0);
  report_row("rough", "rough spheres: alpha' -2.5..100 x mu 1..50", law, exact, ns, &e,
             "relative force error vs GW solver m = 200 (max; rms)", note);
}

int main(void)
{
  report_header();
  double ns, P[NS];
  solve_scene(M_REF, Pref, &ns);
  row("GW solver m = 200", 1, ns, Pref, "solver time per overlap");

  /* the sphere laws, bound per mu; timed over the whole scene */
  static dc_feng_pair feng_t[NMU], feng_f[NMU];
  static dc_gw_table_pair table[NMU];
  for (int j = 0; j < NMU; j++) {
    dc_feng_law Lt, Lf;
    static dc_gw_table_law T;
    if (dc_feng_init(MU[j], DC_FENG_TABLE, &Lt) || dc_feng_init(MU[j], DC_FENG_FITTED, &Lf) ||
        dc_gw_table_init(MU[j], &T) || dc_feng_pair_init(&Lt, ESTAR, SIGMA, &feng_t[j]) ||
        dc_feng_pair_init(&Lf, ESTAR, SIGMA, &feng_f[j]) || dc_gw_table_pair_init(&T, ESTAR, SIGMA, &table[j]))
      exit(1);
  }
  /* the scene as flat arrays, so that the timed loops only call the law */
  static double x[NS];
  static const dc_feng_pair *ft[NS], *ff[NS];
  static const dc_gw_table_pair *tt[NS];
  for (int k = 0; k < NS; k++) {
    x[k] = ALPHA[k % NA];
    ft[k] = &feng_t[k / NA], ff[k] = &feng_f[k / NA], tt[k] = &table[k / NA];
  }
  dc_hertz_geom circle;
  dc_hertz_geometry_circle(1.0, &circle);
  double p, kn;
  dc_gw_rough_state gs;
#define SCENE(P_k, call)                                                        \
  do {                                                                          \
    for (int i = 0; i < NS; i++) { call; P[i] = P_k; }                          \
    REPORT_TIME(ns, NS, { call; acc += P_k; });                                 \
  } while (0)
  SCENE(p, dc_gw_table_pair_force(tt[i], 1.0, x[i], &p, &kn));
  row("tabulated GW law (gw_rough default)", 0, ns, P, "");
  SCENE(p, dc_feng_pair_force(ft[i], 1.0, x[i], &p, &kn));
  row("Feng law: table coefficients", 0, ns, P, "roughSphereLaw feng");
  SCENE(p, dc_feng_pair_force(ff[i], 1.0, x[i], &p, &kn));
  row("Feng law: fitted coefficients", 0, ns, P, "roughSphereLaw feng fengFitted on");
  SCENE(gs.F, dc_gw_rough_elliptic(&circle, ESTAR, 1.0, SIGMA, x[i], &gs));
  row("GW closed form (Eq. 33; n_asp = 1)", 0, ns, P, "gwElliptic on");

  const int ms[] = {5, 10, 20};
  for (int j = 0; j < 3; j++) {
    char law[64];
    solve_scene(ms[j], P, &ns);
    snprintf(law, sizeof law, "GW solver m = %d", ms[j]);
    row(law, 0, ns, P, "solver time per overlap");
  }
  return 0;
}
