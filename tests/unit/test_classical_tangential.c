/* Classical tangential laws (dc/classical_tangential.h): the sliding limit
   mu F_n, the stick stiffness of every law and stiffness setting (against
   the notes' forms: Mindlin's ratio (1 - nu)/(1 - nu/2), Tsuji's
   (2R)^1/2 E / ((2 - nu)(1 + nu)) delta^1/2, Langston's slip distance
   mu (2 - nu)/(2 (1 - nu)) delta_n), energies (dissipation per cycle of
   the spring with sliding and of Langston's law; Walton-Braun's virgin and
   reversal curves and its stable loop against tests/reference/classical.csv),
   the tangential restitution of Deen's damping, the damping forms, 3D
   (plane rotation, i/j swap), the parameter checks, the history fields
   each law owns, edge magnitudes and a random never-NaN sweep, in which
   the inline unchecked step (classical_tangential_step.h, checked = 0)
   matches the checked one bit for bit on every call the checked one
   accepts and never returns a non-finite result. */
#include "check.h"
#include "dc/classical_tangential.h"
#include "dc/classical_tangential_step.h"
#include "dc/status.h"
#include <float.h>
#include <string.h>

typedef dc_classical_tangential_params ct_params;
typedef dc_classical_tangential ct_model;
typedef dc_classical_tangential_state ct_state;
typedef dc_classical_tangential_out ct_out;
typedef dc_classical_tangential_contact ct_contact;

static const double NZ[3] = {0.0, 0.0, 1.0};

static ct_params params0(int law)
{
  ct_params p;
  memset(&p, 0, sizeof p);
  p.law = law;
  p.mu = 0.4;
  p.kt = 2e5;
  p.gammat = 0.05;
  p.Gstar = 7e9;
  p.Estar = 3e10;
  p.stiffness = DC_CT_KT_GIVEN;
  p.damping = DC_CT_DAMP_NONE;
  return p;
}

static ct_model model(const ct_params *p)
{
  ct_model m;
  dc_param_error err;
  const int st = dc_classical_tangential_init(p, &m, &err);
  CHECK(st == DC_OK);
  return m;
}

static dc_patch patch_of(double a, double F)
{
  dc_patch pa;
  memset(&pa, 0, sizeof pa);
  pa.a = pa.b = a;
  pa.F_elastic = pa.F_bound = F;
  pa.formed = 1.0;
  return pa;
}

static const ct_contact C0 = {5e-6, 1e6, 0.02};

static int step1(const ct_model *m, const dc_patch *pa, double dx, double v, ct_state *h, ct_out *o)
{
  const double du[3] = {dx, 0.0, 0.0}, vt[3] = {v, 0.0, 0.0};
  return dc_classical_tangential_step(m, pa, &C0, NZ, du, vt, 0.0, h, o);
}

static double norm3(const double *v)
{
  const double m = fmax(fabs(v[0]), fmax(fabs(v[1]), fabs(v[2])));
  if (!(m > 0.0) || !isfinite(m)) return m;
  const double a = v[0] / m, b = v[1] / m, c = v[2] / m;
  return m * sqrt(a * a + b * b + c * c);
}

/* ------------------------------------------------------------------ */

static void test_sliding_limit(void)
{
  const dc_patch pa = patch_of(1e-4, 3.0);
  const double lim = 0.4 * 3.0;
  for (int law = 0; law <= DC_CT_INCREMENTAL; law++) {
    if (law == DC_CT_VISCOUS) continue;
    ct_params p = params0(law);
    p.gammat = 1.0;
    p.damping = DC_CT_DAMP_GIVEN;
    p.eta_l = 0.3;
    p.t_visc = 1e-7;
    const ct_model m = model(&p);
    ct_state h;
    memset(&h, 0, sizeof h);
    ct_out o;
    int ok = 1, never_above = 1;
    /* load far past the slip point, with velocity 2 m/s, along x then y */
    for (int i = 0; i < 400; i++) {
      const double dx = i < 200 ? 1e-6 : 0.0, dy = i < 200 ? 0.0 : 1e-6;
      const double du[3] = {dx, dy, 0.0}, vt[3] = {2.0 * (dx > 0), 2.0 * (dy > 0), 0.0};
      ok &= dc_classical_tangential_step(&m, &pa, &C0, NZ, du, vt, 0.0, &h, &o) == DC_OK;
      never_above &= norm3(o.Ft) <= lim * (1.0 + 1e-15);
    }
    char what[64];
    snprintf(what, sizeof what, "law %d slides at mu F_n", law);
    CHECK(ok && never_above);
    CHECK_REL(norm3(o.Ft), lim, 1e-15, what);
    CHECK(o.sliding == 1 && o.kt == 0.0);
    /* in the direction of the last motion (y) */
    CHECK(o.Ft[1] > 0.99 * lim && fabs(o.Ft[2]) == 0.0);
  }
  /* Coulomb: mu F_n along v; nothing at rest */
  ct_params p = params0(DC_CT_COULOMB);
  const ct_model m = model(&p);
  ct_state h = {{0}, {0}};
  ct_out o;
  const double du[3] = {0}, vt[3] = {3.0, -4.0, 0.0};
  CHECK(dc_classical_tangential_step(&m, &pa, &C0, NZ, du, vt, 0.0, &h, &o) == DC_OK);
  CHECK_REL(o.Ft[0], 0.6 * lim, 1e-15, "Coulomb x");
  CHECK_REL(o.Ft[1], -0.8 * lim, 1e-15, "Coulomb y");
  const double v0[3] = {0};
  CHECK(dc_classical_tangential_step(&m, &pa, &C0, NZ, du, v0, 0.0, &h, &o) == DC_OK);
  CHECK(o.Ft[0] == 0.0 && o.Ft[1] == 0.0 && o.sliding == 0);
  /* viscous: eta v, no limit; viscous with sliding below the limit */
  p = params0(DC_CT_VISCOUS);
  p.mu = -1.0;   /* not read */
  ct_model mv = model(&p);
  CHECK(dc_classical_tangential_step(&mv, &pa, &C0, NZ, du, vt, 0.0, &h, &o) == DC_OK);
  CHECK_REL(o.Ft[0], 0.05 * 3.0, 1e-15, "viscous force");
  CHECK(o.gammat == 0.05);
  p = params0(DC_CT_VISCOUS_SLIDING);
  mv = model(&p);
  const double vs[3] = {1.0, 0.0, 0.0};
  CHECK(dc_classical_tangential_step(&mv, &pa, &C0, NZ, du, vs, 0.0, &h, &o) == DC_OK);
  CHECK(o.Ft[0] == 0.05 && o.sliding == 0);
}

