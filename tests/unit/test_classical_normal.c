/* Classical normal laws (dc/classical_normal.h) and the lecture-note
   damping laws (dc/damping.h): every analytic figure of the notes' Sec. 3
   (collision duration, maximum overlap, restitution against impact
   velocity, residual overlap and maximum force of the hysteretic law, the
   matched stiffnesses) against the closed forms and the 30-digit
   integrations of tests/reference/classical.csv (gen_classical.py), by
   integrating the head-on collision m delta'' = -F with the C law (RK4,
   events located by bisection on sub-steps) at step sizes from Tc/25 to
   Tc/800 (graded towards delta = 0), showing convergence. Then the parameter checks (names), the
   hysteretic reloading path, magnitudes at the edges of the doubles, and a
   random never-NaN sweep. */
#include "check.h"
#include "dc/classical_normal.h"
#include "dc/damping.h"
#include "dc/hertz_elliptic.h"
#include "dc/status.h"
#include <float.h>
#include <string.h>

/* ------------------------------------------------------------------ */
/* The collision integrator                                            */

typedef struct {
  dc_classical_normal m;
  double R, meff;
} law_t;

typedef struct {
  double Tc, dmax, e, Fmax, dres;
} figs_t;

static int law_failures;

/* Total force at (x, v) with history h (updated). At x <= 0, where the
   law has no contact, the force is continued by its tangent,
   F(0+) + kn x, so that an RK4 stage just past the end of the contact sees
   the same smooth law (the linear spring-dashpot jumps to eta v there). */
static double force(const law_t *L, double x, double v, dc_classical_normal_state *h, double *Fel)
{
  dc_classical_normal_out o;
  const double xl = x > 0.0 ? x : DBL_MIN;
  dc_classical_normal_state c = *h;
  if (dc_classical_normal_step(&L->m, L->R, L->meff, xl, v, x > 0.0 ? h : &c, &o) != DC_OK) {
    law_failures++;
    return 0.0;
  }
  if (Fel) *Fel = o.c.F;
  if (x > 0.0) return o.F;
  const double F = o.F + o.c.kn * x;
  return L->m.p.limit && F < 0.0 ? 0.0 : F;
}

/* one RK4 step of x'' = -F/m; the stages see copies of the history */
static void rk4(const law_t *L, double x, double v, const dc_classical_normal_state *h, double dt, double *x1,
                double *v1)
{
  const double im = 1.0 / L->meff;
  dc_classical_normal_state c;
  c = *h; const double a1 = -force(L, x, v, &c, NULL) * im;
  const double x2 = x + 0.5 * dt * v, v2 = v + 0.5 * dt * a1;
  c = *h; const double a2 = -force(L, x2, v2, &c, NULL) * im;
  const double x3 = x + 0.5 * dt * v2, v3 = v + 0.5 * dt * a2;
  c = *h; const double a3 = -force(L, x3, v3, &c, NULL) * im;
  const double x4 = x + dt * v3, v4 = v + dt * a3;
  c = *h; const double a4 = -force(L, x4, v4, &c, NULL) * im;
  *x1 = x + dt / 6.0 * (v + 2.0 * v2 + 2.0 * v3 + v4);
  *v1 = v + dt / 6.0 * (a1 + 2.0 * a2 + 2.0 * a3 + a4);
}

/* event function: 0 overlap, 1 total force, 2 velocity */
static double event(const law_t *L, int kind, double x, double v, const dc_classical_normal_state *h)
{
  if (kind == 0) return x;
  if (kind == 2) return v;
  dc_classical_normal_state c = *h;
  return x > 0.0 ? force(L, x, v, &c, NULL) : 0.0;
}

/* the sub-step tau in (0, dt] where the event changes sign (g(0) > 0) */
static double locate(const law_t *L, int kind, double x, double v, const dc_classical_normal_state *h, double dt)
{
  double lo = 0.0, hi = dt;
  for (int it = 0; it < 200 && hi - lo > 1e-17 * dt; it++) {
    const double mid = 0.5 * (lo + hi);
    double xm, vm;
    rk4(L, x, v, h, mid, &xm, &vm);
    if (event(L, kind, xm, vm, h) > 0.0) lo = mid;
    else hi = mid;
  }
  return hi;
}

/* Head-on collision from delta = 0 at v0; the contact ends where the
   overlap (end_on_force = 0) or the total force (1) reaches 0. Steps of
   dt, graded in proportion to the overlap below x_grade (delta_max) down
   to dt floor: delta^1/4 and delta^1/2 in the damping are not smooth
   where delta = 0 (the velocity error of a step h there is ~ h^(1+q)), and
   uniform steps converge with order 5/4 (Tsuji) or 3/2 only; a floor
   (dt/Tc)^5/2 keeps order 4. */
