/* Speed-versus-error report, family "classical normal": the lecture notes'
   classical normal laws (dc/classical_normal.h) against Hertz with
   restitution damping (stock LIGGGHTS `hertz`, hertz_elliptic's default)
   on an impact series.

   Scene: two spheres of diameter 3 mm, density 2500 kg/m^3, E = 5 MPa,
   nu = 0.3 (those of the report's LIGGGHTS packing), restitution e = 0.5,
   collide head-on at 0.05, 0.1, 0.2, 0.5, 1 and 2 m/s; the characteristic
   velocity of the matched stiffnesses and of the fitted coefficients is
   0.5 m/s. Each collision is integrated (classical Runge-Kutta, 20000
   steps per Hertz collision time, the first one split into 40 doubling
   steps, the end of contact found by bisection within the last step) until the overlap returns to 0 or, for the
   hysteretic laws, the force vanishes at the residual overlap. Reference:
   the same integration of F = 4/3 E* R^1/2 delta^3/2 + 2 (5/6)^1/2
   (-beta) (S m)^1/2 d(delta)/dt, S = dF_el/d delta, written out here
   (beta = ln e / (ln^2 e + pi^2)^1/2). The integrator is checked first
   against the closed forms of the elastic Hertz and the damped linear
   collision (the program stops if they disagree by 1e-7).
   Coefficients without a restitution setting are fitted here so that the
   law rebounds with e at 0.5 m/s: viscoelasticTime (BSHP),
   kuwabaraKonoDamping, unloadingStiffnessSlope (hlsVariable); they are
   written to the file named by the first argument, for the LIGGGHTS scene.

   Error: max over the impact speeds of the relative error of the rebound
   velocity and of the collision duration. Kernel call:
   dc_classical_normal_step along the reference collision. Prints CSV
   (report_common.h). */
#include "dc/classical_normal.h"
#include "dc/damping.h"
#include "dc/status.h"
#include <float.h>
#include "report_common.h"

static const double E_YOUNG = 5e6, NU = 0.3, DENSITY = 2500.0, DIAMETER = 3e-3, E_REST = 0.5, V_CHAR = 0.5;
static const double SPEEDS[] = {0.05, 0.1, 0.2, 0.5, 1.0, 2.0};
enum { NV = sizeof SPEEDS / sizeof SPEEDS[0] };
#define STEPS_PER_TC 20000
#define NTIME 4096

static double Estar, Reff, meff;

/* A law under test: a c_core classical law, or (ref = 1) the reference. */
typedef struct {
  int ref;
  dc_classical_normal m;
} law;

typedef struct {
  double e, Tc;
} collision;

/* Total normal force and elastic force of the contact at (delta, ddelta);
   h: the law's history, updated. The overlap is taken as at least DBL_MIN:
   the contact acts from touch on (a dashpot pushes at delta = 0+), and an
   integration stage just past the end of contact sees the same law. */
static void force(const law *L, double delta, double ddelta, dc_classical_normal_state *h, double *F, double *Fel)
{
  delta = fmax(delta, DBL_MIN);
  if (L->ref) {
    const double lne = log(E_REST), beta = lne / sqrt(lne * lne + M_PI * M_PI);
    const double K = 4.0 / 3.0 * Estar * sqrt(Reff), S = 1.5 * K * sqrt(delta);
    *Fel = K * delta * sqrt(delta);
    *F = *Fel + 2.0 * sqrt(5.0 / 6.0) * (-beta) * sqrt(S * meff) * ddelta;
    return;
  }
  dc_classical_normal_out o;
  if (dc_classical_normal_step(&L->m, Reff, meff, delta, ddelta, h, &o) != DC_OK) {
    fprintf(stderr, "bench_report_impact: law failed at delta %g\n", delta);
    exit(1);
  }
  *F = o.F;
  *Fel = o.c.F;
}

/* One Runge-Kutta step of m delta'' = -F from (x, v) over dt; the history
   is advanced only by the accepted end state (stages use copies). */