/* Stick stiffness: F = K du for a small first step. */
static void test_stiffness(void)
{
  const double E = 63e9, nu = 0.2, G = E / (2.0 * (1.0 + nu));
  const double Estar = E / (2.0 * (1.0 - nu * nu)), Gstar = G / (2.0 * (2.0 - nu));
  const double Rp = 1e-3, R = 0.5 * Rp, dn = 1e-6, a = sqrt(R * dn);
  const double Fn = 4.0 / 3.0 * Estar * sqrt(R) * pow(dn, 1.5);
  const dc_patch pa = patch_of(a, Fn);
  const double dx = 1e-12;
  struct { int law, stiffness; double K; const char *what; } cases[] = {
    {DC_CT_SPRING_SLIDING, DC_CT_KT_GIVEN, 2e5, "given kt"},
    {DC_CT_SPRING_DASHPOT_SLIDING, DC_CT_KT_RATIO, (1.0 - nu) / (1.0 - 0.5 * nu) * C0.kn,
     "ratio (1 - nu)/(1 - nu/2) K_n (notes 4.6)"},
    {DC_CT_SPRING_SLIDING, DC_CT_KT_MINDLIN, 8.0 * Gstar * a, "Mindlin 8 G* a"},
    {DC_CT_DI_RENZO, 0, 16.0 / 3.0 * Gstar * sqrt(R * dn), "Di Renzo-Di Maio 16/3 G* (R delta_n)^1/2"},
    {DC_CT_TSUJI, 0, sqrt(2.0 * Rp) * E / ((2.0 - nu) * (1.0 + nu)) * sqrt(dn),
     "Tsuji (2R)^1/2 E/((2 - nu)(1 + nu)) delta_n^1/2"},
    {DC_CT_LANGSTON, 0, 8.0 * Gstar * a, "Langston initial slope"},
    {DC_CT_ZHENG, 0, 8.0 * Gstar * a, "Zheng initial slope"},
    {DC_CT_INCREMENTAL, DC_CT_KT_MINDLIN, 8.0 * Gstar * a, "incremental K0"},
  };
  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
    ct_params p = params0(cases[i].law);
    p.stiffness = cases[i].stiffness;
    p.Gstar = Gstar;
    p.Estar = Estar;
    p.damping = DC_CT_DAMP_NONE;
    p.mu = 0.5;
    const ct_model m = model(&p);
    ct_state h;
    memset(&h, 0, sizeof h);
    ct_out o;
    CHECK(step1(&m, &pa, dx, 0.0, &h, &o) == DC_OK);
    const double tol = cases[i].law >= DC_CT_LANGSTON && cases[i].law != DC_CT_TSUJI ? 1e-6 : 1e-14;
    CHECK_REL(o.Ft[0] / dx, cases[i].K, tol, cases[i].what);
    if (cases[i].law != DC_CT_LANGSTON && cases[i].law != DC_CT_ZHENG && cases[i].law != DC_CT_INCREMENTAL)
      CHECK_REL(o.kt, cases[i].K, 1e-14, cases[i].what);
  }
  /* Langston's slip distance: 3 mu F_n / (2 K0) = notes' mu (2 - nu)/(2 (1 - nu)) delta_n */
  ct_params p = params0(DC_CT_LANGSTON);
  p.Gstar = Gstar;
  p.mu = 0.5;
  const ct_model m = model(&p);
  const double d = 0.5 * (2.0 - nu) / (2.0 * (1.0 - nu)) * dn;
  ct_state h;
  ct_out o;
  /* just below and at d: F = mu F_n (1 - (1 - x)^3/2) */
  memset(&h, 0, sizeof h);
  CHECK(step1(&m, &pa, 0.999 * d, 0.0, &h, &o) == DC_OK);
  CHECK_REL(o.Ft[0], 0.5 * Fn * (1.0 - pow(0.001, 1.5)), 1e-12, "Langston below slip");
  CHECK(!o.sliding);
  memset(&h, 0, sizeof h);
  CHECK(step1(&m, &pa, d * (1.0 + 1e-12), 0.0, &h, &o) == DC_OK);
  CHECK(o.sliding);
  CHECK_REL(h.spring[0], d, 1e-12, "Langston slip distance = notes' mu (2 - nu)/(2 (1 - nu)) delta_n");
}

/* Work of the force over a displacement path x_k (trapezoid). */
static double cycle_work(const ct_model *m, const dc_patch *pa, double A, int n, int cycles, ct_state *h,
                         double *Fpeak)
{
  ct_out o;
  double x = 0.0, F = 0.0, W = 0.0;
  /* 0 -> A, then cycles of A -> -A -> A; the work of the last cycle */
  const int quarter = n;
  for (int i = 0; i < quarter; i++) {
    step1(m, pa, A / n, 0.0, h, &o);
    x += A / n;
    F = o.Ft[0];
  }
  for (int c = 0; c < cycles; c++) {
    W = 0.0;
    for (int i = 0; i < 4 * n; i++) {
      const double dx = i < 2 * n ? -A / n : A / n;
      step1(m, pa, dx, 0.0, h, &o);
      W += 0.5 * (F + o.Ft[0]) * dx;
      F = o.Ft[0];
      x += dx;
    }
  }
  if (Fpeak) *Fpeak = F;
  return W;
}