static figs_t collide(const law_t *L, double v0, double dt0, int end_on_force, double x_grade, double floor)
{
  figs_t f = {0, 0, 0, 0, 0};
  dc_classical_normal_state h = {0.0};
  double t = 0.0, x = 0.0, v = v0;
  int turned = 0;
  for (long n = 0; n < 10000000L; n++) {
    double x1, v1;
    const double dt = x_grade > 0.0 ? dt0 * fmin(1.0, fmax(floor, x / x_grade)) : dt0;
    rk4(L, x, v, &h, dt, &x1, &v1);
    if (!turned && v1 <= 0.0) {
      /* land on the turning point: the maximum overlap */
      const double tau = locate(L, 2, x, v, &h, dt);
      rk4(L, x, v, &h, tau, &x, &v);
      t += tau;
      force(L, x, v, &h, &f.Fmax);
      f.dmax = x;
      turned = 1;
      continue;
    }
    if (turned && event(L, end_on_force, x1, v1, &h) <= 0.0) {
      const double tau = locate(L, end_on_force, x, v, &h, dt);
      rk4(L, x, v, &h, tau, &x, &v);
      f.Tc = t + tau;
      f.e = fabs(v) / v0;
      f.dres = x;
      return f;
    }
    x = x1;
    v = v1;
    t += dt;
    force(L, x, v, &h, NULL);   /* commit the history */
  }
  return f;
}

static double rel(double a, double b) { return fabs(a - b) / fmax(fabs(b), 1e-300); }

/* Integrates at Tc/N for N = 25 .. 800; checks the finest against want
   within tol and that the error falls (or is at rounding) as N grows.
   Prints the table when label is given. */
static const int NS[] = {25, 50, 100, 200, 400, 800};
enum { NN = 6 };

static double converge(const law_t *L, double v0, int end_on_force, const figs_t *want, int with_res,
                       double tol, const char *label)
{
  double err[NN][5];
  double worst = 0.0;
  for (int k = 0; k < NN; k++) {
    const figs_t g = collide(L, v0, want->Tc / NS[k], end_on_force, want->dmax, pow(1.0 / NS[k], 2.5));
    err[k][0] = rel(g.Tc, want->Tc);
    err[k][1] = rel(g.dmax, want->dmax);
    err[k][2] = rel(g.e, want->e);
    err[k][3] = rel(g.Fmax, want->Fmax);
    err[k][4] = with_res ? fabs(g.dres - want->dres) / want->dmax : 0.0;
  }
  for (int j = 0; j < 5; j++) {
    const double fine = err[NN - 1][j], coarse = err[0][j];
    if (fine > worst) worst = fine;
    char what[128];
    snprintf(what, sizeof what, "%s figure %d at Tc/800: error %.3g within %.1g", label ? label : "collision", j,
             fine, tol);
    check_true_(fine <= tol, what, __FILE__, __LINE__);
    snprintf(what, sizeof what, "%s figure %d converges: %.3g at Tc/25, %.3g at Tc/800", label ? label : "collision",
             j, coarse, fine);
    check_true_(fine <= 1e-12 || coarse >= 20.0 * fine, what, __FILE__, __LINE__);
  }
  if (label) {
    printf("%s (relative errors; residual overlap / delta_max)\n", label);
    printf("  %-8s %-10s %-10s %-10s %-10s %-10s\n", "steps", "Tc", "dmax", "e", "Fmax", "dres");
    for (int k = 0; k < NN; k++)
      printf("  Tc/%-5d %-10.3g %-10.3g %-10.3g %-10.3g %-10.3g\n", NS[k], err[k][0], err[k][1], err[k][2],
             err[k][3], err[k][4]);
  }
  return worst;
}

static void make_law(law_t *L, const dc_classical_normal_params *p, double R, double meff)
{
  dc_param_error err;
  const int st = dc_classical_normal_init(p, &L->m, &err);
  CHECK(st == DC_OK);
  L->R = R;
  L->meff = meff;
}

static dc_classical_normal_params params0(int law)
{
  dc_classical_normal_params p;
  memset(&p, 0, sizeof p);
  p.law = law;
  p.stiffness = DC_CLASSICAL_K_GIVEN;
  p.damping = DC_DAMPING_NONE;
  p.e = 1.0;
  return p;
}

/* ------------------------------------------------------------------ */
/* Table-driven figures                                                */

static void test_constants(FILE *f)
{
  double v[8];
  CHECK(check_next_tagged_row(f, "const", v, 8) == 5);
  CHECK_REL(DC_CLASSICAL_HERTZ_TC, v[0], 1e-16, "c_T");
  CHECK_REL(DC_CLASSICAL_MATCH_DURATION, v[1], 1e-16, "duration matching constant");
  CHECK_REL(DC_CLASSICAL_MATCH_OVERLAP, v[2], 1e-16, "overlap matching constant");
  /* the notes' rounded figures: 2.870 and 2.86 (c_T), 1.198, 1.053, 0.2996 */
  printf("notes' constants: c_T %.6f (printed 2.870, 2.86), duration %.6f (1.198), overlap/energy %.6f (1.053), "
         "HLS duration %.6f (0.2996), BSHP C1 %.6f\n", v[0], v[1], v[2], v[3], v[4]);
  CHECK(fabs(v[0] - 2.870) < 2e-3 && fabs(v[0] - 2.86) < 1e-2);
  CHECK(fabs(v[1] - 1.198) < 2e-3 && fabs(v[2] - 1.053) < 1e-4 && fabs(v[3] - 0.2996) < 4e-4);
}