static void rk4(const law *L, const dc_classical_normal_state *h, double x, double v, double dt, double *x1, double *v1)
{
  double F, Fel;
  dc_classical_normal_state c = *h;
  force(L, x, v, &c, &F, &Fel);
  const double k1x = v, k1v = -F / meff;
  c = *h;
  force(L, x + 0.5 * dt * k1x, v + 0.5 * dt * k1v, &c, &F, &Fel);
  const double k2x = v + 0.5 * dt * k1v, k2v = -F / meff;
  c = *h;
  force(L, x + 0.5 * dt * k2x, v + 0.5 * dt * k2v, &c, &F, &Fel);
  const double k3x = v + 0.5 * dt * k2v, k3v = -F / meff;
  c = *h;
  force(L, x + dt * k3x, v + dt * k3v, &c, &F, &Fel);
  const double k4x = v + dt * k3v, k4v = -F / meff;
  *x1 = x + dt / 6.0 * (k1x + 2 * k2x + 2 * k3x + k4x);
  *v1 = v + dt / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v);
}

/* In contact: overlap, and a repulsive elastic force once unloading (the
   hysteretic laws let go at the residual overlap). */
static int touching(const law *L, const dc_classical_normal_state *h, double x, double v)
{
  if (!(x > 0.0)) return 0;
  double F, Fel;
  dc_classical_normal_state c = *h;
  force(L, x, v, &c, &F, &Fel);
  return v > 0.0 || Fel > 0.0;
}

/* Elastic Hertz collision duration at v0 (the time scale of the steps). */
static double hertz_tc(double v0)
{
  dc_classical_collision c;
  dc_classical_hertz_collision(4.0 / 3.0 * Estar * sqrt(Reff), meff, v0, &c);
  return c.Tc;
}

/* One collision at impact velocity v0; with path, its states (overlap,
   rate) at every step go there (at most MAXPATH, their count to *npath). */
#define MAXPATH (2 * STEPS_PER_TC)
static collision collide(const law *L, double v0, double (*path)[2], int *npath)
{
  const double dt0 = hertz_tc(v0) / STEPS_PER_TC;
  dc_classical_normal_state h = {0};
  double x = 0.0, v = v0, t = 0.0;
  for (long n = 0; n < 20L * STEPS_PER_TC; n++) {
    /* the first step in 40 doubling ones: damping ~ delta^1/4 or delta^1/2
       has no bounded derivative at touch */
    const double dt = n < 40 ? ldexp(dt0, (int)n - 40) : dt0;
    double x1, v1, F, Fel;
    rk4(L, &h, x, v, dt, &x1, &v1);
    if (!touching(L, &h, x1, v1)) {
      /* the end lies in this step: bisect on its length */
      double lo = 0.0, hi = dt;
      for (int it = 0; it < 60; it++) {
        const double mid = 0.5 * (lo + hi);
        rk4(L, &h, x, v, mid, &x1, &v1);
        if (touching(L, &h, x1, v1)) lo = mid; else hi = mid;
      }
      rk4(L, &h, x, v, hi, &x1, &v1);
      return (collision){-v1 / v0, t + hi};
    }
    x = x1, v = v1, t += dt;
    force(L, x, v, &h, &F, &Fel);   /* accept: advance the history */
    if (path && n < MAXPATH) path[n][0] = x, path[n][1] = v, *npath = (int)n + 1;
  }
  fprintf(stderr, "bench_report_impact: no rebound within 20 collision times\n");
  exit(1);
}

/* The integrator against closed forms: elastic Hertz (duration) and the
   damped linear spring-dashpot (restitution, duration). */