/* One cycle X -> -X -> X from the state h at x = X with force F0 there. */
static double cycle_work_from(const ct_model *m, const dc_patch *pa, double X, int n, double F0, ct_state *h,
                              double *Fend)
{
  ct_out o;
  double F = F0, W = 0.0;
  for (int i = 0; i < 4 * n; i++) {
    const double dx = i < 2 * n ? -X / n : X / n;
    step1(m, pa, dx, 0.0, h, &o);
    W += 0.5 * (F + o.Ft[0]) * dx;
    F = o.Ft[0];
  }
  *Fend = F;
  return W;
}

static void test_energy(void)
{
  const dc_patch pa = patch_of(1e-4, 1.0);
  /* linear spring with sliding: 4 mu F (A - mu F / K) per cycle */
  ct_params p = params0(DC_CT_SPRING_SLIDING);
  p.mu = 0.5;
  p.kt = 1e5;
  ct_model m = model(&p);
  const double A = 2e-5, lim = 0.5;
  ct_state h;
  double W[3];
  const int ns[3] = {50, 500, 5000};
  for (int k = 0; k < 3; k++) {
    memset(&h, 0, sizeof h);
    W[k] = cycle_work(&m, &pa, A, ns[k], 2, &h, NULL);
  }
  const double W0 = 4.0 * lim * (A - lim / 1e5);
  printf("spring with sliding, cycle energy vs 4 mu F (A - mu F/K): steps/quarter 50 %.3g, 500 %.3g, 5000 %.3g\n",
         fabs(W[0] / W0 - 1), fabs(W[1] / W0 - 1), fabs(W[2] / W0 - 1));
  /* exact at every step size here: the force is piecewise linear in x
     with its corners on the steps */
  CHECK_REL(W[0], W0, 1e-12, "spring with sliding: cycle energy");
  CHECK_REL(W[2], W0, 1e-12, "spring with sliding: cycle energy");
  /* within the elastic range nothing is lost */
  memset(&h, 0, sizeof h);
  CHECK(fabs(cycle_work(&m, &pa, 0.5 * lim / 1e5, 500, 2, &h, NULL)) < 1e-20);

  /* Langston: elastic below d, 4 mu F (A - d) per cycle beyond */
  p = params0(DC_CT_LANGSTON);
  p.mu = 0.5;
  p.Gstar = 1e9;
  m = model(&p);
  const double K0 = 8e9 * 1e-4, d = 1.5 * lim / K0;
  for (int k = 0; k < 3; k++) {
    memset(&h, 0, sizeof h);
    W[k] = cycle_work(&m, &pa, 3.0 * d, ns[k], 2, &h, NULL);
  }
  const double WL = 4.0 * lim * (3.0 * d - d);
  printf("Langston, cycle energy vs 4 mu F (A - d): 50 %.3g, 500 %.3g, 5000 %.3g\n", fabs(W[0] / WL - 1),
         fabs(W[1] / WL - 1), fabs(W[2] / WL - 1));
  CHECK_REL(W[2], WL, 1e-6, "Langston: cycle energy");
  memset(&h, 0, sizeof h);
  CHECK(fabs(cycle_work(&m, &pa, 0.9 * d, 500, 2, &h, NULL)) < 1e-12 * lim * d);

  /* Walton-Braun: virgin curve and reversal exact at any step size */
  p = params0(DC_CT_INCREMENTAL);
  p.kt = 1e5;
  p.mu = 1.0;
  m = model(&p);
  const double K = 1e5, N = 1.0;
  memset(&h, 0, sizeof h);
  ct_out o;
  double x = 0.0;
  int ok = 1;
  for (int i = 0; i < 7; i++) {   /* 7 uneven steps to 1.3e-5 */
    const double dx = 1.3e-5 * (i + 1) / 28.0;
    step1(&m, &pa, dx, 0.0, &h, &o);
    x += dx;
    const double want = N * (1.0 - pow(1.0 - 2.0 * K * x / (3.0 * N), 1.5));
    ok &= fabs(o.Ft[0] - want) <= 2e-15 * N;
  }
  CHECK(ok);   /* virgin: F = mu N (1 - (1 - 2 K0 x / (3 mu N))^3/2) */
  const double T1 = o.Ft[0];
  double xi = 0.0;
  ok = 1;
  for (int i = 0; i < 5; i++) {
    const double dx = 4e-6;
    step1(&m, &pa, -dx, 0.0, &h, &o);
    xi += dx;
    const double D = N + T1;
    const double want = T1 - D * (1.0 - pow(fmax(0.0, 1.0 - 2.0 * K * xi / (3.0 * D)), 1.5));
    ok &= fabs(o.Ft[0] - want) <= 4e-15 * N;
  }
  CHECK(ok);   /* after the reversal at T*: T* - T = (mu N + T*)(1 - (1 - 2 K0 xi/(3 (mu N + T*)))^3/2) */
  /* the sign s in the numerator: a reversal from the limit unloads with K0, and the force never exceeds mu N */
  memset(&h, 0, sizeof h);
  step1(&m, &pa, 1e-4, 0.0, &h, &o);
  CHECK(o.Ft[0] == N && o.sliding);
  step1(&m, &pa, -1e-9, 0.0, &h, &o);
  CHECK_REL((N - o.Ft[0]) / 1e-9, K, 1e-5, "reversal from the limit: stiffness K0");

  /* stable loops against the table (gen_classical.py) */
  FILE *f = check_open_reference("classical.csv");
  if (!f) return;
  double v[8];
  int rows = 0;
  while (check_next_tagged_row(f, "wbloop", v, 8) == 6) {
    p = params0(DC_CT_INCREMENTAL);
    p.kt = v[0];
    p.mu = v[1];
    m = model(&p);
    const double X = v[2];
    double Wc[3], TA = 0.0;
    /* the symmetric loop attracts slowly (each half cycle keeps about 0.9
       of the offset): 400 cycles at 50 steps a quarter first, exact
       since each step is; then one cycle at each step size */
    ct_state hs;
    memset(&hs, 0, sizeof hs);
    cycle_work(&m, &pa, X, 50, 400, &hs, &TA);
    for (int k = 0; k < 3; k++) {
      h = hs;
      Wc[k] = cycle_work_from(&m, &pa, X, ns[k], TA, &h, &TA);
    }
    char what[96];
    snprintf(what, sizeof what, "Walton-Braun stable loop amplitude (X = %g)", X);
    CHECK_REL(TA, v[3], 1e-12, what);
    snprintf(what, sizeof what, "Walton-Braun loop energy (X = %g)", X);
    CHECK_REL(Wc[2], v[4], 1e-6, what);
    printf("Walton-Braun X = %g: T_A %.15g (table %.15g); loop energy rel. error, steps/quarter 50 %.3g, "
           "500 %.3g, 5000 %.3g\n", X, TA, v[3], fabs(Wc[0] / v[4] - 1), fabs(Wc[1] / v[4] - 1),
           fabs(Wc[2] / v[4] - 1));
    CHECK(fabs(Wc[2] / v[4] - 1) < 0.02 * fabs(Wc[0] / v[4] - 1) + 1e-12);
    /* first loading reaches the table's virgin value at X */
    memset(&h, 0, sizeof h);
    step1(&m, &pa, X, 0.0, &h, &o);
    CHECK_REL(o.Ft[0], v[5], 1e-14, "virgin curve at X");
    rows++;
  }
  fclose(f);
  CHECK(rows == 3);
}

