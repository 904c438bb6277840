/* Cattaneo-Mindlin-Deresiewicz law (dc/cmd_tangential.h) against the
   closed forms of Mindlin and Deresiewicz and the independent references of
   tests/reference/gen_cmd_tangential.py (cmd_tangential.csv). Prints the
   loop-energy error against the step size and ns per step. */
#include "check.h"
#include "dc/cmd_tangential.h"
#include "dc/elliptic_integrals.h"
#include "dc/status.h"
#include <float.h>
#include <time.h>

static double dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static double norm3(const double *a) { return sqrt(dot3(a, a)); }
static void cross3(const double *a, const double *b, double *c)
{
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

/* a tilted frame: normal n, major axis e1, minor axis e2 (right-handed) */
static const double N0[3] = {0.48, -0.6, 0.64};
static void frame(double n[3], double e1[3], double e2[3])
{
  for (int k = 0; k < 3; k++) n[k] = N0[k];
  const double t[3] = {0.8, 0.64, 0.0};   /* normal to N0 */
  for (int k = 0; k < 3; k++) e1[k] = t[k] / sqrt(1.0496);
  cross3(n, e1, e2);
}

static dc_patch patch_of(double a, double b, const double *axis, double Fb)
{
  dc_patch p;
  p.a = a;
  p.b = b;
  for (int k = 0; k < 3; k++) p.axis[k] = a > b ? axis[k] : 0.0;
  p.F_elastic = Fb;
  p.F_bound = Fb;
  p.formed = 1.0;
  return p;
}

/* The unit circle most tests use: nu = 0.3, one body on a rigid one
   (s0 = 1, s1 = nu), mu = 0.5 and F_bound = 2, semi-axis (2 - nu)/8, so
   that k0 = 1 and mu F_n = 1; the frame n, e1, e2. */
static dc_patch unit_circle(dc_mindlin_pair *m, dc_cmd_params *p, double n[3], double e1[3], double e2[3])
{
  const double nu = 0.3;
  const dc_mindlin_pair mm = {1.0, nu};
  const dc_cmd_params pp = {0.5, 0.0, 0, 0};
  *m = mm;
  *p = pp;
  frame(n, e1, e2);
  return patch_of((2.0 - nu) / 8.0, (2.0 - nu) / 8.0, e1, 2.0);
}

/* one step along the unit direction e by ds (plus a normal part that the
   law must ignore) */
static int step_along(const dc_cmd_params *p, const dc_mindlin_pair *m, const dc_patch *pa, const double *n,
                      const double *e, double ds, dc_cmd_state *h, dc_cmd_out *o)
{
  double du[3];
  for (int k = 0; k < 3; k++) du[k] = ds * e[k] + 0.37 * ds * n[k];
  return dc_cmd_step(p, m, pa, n, du, 0.0, 1e-6, h, o);
}

/* ------------------------------------------------------------------ */
/* The circle at constant F_n, F_t cycled between +-F*: the whole loop
   (Eq. 59 loading, Eq. 67 unloading and reloading) and the energy per
   cycle (Eq. 69) against the closed forms (loop and energy rows). */
static void test_circle_loop(void)
{
  FILE *f = check_open_reference("cmd_tangential.csv");
  if (!f) return;
  /* pair: one body G = 1, nu = 0.3 on a rigid one; a with k0 = 1; mu F_n = 1 */
  const double nu = 0.3;
  const dc_mindlin_pair m = {1.0, nu};
  const double a = (2.0 - nu) / 8.0;
  dc_cmd_params p = {0.5, 0.0, 0, 0};
  double n[3], e1[3], e2[3];
  frame(n, e1, e2);
  const dc_patch pa = patch_of(a, a, e1, 2.0);
  const double dL = 1.5;   /* 3 mu F_n / (2 k0) */
  char tag[16];
  double v[8];
  int rows = 0, erows = 0;
  printf("loop energy (Eq. 69), trapezoid error vs steps per half cycle:\n");
  while (check_read_tagged_row(f, tag, sizeof tag, v, 8) > 0) {
    if (!strcmp(tag, "loop")) {
      /* the point x of the loop for r = v[0]: drive to it along each branch */
      const double r = v[0], x = v[1], ds = dL * (1.0 - cbrt((1.0 - r) * (1.0 - r)));
      dc_cmd_state h;
      dc_cmd_out o;
      memset(&h, 0, sizeof h);
      const int N = 64;
      double d = 0.0;
      int ok = 1;
      if (x >= 0.0) {   /* virgin branch up to x */
        for (int i = 0; i < N; i++) { ok &= step_along(&p, &m, &pa, n, e2, x / N, &h, &o) == DC_OK; d += x / N; }
        CHECK_REL(dot3(o.Ft, e2), v[2], 1e-13, "virgin branch (Eq. 59)");
        for (int i = 0; i < N; i++) ok &= step_along(&p, &m, &pa, n, e2, (ds - x) / N, &h, &o) == DC_OK;
      } else {
        for (int i = 0; i < N; i++) ok &= step_along(&p, &m, &pa, n, e2, ds / N, &h, &o) == DC_OK;
      }
      CHECK_REL(dot3(o.Ft, e2), r, 1e-13, "turning point F*");
      /* unloading to x, on to -ds, reloading to x */
      for (int i = 0; i < N; i++) ok &= step_along(&p, &m, &pa, n, e2, -(ds - x) / N, &h, &o) == DC_OK;
      CHECK_ABS(dot3(o.Ft, e2), v[3], 2e-14, "unloading branch (Eq. 67)");
      for (int i = 0; i < N; i++) ok &= step_along(&p, &m, &pa, n, e2, -(x + ds) / N, &h, &o) == DC_OK;
      CHECK_REL(dot3(o.Ft, e2), -r, 1e-13, "turning point -F*");
      for (int i = 0; i < N; i++) ok &= step_along(&p, &m, &pa, n, e2, (x + ds) / N, &h, &o) == DC_OK;
      CHECK_ABS(dot3(o.Ft, e2), v[4], 2e-14, "reloading branch");
      CHECK(ok);
      CHECK(fabs(dot3(o.Ft, n)) < 1e-15 && fabs(dot3(o.Ft, e1)) < 1e-15);
      rows++;
    } else if (!strcmp(tag, "energy")) {
      const double r = v[0], E69 = v[1], ds = dL * (1.0 - cbrt((1.0 - r) * (1.0 - r)));
      CHECK_REL(v[2], E69, 1e-24, "Eq. 69 = quadrature of the loop (generator)");
      double err = 0.0, err_prev = 0.0;
      printf("  F*/mu F_n = %.2f:", r);
      for (int N = 10; N <= 100000; N *= 10) {
        dc_cmd_state h;
        dc_cmd_out o;
        memset(&h, 0, sizeof h);
        for (int i = 0; i < N; i++) step_along(&p, &m, &pa, n, e1, ds / N, &h, &o);
        /* one cycle: +ds -> -ds -> +ds; E = closed integral of F d(delta) (trapezoid) */
        double E = 0.0, F0 = dot3(o.Ft, e1), Fmax = 0.0;
        for (int sgn = -1; sgn <= 1; sgn += 2)
          for (int i = 0; i < 2 * N; i++) {
            step_along(&p, &m, &pa, n, e1, sgn * ds / N, &h, &o);
            const double F1 = dot3(o.Ft, e1);
            E += 0.5 * (F0 + F1) * sgn * ds / N;
            F0 = F1;
            Fmax = fmax(Fmax, fabs(F1));
          }
        err_prev = err;
        err = fabs(E - E69) / E69;
        printf("  N %6d: %.2e", N, err);
        if (N == 100 && r == 0.8) CHECK(err < 1e-4);
        CHECK(Fmax <= r * (1.0 + 1e-10));   /* the sum of N steps ds/N drifts by rounding */
      }
      printf("  (order %.2f)\n", log10(err_prev / err));
      CHECK(err < 1e-9);
      erows++;
    }
  }
  fclose(f);
  CHECK(rows == 36 && erows == 4);
}

/* ------------------------------------------------------------------ */
/* Ellipse, no slip: stiffness |F|/|delta| and the angle psi between the
   displacement and the major axis, 12 force directions (noslip rows,
   Cerruti quadrature); the tangent stiffness along du. */
static void test_ellipse_noslip(void)
{
  FILE *f = check_open_reference("cmd_tangential.csv");
  if (!f) return;
  double n[3], e1[3], e2[3];
  frame(n, e1, e2);
  double v[8];
  int rows = 0;
  double worst_k = 0.0, worst_a = 0.0;
  while (check_next_tagged_row(f, "noslip", v, 8) > 0) {
    const double g = v[0], nu = v[1], th = v[2], k = v[3], psi = v[4];
    const dc_mindlin_pair m = {1.0, nu};
    dc_cmd_params p = {1e6, 0.0, 0, 0};   /* slip negligible at delta = 1e-9 */
    const dc_patch pa = patch_of(1.0, g, e1, 1.0);
    double e[3];
    for (int i = 0; i < 3; i++) e[i] = cos(psi) * e1[i] + sin(psi) * e2[i];
    dc_cmd_state h;
    dc_cmd_out o;
    memset(&h, 0, sizeof h);
    const double d = 1e-9;
    CHECK(step_along(&p, &m, &pa, n, e, d, &h, &o) == DC_OK);
    const double F = norm3(o.Ft), ang = atan2(dot3(o.Ft, e2), dot3(o.Ft, e1));
    worst_k = fmax(worst_k, fabs(F / d - k) / k);
    worst_a = fmax(worst_a, fabs(ang - th));
    CHECK_REL(F / d, k, 1e-13, "no-slip stiffness along the force (Eqs. 56-57)");
    CHECK_ABS(ang, th, 1e-13, "force angle theta for displacement angle psi (Eq. 58)");
    CHECK_REL(o.kt, dot3(o.Ft, e) / d, 1e-12, "tangent stiffness along du");
    CHECK(fabs(dot3(o.Ft, n)) < 1e-20);
    rows++;
  }
  fclose(f);
  CHECK(rows == 144);
  printf("ellipse no-slip, 144 rows: stiffness error %.1e, force angle error %.1e rad\n", worst_k, worst_a);
}

/* Micro-slip on the ellipse (micro rows: Eqs. 60-61 on the axes, Eq. 59
   at theta = pi/4), force direction fixed at theta. */
static void test_ellipse_microslip(void)
{
  FILE *f = check_open_reference("cmd_tangential.csv");
  if (!f) return;
  double n[3], e1[3], e2[3];
  frame(n, e1, e2);
  double v[8];
  int rows = 0;
  double worst = 0.0;
  dc_cmd_state h;
  dc_cmd_out o;
  double dprev = 0.0, key[3] = {-1, -1, -1};
  while (check_next_tagged_row(f, "micro", v, 8) > 0) {
    const double g = v[0], nu = v[1], th = v[2], psi = v[3], F = v[5], d = v[6];
    const dc_mindlin_pair m = {1.0, nu};
    dc_cmd_params p = {0.5, 0.0, 0, 0};
    const dc_patch pa = patch_of(1.0, g, e1, 2.0);
    if (key[0] != g || key[1] != nu || key[2] != th) {   /* a new curve: fresh contact */
      memset(&h, 0, sizeof h);
      dprev = 0.0;
      key[0] = g; key[1] = nu; key[2] = th;
    }
    double e[3];
    for (int i = 0; i < 3; i++) e[i] = cos(psi) * e1[i] + sin(psi) * e2[i];
    for (int i = 0; i < 16; i++) CHECK(step_along(&p, &m, &pa, n, e, (d - dprev) / 16, &h, &o) == DC_OK);
    dprev = d;
    const double Fl = norm3(o.Ft), ang = atan2(dot3(o.Ft, e2), dot3(o.Ft, e1));
    worst = fmax(worst, fabs(Fl - F));
    CHECK_ABS(Fl, F, 1e-13, "micro-slip force (Eqs. 59-61)");
    CHECK_ABS(ang, th, 1e-12, "micro-slip force direction");
    rows++;
  }
  fclose(f);
  CHECK(rows == 72);
  printf("ellipse micro-slip, 72 rows (theta = 0, pi/2: Eqs. 60-61; pi/4: Eq. 59): max error %.1e mu F_n\n", worst);
}

/* Twisting: stiffness against the quadrature and Eq. 77, the full-slip
   moment, the first-loading curve, and the circle's 16 G a^3/3 and
   3 pi mu F a/16 (twist rows). */
static void test_twist(void)
{
  FILE *f = check_open_reference("cmd_tangential.csv");
  if (!f) return;
  double n[3], e1[3], e2[3];
  frame(n, e1, e2);
  double v[8];
  int rows = 0;
  while (check_next_tagged_row(f, "twist", v, 8) > 0) {
    const double g = v[0], nu = v[1];
    const dc_mindlin_pair m = {1.0, nu};
    double k, Ms;
    CHECK(dc_cmd_twist_stiffness(&m, 1.0, g, &k) == DC_OK);
    CHECK_REL(k, v[2], 2e-14, "torsional stiffness vs Cerruti quadrature");
    CHECK_REL(k, v[3], 2e-14, "torsional stiffness vs review Eq. 77");
    CHECK(dc_cmd_twist_slip_moment(0.4, 2.5, 1.0, g, &Ms) == DC_OK);
    CHECK_REL(Ms, v[4], 2e-15, "full-slip moment");
    if (g == 1.0) {
      CHECK_REL(k, 16.0 / 3.0, 1e-15, "circle: 16 G a^3 / 3");
      CHECK_REL(Ms, 3.0 * M_PI / 16.0, 1e-15, "circle: 3 pi mu F a / 16");
    }
    /* the law: first loading M = Ms [1 - (1 - 2 k phi/(3 Ms))^3/2], then full slip */
    dc_cmd_params p = {0.4, 0.0, 0, 1};
    const dc_patch pa = patch_of(1.0, g, e1, 2.5);
    dc_cmd_state h;
    dc_cmd_out o;
    memset(&h, 0, sizeof h);
    const double phis = 1.5 * Ms / k, zero[3] = {0, 0, 0};
    double phi = 0.0;
    CHECK(dc_cmd_step(&p, &m, &pa, n, zero, 1e-12 * phis, 1e-6, &h, &o) == DC_OK);
    CHECK_REL(o.Mt, k * 1e-12 * phis, 1e-11, "no-slip torsional stiffness in the step");
    CHECK_REL(o.kr, k, 1e-11, "torsional tangent stiffness at the start");
    phi = 1e-12 * phis;
    for (int i = 1; i <= 32; i++) {
      const double to = phis * i / 32.0;
      CHECK(dc_cmd_step(&p, &m, &pa, n, zero, to - phi, 1e-6, &h, &o) == DC_OK);
      phi = to;
      CHECK_ABS(o.Mt, Ms * (1.0 - pow(1.0 - phi / phis, 1.5)), 1e-14 * Ms, "twisting, first loading");
    }
    CHECK(dc_cmd_step(&p, &m, &pa, n, zero, 3.0 * phis, 1e-6, &h, &o) == DC_OK);
    CHECK_REL(o.Mt, Ms, 1e-15, "twisting: full slip at M_s");
    CHECK(o.kr == 0.0);
    CHECK(dc_cmd_step(&p, &m, &pa, n, zero, -0.5 * phis, 1e-6, &h, &o) == DC_OK);
    CHECK_ABS(o.Mt, Ms - 2.0 * Ms * (1.0 - pow(1.0 - 0.25, 1.5)), 1e-14 * Ms, "twisting, unloading (Masing)");
    CHECK(o.Ft[0] == 0.0 && o.Ft[1] == 0.0 && o.Ft[2] == 0.0);
    rows++;
  }
  fclose(f);
  CHECK(rows == 15);
}


/* ------------------------------------------------------------------ */
/* Nested reversals at constant F_n (nested rows: Masing with memory). */
static void test_nested(void)
{
  FILE *f = check_open_reference("cmd_tangential.csv");
  if (!f) return;
  dc_mindlin_pair m;
  dc_cmd_params p;
  double n[3], e1[3], e2[3];
  const dc_patch pa = unit_circle(&m, &p, n, e1, e2);   /* k0 = 1, mu F_n = 1 */
  dc_cmd_state h;
  dc_cmd_out o;
  memset(&h, 0, sizeof h);
  double v[4], d = 0.0, worst = 0.0;
  int rows = 0, maxseg = 0;
  while (check_next_tagged_row(f, "nested", v, 4) > 0) {
    for (int i = 0; i < 10; i++) step_along(&p, &m, &pa, n, e1, (v[0] - d) / 10, &h, &o);
    d = v[0];
    worst = fmax(worst, fabs(dot3(o.Ft, e1) - v[1]));
    CHECK_ABS(dot3(o.Ft, e1), v[1], 1e-14, "nested reversals (Masing with memory)");
    maxseg = (int)fmax(maxseg, h.nseg);
    rows++;
  }
  fclose(f);
  CHECK(rows == 40);
  printf("nested reversals, 40 points: max error %.1e mu F_n, at most %d pieces\n", worst, maxseg);
}

/* More turning points than DC_CMD_MAX_TURNS: exact while they fit; beyond,
   the least-change merge forgets the smallest loop (force kept); loading
   past the largest turning point returns to the virgin curve. */
static void masing_ref(int ntp, const double *td, const double *tf, double d, double *F)
{
  /* branch from the last turning point of the list (virgin if none) */
  const double dL = 1.5;
  double x;
  if (ntp == 0) { x = fmin(fabs(d) / dL, 1.0); *F = copysign(1.0 - pow(1.0 - x, 1.5), d); return; }
  const double h = 0.5 * (d - td[ntp - 1]);
  x = fmin(fabs(h) / dL, 1.0);
  *F = tf[ntp - 1] + 2.0 * copysign(1.0 - pow(1.0 - x, 1.5), h);
}

/* turning points amp0 * q^t (alternating sign), 12 of them; returns the
   largest error within the cap and beyond */
static void turn_sequence(double amp0, double q, double *worst_in, double *worst_out)
{
  dc_mindlin_pair m;
  dc_cmd_params p;
  double n[3], e1[3], e2[3];
  const dc_patch pa = unit_circle(&m, &p, n, e1, e2);
  dc_cmd_state h;
  dc_cmd_out o;
  memset(&h, 0, sizeof h);
  enum { NT = 12 };
  double td[NT], tf[NT], d = 0.0, Fprev = 0.0, jump = 0.0, amp = amp0;
  int ntp = 0;
  *worst_in = *worst_out = 0.0;
  for (int t = 0; t < NT; t++, amp *= q) {
    const double to = (t % 2 ? -1.0 : 1.0) * amp;
    for (int i = 0; i < 50; i++) {
      const double dd = (to - d) / (50 - i);
      step_along(&p, &m, &pa, n, e1, dd, &h, &o);
      d += dd;
      double Fr;
      masing_ref(ntp, td, tf, d, &Fr);
      const double e = fabs(dot3(o.Ft, e1) - Fr);
      if (ntp <= DC_CMD_MAX_TURNS) *worst_in = fmax(*worst_in, e);
      else *worst_out = fmax(*worst_out, e);
      jump = fmax(jump, fabs(dot3(o.Ft, e1) - Fprev) / fabs(dd));
      Fprev = dot3(o.Ft, e1);
      CHECK(h.nseg <= DC_CMD_MAX_SEG && norm3(o.Ft) <= 1.0 + 1e-12);
    }
    td[ntp] = d;
    masing_ref(ntp, td, tf, d, &tf[ntp]);
    ntp++;
  }
  CHECK(jump <= 1.0 + 1e-9);   /* never stiffer than no slip: the force stays continuous */
  /* past the largest turning point: the virgin curve again */
  for (int i = 0; i < 100; i++) {
    const double dd = (1.4 - d) / (100 - i);
    step_along(&p, &m, &pa, n, e1, dd, &h, &o);
    d += dd;
  }
  CHECK_ABS(dot3(o.Ft, e1), 1.0 - pow(1.0 - 1.4 / 1.5, 1.5), 1e-13, "virgin curve after the capped loops");
}

static void test_turn_cap(void)
{
  double in, out;
  turn_sequence(1.2, 0.6, &in, &out);
  CHECK(in < 1e-14 && out < 1e-3);
  printf("12 turning points (cap %d), amplitudes 1.2 x 0.6^k: max error %.1e within the cap, %.1e beyond (mu F_n)\n",
         DC_CMD_MAX_TURNS, in, out);
  turn_sequence(1.2, 0.92, &in, &out);
  CHECK(in < 1e-14 && out < 0.05);
  printf("12 turning points (cap %d), amplitudes 1.2 x 0.92^k: max error %.1e within the cap, %.1e beyond (mu F_n)\n",
         DC_CMD_MAX_TURNS, in, out);
}

/* ------------------------------------------------------------------ */
/* Varying normal force: Eqs. 70-71 (rows eq70, eq70ns, eq71, eq71ns) and
   the oscillating oblique force of Eqs. 72-75 (oblique, energy75). Circle,
   Hertz: a = (N/N0)^1/3, k0 = a, mu = 1/2, N0 = 2. */
static const double VN_N0 = 2.0;
static dc_mindlin_pair vn_pair(void)
{
  const double s0 = 8.0 / 1.7;
  return (dc_mindlin_pair){s0, 0.3 * s0};   /* nu = 0.3: k0 = 8 a / (2 s0 - s1) = a */
}
static dc_patch vn_patch(double N, const double *e1)
{
  const double a = cbrt(N / VN_N0);
  return patch_of(a, a, e1, N);
}

/* drives delta along e1 from d0 to d1 in k steps with N = N0 + g |delta - dref| */
static void vn_drive(dc_cmd_state *h, dc_cmd_out *o, double d0, double d1, int k, double g, double dref)
{
  const dc_mindlin_pair m = vn_pair();
  dc_cmd_params p = {0.5, 0.0, 0, 0};
  double n[3], e1[3], e2[3];
  frame(n, e1, e2);
  for (int i = 1; i <= k; i++) {
    const double d = d0 + (d1 - d0) * i / k, dprev = d0 + (d1 - d0) * (i - 1) / k;
    const dc_patch pa = vn_patch(VN_N0 + g * fabs(d - dref), e1);
    CHECK(step_along(&p, &m, &pa, n, e1, d - dprev, h, o) == DC_OK);
  }
}

static void test_varying_normal(void)
{
  FILE *f = check_open_reference("cmd_tangential.csv");
  if (!f) return;
  double n[3], e1[3], e2[3];
  frame(n, e1, e2);
  const double dst = 1.5 * (1.0 - cbrt(0.4 * 0.4));   /* virgin loading to T* = 0.6 at N0 */
  char tag[16];
  double v[4];
  double worst[4] = {0, 0, 0, 0};
  int rows[4] = {0, 0, 0, 0};
  printf("varying normal force, error vs steps per 0.1 of delta:\n");
  while (check_read_tagged_row(f, tag, sizeof tag, v, 4) > 0) {
    int kind = !strcmp(tag, "eq70") ? 0 : !strcmp(tag, "eq70ns") ? 1 : !strcmp(tag, "eq71") ? 2 : !strcmp(tag, "eq71ns") ? 3 : -1;
    if (kind < 0) continue;
    const double d = v[0], T = v[2];
    const double g = kind % 2 ? 4.0 : 1.0;
    double err[3];
    for (int s = 0, k = 1; s < 3; s++, k *= 10) {
      dc_cmd_state h;
      dc_cmd_out o;
      memset(&h, 0, sizeof h);
      if (kind < 2) {
        vn_drive(&h, &o, 0.0, d, (int)lround(k * d / 0.1), g, 0.0);
      } else {
        vn_drive(&h, &o, 0.0, dst, 64, 0.0, 0.0);
        vn_drive(&h, &o, dst, d, (int)lround(k * (dst - d) / 0.1), g, dst);
      }
      err[s] = fabs(dot3(o.Ft, e1) - T);
    }
    worst[kind] = fmax(worst[kind], err[2]);
    if (kind % 2 == 0) {   /* slip: exact at any step size */
      CHECK(err[0] < 1e-14 && err[1] < 1e-14 && err[2] < 1e-13);
    } else {               /* no slip: the entering rim (linear in xi^2 per step), second order */
      CHECK(err[2] < 1e-6 && err[1] > 50.0 * err[2]);
      if (rows[kind] == 8 || (kind == 1 && rows[kind] == 11)) printf("  %s delta %.2f: %.1e %.1e %.1e (1, 10, 100 steps)\n", tag, d, err[0], err[1], err[2]);
    }
    rows[kind]++;
  }
  fclose(f);
  CHECK(rows[0] == 12 && rows[1] == 12 && rows[2] == 9 && rows[3] == 9);
  printf("  Eq. 70 slip %.1e, no slip %.1e; Eq. 71 (corrected) slip %.1e, no slip %.1e (100 steps)\n", worst[0],
         worst[1], worst[2], worst[3]);
}

/* one force-controlled step: the displacement along e1 that gives T with
   N = N0 + T/Xi (bracketed secant, Illinois, on copies of the state) */
static double vn_goto(dc_cmd_state *h, dc_cmd_out *o, double T, double Xi)
{
  const dc_mindlin_pair m = vn_pair();
  dc_cmd_params p = {0.5, 0.0, 0, 0};
  double n[3], e1[3], e2[3];
  frame(n, e1, e2);
  const dc_patch pa = vn_patch(VN_N0 + T / Xi, e1);
  dc_cmd_state c;
#define VN_F(x, fx) do { c = *h; step_along(&p, &m, &pa, n, e1, (x), &c, o); fx = dot3(o->Ft, e1) - T; } while (0)
  double a = 0.0, fa, b, fb;
  VN_F(a, fa);
  if (fa == 0.0) { *h = c; return 0.0; }
  double w = 1e-3;
  for (;;) {   /* bracket */
    b = fa < 0.0 ? w : -w;
    VN_F(b, fb);
    if ((fa < 0.0) != (fb < 0.0) || fb == 0.0) break;
    w *= 4.0;
  }
  int side = 0;
  for (int it = 0; it < 200; it++) {
    const double x = (a * fb - b * fa) / (fb - fa);
    double fx;
    VN_F(x, fx);
    if (fx == 0.0 || fabs(b - a) < 1e-16 * fabs(x) + 1e-300) { a = b = x; break; }
    if ((fx < 0.0) == (fb < 0.0)) { b = x; fb = fx; if (side == -1) fa *= 0.5; side = -1; }
    else { a = x; fa = fx; if (side == 1) fb *= 0.5; side = 1; }
  }
#undef VN_F
  const double dd = fabs(fa) < fabs(fb) ? a : b;
  step_along(&p, &m, &pa, n, e1, dd, h, o);
  return dd;
}

static void test_oblique(void)
{
  FILE *f = check_open_reference("cmd_tangential.csv");
  if (!f) return;
  const double Xi = 1.0, Ts = 0.5;   /* Theta = mu/Xi = 1/2, Lambda* = 1/2 */
  const double Y = -1.0 / 3.0, ends[5][2] = {{0, Ts}, {Ts, Y * Ts}, {Y * Ts, -Ts}, {-Ts, Ts}, {Ts, -Ts}};
  double v[4], E75 = 0.0, worst = 0.0;
  int rows = 0;
  if (check_next_tagged_row(f, "energy75", v, 4) > 0) E75 = v[2];
  rewind(f);
  /* phases as in the generator, 8 rows each; 32 force steps per row */
  dc_cmd_state h;
  dc_cmd_out o;
  memset(&h, 0, sizeof h);
  double d = 0.0, Tprev = 0.0;
  while (check_next_tagged_row(f, "oblique", v, 4) > 0) {
    const int ph = (int)v[0];
    const double T = v[1];
    for (int i = 1; i <= 32; i++) d += vn_goto(&h, &o, Tprev + (T - Tprev) * i / 32, Xi);
    Tprev = T;
    worst = fmax(worst, fabs(d - v[2]));
    CHECK_ABS(d, v[2], 1e-12, "oblique oscillation: delta(T) of Eqs. 72-74");
    CHECK(ph >= 0 && ph < 5 && (ends[ph][0] - T) * (ends[ph][1] - T) <= 0.0);
    rows++;
  }
  fclose(f);
  CHECK(rows == 40);
  printf("oblique oscillation (Eqs. 72-74), 40 points: max error %.1e in delta\n", worst);
  /* Eq. 75: the area of the stabilised loop, trapezoid */
  printf("  stabilised loop energy (Eq. 75), error vs force steps per half cycle:");
  double err = 0.0;
  for (int N = 100; N <= 100000; N *= 10) {
    dc_cmd_state c = h;   /* at S: T = -T*, stabilised */
    double E = 0.0, T0 = -Ts;
    for (int half = 0; half < 2; half++)
      for (int i = 1; i <= N; i++) {
        const double T1 = half == 0 ? -Ts + 2.0 * Ts * i / N : Ts - 2.0 * Ts * i / N;
        const double dd = vn_goto(&c, &o, T1, Xi);
        E += 0.5 * (T0 + T1) * dd;
        T0 = T1;
      }
    err = fabs(E - E75) / E75;
    printf("  N %5d: %.2e", N, err);
  }
  printf("\n");
  CHECK(err < 1e-9);
}

/* ------------------------------------------------------------------ */
/* Three dimensions. */

/* a circular displacement path of radius R at constant F_n (circle, k0 = 1,
   mu F_n = 1): bounded by mu F_n, Lipschitz with the no-slip stiffness,
   |F| steady on the third turn; for R >> delta_L gross sliding along the
   path's velocity */
static void circle_path(double R, double *Fmin, double *Fmax, double *lag, double *lip)
{
  dc_mindlin_pair m;
  dc_cmd_params p;
  double n[3], e1[3], e2[3];
  const dc_patch pa = unit_circle(&m, &p, n, e1, e2);
  dc_cmd_state h;
  dc_cmd_out o;
  memset(&h, 0, sizeof h);
  const int K = 2000;
  double F0[3] = {0, 0, 0}, d0[2] = {0, 0};
  *Fmin = HUGE_VAL; *Fmax = 0.0; *lag = 0.0; *lip = 0.0;
  for (int i = 1 - K / 4; i <= 3 * K; i++) {   /* straight out to radius R, then three turns about 0 */
    const double t = 2.0 * M_PI * i / K;
    const double d1[2] = {i <= 0 ? R * (i + K / 4) / (K / 4) : R * cos(t), i <= 0 ? 0.0 : R * sin(t)};
    double du[3];
    for (int k = 0; k < 3; k++) du[k] = (d1[0] - d0[0]) * e1[k] + (d1[1] - d0[1]) * e2[k];
    CHECK(dc_cmd_step(&p, &m, &pa, n, du, 0.0, 1e-6, &h, &o) == DC_OK);
    const double F = norm3(o.Ft);
    CHECK(F <= 1.0 + 1e-12 && fabs(dot3(o.Ft, n)) < 1e-14);
    double dF[3];
    for (int k = 0; k < 3; k++) dF[k] = o.Ft[k] - F0[k];
    *lip = fmax(*lip, norm3(dF) / norm3(du));
    if (i > 2 * K) {
      *Fmin = fmin(*Fmin, F);
      *Fmax = fmax(*Fmax, F);
      const double v[2] = {-sin(t), cos(t)}, f[2] = {dot3(o.Ft, e1), dot3(o.Ft, e2)};
      *lag = fmax(*lag, acos(fmin(1.0, (f[0] * v[0] + f[1] * v[1]) / F)));
    }
    memcpy(F0, o.Ft, sizeof F0);
    d0[0] = d1[0]; d0[1] = d1[1];
  }
}

static void test_3d(void)
{
  double Fmin, Fmax, lag, lip;
  circle_path(0.3, &Fmin, &Fmax, &lag, &lip);
  printf("circular path R = 0.2 delta_L: |F| %.6f .. %.6f mu F_n on the third turn, Lipschitz %.4f k0\n", Fmin, Fmax, lip);
  CHECK(Fmax - Fmin < 1e-3 && Fmax < 1.0 && lip <= 1.0 + 1e-9);
  circle_path(7.5, &Fmin, &Fmax, &lag, &lip);
  printf("circular path R = 5 delta_L: |F| %.6f .. %.6f mu F_n, angle to the velocity <= %.4f rad, Lipschitz %.4f k0\n",
         Fmin, Fmax, lag, lip);
  CHECK(Fmax - Fmin < 1e-3 && Fmin > 0.95 && lag < 0.2 && lip <= 1.0 + 1e-9);

  /* an L-shaped path: the stuck core and the slipping rim both resist the
     turn, the perpendicular stiffness is k0 at first; then sliding along e2 */
  dc_mindlin_pair m;
  dc_cmd_params p;
  double n[3], e1[3], e2[3];
  const dc_patch pa = unit_circle(&m, &p, n, e1, e2);
  dc_cmd_state h;
  dc_cmd_out o;
  memset(&h, 0, sizeof h);
  const double ds = 1.5 * (1.0 - cbrt(0.2 * 0.2));   /* F = 0.8 mu F_n */
  for (int i = 0; i < 100; i++) step_along(&p, &m, &pa, n, e1, ds / 100, &h, &o);
  const double Fx = dot3(o.Ft, e1);
  step_along(&p, &m, &pa, n, e2, 1e-7, &h, &o);
  CHECK_REL(dot3(o.Ft, e2) / 1e-7, 1.0, 1e-5, "L path: perpendicular stiffness k0 at the turn");
  CHECK_REL(dot3(o.Ft, e1), Fx, 1e-6, "L path: the force along e1 kept at the turn");
  for (int i = 0; i < 1000; i++) step_along(&p, &m, &pa, n, e2, 0.01, &h, &o);
  CHECK(dot3(o.Ft, e2) > 0.999 && norm3(o.Ft) <= 1.0 + 1e-12);

  /* the contact plane turns by 90 degrees (rolling) without slip: the force
     turns with it, magnitude kept */
  memset(&h, 0, sizeof h);
  for (int i = 0; i < 100; i++) step_along(&p, &m, &pa, n, e1, ds / 100, &h, &o);
  const double F1 = norm3(o.Ft);
  double nn[3];
  const double zero[3] = {0, 0, 0};
  for (int i = 1; i <= 1000; i++) {
    const double t = 0.5 * M_PI * i / 1000;   /* n turns about e2 towards e1 */
    for (int k = 0; k < 3; k++) nn[k] = cos(t) * n[k] + sin(t) * e1[k];
    CHECK(dc_cmd_step(&p, &m, &pa, nn, zero, 0.0, 1e-6, &h, &o) == DC_OK);
  }
  CHECK_REL(norm3(o.Ft), F1, 1e-13, "plane turned by 90 degrees: |F| kept");
  CHECK_REL(-dot3(o.Ft, n), F1, 1e-13, "plane turned by 90 degrees: F along the turned e1 (-n)");
  /* a turn by 178.5 degrees in one step (projection, magnitude kept) */
  for (int k = 0; k < 3; k++) nn[k] = -cos(0.026) * n[k] + sin(0.026) * e2[k];
  dc_cmd_state h2;
  memset(&h2, 0, sizeof h2);
  for (int i = 0; i < 100; i++) step_along(&p, &m, &pa, n, e1, ds / 100, &h2, &o);
  CHECK(dc_cmd_step(&p, &m, &pa, nn, zero, 0.0, 1e-6, &h2, &o) == DC_OK);
  CHECK_REL(norm3(o.Ft), F1, 1e-13, "plane turned by 178.5 degrees: |F| kept");
  CHECK(fabs(dot3(o.Ft, nn)) < 1e-14);

  /* a straight path in any direction of the plane gives the 1D result */
  for (int j = 0; j < 8; j++) {
    const double ang = 0.7 * j;
    double e[3];
    for (int k = 0; k < 3; k++) e[k] = cos(ang) * e1[k] + sin(ang) * e2[k];
    memset(&h, 0, sizeof h);
    for (int i = 0; i < 10; i++) step_along(&p, &m, &pa, n, e, ds / 10, &h, &o);
    CHECK_REL(dot3(o.Ft, e), 0.8, 1e-14, "straight path in any direction");
  }
}

/* i and j swapped: n, du negated, twist increment the same, history
   fields with flips = 1 negated: the force is exactly negated, the moment
   the same, and the histories stay each other's image */
static void test_swap(void)
{
  const dc_mindlin_pair m = {0.8, 0.2};
  dc_cmd_params p = {0.4, 1e-4, 1, 1};
  double n[3], e1[3], e2[3];
  frame(n, e1, e2);
  dc_cmd_state A, B;
  dc_cmd_out oa, ob;
  memset(&A, 0, sizeof A);
  memset(&B, 0, sizeof B);
  unsigned long long x = 12345;
  int same = 1;
  for (int i = 0; i < 2000; i++) {
    const double t = 0.002 * i;
    double nr[3], nb[3], du[3], db[3];
    for (int k = 0; k < 3; k++) nr[k] = cos(t) * n[k] + sin(t) * e2[k];
    for (int k = 0; k < 3; k++) { nb[k] = -nr[k]; du[k] = 1e-3 * (check_uniform(&x) - 0.5); db[k] = -du[k]; }
    const double a = 1.0 + 0.3 * sin(0.01 * i), b = a * (0.5 + 0.2 * cos(0.02 * i));
    double ax[3];
    for (int k = 0; k < 3; k++) ax[k] = cos(t) * e1[k] - sin(t) * 0.0;
    const dc_patch pa = patch_of(a, b, ax, 1.0 + 0.5 * sin(0.03 * i));
    const dc_patch pb = patch_of(a, b, ax, 1.0 + 0.5 * sin(0.03 * i));
    const double dphi = 1e-3 * (check_uniform(&x) - 0.5);
    CHECK(dc_cmd_step(&p, &m, &pa, nr, du, dphi, 1e-4, &A, &oa) == DC_OK);
    CHECK(dc_cmd_step(&p, &m, &pb, nb, db, dphi, 1e-4, &B, &ob) == DC_OK);
    for (int k = 0; k < 3; k++) same &= ob.Ft[k] == -oa.Ft[k];
    same &= ob.Mt == oa.Mt && ob.kt == oa.kt && ob.kr == oa.kr;
    const double *ha = (const double *)&A, *hb = (const double *)&B;
    for (int k = 0; k < DC_CMD_HISTORY_NFIELDS; k++) same &= hb[k] == (dc_cmd_history[k].flips ? -ha[k] : ha[k]);
  }
  CHECK(same);
  /* the field table: unique names, vectors flip, the rest does not */
  int ok = 1;
  for (int k = 0; k < DC_CMD_HISTORY_NFIELDS; k++)
    for (int j = 0; j < k; j++) ok &= strcmp(dc_cmd_history[k].name, dc_cmd_history[j].name) != 0;
  CHECK(ok && DC_CMD_HISTORY_NFIELDS == 86);
  CHECK(dc_cmd_history[0].flips && dc_cmd_history[3].flips == 0 && dc_cmd_history[4].flips == 0);
  CHECK(!strcmp(dc_cmd_history[DC_CMD_HISTORY_NFIELDS - 1].name, "cmd_t1_7"));
}

/* F_n -> 0 while loaded tangentially, then loss of contact */
static void test_unloading_to_zero(void)
{
  const dc_mindlin_pair m = vn_pair();
  dc_cmd_params p = {0.5, 0.0, 0, 1};
  double n[3], e1[3], e2[3];
  frame(n, e1, e2);
  dc_cmd_state h;
  dc_cmd_out o;
  memset(&h, 0, sizeof h);
  vn_drive(&h, &o, 0.0, 0.5, 50, 0.0, 0.0);   /* F = 0.8 mu N0 ... */
  const double zero[3] = {0, 0, 0};
  for (int i = 1; i <= 200; i++) {
    const double N = VN_N0 * pow(1.0 - i / 200.0, 2.0);
    const dc_patch pa = vn_patch(N, e1);
    CHECK(dc_cmd_step(&p, &m, &pa, n, zero, 1e-4, 1e-6, &h, &o) == DC_OK);
    CHECK(norm3(o.Ft) <= 0.5 * N * (1.0 + 1e-12));
  }
  CHECK(norm3(o.Ft) == 0.0 && h.nseg == 0.0);   /* a = 0: the springs have left */
  dc_patch off = vn_patch(1.0, e1);
  off.formed = 0.0;
  CHECK(dc_cmd_step(&p, &m, &off, n, zero, 0.0, 1e-6, &h, &o) == DC_OK);
  dc_cmd_state z;
  memset(&z, 0, sizeof z);
  CHECK(!memcmp(&h, &z, sizeof h) && o.Ft[0] == 0.0 && o.Mt == 0.0);
  /* F_bound = 0 with an area (an adhesive neck at its limit): no force */
  dc_patch zb = vn_patch(1.0, e1);
  zb.F_bound = 0.0;
  CHECK(step_along(&p, &m, &zb, n, e1, 1e-3, &h, &o) == DC_OK && norm3(o.Ft) == 0.0 && o.Mt == 0.0);
  /* a new contact: fresh, no slip */
  memset(&h, 0, sizeof h);
  const dc_patch pa = vn_patch(VN_N0, e1);
  CHECK(step_along(&p, &m, &pa, n, e1, 1e-9, &h, &o) == DC_OK);
  CHECK_REL(dot3(o.Ft, e1), 1e-9, 1e-8, "a new contact: k0 du");
}

/* Eq. 85: F_dis = A_t theta K0 du/dt; capped at mu F_bound */
static void test_dissipation(void)
{
  const dc_mindlin_pair m = vn_pair();
  dc_cmd_params p = {0.5, 2e-4, 1, 0};
  double n[3], e1[3], e2[3];
  frame(n, e1, e2);
  dc_cmd_state h;
  dc_cmd_out o;
  memset(&h, 0, sizeof h);
  const dc_patch pa = patch_of(1.0, 0.5, e1, VN_N0);
  double km, kn;
  CHECK(dc_cmd_stiffness(&m, 1.0, 0.5, &km, &kn) == DC_OK && kn > km);
  const double d = 1e-8, dt = 1e-5;
  double du[3];
  for (int k = 0; k < 3; k++) du[k] = d * e2[k];
  CHECK(dc_cmd_step(&p, &m, &pa, n, du, 0.0, dt, &h, &o) == DC_OK);
  CHECK_REL(dot3(o.Ft, e2), kn * d * (1.0 + 2e-4 / dt), 1e-8, "Eq. 85 on the minor axis: (1 + A_t/dt) k_minor du");
  CHECK_REL(o.kt, kn, 1e-8, "tangent stiffness along the minor axis");
  for (int k = 0; k < 3; k++) du[k] = 10.0 * e1[k];
  CHECK(dc_cmd_step(&p, &m, &pa, n, du, 0.0, dt, &h, &o) == DC_OK);
  CHECK_REL(norm3(o.Ft), 0.5 * VN_N0, 1e-15, "sliding: mu F_bound");
  CHECK(o.kt == 0.0 && o.stick == 0.0);
}

/* Status codes (dc/status.h) and the parameter check. */
static void test_status(void)
{
  const dc_mindlin_pair m = {1.0, 0.3};
  dc_cmd_params p = {0.5, 0.0, 0, 1};
  double n[3], e1[3], e2[3];
  frame(n, e1, e2);
  dc_cmd_state h, h0;
  dc_cmd_out o, o0;
  memset(&h, 0, sizeof h);
  const dc_patch good = patch_of(1.0, 0.5, e1, 1.0);
  step_along(&p, &m, &good, n, e1, 0.01, &h, &o);
  h0 = h;
  memset(&o, 0x5A, sizeof o);
  o0 = o;
  const double du[3] = {1e-3, 0, 0};
#define BAD(call) do { CHECK((call) == DC_EDOM); CHECK(!memcmp(&h, &h0, sizeof h) && !memcmp(&o, &o0, sizeof o)); } while (0)
  dc_patch pa = good;
  pa.a = NAN;            BAD(dc_cmd_step(&p, &m, &pa, n, du, 0.0, 1e-6, &h, &o));
  pa = good; pa.b = 1.5; BAD(dc_cmd_step(&p, &m, &pa, n, du, 0.0, 1e-6, &h, &o));
  pa = good; pa.F_bound = -1.0; BAD(dc_cmd_step(&p, &m, &pa, n, du, 0.0, 1e-6, &h, &o));
  pa = good; pa.axis[0] = pa.axis[1] = pa.axis[2] = 0.0; BAD(dc_cmd_step(&p, &m, &pa, n, du, 0.0, 1e-6, &h, &o));
  pa = good; pa.axis[1] = INFINITY; BAD(dc_cmd_step(&p, &m, &pa, n, du, 0.0, 1e-6, &h, &o));
  const double n2[3] = {0.0, 0.0, 1.01}, dn[3] = {0.0, NAN, 0.0};
  BAD(dc_cmd_step(&p, &m, &good, n2, du, 0.0, 1e-6, &h, &o));
  BAD(dc_cmd_step(&p, &m, &good, n, dn, 0.0, 1e-6, &h, &o));
  BAD(dc_cmd_step(&p, &m, &good, n, du, INFINITY, 1e-6, &h, &o));
  const dc_mindlin_pair mb = {1.0, 0.6};
  BAD(dc_cmd_step(&p, &mb, &good, n, du, 0.0, 1e-6, &h, &o));
  dc_cmd_params pb = p;
  pb.mu = -0.1;          BAD(dc_cmd_step(&pb, &m, &good, n, du, 0.0, 1e-6, &h, &o));
  pb = p; pb.dissipation = 1; BAD(dc_cmd_step(&pb, &m, &good, n, du, 0.0, 0.0, &h, &o));
  pb = p; pb.twisting = 2; BAD(dc_cmd_step(&pb, &m, &good, n, du, 0.0, 1e-6, &h, &o));
  h.nseg = 9;            CHECK(dc_cmd_step(&p, &m, &good, n, du, 0.0, 1e-6, &h, &o) == DC_EDOM); h = h0;
  h.seg[0].u1[1] = NAN;     CHECK(dc_cmd_step(&p, &m, &good, n, du, 0.0, 1e-6, &h, &o) == DC_EDOM); h = h0;
  CHECK(!memcmp(&o, &o0, sizeof o));
  /* twisting off: dphi is not read */
  pb = p; pb.twisting = 0;
  CHECK(dc_cmd_step(&pb, &m, &good, n, du, NAN, 1e-6, &h, &o) == DC_OK && o.Mt == 0.0);
#undef BAD
  /* overflow: DC_ERANGE, untouched */
  h = h0;
  memcpy(&o, &o0, sizeof o);
  const double huge[3] = {1e300, 1e300, 0};
  const dc_patch big = patch_of(1e300, 1e300, e1, 1e300);
  const int st = dc_cmd_step(&p, &m, &big, n, huge, 1e300, 1e-6, &h, &o);
  CHECK(st == DC_ERANGE || st == DC_OK);
  if (st != DC_OK) CHECK(!memcmp(&h, &h0, sizeof h) && !memcmp(&o, &o0, sizeof o));
  /* parameter check */
  dc_param_error err;
  dc_cmd_params q = {0.5, 0.0, 0, 0};
  CHECK(dc_cmd_check(&q, &err) == DC_OK);
  q.mu = -1.0;
  CHECK(dc_cmd_check(&q, &err) == DC_EDOM && !strcmp(err.name, "coefficientFriction") && err.value == -1.0);
  q.mu = INFINITY;
  CHECK(dc_cmd_check(&q, &err) == DC_EDOM && !strcmp(err.name, "coefficientFriction"));
  q.mu = 0.0; q.t_visc = NAN;
  CHECK(dc_cmd_check(&q, &err) == DC_EDOM && !strcmp(err.name, "tangentialViscoelasticTime"));
  q.t_visc = 0.0; q.dissipation = 3;
  CHECK(dc_cmd_check(&q, &err) == DC_EDOM && !strcmp(err.name, "cmdDissipation"));
  q.dissipation = 1; q.twisting = -1;
  CHECK(dc_cmd_check(&q, &err) == DC_EDOM && !strcmp(err.name, "cmdTwisting"));
  double k1 = -1, k2 = -1;
  CHECK(dc_cmd_stiffness(&m, 1.0, 0.0, &k1, &k2) == DC_EDOM && k1 == -1 && k2 == -1);
  CHECK(dc_cmd_twist_stiffness(&m, 1.0, 1.0 + 1e-9, &k1) == DC_EDOM && k1 == -1);
  CHECK(dc_cmd_twist_slip_moment(-1.0, 1.0, 1.0, 1.0, &k1) == DC_EDOM && k1 == -1);
}

/* A corrupted history (a wrapper's restart file, a bad memory copy): piece
   counts that are NaN, infinite, beyond int's range, negative or
   fractional give DC_EDOM with h and out untouched, with and without
   twisting (they were converted to int before their range was checked:
   undefined behaviour for NaN and values beyond int's range). Without
   twisting nseg_t is not read. */
static void test_corrupted_history(void)
{
  const dc_mindlin_pair m = {1.0, 0.3};
  double n[3], e1[3], e2[3];
  frame(n, e1, e2);
  const dc_patch good = patch_of(1.0, 0.5, e1, 1.0);
  const double du[3] = {1e-3, 0, 0};
  static const double bad[] = {NAN, -NAN, INFINITY, -INFINITY, 1e300, -1e300, 3e9, -3e9, 2147483648.0,
                               -2147483649.0, 9.0, 1e10, -5.0, -1.0, 2.5, 0.5, -0.5, 8.000000000000002};
  for (int tw = 0; tw < 2; tw++) {
    const dc_cmd_params p = {0.5, 0.0, 0, tw};
    dc_cmd_state h, h0;
    dc_cmd_out o, o0;
    memset(&h, 0, sizeof h);
    /* a history of a few pieces (three force reversals, and a twist) */
    for (int s = 0; s < 4; s++) {
      const double d[3] = {(s & 1 ? -1.0 : 1.0) * 0.3 * e1[0], (s & 1 ? -1.0 : 1.0) * 0.3 * e1[1],
                           (s & 1 ? -1.0 : 1.0) * 0.3 * e1[2]};
      CHECK(dc_cmd_step(&p, &m, &good, n, d, s & 1 ? -0.2 : 0.2, 1e-6, &h, &o) == DC_OK);
    }
    CHECK(h.nseg >= 2.0 && (!tw || h.nseg_t >= 1.0));
    h0 = h;
    memset(&o, 0x5A, sizeof o);
    o0 = o;
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
      for (int field = 0; field < 2; field++) {
        h = h0;
        if (field == 0) h.nseg = bad[i];
        else h.nseg_t = bad[i];
        const dc_cmd_state hc = h;
        const int st = dc_cmd_step(&p, &m, &good, n, du, 0.01, 1e-6, &h, &o);
        if (field == 1 && !tw) {
          /* not read without twisting, and not written */
          CHECK(st == DC_OK && !memcmp(&h.nseg_t, &hc.nseg_t, sizeof h.nseg_t));
          memcpy(&o, &o0, sizeof o);
          continue;
        }
        if (!CHECK(st == DC_EDOM && !memcmp(&h, &hc, sizeof h) && !memcmp(&o, &o0, sizeof o)))
          printf("  twisting %d, %s = %.17g: status %d\n", tw, field ? "nseg_t" : "nseg", bad[i], st);
      }
    }
    /* the counts of the uncorrupted history still work, and -0 is 0 */
    h = h0;
    CHECK(dc_cmd_step(&p, &m, &good, n, du, 0.01, 1e-6, &h, &o) == DC_OK);
    memset(&h, 0, sizeof h);
    h.nseg = -0.0;
    h.nseg_t = -0.0;
    CHECK(dc_cmd_step(&p, &m, &good, n, du, 0.01, 1e-6, &h, &o) == DC_OK);
  }
}