static void test_matched(FILE *f)
{
  double v[12];
  int rows = 0;
  while (check_next_tagged_row(f, "match", v, 12) == 10) {
    const int law = (int)v[0], method = (int)v[1];
    dc_classical_normal_params p = params0(law);
    p.stiffness = method;
    p.e = v[2];
    p.Estar = v[3];
    p.v_char = v[6];
    law_t L;
    make_law(&L, &p, v[4], v[5]);
    double K;
    CHECK(dc_classical_normal_stiffness(&L.m, v[4], v[5], &K) == DC_OK);
    char what[96];
    snprintf(what, sizeof what, "matched K (law %d, method %d, e %g)", law, method, v[2]);
    CHECK_REL(K, v[7], 4e-15, what);
    /* the matched collision against the Hertz collision */
    dc_classical_collision c;
    if (law == DC_CLASSICAL_LSD) {
      CHECK(dc_classical_lsd_collision(K, L.m.zeta * sqrt(v[5] * K), v[5], v[6], 0, &c) == DC_OK);
    } else {
      CHECK(dc_classical_hls_collision(law, K, v[2], v[5], v[6], &c) == DC_OK);
    }
    if (method == DC_CLASSICAL_K_DURATION) CHECK_REL(c.Tc, v[8], 1e-14, "equal duration");
    if (method == DC_CLASSICAL_K_OVERLAP) CHECK_REL(c.dmax, v[9], 1e-14, "equal maximum overlap");
    if (method == DC_CLASSICAL_K_ENERGY) {
      const double Khz = 4.0 / 3.0 * v[3] * sqrt(v[4]);
      CHECK_REL(0.5 * K * v[9] * v[9], 0.4 * Khz * pow(v[9], 2.5), 1e-14, "equal strain energy");
    }
    /* and integrated with the C law */
    if (method != DC_CLASSICAL_K_ENERGY && v[2] == 0.3) {
      const figs_t g = collide(&L, v[6], c.Tc / 400, law != DC_CLASSICAL_LSD, 0.0, 1.0);
      if (method == DC_CLASSICAL_K_DURATION) CHECK_REL(g.Tc, v[8], 1e-9, "integrated duration = Hertz's");
      else CHECK_REL(g.dmax, v[9], 1e-9, "integrated maximum overlap = Hertz's");
    }
    rows++;
  }
  CHECK(rows == 18);
}

static void test_lsd(FILE *f)
{
  double v[12];
  int rows = 0;
  double worst = 0.0;
  while (check_next_tagged_row(f, "lsd", v, 12) == 9) {
    const double e = v[0], v0 = v[1], m = v[2], K = v[3], eta = v[5];
    const int limit = (int)v[4];
    dc_classical_normal_params p = params0(DC_CLASSICAL_LSD);
    p.kn = K;
    p.e = e;
    p.limit = limit;
    law_t L;
    make_law(&L, &p, 5e-4, m);
    /* the law's eta from e (notes: eta = -2 ln e (m K)^1/2 / (ln^2 e + pi^2)^1/2) */
    dc_classical_normal_state h = {0};
    dc_classical_normal_out o;
    CHECK(dc_classical_normal_step(&L.m, 5e-4, m, 1e-7, 0.0, &h, &o) == DC_OK);
    CHECK(e == 1.0 ? o.gamma == 0.0 : rel(o.gamma, eta) < 2e-15);
    dc_classical_collision c;
    CHECK(dc_classical_lsd_collision(K, eta, m, v0, limit, &c) == DC_OK);
    CHECK_REL(c.Tc, v[6], 4e-15, "LSD closed-form Tc");
    CHECK_REL(c.dmax, v[7], 4e-15, "LSD closed-form delta_max");
    CHECK_REL(c.e, v[8], 4e-15, "LSD closed-form restitution");
    if (!limit) {
      CHECK_REL(c.e, e, 4e-15, "LSD restitution = e");
    } else if (e < 1.0) {
      /* time reduction: the force ends earlier, the restitution is larger */
      dc_classical_collision cu;
      CHECK(dc_classical_lsd_collision(K, eta, m, v0, 0, &cu) == DC_OK);
      CHECK(c.e > cu.e && c.Tc < cu.Tc && c.dmax == cu.dmax);
      printf("LSD e = %g with limitForce: restitution %.6f, duration %.4f of pi/W\n", e, c.e, c.Tc / cu.Tc);
    }
    figs_t want = {v[6], v[7], v[8], 0.0, 0.0};
    /* the elastic force at the turning point is K delta_max */
    want.Fmax = K * v[7];
    char label[96];
    snprintf(label, sizeof label, "LSD e = %g%s", e, limit ? ", limitForce" : "");
    const double w = converge(&L, v0, limit, &want, 0, 1e-10, (e == 0.5) ? label : NULL);
    if (w > worst) worst = w;
    rows++;
  }
  CHECK(rows == 8);
  printf("LSD: %d collisions, worst error at Tc/800 %.3g\n", rows, worst);
}