/* Deen et al.: with eta_t from e_t, a stuck contact of tangential mass
   2/7 m rebounds with e_t (RK4 of m_t x'' = -F, stages on copies of the
   history). */
static void test_deen(void)
{
  const dc_patch pa = patch_of(1e-4, 1e3);
  const double et[] = {0.0, 0.2, 0.6, 1.0};
  for (int k = 0; k < 4; k++) {
    ct_params p = params0(DC_CT_SPRING_DASHPOT_SLIDING);
    p.mu = 1.0;   /* friction out of reach */
    p.kt = 1e5;
    p.damping = DC_CT_DAMP_RESTITUTION;
    p.e_t = et[k];
    const ct_model m = model(&p);
    const double mt = 2.0 / 7.0 * C0.meff;
    const double l = log(et[k]);
    const double eta = et[k] == 0.0 ? 2.0 * sqrt(mt * 1e5) : -2.0 * l * sqrt(mt * 1e5) / sqrt(l * l + M_PI * M_PI);
    ct_state h;
    memset(&h, 0, sizeof h);
    ct_out o;
    step1(&m, &pa, 0.0, 1.0, &h, &o);
    CHECK_REL(o.gammat + 1e-300, eta + 1e-300, 1e-14, "Deen eta_t = -2 ln e_t (2/7 m K)^1/2 / (ln^2 e_t + pi^2)^1/2");
    if (et[k] == 0.0) continue;   /* critical: no rebound */
    memset(&h, 0, sizeof h);
    const double W = sqrt(1e5 / mt - eta * eta / (4.0 * mt * mt));
    const int n = 2000;
    const double dt = M_PI / W / n;
    double x = 0.0, v = 1.0;
    /* force of the law at (xs, vs) from the committed state (x, h) */
#define FORCE(xs, vs, out)                                                         \
    do {                                                                           \
      ct_state c_ = h;                                                             \
      ct_out o_;                                                                   \
      const double du_[3] = {(xs) - x, 0, 0}, vt_[3] = {(vs), 0, 0};               \
      dc_classical_tangential_step(&m, &pa, &C0, NZ, du_, vt_, 0.0, &c_, &o_);     \
      out = -o_.Ft[0] / mt;                                                        \
    } while (0)
    for (int i = 0; i < n; i++) {
      double a1, a2, a3, a4;
      FORCE(x, v, a1);
      FORCE(x + 0.5 * dt * v, v + 0.5 * dt * a1, a2);
      FORCE(x + 0.5 * dt * (v + 0.5 * dt * a1), v + 0.5 * dt * a2, a3);
      FORCE(x + dt * (v + 0.5 * dt * a2), v + dt * a3, a4);
      const double x1 = x + dt / 6.0 * (v + 2.0 * (v + 0.5 * dt * a1) + 2.0 * (v + 0.5 * dt * a2) + v + dt * a3);
      const double v1 = v + dt / 6.0 * (a1 + 2.0 * a2 + 2.0 * a3 + a4);
      const double du[3] = {x1 - x, 0, 0}, vt[3] = {v1, 0, 0};
      dc_classical_tangential_step(&m, &pa, &C0, NZ, du, vt, 0.0, &h, &o);
      x = x1;
      v = v1;
    }
#undef FORCE
    char what[64];
    snprintf(what, sizeof what, "tangential restitution e_t = %g", et[k]);
    CHECK_REL(-v, et[k], 1e-10, what);
    CHECK(fabs(x) < 1e-12 * (1.0 / W));
  }
}