/* A seeded random sweep: 1e5 steps of random patches (circles, ellipses
   down to b/a = 1e-3, F_bound including 0, now and then not formed),
   normals turning slowly and now and then jumping, displacements from
   1e-6 to 1e2 delta_L, twisting and dissipation on: always DC_OK, finite,
   |Ft| <= mu F_bound (1 + 1e-12), Ft normal to n, |Mt| <= M_s; and
   dc_cmd_step_trusted gives the same status and bits at every step. */
static void test_random_sweep(void)
{
  unsigned long long x = 0x2545F4914F6CDD1Dull;
  const dc_mindlin_pair m = {2e-10, 5e-11};
  dc_cmd_params p = {0.3, 1e-6, 1, 1};
  double n[3] = {0, 0, 1};
  dc_cmd_state h;
  dc_cmd_out o;
  memset(&h, 0, sizeof h);
  long bad = 0, bound = 0, normal = 0, moment = 0, nonok = 0, trusted = 0;
  double a = 1e-4, b = 1e-4, Fb = 1.0, ax[3] = {1, 0, 0};
  for (long i = 0; i < 100000; i++) {
    const double r = check_uniform(&x);
    /* the normal: a small turn, or now and then a jump */
    double t[3] = {check_uniform(&x) - 0.5, check_uniform(&x) - 0.5, check_uniform(&x) - 0.5};
    const double turn = r < 0.01 ? 3.0 : 0.02 * check_uniform(&x);
    for (int k = 0; k < 3; k++) n[k] += turn * t[k];
    const double ln = norm3(n);
    for (int k = 0; k < 3; k++) n[k] /= ln;
    /* the patch: slow drift, now and then a new shape */
    if (check_uniform(&x) < 0.02) {
      a = 1e-6 * pow(10.0, 3.0 * check_uniform(&x));
      b = check_uniform(&x) < 0.4 ? a : a * pow(10.0, -3.0 * check_uniform(&x));
    } else {
      a *= 1.0 + 0.01 * (check_uniform(&x) - 0.5);
      b = fmin(a, b * (1.0 + 0.01 * (check_uniform(&x) - 0.5)));
    }
    Fb = check_uniform(&x) < 0.03 ? 0.0 : fabs(Fb * (1.0 + 0.1 * (check_uniform(&x) - 0.5))) + 1e-3 * check_uniform(&x);
    double an[3];
    cross3(n, t, an);
    const double la = norm3(an);
    for (int k = 0; k < 3; k++) ax[k] = la > 0.0 ? an[k] / la : 0.0;
    dc_patch pa = patch_of(a, b, ax, Fb);
    if (la == 0.0) pa.b = pa.a;
    if (check_uniform(&x) < 0.002) pa.formed = 0.0;
    const double dL = 1.5 * p.mu * Fb * (2.0 * m.s0 - m.s1) / (8.0 * a) + 1e-300;
    const double mag = dL * pow(10.0, -6.0 + 8.0 * check_uniform(&x));
    double du[3] = {mag * (check_uniform(&x) - 0.5), mag * (check_uniform(&x) - 0.5), mag * (check_uniform(&x) - 0.5)};
    const double dphi = mag / a * (check_uniform(&x) - 0.5);
    dc_cmd_state ht = h;
    dc_cmd_out ot;
    const int stt = dc_cmd_step_trusted(&p, &m, &pa, n, du, dphi, 1e-5, &ht, &ot);
    const int st = dc_cmd_step(&p, &m, &pa, n, du, dphi, 1e-5, &h, &o);
    /* the trusted step: the same status and bits on inputs in the domain */
    if (stt != st || (st == DC_OK && (memcmp(&ht, &h, sizeof h) || memcmp(&ot, &o, sizeof o)))) trusted++;
    if (st != DC_OK) { nonok++; continue; }
    if (!(isfinite(o.Ft[0]) && isfinite(o.Ft[1]) && isfinite(o.Ft[2]) && isfinite(o.kt) && isfinite(o.Mt) &&
          isfinite(o.kr) && isfinite(o.stick)))
      bad++;
    if (norm3(o.Ft) > p.mu * Fb * (1.0 + 1e-12)) bound++;
    if (fabs(dot3(o.Ft, n)) > 1e-12 * (p.mu * Fb + 1e-300)) normal++;
    double Ms = 0.0;
    if (pa.formed != 0.0) dc_cmd_twist_slip_moment(p.mu, Fb, pa.a, pa.b, &Ms);
    if (fabs(o.Mt) > Ms * (1.0 + 1e-12)) moment++;
  }
  CHECK(nonok == 0 && bad == 0 && bound == 0 && normal == 0 && moment == 0 && trusted == 0);
  printf("random sweep, 1e5 steps: %ld not OK, %ld non-finite, %ld over mu F_bound, %ld off the plane, %ld over M_s, "
         "%ld where dc_cmd_step_trusted differs\n", nonok, bad, bound, normal, moment, trusted);
}