static void test_hertz(FILE *f)
{
  double v[16];
  int rows = 0;
  double worst = 0.0;
  /* restitution per (law, param, limit) over the impact velocities */
  double e_prev[8] = {0};
  int law_prev = -1;
  double par_prev = -1.0;
  while (check_next_tagged_row(f, "hertz", v, 16) == 12) {
    const int law = (int)v[0];
    const double par = v[1], coef = v[2], Estar = v[3], R = v[4], m = v[5], v0 = v[6];
    const int limit = (int)v[7];
    dc_classical_normal_params p = params0(DC_CLASSICAL_HERTZ);
    p.damping = law;
    p.Estar = Estar;
    p.limit = limit;
    if (law == DC_DAMPING_RESTITUTION || law == DC_DAMPING_TSUJI) p.e = par;
    if (law == DC_DAMPING_VISCOELASTIC) p.A = par;
    if (law == DC_DAMPING_KUWABARA_KONO) p.eta_kk = par;
    law_t L;
    make_law(&L, &p, R, m);
    if (law != DC_DAMPING_NONE) CHECK_REL(L.m.dcoef, coef, 4e-16, "damping coefficient");
    const figs_t want = {v[8], v[9], v[10], v[11], 0.0};
    if (law == DC_DAMPING_NONE) {
      dc_classical_collision c;
      CHECK(dc_classical_hertz_collision(4.0 / 3.0 * Estar * sqrt(R), m, v0, &c) == DC_OK);
      CHECK_REL(c.Tc, want.Tc, 4e-15, "Hertz closed-form Tc");
      CHECK_REL(c.dmax, want.dmax, 4e-15, "Hertz closed-form delta_max");
      CHECK_REL(c.Fmax, want.Fmax, 4e-15, "Hertz closed-form F_max");
    }
    char label[128];
    snprintf(label, sizeof label, "Hertz damping %d (%g) v0 = %g%s", law, par, v0, limit ? ", limitForce" : "");
    const int show = (law == DC_DAMPING_NONE && v0 == 1.0) || (law == DC_DAMPING_TSUJI && par == 0.5 && v0 == 1.0) ||
                     (law == DC_DAMPING_KUWABARA_KONO && v0 == 1.0 && !limit);
    const double w = converge(&L, v0, limit, &want, 0, 1e-10, show ? label : NULL);
    if (w > worst) worst = w;
    /* restitution against impact velocity (rows come by law, param, v0, limit) */
    if (law != law_prev || par != par_prev) { e_prev[0] = e_prev[1] = -1.0; law_prev = law; par_prev = par; }
    if (e_prev[limit] >= 0.0) {
      if (law == DC_DAMPING_TSUJI || law == DC_DAMPING_RESTITUTION || law == DC_DAMPING_NONE)
        CHECK_REL(want.e, e_prev[limit], 1e-15, "restitution independent of the impact velocity");
      else
        CHECK(want.e < e_prev[limit]);   /* falls with the impact velocity */
    }
    e_prev[limit] = want.e;
    if (law == DC_DAMPING_RESTITUTION && !limit) CHECK_REL(want.e, par, 1e-15, "restitution damping gives e");
    if (law == DC_DAMPING_TSUJI && !limit) {
      /* the notes' coefficient: close to e, not exact */
      CHECK(fabs(want.e / par - 1.0) < 0.017);
      if (v0 == 1.0) printf("Tsuji (notes' coefficient) e = %.1f: restitution %.6f\n", par, want.e);
    }
    if (limit) CHECK(want.e >= e_prev[0] - 1e-15 || law == DC_DAMPING_NONE);
    rows++;
  }
  CHECK(rows == 79);
  printf("Hertz family: %d collisions, worst error at Tc/800 %.3g\n", rows, worst);
}

static void test_hls(FILE *f)
{
  double v[12];
  int rows = 0;
  double worst = 0.0;
  while (check_next_tagged_row(f, "hls", v, 12) == 10) {
    const int law = (int)v[0];
    const double KL = v[1], x = v[2], m = v[3], v0 = v[4];
    dc_classical_normal_params p = params0(law);
    p.kn = KL;
    if (law == DC_CLASSICAL_HLS_CONSTANT) p.e = x;
    else p.S = x;
    law_t L;
    make_law(&L, &p, 5e-4, m);
    dc_classical_collision c;
    CHECK(dc_classical_hls_collision(law, KL, x, m, v0, &c) == DC_OK);
    CHECK_REL(c.Tc, v[5], 4e-15, "HLS closed-form Tc");
    CHECK_REL(c.dmax, v[6], 4e-15, "HLS closed-form delta_max");
    CHECK(fabs(c.dres - v[7]) <= 4e-15 * v[6]);
    CHECK_REL(c.Fmax, v[8], 4e-15, "HLS closed-form F_max");
    CHECK_REL(c.e, v[9], 4e-15, "HLS closed-form restitution");
    const figs_t want = {v[5], v[6], v[9], v[8], v[7]};
    char label[96];
    snprintf(label, sizeof label, "HLS law %d (%g) v0 = %g", law, x, v0);
    const int show = v0 == 1.0 && ((law == DC_CLASSICAL_HLS_CONSTANT && x == 0.6) || x == 1e5);
    const double w = converge(&L, v0, 1, &want, 1, 1e-10, show ? label : NULL);
    if (w > worst) worst = w;
    rows++;
  }
  CHECK(rows == 21);
  printf("HLS: %d collisions, worst error at Tc/800 %.3g\n", rows, worst);
}