static void test_damping_forms(void)
{
  const double Gs = 1e9, a = 1e-4, Fn = 2.0, mu = 0.5;
  const dc_patch pa = patch_of(a, Fn);
  const double K0 = 8.0 * Gs * a, d = 1.5 * mu * Fn / K0;
  /* Langston: F = mu F (1 - (1 - x)^3/2) + eta (4 m k)^1/2 v, k = K0 (1 - x)^1/2 */
  ct_params p = params0(DC_CT_LANGSTON);
  p.Gstar = Gs;
  p.mu = mu;
  p.eta_l = 0.3;
  ct_model m = model(&p);
  ct_state h;
  memset(&h, 0, sizeof h);
  ct_out o;
  const double x = 0.4 * d, vel = 1e-3;
  step1(&m, &pa, x, vel, &h, &o);
  const double k = K0 * sqrt(0.6);
  CHECK_REL(o.Ft[0], mu * Fn * (1.0 - pow(0.6, 1.5)) + 0.3 * sqrt(4.0 * C0.meff * k) * vel, 1e-14,
            "Langston force with the notes' viscous term (velocity, not delta_t)");
  CHECK_REL(o.kt, k, 1e-15, "Langston tangent stiffness");
  /* Zheng: + A_t (1 - 0.4 A_t |v|/d) k v, factor kept >= 0 */
  p = params0(DC_CT_ZHENG);
  p.Gstar = Gs;
  p.mu = mu;
  p.t_visc = 1e-6;
  m = model(&p);
  memset(&h, 0, sizeof h);
  step1(&m, &pa, x, vel, &h, &o);
  CHECK_REL(o.Ft[0], mu * Fn * (1.0 - pow(0.6, 1.5)) + 1e-6 * (1.0 - 0.4 * 1e-6 * vel / d) * k * vel, 1e-14,
            "Zheng force");
  memset(&h, 0, sizeof h);
  step1(&m, &pa, x, -1e6, &h, &o);   /* 0.4 A_t |v| / d > 1: no viscous part */
  CHECK_REL(o.Ft[0], mu * Fn * (1.0 - pow(0.6, 1.5)), 1e-14, "Zheng factor clipped at 0");
  /* Tsuji: eta_t = eta_n; damping NORMAL the same */
  p = params0(DC_CT_TSUJI);
  p.Gstar = Gs;
  m = model(&p);
  memset(&h, 0, sizeof h);
  step1(&m, &pa, 0.0, 1e-3, &h, &o);
  CHECK(o.gammat == C0.gamman && o.Ft[0] == C0.gamman * 1e-3);
  /* linear spring-dashpot sliding: spring set so that K s + eta v = the limit (notes 4.6) */
  p = params0(DC_CT_SPRING_DASHPOT_SLIDING);
  p.damping = DC_CT_DAMP_GIVEN;
  p.gammat = 10.0;
  p.mu = mu;
  m = model(&p);
  memset(&h, 0, sizeof h);
  step1(&m, &pa, 1e-4, 0.01, &h, &o);
  CHECK(o.sliding && o.Ft[0] == mu * Fn);
  CHECK_REL(h.spring[0], (mu * Fn - 10.0 * 0.01) / 2e5, 1e-14, "notes: delta_t = (mu F_n - eta v)/K_t");
}

/* 3D: the history turns with the plane; swapping i and j flips everything. */
static void test_3d(void)
{
  const dc_patch pa = patch_of(1e-4, 1.0);
  for (int law = DC_CT_SPRING_SLIDING; law <= DC_CT_INCREMENTAL; law++) {
    ct_params p = params0(law);
    p.stiffness = DC_CT_KT_MINDLIN;
    p.Gstar = 1e9;
    p.mu = 0.5;
    p.damping = DC_CT_DAMP_GIVEN;
    p.eta_l = 0.1;
    p.t_visc = 1e-7;
    const ct_model m = model(&p);
    ct_state h, hs;
    memset(&h, 0, sizeof h);
    memset(&hs, 0, sizeof hs);
    ct_out o, os;
    unsigned long long s = 12345u + law;
    int ok = 1, in_plane = 1, swap = 1, bounded = 1;
    double n[3] = {0.0, 0.0, 1.0};
    for (int i = 0; i < 2000; i++) {
      /* the normal wanders */
      n[0] += 0.02 * (check_uniform(&s) - 0.5);
      n[1] += 0.02 * (check_uniform(&s) - 0.5);
      const double ln = norm3(n);
      for (int k = 0; k < 3; k++) n[k] /= ln;
      double du[3], vt[3];
      for (int k = 0; k < 3; k++) {
        du[k] = 4e-8 * (check_uniform(&s) - 0.5 + (k == 0 ? 0.3 * sin(i * 0.01) : 0.0));
        vt[k] = du[k] / 1e-6;
      }
      ok &= dc_classical_tangential_step(&m, &pa, &C0, n, du, vt, 0.0, &h, &o) == DC_OK;
      const double ns[3] = {-n[0], -n[1], -n[2]}, dus[3] = {-du[0], -du[1], -du[2]},
                   vts[3] = {-vt[0], -vt[1], -vt[2]};
      ok &= dc_classical_tangential_step(&m, &pa, &C0, ns, dus, vts, 0.0, &hs, &os) == DC_OK;
      for (int k = 0; k < 3; k++) swap &= os.Ft[k] == -o.Ft[k] && hs.spring[k] == -h.spring[k];
      in_plane &= fabs(o.Ft[0] * n[0] + o.Ft[1] * n[1] + o.Ft[2] * n[2]) <= 1e-12 * (norm3(o.Ft) + 1e-300);
      bounded &= norm3(o.Ft) <= 0.5 * (1.0 + 1e-15);
    }
    char what[64];
    snprintf(what, sizeof what, "law %d in 3D", law);
    check_true_(ok && in_plane && swap && bounded, what, __FILE__, __LINE__);
  }
  /* a turned plane keeps the spring's length */
  ct_params p = params0(DC_CT_SPRING_SLIDING);
  p.mu = 10.0;
  const ct_model m = model(&p);
  ct_state h;
  memset(&h, 0, sizeof h);
  ct_out o;
  step1(&m, &pa, 1e-6, 0.0, &h, &o);
  const double n2[3] = {sin(0.3), 0.0, cos(0.3)}, zero[3] = {0};
  CHECK(dc_classical_tangential_step(&m, &pa, &C0, n2, zero, zero, 0.0, &h, &o) == DC_OK);
  CHECK_REL(norm3(h.spring), 1e-6, 1e-15, "turned spring keeps its length");
  CHECK(fabs(h.spring[0] * n2[0] + h.spring[2] * n2[2]) < 1e-20);
  /* not formed: history reset */
  dc_patch off = pa;
  off.formed = 0.0;
  CHECK(dc_classical_tangential_step(&m, &off, &C0, NZ, zero, zero, 0.0, &h, &o) == DC_OK);
  CHECK(h.spring[0] == 0.0 && o.Ft[0] == 0.0);
  /* du = NULL: vt dt */
  const double vt[3] = {2.0, 0.0, 0.0};
  CHECK(dc_classical_tangential_step(&m, &pa, &C0, NZ, NULL, vt, 1e-7, &h, &o) == DC_OK);
  CHECK_REL(h.spring[0], 2e-7, 1e-15, "du = vt dt");
  CHECK(dc_classical_tangential_step(&m, &pa, &C0, NZ, NULL, vt, 0.0, &h, &o) == DC_EDOM);
}

