/* Speed-versus-error report, family "tangential": the lecture notes'
   classical tangential laws (dc/classical_tangential.h) against
   Cattaneo-Mindlin-Deresiewicz (cmd_tangential, dc/cmd_tangential.h) on a
   shear-cycle path.

   Scene: two spheres of diameter 3 mm, E = 5 MPa, nu = 0.3 (the report's
   LIGGGHTS packing), held at overlap 10 um (Hertz: F_n = 3.2 mN, contact
   radius a = 87 um), friction mu = 0.5; the tangential displacement goes
   0 -> X -> -X -> X with X = 0.5 d_s (micro-slip), then on to 2 d_s and
   through -2 d_s -> 2 d_s (gross sliding), d_s = 3 mu F_n / (16 G* a) the
   slip distance of Mindlin's first loading, in steps of d_s / 200 (one per
   1e-5 s). Laws: spring with sliding of Mindlin's stiffness 8 G* a (this
   is stock `tangential history`; springDashpotSliding and tsuji are the
   same on this path, whose damping force is nil, and so is the stiffness
   setting ratio 4 G* / E* K_n with the Hertz stiffness), Di Renzo-Di Maio,
   Langston (zheng without its viscous term), incrementally slipping
   friction with K0 = 8 G* a, Coulomb. The viscous laws have no
   rate-independent counterpart and are left out.

   Error: max |F_t - F_t,cmd| over the path / mu F_n. Kernel call: one step
   of the law along the path.

   Rough scenes: the same spheres rough (GW closed form, sigma = 10 um per
   contact, n_asp = 1) on the same path, at sigma = delta (h = -1) and
   before touch (delta = -sigma, h = 1), the normal force the closed form's
   (F_b of both). Exact law: cmd_tangential on the summits' patch of review
   Eq. 83 with F_1/2 from its Bessel closed form (dc_gw_F_closed, GSL), the
   slip distance its own. Laws: cmd_tangential with tangentialRoughness on
   (dc_rough_tangential_axes every step, then the step), cmd_tangential on
   the smooth contact's patch (a = (R delta)^1/2, none before touch) and
   spring with sliding of Mindlin's stiffness 8 G* a (stock history).
   Prints CSV (report_common.h). */
#include "dc/classical_tangential.h"
#include "dc/cmd_tangential.h"
#include "dc/gw_integrals.h"
#include "dc/gw_rough.h"
#include "dc/hertz_elliptic.h"
#include "dc/rough_tangential.h"
#include "dc/mindlin.h"
#include "dc/status.h"
#include "report_common.h"
#include <string.h>

static const double E_YOUNG = 5e6, NU = 0.3, DIAMETER = 3e-3, DELTA_N = 1e-5, MU = 0.5, DT = 1e-5;
#define PER_DS 200
#define MAXSTEP (16 * PER_DS)

static double du[MAXSTEP], Fref[MAXSTEP];
static int nstep;
static dc_patch patch;
static const double NZ[3] = {0.0, 0.0, 1.0};

/* The path as displacement increments: straight runs between turning
   points (in units of d_s). */
static void build_path(double ds)
{
  const double turns[] = {0.5, -0.5, 0.5, 2.0, -2.0, 2.0};
  double x = 0.0;
  nstep = 0;
  for (size_t k = 0; k < sizeof turns / sizeof turns[0]; k++) {
    const int n = (int)lround(fabs(turns[k] - x) * PER_DS);
    for (int i = 0; i < n; i++) du[nstep++] = (turns[k] - x) / n * ds;
    x = turns[k];
  }
}

typedef struct {
  const char *name;
  int law, exact;   /* law: a dc_ct_law, or -1 for cmd_tangential */
} law_row;

static dc_cmd_params cmdp;
static dc_mindlin_pair pair;

/* Rough scenes: the patch of the law (-2: the summits' patch computed each
   step from the geometry, as gw_rough does for the wrapper). */
static dc_hertz_geom rgeom;
static double rsigma, rdelta;

/* The law's force along x at every step into F (NULL: just run it). */
static void run(const dc_classical_tangential *m, int law, double *F, double *acc)
{
  const dc_classical_tangential_contact c = {1.0, 0.0, 0.0};
  dc_classical_tangential_state h;
  dc_cmd_state hc;
  memset(&h, 0, sizeof h);
  memset(&hc, 0, sizeof hc);
  for (int i = 0; i < nstep; i++) {
    const double d[3] = {du[i], 0.0, 0.0}, v[3] = {du[i] / DT, 0.0, 0.0};
    double fx;
    if (law == -2) {
      dc_cmd_out o;
      dc_patch p = patch;
      dc_rough_tangential_axes(&rgeom, 1.0, rsigma, rdelta, &p.a, &p.b);
      dc_cmd_step(&cmdp, &pair, &p, NZ, d, 0.0, DT, &hc, &o);
      fx = o.Ft[0];
    } else if (law < 0) {
      dc_cmd_out o;
      dc_cmd_step(&cmdp, &pair, &patch, NZ, d, 0.0, DT, &hc, &o);
      fx = o.Ft[0];
    } else {
      dc_classical_tangential_out o;
      dc_classical_tangential_step(m, &patch, &c, NZ, d, v, DT, &h, &o);
      fx = o.Ft[0];
    }
    if (F) F[i] = fx;
    *acc += fx;
  }
}