/* ------------------------------------------------------------------ */
/* Laws at one point                                                   */

static void test_point_laws(void)
{
  const double Estar = 3e10, R = 5e-4, m = 5e-6, d = 1e-6, dd = 0.3;
  const double Khz = 4.0 / 3.0 * Estar * sqrt(R);
  dc_classical_normal_state h = {0};
  dc_classical_normal_out o;
  law_t L;
  /* BSHP: the notes' F_dis = K_HZ A' delta^1/2 ddelta is viscoelasticTime A = 2/3 A' */
  dc_classical_normal_params p = params0(DC_CLASSICAL_HERTZ);
  p.Estar = Estar;
  p.damping = DC_DAMPING_VISCOELASTIC;
  const double Ap = 3e-7;
  p.A = 2.0 / 3.0 * Ap;
  make_law(&L, &p, R, m);
  CHECK(dc_classical_normal_step(&L.m, R, m, d, dd, &h, &o) == DC_OK);
  CHECK_REL(o.gamma * dd, Khz * Ap * sqrt(d) * dd, 1e-15, "BSHP in the notes' form");
  CHECK_REL(o.c.F, Khz * pow(d, 1.5), 1e-15, "Hertz K_HZ delta^3/2");
  CHECK_REL(o.F, o.c.F + o.gamma * dd, 1e-16, "total force");
  /* Kuwabara-Kono: eta delta^1/2 */
  p.damping = DC_DAMPING_KUWABARA_KONO;
  p.eta_kk = 700.0;
  make_law(&L, &p, R, m);
  dc_classical_normal_step(&L.m, R, m, d, dd, &h, &o);
  CHECK_REL(o.gamma, 700.0 * sqrt(d), 1e-15, "Kuwabara-Kono eta delta^1/2");
  /* Tsuji: eta delta^1/4, eta = -2.2664 ln e (m K_HZ)^1/2 / (ln^2 e + 10.1354)^1/2 */
  p.damping = DC_DAMPING_TSUJI;
  p.e = 0.4;
  make_law(&L, &p, R, m);
  dc_classical_normal_step(&L.m, R, m, d, dd, &h, &o);
  const double l = log(0.4);
  CHECK_REL(o.gamma, -2.2664 * l * sqrt(m * Khz) / sqrt(l * l + 10.1354) * pow(d, 0.25), 1e-14, "Tsuji eta delta^1/4");
  /* restitution damping: LIGGGHTS' hertz arithmetic, bit for bit */
  p.damping = DC_DAMPING_RESTITUTION;
  make_law(&L, &p, R, m);
  dc_classical_normal_step(&L.m, R, m, d, dd, &h, &o);
  double kn, S, beta;
  dc_hertz_stiffness(Estar, R, d, &kn, &S);
  dc_damping_beta(0.4, &beta);
  CHECK(o.c.F == kn * d && o.gamma == dc_damping_restitution(beta, S, m) && o.c.kn == S);
  /* limitForce: no attraction */
  p.limit = 1;
  make_law(&L, &p, R, m);
  dc_classical_normal_step(&L.m, R, m, d, -1e3, &h, &o);
  CHECK(o.F == 0.0 && o.c.F > 0.0);
  /* the patch: circle (R delta)^1/2, friction load = elastic force */
  CHECK_REL(o.c.a, sqrt(R * d), 1e-15, "contact radius");
  CHECK(o.c.b == o.c.a && o.c.F_bound == o.c.F && o.c.formed == 1);
  /* apart: zeros, history reset */
  h.delta_max = 1e-6;
  CHECK(dc_classical_normal_step(&L.m, R, m, -1e-9, 0.1, &h, &o) == DC_OK);
  CHECK(o.F == 0.0 && o.c.formed == 0 && h.delta_max == 0.0);
}

/* Walton-Braun reloading follows the unloading line back to delta_max,
   then the loading line (no force jump); variable K_U = K_L (1 + S delta_max). */