static void check_integrator(void)
{
  const double K = 1e3, eta = 2e-2;
  dc_classical_normal_params p = {0};
  p.law = DC_CLASSICAL_HERTZ, p.damping = DC_DAMPING_NONE, p.Estar = Estar;
  law hz = {0};
  dc_param_error err;
  dc_classical_normal_init(&p, &hz.m, &err);
  const collision c = collide(&hz, V_CHAR, NULL, NULL);
  /* a linear law with this K and eta: LSD with K given and e from eta */
  const double W = sqrt(K / meff - eta * eta / (4 * meff * meff)), e = exp(-eta / (2 * meff) * M_PI / W);
  p.law = DC_CLASSICAL_LSD, p.stiffness = DC_CLASSICAL_K_GIVEN, p.kn = K, p.e = e;
  law lsd = {0};
  dc_classical_normal_init(&p, &lsd.m, &err);
  const collision d = collide(&lsd, V_CHAR, NULL, NULL);
  dc_classical_collision lc;
  dc_classical_lsd_collision(K, lsd.m.zeta * sqrt(meff * K), meff, V_CHAR, 0, &lc);
  const double worst = fmax(fmax(fabs(c.Tc / hertz_tc(V_CHAR) - 1), fabs(c.e - 1)),
                            fmax(fabs(d.e / lc.e - 1), fabs(d.Tc / lc.Tc - 1)));
  if (!(worst < 1e-7)) {
    fprintf(stderr, "bench_report_impact: integrator off the closed forms by %.3g\n", worst);
    exit(1);
  }
}

/* A c_core law from its settings; the coefficient x is the fitted one
   (viscoelasticTime A, kuwabaraKonoDamping eta or unloadingStiffnessSlope S). */
static law classical(int lawid, int stiffness, int damping, double x)
{
  dc_classical_normal_params p = {0};
  p.law = lawid, p.stiffness = stiffness, p.damping = damping;
  p.Estar = Estar, p.v_char = V_CHAR, p.e = E_REST, p.A = x, p.eta_kk = x, p.S = x;
  law L = {0};
  dc_param_error err;
  if (dc_classical_normal_init(&p, &L.m, &err) != DC_OK) {
    fprintf(stderr, "bench_report_impact: %s = %g outside %s\n", err.name, err.value, err.range);
    exit(1);
  }
  return L;
}

/* The coefficient x in (0, inf) of a law whose restitution at V_CHAR falls
   as x grows, such that it is E_REST (bisection in log x). */
static double fit(int lawid, int stiffness, int damping, double x0)
{
  double lo = x0, hi = x0;
  law L = classical(lawid, stiffness, damping, hi);
  while (collide(&L, V_CHAR, NULL, NULL).e > E_REST) hi *= 4.0, L = classical(lawid, stiffness, damping, hi);
  L = classical(lawid, stiffness, damping, lo);
  while (collide(&L, V_CHAR, NULL, NULL).e < E_REST) lo /= 4.0, L = classical(lawid, stiffness, damping, lo);
  for (int it = 0; it < 50; it++) {
    const double mid = sqrt(lo * hi);
    L = classical(lawid, stiffness, damping, mid);
    if (collide(&L, V_CHAR, NULL, NULL).e > E_REST) lo = mid; else hi = mid;
  }
  return sqrt(lo * hi);
}

static double path[MAXPATH][2];
static double xs[NTIME], vs[NTIME];