static void expect_error(const ct_params *p, const char *name)
{
  dc_param_error err;
  memset(&err, 0, sizeof err);
  const int st = dc_classical_tangential_check(p, &err);
  char what[128];
  snprintf(what, sizeof what, "check names %s (got %s)", name, err.name ? err.name : "nothing");
  check_true_(st == DC_EDOM && err.name && !strcmp(err.name, name), what, __FILE__, __LINE__);
}

static void test_checks(void)
{
  ct_params p = params0(DC_CT_SPRING_DASHPOT_SLIDING);
  dc_param_error err;
  CHECK(dc_classical_tangential_check(&p, &err) == DC_OK);
  ct_params q = p; q.law = 10; expect_error(&q, "classicalTangential");
  q = p; q.mu = -0.1; expect_error(&q, "coefficientFriction");
  q = p; q.stiffness = 3; expect_error(&q, "classicalTangentialStiffness");
  q = p; q.kt = 0.0; expect_error(&q, "kt");
  q = p; q.stiffness = DC_CT_KT_MINDLIN; q.Gstar = 0.0; expect_error(&q, "youngsModulus");
  q = p; q.stiffness = DC_CT_KT_RATIO; q.Estar = NAN; expect_error(&q, "youngsModulus");
  q = p; q.damping = 4; expect_error(&q, "classicalTangentialDamping");
  q = p; q.damping = DC_CT_DAMP_GIVEN; q.gammat = -1.0; expect_error(&q, "gammat");
  q = p; q.damping = DC_CT_DAMP_RESTITUTION; q.e_t = 1.1; expect_error(&q, "coefficientRestitutionTangential");
  q = params0(DC_CT_LANGSTON); q.eta_l = -1.0; expect_error(&q, "langstonDamping");
  q = params0(DC_CT_ZHENG); q.t_visc = INFINITY; expect_error(&q, "tangentialViscoelasticTime");
  q = params0(DC_CT_VISCOUS); q.gammat = NAN; expect_error(&q, "gammat");
  q = params0(DC_CT_DI_RENZO); q.Gstar = -1.0; expect_error(&q, "youngsModulus");
  /* unused fields are not read */
  q = params0(DC_CT_COULOMB); q.kt = NAN; q.Gstar = NAN; q.gammat = NAN; q.damping = 99;
  CHECK(dc_classical_tangential_check(&q, &err) == DC_OK);
  char buf[160];
  q = p; q.mu = -2.0;
  dc_classical_tangential_check(&q, &err);
  dc_param_error_format(&err, 2, 3, buf, sizeof buf);
  CHECK(!strcmp(buf, "coefficientFriction = -2 for types 2 and 3 is outside [0, inf)"));
  /* history table */
  CHECK(DC_CT_HISTORY_NFIELDS * sizeof(double) == sizeof(ct_state));
  int flips = 1;
  for (int k = 0; k < DC_CT_HISTORY_NFIELDS; k++) flips &= dc_classical_tangential_history[k].flips == 1;
  CHECK(flips && !strcmp(dc_classical_tangential_history[0].name, "ct_spring_x"));
}