/* ns per step, DEM-like (printed, not asserted): partial slip (the
   displacement oscillates within about delta_L / 4 and turns slowly), the
   patch breathes by +-10 %, the normal turns by 1e-4 rad per step; the
   same loop without the call is timed and subtracted. Also the simplest
   case: a constant patch and a small oscillation along one line. */
static double timing_loop(int c, int call, double *pieces)
{
  const dc_mindlin_pair m = {2e-10, 5e-11};   /* steel-like, s0 = sum 1/G_i */
  double n0[3], e1[3], e2[3];
  frame(n0, e1, e2);
  dc_cmd_params p = {0.3, 0.0, 0, c >= 2 && c < 4};
  const int ell = c % 2, simple = c >= 4;
  dc_cmd_state h;
  dc_cmd_out o;
  memset(&h, 0, sizeof h);
  memset(&o, 0, sizeof o);
  const long K = 1000000;
  volatile double sink = 0.0;
  double pc = 0.0;
  struct timespec t0, t1;
  clock_gettime(CLOCK_MONOTONIC, &t0);
  for (long i = 0; i < K; i++) {
    const double s = simple ? 1.0 : 1.0 + 0.1 * sin(1e-4 * i), tn = simple ? 0.0 : 1e-4 * i;
    const double a = 1e-4 * s, b = ell ? 0.5 * a : a;
    double n[3], ax[3];
    const double ct = cos(tn), st = sin(tn);
    for (int k = 0; k < 3; k++) {
      n[k] = ct * n0[k] + st * e2[k];
      ax[k] = e1[k];
    }
    const dc_patch pa = patch_of(a, b, ax, 2.0 * s * s * s);
    const double ang = simple ? 0.0 : 1e-3 * i, d = 1e-10 * sin(2e-3 * i), ca = cos(ang), sa = sin(ang);
    double du[3];
    for (int k = 0; k < 3; k++) du[k] = d * (ca * e1[k] + sa * e2[k]);
    if (call) {
      dc_cmd_step(&p, &m, &pa, n, du, d / a, 1e-6, &h, &o);
      pc += h.nseg + h.nseg_t;
    } else {
      o.Ft[0] = du[0] + n[1] + pa.a;
    }
    sink = sink + o.Ft[0];
  }
  clock_gettime(CLOCK_MONOTONIC, &t1);
  *pieces = pc / K;
  return ((double)(t1.tv_sec - t0.tv_sec) * 1e9 + (double)(t1.tv_nsec - t0.tv_nsec)) / K;
}

static void timing(void)
{
  static const char *what[6] = {"circle", "ellipse b/a = 0.5", "circle, twisting on", "ellipse b/a = 0.5, twisting on",
                                "circle, constant patch, one line", "ellipse, constant patch, one line"};
  for (int c = 0; c < 6; c++) {
    double pieces, dummy;
    double best = HUGE_VAL;
    for (int r = 0; r < 2; r++) best = fmin(best, timing_loop(c, 1, &pieces) - timing_loop(c, 0, &dummy));
    printf("dc_cmd_step, %s: %.0f ns per call (%.1f pieces on average)\n", what[c], best, pieces);
  }
}

int main(void)
{
  test_circle_loop();
  test_ellipse_noslip();
  test_ellipse_microslip();
  test_twist();
  test_nested();
  test_turn_cap();
  test_varying_normal();
  test_oblique();
  test_3d();
  test_swap();
  test_unloading_to_zero();
  test_dissipation();
  test_status();
  test_corrupted_history();
  test_random_sweep();
  timing();
  return check_summary("test_cmd_tangential");
}