int main(int argc, char **argv)
{
  const double m = DENSITY * M_PI / 6.0 * DIAMETER * DIAMETER * DIAMETER;
  Estar = 1.0 / (2.0 * (1.0 - NU * NU) / E_YOUNG);
  Reff = 0.25 * DIAMETER;
  meff = 0.5 * m;
  check_integrator();

  /* the reference series, and its collision at V_CHAR as the timing path */
  law ref = {0};
  ref.ref = 1;
  collision R[NV];
  int npath = 0;
  for (int k = 0; k < NV; k++) R[k] = collide(&ref, SPEEDS[k], SPEEDS[k] == V_CHAR ? path : NULL, &npath);
  for (int i = 0; i < NTIME; i++) {
    const int j = (int)((long)i * npath / NTIME);
    xs[i] = path[j][0], vs[i] = path[j][1];
  }

  const double tc = hertz_tc(V_CHAR), S_scale = 1.0 / (V_CHAR * tc);
  const double A = fit(DC_CLASSICAL_HERTZ, 0, DC_DAMPING_VISCOELASTIC, 0.1 * tc);
  const double eta = fit(DC_CLASSICAL_HERTZ, 0, DC_DAMPING_KUWABARA_KONO, 0.2 * tc * Estar * sqrt(Reff));
  const double S = fit(DC_CLASSICAL_HLS_VARIABLE, DC_CLASSICAL_K_OVERLAP, 0, S_scale);
  if (argc > 1) {
    FILE *f = fopen(argv[1], "w");
    if (!f) return 1;
    fprintf(f, "characteristicVelocity %.17g\nviscoelasticTime %.17g\nkuwabaraKonoDamping %.17g\n"
               "unloadingStiffnessSlope %.17g\n", V_CHAR, A, eta, S);
    fclose(f);
  }

  struct {
    const char *name;
    law L;
    int exact;
  } laws[] = {
      {"hertz: restitution damping", classical(DC_CLASSICAL_HERTZ, 0, DC_DAMPING_RESTITUTION, 0), 1},
      {"hertz: tsuji damping", classical(DC_CLASSICAL_HERTZ, 0, DC_DAMPING_TSUJI, 0), 0},
      {"hertz: viscoelastic damping (A fitted)", classical(DC_CLASSICAL_HERTZ, 0, DC_DAMPING_VISCOELASTIC, A), 0},
      {"hertz: kuwabaraKono damping (eta fitted)", classical(DC_CLASSICAL_HERTZ, 0, DC_DAMPING_KUWABARA_KONO, eta), 0},
      {"hertz: no damping", classical(DC_CLASSICAL_HERTZ, 0, DC_DAMPING_NONE, 0), 0},
      {"lsd: stiffness duration", classical(DC_CLASSICAL_LSD, DC_CLASSICAL_K_DURATION, 0, 0), 0},
      {"lsd: stiffness overlap", classical(DC_CLASSICAL_LSD, DC_CLASSICAL_K_OVERLAP, 0, 0), 0},
      {"lsd: stiffness energy", classical(DC_CLASSICAL_LSD, DC_CLASSICAL_K_ENERGY, 0, 0), 0},
      {"hlsConstant: stiffness duration", classical(DC_CLASSICAL_HLS_CONSTANT, DC_CLASSICAL_K_DURATION, 0, 0), 0},
      {"hlsConstant: stiffness overlap", classical(DC_CLASSICAL_HLS_CONSTANT, DC_CLASSICAL_K_OVERLAP, 0, 0), 0},
      {"hlsVariable: stiffness overlap (S fitted)",
       classical(DC_CLASSICAL_HLS_VARIABLE, DC_CLASSICAL_K_OVERLAP, 0, S), 0},
  };
  report_header();
  for (size_t k = 0; k < sizeof laws / sizeof laws[0]; k++) {
    const law *L = &laws[k].L;
    report_err e = {0}, er = {0}, et = {0};
    for (int j = 0; j < NV; j++) {
      const collision c = collide(L, SPEEDS[j], NULL, NULL);
      report_err_add(&er, c.e / R[j].e - 1.0);
      report_err_add(&et, c.Tc / R[j].Tc - 1.0);
      report_err_add(&e, c.e / R[j].e - 1.0);
      report_err_add(&e, c.Tc / R[j].Tc - 1.0);
    }
    double ns;
    dc_classical_normal_state h = {0};
    dc_classical_normal_out o;
    REPORT_TIME(ns, NTIME, {
      if (i == 0) h.delta_max = 0.0;
      dc_classical_normal_step(&L->m, Reff, meff, xs[i], vs[i], &h, &o);
      acc += o.F;
    });
    char note[96];
    snprintf(note, sizeof note, "rebound %.2g; duration %.2g", er.max, et.max);
    report_row("classical normal", "sphere impacts 0.05-2 m/s e = 0.5", laws[k].name, laws[k].exact, ns, &e,
               "max relative error of rebound velocity and collision time (rms)", note);
  }
  return 0;
}