/* The history a law owns, and edge magnitudes (cases of test_fuzz.c). */
static void test_history_and_edges(void)
{
  /* the laws but INCREMENTAL neither read nor write the reversal force (a
     wrapper stores only the spring; the next fields may be another
     model's): a NaN there was DC_EDOM, finite values were zeroed */
  for (int law = DC_CT_COULOMB; law <= DC_CT_TSUJI; law++) {
    const ct_params p = params0(law);
    const ct_model m = model(&p);
    const dc_patch pa = patch_of(1e-4, 1.0);
    for (int k = 0; k < 2; k++) {
      ct_state h = {{1e-7, 0.0, 0.0}, {k ? 7.0 : NAN, -1.5, 2.0}};
      const ct_state h0 = h;
      ct_out o;
      CHECK(step1(&m, &pa, 1e-8, 1e-3, &h, &o) == DC_OK && !memcmp(h.rev, h0.rev, sizeof h.rev));
    }
  }
  /* Langston limited by its viscous part: sliding, so no tangent stiffness
     (was K0 (1 - x)^1/2) */
  ct_params p = params0(DC_CT_LANGSTON);
  p.Gstar = 1e9;
  p.mu = 0.5;
  p.eta_l = 0.3;
  ct_model m = model(&p);
  dc_patch pa = patch_of(1e-4, 2.0);
  ct_state h;
  memset(&h, 0, sizeof h);
  ct_out o;
  const double d = 1.5 * p.mu * 2.0 / (8.0 * p.Gstar * 1e-4);
  CHECK(step1(&m, &pa, 0.1 * d, 10.0, &h, &o) == DC_OK && o.sliding == 1 && o.kt == 0.0);
  CHECK_REL(norm3(o.Ft), p.mu * 2.0, 1e-15, "Langston limited by its viscous part");
  /* Langston with the slip distance 1.5 mu F/K0 below the doubles (K0 =
     8e210, mu F = 4e-201): was DC_ERANGE (0/0), the force is mu F along
     the spring */
  p = params0(DC_CT_LANGSTON);
  p.Gstar = 1e10;
  m = model(&p);
  pa = patch_of(1e200, 1e-200);
  memset(&h, 0, sizeof h);
  CHECK(step1(&m, &pa, 1e-9, 0.0, &h, &o) == DC_OK && o.sliding == 1 && o.kt == 0.0);
  CHECK_REL(o.Ft[0], 0.4 * 1e-200, 1e-15, "Langston at the limit, slip distance underflowed");
  /* Coulomb with a subnormal velocity: was above mu F by 1e-11 and out of
     the plane (too few bits for a direction) */
  p = params0(DC_CT_COULOMB);
  m = model(&p);
  pa = patch_of(1e-4, 1.0);
  memset(&h, 0, sizeof h);
  const double n[3] = {0.6, 0.0, 0.8}, vt[3] = {3e-313, -1.5e-313, 5.2e-313};
  CHECK(dc_classical_tangential_step(&m, &pa, &C0, n, NULL, vt, 1e-6, &h, &o) == DC_OK);
  const double F = norm3(o.Ft);
  CHECK(F <= 0.4 * (1.0 + 2e-16) && F >= 0.4 * (1.0 - 4e-16));
  CHECK(fabs(o.Ft[0] * n[0] + o.Ft[1] * n[1] + o.Ft[2] * n[2]) <= 1e-16);
}

static double wild(unsigned long long *s)
{
  const double specials[] = {0.0, -0.0, 1.0, -1.0, DBL_MIN, DBL_MAX, -DBL_MAX, 5e-324, 1e-300, 1e300,
                             INFINITY, -INFINITY, NAN};
  if (check_uniform(s) < 0.3) return specials[(int)(check_uniform(s) * 13) % 13];
  const double mag = pow(10.0, -320.0 + 628.0 * check_uniform(s));
  return check_uniform(s) < 0.3 ? -mag : mag;
}

static double typical(unsigned long long *s, double lo, double hi) { return lo * pow(hi / lo, check_uniform(s)); }

/* Every field bit for bit (not the padding). */
static int same_out(const ct_out *a, const ct_out *b)
{
  return memcmp(a->Ft, b->Ft, sizeof a->Ft) == 0 && memcmp(&a->kt, &b->kt, sizeof a->kt) == 0 &&
         memcmp(&a->gammat, &b->gammat, sizeof a->gammat) == 0 && a->sliding == b->sliding;
}