static void test_hls_path(void)
{
  for (int law = DC_CLASSICAL_HLS_CONSTANT; law <= DC_CLASSICAL_HLS_VARIABLE; law++) {
    dc_classical_normal_params p = params0(law);
    p.kn = 1e6;
    p.e = 0.5;
    p.S = 2e5;
    law_t L;
    make_law(&L, &p, 5e-4, 5e-6);
    dc_classical_normal_state h = {0};
    dc_classical_normal_out o;
    const double d1 = 2e-6;
    const double KU = law == DC_CLASSICAL_HLS_CONSTANT ? 4e6 : 1e6 * (1.0 + 2e5 * d1);
    const double dres = d1 * (1.0 - 1e6 / KU);
    double prevF = 0.0;
    int ok = 1, monotone = 1;
    /* load 0 -> d1, unload to (d1 + dres)/2, reload to 1.5 d1, unload to 0 */
    const int N = 400;
    for (int i = 0; i <= 4 * N; i++) {
      double d;
      if (i <= N) d = d1 * i / N;
      else if (i <= 2 * N) d = d1 - (d1 - 0.5 * (d1 + dres)) * (i - N) / N;
      else if (i <= 3 * N) d = 0.5 * (d1 + dres) + (1.5 * d1 - 0.5 * (d1 + dres)) * (i - 2 * N) / N;
      else d = 1.5 * d1 * (1.0 - (double)(i - 3 * N) / N);
      ok &= dc_classical_normal_step(&L.m, 5e-4, 5e-6, d, 0.0, &h, &o) == DC_OK;
      double want;
      if (i <= N) want = 1e6 * d;
      else if (i <= 3 * N) want = d <= d1 ? KU * (d - dres) : 1e6 * d;
      else {
        const double dm = 1.5 * d1;
        const double KU2 = law == DC_CLASSICAL_HLS_CONSTANT ? 4e6 : 1e6 * (1.0 + 2e5 * dm);
        want = fmax(0.0, 1e6 * dm + KU2 * (d - dm));
      }
      ok &= fabs(o.c.F - want) <= 1e-12 * 1e6 * d1;
      if (i > 2 * N && i <= 3 * N) monotone &= o.c.F >= prevF;
      prevF = o.c.F;
    }
    CHECK(ok);
    CHECK(monotone);
  }
}

/* ------------------------------------------------------------------ */
/* Parameter checks and the random never-NaN sweep                     */

static void expect_error(const dc_classical_normal_params *p, const char *name)
{
  dc_param_error err;
  memset(&err, 0, sizeof err);
  const int st = dc_classical_normal_check(p, &err);
  char what[128];
  snprintf(what, sizeof what, "check names %s (got %s)", name, err.name ? err.name : "nothing");
  check_true_(st == DC_EDOM && err.name && !strcmp(err.name, name), what, __FILE__, __LINE__);
}

static void test_checks(void)
{
  dc_classical_normal_params p = params0(DC_CLASSICAL_LSD);
  p.kn = 1e6;
  p.e = 0.5;
  dc_param_error err;
  CHECK(dc_classical_normal_check(&p, &err) == DC_OK);
  dc_classical_normal_params q = p; q.law = 7; expect_error(&q, "classicalNormal");
  q = p; q.limit = 2; expect_error(&q, "limitForce");
  q = p; q.kn = 0.0; expect_error(&q, "kn");
  q = p; q.kn = NAN; expect_error(&q, "kn");
  q = p; q.e = 0.0; expect_error(&q, "coefficientRestitution");
  q = p; q.e = 1.5; expect_error(&q, "coefficientRestitution");
  q = p; q.stiffness = 5; expect_error(&q, "classicalStiffness");
  q = p; q.stiffness = DC_CLASSICAL_K_DURATION; q.Estar = 1e10; q.v_char = 0.0; expect_error(&q, "characteristicVelocity");
  q = p; q.stiffness = DC_CLASSICAL_K_OVERLAP; q.Estar = -1.0; q.v_char = 1.0; expect_error(&q, "youngsModulus");
  q = p; q.law = DC_CLASSICAL_HLS_VARIABLE; q.S = -1.0; expect_error(&q, "unloadingStiffnessSlope");
  q = p; q.law = DC_CLASSICAL_HLS_VARIABLE; q.S = 1.0; q.stiffness = DC_CLASSICAL_K_DURATION; q.Estar = 1e10;
  q.v_char = 1.0; expect_error(&q, "classicalStiffness");
  q = p; q.law = DC_CLASSICAL_HERTZ; q.Estar = 0.0; expect_error(&q, "youngsModulus");
  q = p; q.law = DC_CLASSICAL_HERTZ; q.Estar = 1e9; q.damping = 9; expect_error(&q, "damping");
  q = p; q.law = DC_CLASSICAL_HERTZ; q.Estar = 1e9; q.damping = DC_DAMPING_VISCOELASTIC; q.A = -1e-9;
  expect_error(&q, "viscoelasticTime");
  q = p; q.law = DC_CLASSICAL_HERTZ; q.Estar = 1e9; q.damping = DC_DAMPING_KUWABARA_KONO; q.eta_kk = INFINITY;
  expect_error(&q, "kuwabaraKonoDamping");
  q = p; q.law = DC_CLASSICAL_HERTZ; q.Estar = 1e9; q.damping = DC_DAMPING_TSUJI; q.e = 0.0;
  expect_error(&q, "coefficientRestitution");
  /* fields a law does not use are not read */
  q = p; q.law = DC_CLASSICAL_HERTZ; q.Estar = 1e9; q.damping = DC_DAMPING_NONE; q.e = NAN; q.kn = NAN;
  CHECK(dc_classical_normal_check(&q, &err) == DC_OK);
  /* the message */
  char buf[160];
  q = p; q.kn = -3.0;
  dc_classical_normal_check(&q, &err);
  dc_param_error_format(&err, 1, 2, buf, sizeof buf);
  CHECK(!strcmp(buf, "kn = -3 for types 1 and 2 is outside (0, inf)"));
  /* damping.h */
  double a;
  CHECK(dc_damping_tsuji_alpha(0.0, &a) == DC_EDOM && dc_damping_tsuji_alpha(1.0, &a) == DC_OK && a == 0.0);
}

