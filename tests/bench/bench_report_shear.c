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
   friction with K0 = 8 G* a, Coulomb, and cmd_tangential's bounded
   memory (cmdMemory turningPoints, dc/cmd_turning_points.h; this path has
   3 turning points at constant load: exact to rounding). The viscous laws
   have no rate-independent counterpart and are left out.

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
   Oblique impacts: a sphere of alumina (Chung & Ooi 2011: R = 2.5 mm,
   E = 380 GPa, nu = 0.23, 4000 kg/m^3, mu = 0.092) hits a plane of the
   same at 3.9 m/s, incidence 5-80 degrees from the normal (micro-slip to
   gross sliding), elastic Hertz; the contact point's slip s changes by
   -7/2 F_t / m (translation and rolling); symplectic Euler at Tc/4000.
   Error: max over the angles of |beta - beta cmd_tangential|, beta =
   s'/s the tangential restitution of the contact point. The same with
   the elliptic patch of an ellipsoid tip (relative radii 2.5 and 1 mm,
   the sphere's mass and inertia kept: a test of the laws, not of the
   body), sliding at 30 degrees from the patch's major axis (the force not
   parallel to the slip).

   Prints CSV (report_common.h). */
#include "dc/classical_tangential.h"
#include "dc/cmd_tangential.h"
#include "dc/cmd_turning_points.h"
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
  int law, exact;   /* law: a dc_ct_law, or -1 for cmd_tangential, -3 its turningPoints */
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
  dc_cmdtp_state ht;
  memset(&h, 0, sizeof h);
  memset(&hc, 0, sizeof hc);
  memset(&ht, 0, sizeof ht);
  for (int i = 0; i < nstep; i++) {
    const double d[3] = {du[i], 0.0, 0.0}, v[3] = {du[i] / DT, 0.0, 0.0};
    double fx;
    if (law == -2) {
      dc_cmd_out o;
      dc_patch p = patch;
      dc_rough_tangential_axes(&rgeom, 1.0, rsigma, rdelta, &p.a, &p.b);
      dc_cmd_step(&cmdp, &pair, &p, NZ, d, 0.0, DT, &hc, &o);
      fx = o.Ft[0];
    } else if (law == -3) {
      dc_cmd_out o;
      dc_cmdtp_step(&cmdp, &pair, &patch, NZ, d, 0.0, DT, &ht, &o);
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
static int law_model(int law, double mu, double Gstar, double Estar, dc_classical_tangential *m)
{
  memset(m, 0, sizeof *m);
  if (law < 0) return DC_OK;
  dc_classical_tangential_params p;
  memset(&p, 0, sizeof p);
  p.law = law;
  p.stiffness = DC_CT_KT_MINDLIN;
  p.damping = DC_CT_DAMP_NONE;
  p.mu = mu;
  p.Gstar = Gstar;
  p.Estar = Estar;
  dc_param_error err;
  return dc_classical_tangential_init(&p, m, &err);
}

/* Oblique impacts (header): beta at each angle into beta[], the steps
   taken into *steps. ell: the ellipsoid tip's patch. */
#define NANGLE 9
static const double ANGLES[NANGLE] = {5, 10, 20, 30, 40, 50, 60, 70, 80};

static int oblique(const dc_classical_tangential *m, int law, int ell, double *beta, long *steps, double *acc)
{
  const double E = 3.8e11, nu = 0.23, R = 2.5e-3, v = 3.9, mass = 4000.0 * 4.0 / 3.0 * M_PI * R * R * R;
  const double Estar = E / (2.0 * (1.0 - nu * nu)), mu = 0.092;
  dc_hertz_geom g;
  if (dc_hertz_geometry(R, ell ? 1e-3 : R, &g) != DC_OK) return 1;
  dc_mindlin_pair mp;
  if (dc_mindlin_pair_init(E, nu, E, nu, &mp) != DC_OK) return 1;
  const dc_cmd_params cp = {mu, 0.0, 0, 0};
  const double Tc = 2.87 * pow(mass * mass / (g.R_force * Estar * Estar * v), 0.2), dt = Tc / 4000.0;
  /* the patch's major axis at 30 degrees from the slip (x) on the ellipse */
  const double ax[3] = {ell ? cos(M_PI / 6.0) : 0.0, ell ? sin(M_PI / 6.0) : 0.0, 0.0};
  const dc_classical_tangential_contact cc = {mass, 0.0, 0.0};
  *steps = 0;
  for (int k = 0; k < NANGLE; k++) {
    const double th = ANGLES[k] * M_PI / 180.0, vt = v * sin(th);
    double vn = v * cos(th), delta = 0.0, sl[2] = {vt, 0.0};
    dc_cmd_state hc;
    dc_cmdtp_state ht;
    dc_classical_tangential_state hs;
    memset(&hc, 0, sizeof hc);
    memset(&ht, 0, sizeof ht);
    memset(&hs, 0, sizeof hs);
    for (;;) {
      delta += vn * dt;
      if (delta <= 0.0) break;
      dc_hertz_state h;
      if (dc_hertz_contact(&g, Estar, delta, &h) != DC_OK) return 1;
      const dc_patch pa = {h.a, h.b, {ax[0], ax[1], ax[2]}, h.F, h.F, 1.0};
      const double du[3] = {sl[0] * dt, sl[1] * dt, 0.0}, vv[3] = {sl[0], sl[1], 0.0};
      double Ft[3];
      int st;
      if (law == -1 || law == -3) {
        dc_cmd_out o;
        st = law == -1 ? dc_cmd_step(&cp, &mp, &pa, NZ, du, 0.0, dt, &hc, &o)
                       : dc_cmdtp_step(&cp, &mp, &pa, NZ, du, 0.0, dt, &ht, &o);
        memcpy(Ft, o.Ft, sizeof Ft);
      } else {
        dc_classical_tangential_out o;
        st = dc_classical_tangential_step(m, &pa, &cc, NZ, du, vv, dt, &hs, &o);
        memcpy(Ft, o.Ft, sizeof Ft);
      }
      if (st != DC_OK) return 1;
      vn -= h.F / mass * dt;
      sl[0] -= 3.5 * Ft[0] / mass * dt;
      sl[1] -= 3.5 * Ft[1] / mass * dt;
      *acc += Ft[0];
      ++*steps;
    }
    if (beta) beta[k] = sl[0] / vt;
  }
  return 0;
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
      {"cmd_tangential cmdMemory turningPoints", -3, 0},
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
    if (law_model(rows[k].law, MU, Gstar, Estar, &m) != DC_OK) return 1;
    run(&m, rows[k].law, F, &acc);
    report_err e = {0};
    for (int i = 0; i < nstep; i++) report_err_add(&e, (F[i] - Fref[i]) / (MU * Fn));
    double ns;
    REPORT_TIME(ns, 1, run(&m, rows[k].law, NULL, &acc));
    report_row("tangential", "shear cycles 0.5 and 2 slip distances", rows[k].name, rows[k].exact, ns / nstep, &e,
               "max |F_t - F_t cmd_tangential| / mu F_n (rms)", "");
  }

  /* oblique impacts, sphere and ellipsoid tip */
  for (int ell = 0; ell < 2; ell++) {
    const char *scene = ell ? "oblique impacts 5-80 deg: ellipsoid tip's patch (b/a 0.56)"
                            : "oblique impacts 5-80 deg (alumina spheres; Chung & Ooi)";
    const law_row orows[] = {
        {"cmd_tangential", -1, 1},
        {"cmd_tangential cmdMemory turningPoints", -3, 0},
        {"springSliding: Mindlin K_t (stock history)", DC_CT_SPRING_SLIDING, 0},
        {"diRenzo", DC_CT_DI_RENZO, 0},
        {"incremental: Mindlin K0", DC_CT_INCREMENTAL, 0},
    };
    double bref[NANGLE], b[NANGLE];
    long steps;
    dc_classical_tangential none;
    memset(&none, 0, sizeof none);
    if (oblique(&none, -1, ell, bref, &steps, &acc)) return 1;
    for (size_t k = 0; k < sizeof orows / sizeof orows[0]; k++) {
      dc_classical_tangential m;
      const double E = 3.8e11, nu = 0.23, G = E / (2.0 * (1.0 + nu));
      if (law_model(orows[k].law, 0.092, G / (2.0 * (2.0 - nu)), E / (2.0 * (1.0 - nu * nu)), &m) != DC_OK) return 1;
      if (oblique(&m, orows[k].law, ell, b, &steps, &acc)) return 1;
      report_err e = {0};
      for (int i = 0; i < NANGLE; i++) report_err_add(&e, b[i] - bref[i]);
      double ns;
      REPORT_TIME(ns, 1, oblique(&m, orows[k].law, ell, NULL, &steps, &acc));
      char note[64];
      snprintf(note, sizeof note, "beta at 10 deg %.4f (exact %.4f)", b[1], bref[1]);
      report_row("tangential", scene, orows[k].name, orows[k].exact, ns / steps, &e,
                 "max |beta - beta cmd_tangential| over the angles (rms)", note);
    }
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
      if (law_model(rrows[k].law, MU, Gstar, Estar, &m) != DC_OK) return 1;
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