static void test_random(void)
{
  unsigned long long s = 0x243f6a8885a308d3ULL;
  long calls = 0, ok_calls = 0, bad = 0;
  int models = 0;
  for (int trial = 0; trial < 3000; trial++) {
    ct_params p;
    memset(&p, 0, sizeof p);
    p.law = (int)(check_uniform(&s) * 10);
    p.stiffness = (int)(check_uniform(&s) * 3);
    p.damping = (int)(check_uniform(&s) * 4);
    const int w = check_uniform(&s) < 0.3;
    p.mu = w ? wild(&s) : typical(&s, 1e-3, 2.0);
    p.kt = w ? wild(&s) : typical(&s, 1e2, 1e9);
    p.gammat = w ? wild(&s) : typical(&s, 1e-6, 1e2);
    p.e_t = w ? wild(&s) : check_uniform(&s);
    p.Gstar = w ? wild(&s) : typical(&s, 1e6, 1e11);
    p.Estar = w ? wild(&s) : typical(&s, 1e6, 1e11);
    p.eta_l = w ? wild(&s) : typical(&s, 1e-3, 2.0);
    p.t_visc = w ? wild(&s) : typical(&s, 1e-12, 1e-3);
    ct_model m;
    dc_param_error err;
    if (dc_classical_tangential_init(&p, &m, &err) != DC_OK) continue;
    models++;
    ct_state h;
    memset(&h, 0, sizeof h);
    for (int k = 0; k < 100; k++) {
      const int ww = check_uniform(&s) < 0.15;
      dc_patch pa = patch_of(ww ? wild(&s) : typical(&s, 1e-8, 1e-2), ww ? wild(&s) : typical(&s, 1e-9, 1e4));
      if (check_uniform(&s) < 0.05) pa.formed = 0.0;
      ct_contact c = {ww ? wild(&s) : typical(&s, 1e-12, 1e3), ww ? wild(&s) : typical(&s, 1e1, 1e10),
                      ww ? wild(&s) : typical(&s, 1e-6, 1e2)};
      double n[3] = {check_uniform(&s) - 0.5, check_uniform(&s) - 0.5, check_uniform(&s) - 0.5};
      const double ln = norm3(n);
      for (int j = 0; j < 3; j++) n[j] /= ln;
      if (ww && check_uniform(&s) < 0.3) n[0] = wild(&s);
      double du[3], vt[3];
      const double scale = typical(&s, 1e-12, 1e-3);
      for (int j = 0; j < 3; j++) {
        du[j] = ww ? wild(&s) : scale * (check_uniform(&s) - 0.5);
        vt[j] = ww ? wild(&s) : scale * 1e5 * (check_uniform(&s) - 0.5);
      }
      if (check_uniform(&s) < 0.02) h.spring[(int)(check_uniform(&s) * 3) % 3] = wild(&s);
      ct_out o, o0;
      memset(&o, 0x7f, sizeof o);
      o0 = o;
      const ct_state h0 = h;
      const double dt = ww ? wild(&s) : 1e-7;
      const int pass_du = check_uniform(&s) >= 0.2;
      ct_out ou = o0;
      ct_state hu = h;
      const int su = dc_classical_tangential_step_law(p.law, 0, &m, &pa, &c, n, pass_du ? du : NULL, vt, dt, &hu, &ou);
      const int st = dc_classical_tangential_step(&m, &pa, &c, n, pass_du ? du : NULL, vt, dt, &h, &o);
      calls++;
      /* unchecked: the same bits where the checked step accepts the inputs;
         an error leaves h and out untouched; DC_OK only with finite results */
      if (st == DC_OK ? (su != DC_OK || !same_out(&ou, &o) || memcmp(&hu, &h, sizeof h))
                      : su != DC_OK ? (memcmp(&ou, &o0, sizeof o) || memcmp(&hu, &h0, sizeof h))
                                    : !(dc_finite3(ou.Ft) && dc_finite3(hu.spring) && dc_finite3(hu.rev) &&
                                        isfinite(ou.kt) && isfinite(ou.gammat))) {
        if (bad < 10) printf("law %d: unchecked step status %d against %d\n", p.law, su, st);
        bad++;
      }
      if (st == DC_OK) {
        ok_calls++;
        const double F = norm3(o.Ft);
        const int fin = isfinite(o.Ft[0]) && isfinite(o.Ft[1]) && isfinite(o.Ft[2]) && isfinite(o.kt) &&
                        isfinite(o.gammat) && isfinite(h.spring[0]) && isfinite(h.spring[1]) && isfinite(h.spring[2]) &&
                        isfinite(h.rev[0]) && isfinite(h.rev[1]) && isfinite(h.rev[2]);
        /* to rounding; subnormal limits to a few units of their last place */
        const int limited = p.law == DC_CT_VISCOUS || !(F > p.mu * pa.F_bound * (1.0 + 1e-12) + 1e-322);
        if (!fin || !limited) {
          if (bad < 10) printf("law %d: fin %d limited %d F %g lim %g\n", p.law, fin, limited, F, p.mu * pa.F_bound);
          bad++;
        }
      } else {
        if (memcmp(&o, &o0, sizeof o) || memcmp(&h, &h0, sizeof h)) {
          if (bad < 10) printf("law %d: status %d touched outputs\n", p.law, st);
          bad++;
        }
        if (st != DC_EDOM && st != DC_ERANGE) bad++;
        if (!isfinite(h.spring[0]) || !isfinite(h.spring[1]) || !isfinite(h.spring[2])) memset(&h, 0, sizeof h);
      }
      /* a non-finite input that is read gives DC_EDOM */
      int finite_in = isfinite(pa.a) && isfinite(pa.F_bound) && isfinite(c.meff) && isfinite(c.kn) &&
                      isfinite(c.gamman) && isfinite(n[0]) && isfinite(vt[0]) && isfinite(vt[1]) &&
                      isfinite(vt[2]) && isfinite(h0.spring[0]) && isfinite(h0.spring[1]) && isfinite(h0.spring[2]);
      if (pass_du) finite_in &= isfinite(du[0]) && isfinite(du[1]) && isfinite(du[2]);
      else finite_in &= isfinite(dt);
      if (!finite_in && st != DC_EDOM) {
        if (bad < 10) printf("law %d: non-finite input, status %d\n", p.law, st);
        bad++;
      }
    }
  }
  printf("random sweep: %d models, %ld calls, %ld DC_OK, %ld contract violations\n", models, calls, ok_calls, bad);
  CHECK(bad == 0);
  CHECK(models > 1000 && ok_calls > 100000);
}

/* Non-finite inputs give DC_EDOM, outputs untouched. */
static void test_edom(void)
{
  ct_params p = params0(DC_CT_SPRING_SLIDING);
  const ct_model m = model(&p);
  const dc_patch pa = patch_of(1e-4, 1.0);
  ct_state h;
  memset(&h, 0, sizeof h);
  ct_out o;
  const double ok3[3] = {1e-9, 0, 0}, bad3[3] = {NAN, 0, 0}, inf3[3] = {0, INFINITY, 0};
  CHECK(dc_classical_tangential_step(&m, &pa, &C0, NZ, bad3, ok3, 0.0, &h, &o) == DC_EDOM);
  CHECK(dc_classical_tangential_step(&m, &pa, &C0, NZ, ok3, inf3, 0.0, &h, &o) == DC_EDOM);
  CHECK(dc_classical_tangential_step(&m, &pa, &C0, inf3, ok3, ok3, 0.0, &h, &o) == DC_EDOM);
  const double n2[3] = {0, 0, 1.1};
  CHECK(dc_classical_tangential_step(&m, &pa, &C0, n2, ok3, ok3, 0.0, &h, &o) == DC_EDOM);
  dc_patch pb = pa;
  pb.F_bound = NAN;
  CHECK(dc_classical_tangential_step(&m, &pb, &C0, NZ, ok3, ok3, 0.0, &h, &o) == DC_EDOM);
  pb = pa;
  pb.a = -1.0;
  CHECK(dc_classical_tangential_step(&m, &pb, &C0, NZ, ok3, ok3, 0.0, &h, &o) == DC_EDOM);
  ct_state hb = h;
  hb.spring[1] = INFINITY;
  CHECK(dc_classical_tangential_step(&m, &pa, &C0, NZ, ok3, ok3, 0.0, &hb, &o) == DC_EDOM);
  const ct_contact cb = {0.0, 1.0, 1.0};
  CHECK(dc_classical_tangential_step(&m, &pa, &cb, NZ, ok3, ok3, 0.0, &h, &o) == DC_EDOM);
}

int main(void)
{
  test_sliding_limit();
  test_stiffness();
  test_energy();
  test_deen();
  test_damping_forms();
  test_3d();
  test_checks();
  test_edom();
  test_history_and_edges();
  test_random();
  return check_summary("classical_tangential");
}