/* ------------------------------------------------------------------ */
/* Magnitudes at the edges of the doubles (cases of test_fuzz.c)      */

static void test_extremes(void)
{
  dc_classical_collision c;
  /* LSD, z = eta / (2 (m K)^1/2) = 1/2 with m K = 2^-1000 below the
     doubles' range of eta/(2m) squared: was DC_EDOM */
  const double t0 = 0x1p-540, s = sqrt(0.75), r = 0.5 / s;
  CHECK(dc_classical_lsd_collision(0x1p40, 0x1p-500, 0x1p-1040, 1.0, 0, &c) == DC_OK);
  CHECK_REL(c.Tc, M_PI * t0 / s, 1e-15, "LSD Tc, m K = 2^-1000");
  CHECK_REL(c.dmax, t0 * exp(-r * M_PI / 3.0), 1e-15, "LSD delta_max, m K = 2^-1000");
  CHECK_REL(c.e, exp(-M_PI * r), 1e-15, "LSD restitution, m K = 2^-1000");
  /* K/m = 2^1200 beyond the doubles: was DC_OK with Tc = 0 */
  CHECK(dc_classical_lsd_collision(0x1p600, 0.0, 0x1p-600, 1.0, 0, &c) == DC_OK);
  CHECK_REL(c.Tc, M_PI * 0x1p-600, 1e-15, "LSD Tc, K/m = 2^1200");
  /* eta = -0 with limitForce: was Tc < 0 (atan2 of -0) */
  dc_classical_collision c0;
  CHECK(dc_classical_lsd_collision(1e5, 0.0, 1e-3, 1.0, 1, &c0) == DC_OK);
  CHECK(dc_classical_lsd_collision(1e5, -0.0, 1e-3, 1.0, 1, &c) == DC_OK);
  CHECK(c.Tc > 0.0 && c.Tc == c0.Tc && c.e == c0.e);
  /* HLS, m/K_L = 2^1320: was DC_ERANGE for delta_max = 2^-40 */
  CHECK(dc_classical_hls_collision(DC_CLASSICAL_HLS_CONSTANT, 0x1p-660, 0.5, 0x1p660, 0x1p-700, &c) == DC_OK);
  CHECK(c.dmax == 0x1p-40 && c.Fmax == 0x1p-700);
  CHECK_REL(c.Tc, 0.5 * M_PI * 0x1p660 * 1.5, 1e-15, "HLS Tc, m/K_L = 2^1320");
  /* HLS variable, S delta_max = 1e600: was e = 0 */
  CHECK(dc_classical_hls_collision(DC_CLASSICAL_HLS_VARIABLE, 1.0, 1e300, 1.0, 1e300, &c) == DC_OK);
  CHECK_REL(c.e, 1e-300, 1e-15, "HLS variable restitution, S delta_max = 1e600");
  /* the variable unloading stiffness K_L (1 + S delta_max) = 1e210 with
     S delta_max = 1e310: was DC_ERANGE */
  dc_classical_normal_params p = params0(DC_CLASSICAL_HLS_VARIABLE);
  p.kn = 1e-100;
  p.S = 1e300;
  law_t L;
  make_law(&L, &p, 1.0, 1.0);
  dc_classical_normal_state h = {0.0};
  dc_classical_normal_out o;
  CHECK(dc_classical_normal_step(&L.m, 1.0, 1.0, 1e10, 0.0, &h, &o) == DC_OK);
  CHECK(o.c.F == 1e-100 * 1e10 && o.c.kn == 1e-100 && h.delta_max == 1e10);
  CHECK(dc_classical_normal_step(&L.m, 1.0, 1.0, 0.99e10, 0.0, &h, &o) == DC_OK);
  CHECK(o.c.F == 0.0 && o.c.kn == 0.0 && h.delta_max == 1e10);
}

static double wild(unsigned long long *s)
{
  const double u = check_uniform(s);
  const double specials[] = {0.0, -0.0, 1.0, -1.0, DBL_MIN, DBL_MAX, -DBL_MAX, 5e-324, 1e-300, 1e300,
                             INFINITY, -INFINITY, NAN};
  if (u < 0.3) return specials[(int)(check_uniform(s) * 13) % 13];
  const double mag = pow(10.0, -320.0 + 628.0 * check_uniform(s));
  return check_uniform(s) < 0.2 ? -mag : mag;
}

static double typical(unsigned long long *s, double lo, double hi)
{
  return lo * pow(hi / lo, check_uniform(s));
}