/* The classical law's model with Mindlin's stiffness and no damping (zeros
   for cmd_tangential's rows, law < 0). */
static int law_model(int law, double Gstar, double Estar, dc_classical_tangential *m)
{
  memset(m, 0, sizeof *m);
  if (law < 0) return DC_OK;
  dc_classical_tangential_params p;
  memset(&p, 0, sizeof p);
  p.law = law;
  p.stiffness = DC_CT_KT_MINDLIN;
  p.damping = DC_CT_DAMP_NONE;
  p.mu = MU;
  p.Gstar = Gstar;
  p.Estar = Estar;
  dc_param_error err;
  return dc_classical_tangential_init(&p, m, &err);
}

int main(void)
{
  const double Estar = E_YOUNG / (2.0 * (1.0 - NU * NU)), G = E_YOUNG / (2.0 * (1.0 + NU));
  const double Gstar = G / (2.0 * (2.0 - NU)), R = 0.25 * DIAMETER;
  const double a = sqrt(R * DELTA_N), Fn = 4.0 / 3.0 * Estar * sqrt(R) * DELTA_N * sqrt(DELTA_N);
  memset(&patch, 0, sizeof patch);
  patch.a = patch.b = a;
  patch.F_elastic = patch.F_bound = Fn;
  patch.formed = 1.0;
  build_path(3.0 * MU * Fn / (16.0 * Gstar * a));
  cmdp.mu = MU;
  if (dc_mindlin_pair_init(E_YOUNG, NU, E_YOUNG, NU, &pair) != DC_OK) return 1;

  const law_row rows[] = {
      {"cmd_tangential", -1, 1},
      {"springSliding: Mindlin K_t (stock history)", DC_CT_SPRING_SLIDING, 0},
      {"diRenzo", DC_CT_DI_RENZO, 0},
      {"langston", DC_CT_LANGSTON, 0},
      {"incremental: Mindlin K0", DC_CT_INCREMENTAL, 0},
      {"coulomb", DC_CT_COULOMB, 0},
  };
  double acc = 0.0, F[MAXSTEP];
  run(NULL, -1, Fref, &acc);
  report_header();
  for (size_t k = 0; k < sizeof rows / sizeof rows[0]; k++) {
    dc_classical_tangential m;
    if (law_model(rows[k].law, Gstar, Estar, &m) != DC_OK) return 1;
    run(&m, rows[k].law, F, &acc);
    report_err e = {0};
    for (int i = 0; i < nstep; i++) report_err_add(&e, (F[i] - Fref[i]) / (MU * Fn));
    double ns;
    REPORT_TIME(ns, 1, run(&m, rows[k].law, NULL, &acc));
    report_row("tangential", "shear cycles 0.5 and 2 slip distances", rows[k].name, rows[k].exact, ns / nstep, &e,
               "max |F_t - F_t cmd_tangential| / mu F_n (rms)", "");
  }

  /* rough: sigma = delta and before touch */
  const double sigma = 1e-5;
  dc_hertz_geometry_circle(R, &rgeom);
  for (int sc = 0; sc < 2; sc++) {
    const double delta = sc == 0 ? sigma : -sigma;
    dc_gw_rough_state rs;
    double F12;
    if (dc_gw_rough_elliptic(&rgeom, Estar, 1.0, sigma, delta, &rs) != DC_OK ||
        dc_gw_F_closed(DC_GW_F12, -delta / sigma, &F12) != DC_OK)
      return 1;
    const double ar = sqrt(R * sigma) * F12;   /* Eq. 83 as the summits' patch: R_asp = R */
    const double as = delta > 0.0 ? sqrt(R * delta) : 0.0;
    dc_patch rough = {ar, ar, {0.0, 0.0, 0.0}, rs.F, rs.F, 1.0}, smooth = {as, as, {0.0, 0.0, 0.0}, rs.F, rs.F, 1.0};
    rsigma = sigma;
    rdelta = delta;
    patch = rough;
    build_path(1.5 * MU * rs.F / (8.0 * Gstar * ar));
    run(NULL, -1, Fref, &acc);
    const char *scene = sc == 0 ? "rough shear cycles at sigma = delta (h = -1)" : "rough shear cycles before touch (h = 1)";
    const law_row rrows[] = {
        {"Eq. 83 exact (F_1/2 closed form) + cmd_tangential", -1, 1},
        {"cmd_tangential tangentialRoughness on", -2, 0},
        {"cmd_tangential (smooth patch)", -1, 0},
        {"springSliding: Mindlin K_t (stock history)", DC_CT_SPRING_SLIDING, 0},
    };
    for (size_t k = 0; k < sizeof rrows / sizeof rrows[0]; k++) {
      dc_classical_tangential m;
      patch = k >= 2 ? smooth : rough;
      if (law_model(rrows[k].law, Gstar, Estar, &m) != DC_OK) return 1;
      run(&m, rrows[k].law, F, &acc);
      report_err e = {0};
      for (int i = 0; i < nstep; i++) report_err_add(&e, (F[i] - Fref[i]) / (MU * rs.F));
      double ns;
      REPORT_TIME(ns, 1, run(&m, rrows[k].law, NULL, &acc));
      report_row("tangential", scene, rrows[k].name, rrows[k].exact, ns / nstep, &e,
                 "max |F_t - F_t summits' cmd_tangential| / mu F_n (rms)", "");
    }
  }
  report_sink = acc;
  return 0;
}