static void test_random(void)
{
  unsigned long long s = 0x9e3779b97f4a7c15ULL;
  long calls = 0, ok_calls = 0, bad = 0;
  int laws_inited = 0;
  for (int trial = 0; trial < 4000; trial++) {
    dc_classical_normal_params p;
    memset(&p, 0, sizeof p);
    p.law = (int)(check_uniform(&s) * 4);
    p.stiffness = (int)(check_uniform(&s) * 4);
    p.damping = (int)(check_uniform(&s) * 5);
    p.limit = check_uniform(&s) < 0.5;
    const int w = check_uniform(&s) < 0.3;
    p.Estar = w ? wild(&s) : typical(&s, 1e5, 1e12);
    p.kn = w ? wild(&s) : typical(&s, 1e2, 1e10);
    p.v_char = w ? wild(&s) : typical(&s, 1e-3, 1e2);
    p.e = w ? wild(&s) : typical(&s, 1e-3, 1.0);
    p.A = w ? wild(&s) : typical(&s, 1e-12, 1e-3);
    p.eta_kk = w ? wild(&s) : typical(&s, 1e-2, 1e6);
    p.S = w ? wild(&s) : typical(&s, 1e-2, 1e8);
    dc_classical_normal m;
    dc_param_error err;
    if (dc_classical_normal_init(&p, &m, &err) != DC_OK) continue;
    laws_inited++;
    dc_classical_normal_state h = {0};
    for (int k = 0; k < 200; k++) {
      const int ww = check_uniform(&s) < 0.2;
      const double R = ww ? wild(&s) : typical(&s, 1e-6, 1.0);
      const double meff = ww ? wild(&s) : typical(&s, 1e-12, 1e3);
      const double d = ww ? wild(&s) : (check_uniform(&s) - 0.1) * typical(&s, 1e-12, 1e-2);
      const double dd = ww ? wild(&s) : (check_uniform(&s) - 0.5) * typical(&s, 1e-4, 1e2);
      if (check_uniform(&s) < 0.02) h.delta_max = wild(&s);
      dc_classical_normal_out o, o0;
      memset(&o, 0x7f, sizeof o);
      o0 = o;
      dc_classical_normal_state h0 = h;
      const int st = dc_classical_normal_step(&m, R, meff, d, dd, &h, &o);
      calls++;
      const int finite_in = isfinite(R) && isfinite(meff) && isfinite(d) && isfinite(dd) && isfinite(h0.delta_max);
      if (st == DC_OK) {
        ok_calls++;
        const int fin = isfinite(o.c.F) && isfinite(o.c.kn) && isfinite(o.c.area) && isfinite(o.c.a) &&
                        isfinite(o.F) && isfinite(o.gamma) && isfinite(o.K) && isfinite(h.delta_max) &&
                        o.c.F >= 0.0 && o.c.F_bound >= 0.0 && (!p.limit || o.F >= 0.0);
        if (!fin) bad++;
      } else {
        if (memcmp(&o, &o0, sizeof o) || memcmp(&h, &h0, sizeof h)) bad++;
        if (st != DC_EDOM && st != DC_ERANGE) bad++;
        if (h.delta_max != h0.delta_max) h = h0;
      }
      if (!finite_in && st != DC_EDOM) bad++;
      if (!isfinite(h.delta_max) || h.delta_max < 0.0) h.delta_max = 0.0;
    }
    /* closed forms under the same sweep */
    dc_classical_collision c, c0;
    for (int k = 0; k < 20; k++) {
      const double a1 = wild(&s), a2 = wild(&s), a3 = wild(&s), a4 = wild(&s);
      memset(&c, 0x7f, sizeof c);
      c0 = c;
      int st = dc_classical_lsd_collision(a1, fabs(a2), a3, a4, k & 1, &c);
      int st2 = dc_classical_hertz_collision(a1, a3, a4, &c);
      int st3 = dc_classical_hls_collision(DC_CLASSICAL_HLS_CONSTANT + (k & 1), a1, fabs(a2), a3, a4, &c);
      calls += 3;
      (void)st; (void)st2; (void)st3;
      if (st == DC_OK || st2 == DC_OK || st3 == DC_OK) {
        if (!(isfinite(c.Tc) && isfinite(c.dmax) && isfinite(c.e) && isfinite(c.Fmax) && isfinite(c.dres))) bad++;
      } else if (memcmp(&c, &c0, sizeof c)) {
        bad++;
      }
    }
  }
  printf("random sweep: %d laws, %ld calls, %ld DC_OK, %ld contract violations\n", laws_inited, calls, ok_calls, bad);
  CHECK(bad == 0);
  CHECK(laws_inited > 500 && ok_calls > 100000);
}

int main(void)
{
  FILE *f = check_open_reference("classical.csv");
  if (f) {
    test_constants(f); rewind(f);
    test_matched(f); rewind(f);
    test_lsd(f); rewind(f);
    test_hertz(f); rewind(f);
    test_hls(f);
    fclose(f);
  }
  test_point_laws();
  test_hls_path();
  test_checks();
  test_extremes();
  test_random();
  CHECK(law_failures == 0);
  return check_summary("classical_normal");
}
