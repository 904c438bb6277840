/* Mindlin-Deresiewicz with bounded memory (dc/cmd_turning_points.h)
   against the exact spring profile (dc/cmd_tangential.h), an independent
   algorithm (piecewise profiles with clamping, grouping and merging), on
   the paths where the profile needs few pieces: virgin loading and loops
   at constant normal force with up to DC_CMDTP_MAX_TURNS turning points,
   on circles and ellipses, turning contact planes, twisting, dissipation.
   Beyond that (more turning points, varying normal force) the difference
   is measured and bounded. Domain errors leave the history untouched. */
#include "check.h"
#include "dc/cmd_tangential.h"
#include "dc/cmd_turning_points.h"
#include "dc/status.h"
#include <float.h>

static double dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static void cross3(const double *a, const double *b, double *c)
{
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

/* a tilted frame: normal n, major axis e1, minor axis e2 */
static void frame(double n[3], double e1[3], double e2[3])
{
  const double n0[3] = {0.48, -0.6, 0.64}, t[3] = {0.8, 0.64, 0.0};
  for (int k = 0; k < 3; k++) {
    n[k] = n0[k];
    e1[k] = t[k] / sqrt(1.0496);
  }
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

/* Both laws side by side on one contact. */
typedef struct {
  dc_cmd_params p;
  dc_mindlin_pair m;
  dc_cmd_state hx;
  dc_cmdtp_state ht;
  double worst;    /* max |F_tp - F_exact| / mu F_b so far */
  double worstM;   /* the same for the moment / M_s */
  int bad;         /* a status other than DC_OK */
} pair_run;

static void run_init(pair_run *r, double mu, int twisting, int dissipation, double tvisc)
{
  memset(r, 0, sizeof *r);
  r->p.mu = mu;
  r->p.twisting = twisting;
  r->p.dissipation = dissipation;
  r->p.t_visc = tvisc;
  r->m.s0 = 1.0;   /* one body G = 1, nu = 0.3 on a rigid one */
  r->m.s1 = 0.3;
}

/* one step of both; the difference of the forces (and moments) */
static void run_step(pair_run *r, const dc_patch *pa, const double *n, const double *du, double dphi)
{
  dc_cmd_out ox, ot;
  const double dt = 1e-6;
  r->bad |= dc_cmd_step(&r->p, &r->m, pa, n, du, dphi, dt, &r->hx, &ox) != DC_OK;
  r->bad |= dc_cmdtp_step(&r->p, &r->m, pa, n, du, dphi, dt, &r->ht, &ot) != DC_OK;
  const double S = r->p.mu * pa->F_bound;
  double d[3];
  for (int k = 0; k < 3; k++) d[k] = ot.Ft[k] - ox.Ft[k];
  const double e = sqrt(dot3(d, d)) / S;
  if (e > r->worst) r->worst = e;
  if (r->p.twisting) {
    double Ms;
    dc_cmd_twist_slip_moment(r->p.mu, pa->F_bound, pa->a, pa->b, &Ms);
    const double em = fabs(ot.Mt - ox.Mt) / Ms;
    if (em > r->worstM) r->worstM = em;
  }
}

/* a straight path through the points x[0..np-1] (units of L = the virgin
   slip distance along e), N steps per unit */
static void run_path(pair_run *r, const dc_patch *pa, const double *n, const double *e, double L, const double *x,
                     int np, int N, double twist_per_unit)
{
  double at = 0.0;
  for (int i = 0; i < np; i++) {
    const int ns = (int)ceil(fabs(x[i] - at) * N);
    const double h = (x[i] - at) / ns;
    for (int j = 0; j < ns; j++) {
      /* a normal part the laws must ignore */
      const double du[3] = {h * L * e[0] + 0.3 * h * L * n[0], h * L * e[1] + 0.3 * h * L * n[1],
                            h * L * e[2] + 0.3 * h * L * n[2]};
      run_step(r, pa, n, du, h * twist_per_unit);
    }
    at = x[i];
  }
}

/* Virgin loading and nested loops at constant F_n (up to 4 remembered
   turning points), gross sliding and back: equal to rounding, on the
   circle and on ellipses along an axis and between them. */
static void test_constant_load(void)
{
  double n[3], e1[3], e2[3];
  frame(n, e1, e2);
  /* turning points (units of the virgin slip distance): 4 nested; past
     the third (Madelung: back on the branch from the second), a reversal,
     past the second and the first (back on the virgin curve), gross
     sliding, and loops from full slip */
  const double path[] = {0.8, -0.5, 0.6, -0.2, 0.7, -0.6, 0.9, 1.3, -0.6, 0.2, -2.0, 1.5, 0.9};
  const int np = (int)(sizeof path / sizeof path[0]);
  const double ratios[] = {1.0, 0.6, 0.2, 1e-3};
  for (int ir = 0; ir < 4; ir++) {
    for (int dir = 0; dir < 3; dir++) {
      pair_run r;
      run_init(&r, 0.5, 0, 0, 0.0);
      const double a = 1e-3, b = ratios[ir] * a;
      const dc_patch pa = patch_of(a, b, e1, 2.0);
      double e[3];
      const double th = dir * M_PI / 5.0;   /* 0, 36 and 72 degrees from the major axis */
      for (int k = 0; k < 3; k++) e[k] = cos(th) * e1[k] + sin(th) * e2[k];
      /* the virgin slip distance along e: |M e| L0 = 1.5 mu F_b / k_major, from one step's stiffness */
      double km, kn;
      dc_cmd_stiffness(&r.m, a, b, &km, &kn);
      const double Me = sqrt(pow(cos(th), 2) + pow(kn / km * sin(th), 2));
      const double L = 1.5 * r.p.mu * pa.F_bound / km / Me;
      run_path(&r, &pa, n, e, L, path, np, 400, 0.0);
      CHECK(!r.bad);
      char what[96];
      snprintf(what, sizeof what, "b/a %g, %g deg: constant-load loops equal the exact profile", ratios[ir],
               th * 180.0 / M_PI);
      CHECK_ABS(r.worst, 0.0, 1e-12, what);
    }
  }
}

/* Twisting: the same memory for the moment (the exact law's twist profile
   is the same spring bed): equal to rounding on a constant-load loop
   with the force held still. Dissipation equal to rounding on nested
   loops that return to no turning point (where a branch meets a
   remembered one, the exact profile's stuck fraction counts the
   touching annulus by rounding for a step, and so its viscous force). */
static void test_twist_and_dissipation(void)
{
  double n[3], e1[3], e2[3];
  frame(n, e1, e2);
  const double path[] = {0.7, -0.4, 0.5, -0.1, 0.3, 1.2, -1.1};
  const int np = (int)(sizeof path / sizeof path[0]);
  for (int ell = 0; ell < 2; ell++) {
    pair_run r;
    run_init(&r, 0.4, 1, 0, 0.0);
    const double a = 2e-3, b = ell ? 0.5 * a : a;
    const dc_patch pa = patch_of(a, b, e1, 3.0);
    double ktw, Ms;
    dc_cmd_twist_stiffness(&r.m, a, b, &ktw);
    dc_cmd_twist_slip_moment(r.p.mu, pa.F_bound, a, b, &Ms);
    const double zero[3] = {0.0, 0.0, 0.0};
    /* twist alone: the moment's loop (the force stays 0) */
    double at = 0.0;
    const double Lt = 1.5 * Ms / ktw;
    for (int i = 0; i < np; i++) {
      const int ns = (int)ceil(fabs(path[i] - at) * 300);
      for (int j = 0; j < ns; j++) run_step(&r, &pa, n, zero, (path[i] - at) / ns * Lt);
      at = path[i];
    }
    CHECK(!r.bad);
    CHECK_ABS(r.worstM, 0.0, 1e-12, ell ? "twist loops (b/a 0.5) equal the exact profile" : "twist loops (circle) equal the exact profile");
    CHECK_ABS(r.worst, 0.0, 1e-300, "no force from twisting alone");
  }
  {
    pair_run r;
    run_init(&r, 0.5, 0, 1, 3e-7);
    const dc_patch pa = patch_of(1e-3, 1e-3, e1, 2.0);
    double km, kn;
    dc_cmd_stiffness(&r.m, pa.a, pa.b, &km, &kn);
    const double nested[] = {0.7, -0.4, 0.5, -0.1, 0.3, 0.0, 0.2};
    run_path(&r, &pa, n, e2, 1.5 * r.p.mu * pa.F_bound / km, nested, 7, 300, 0.0);
    CHECK(!r.bad);
    CHECK_ABS(r.worst, 0.0, 1e-12, "dissipation (Eq. 85) on constant-load loops equals the exact profile");
  }
}

/* A contact plane that turns while the loops go on (the force and the
   turning points turn with it): equal to rounding. */
static void test_turning_plane(void)
{
  double n0[3], e1[3], e2[3];
  frame(n0, e1, e2);
  pair_run r;
  run_init(&r, 0.5, 0, 0, 0.0);
  const dc_patch pa0 = patch_of(1e-3, 0.4e-3, e1, 2.0);
  double km, kn;
  dc_cmd_stiffness(&r.m, pa0.a, pa0.b, &km, &kn);
  const double L = 1.5 * r.p.mu * pa0.F_bound / km;
  const double path[] = {0.8, -0.5, 0.6, -0.2, 0.7, -0.6, 1.2};
  double at = 0.0, ang = 0.0;
  for (int i = 0; i < 7; i++) {
    const int ns = (int)ceil(fabs(path[i] - at) * 300);
    for (int j = 0; j < ns; j++) {
      /* the frame turned about e2 by ang: n, e1 turn, e2 stays */
      ang += 2e-3;
      double n[3], a1[3];
      for (int k = 0; k < 3; k++) {
        n[k] = cos(ang) * n0[k] + sin(ang) * e1[k];
        a1[k] = cos(ang) * e1[k] - sin(ang) * n0[k];
      }
      const dc_patch pa = patch_of(pa0.a, pa0.b, a1, pa0.F_bound);
      const double h = (path[i] - at) / ns * L;
      const double du[3] = {h * a1[0], h * a1[1], h * a1[2]};
      run_step(&r, &pa, n, du, 0.0);
    }
    at = path[i];
  }
  CHECK(!r.bad);
  CHECK_ABS(r.worst, 0.0, 1e-12, "turning plane (2.6 rad over the path): equal to the exact profile");
}

/* More turning points than remembered, and a varying normal force: the
   difference from the exact profile, measured and bounded. */
static void test_beyond(void)
{
  double n[3], e1[3], e2[3];
  frame(n, e1, e2);
  {
    pair_run r;
    run_init(&r, 0.5, 0, 0, 0.0);
    const dc_patch pa = patch_of(1e-3, 1e-3, e1, 2.0);
    double km, kn;
    dc_cmd_stiffness(&r.m, pa.a, pa.b, &km, &kn);
    /* 8 nested turning points, then back out through all of them */
    const double path[] = {0.9, -0.8, 0.7, -0.6, 0.5, -0.4, 0.3, -0.2, 0.1, -0.3, 0.45, -0.65, 0.8, -0.85, 1.2};
    run_path(&r, &pa, n, e1, 1.5 * r.p.mu * pa.F_bound / km, path, 15, 400, 0.0);
    /* measured 0.086: where the path returns through the forgotten points */
    printf("8 nested turning points (4 remembered): max |F - F_exact| = %.3e mu F_n\n", r.worst);
    CHECK(!r.bad);
    CHECK(r.worst < 0.1);
  }
  {
    /* a Hertz contact pressed and released (F_n ~ a^3) while sheared back
       and forth: the varying-load rule against the exact profile */
    pair_run r;
    run_init(&r, 0.5, 0, 0, 0.0);
    const double a0 = 1e-3, F0 = 2.0;
    double km, kn;
    dc_cmd_stiffness(&r.m, a0, a0, &km, &kn);
    const double L = 1.5 * r.p.mu * F0 / km;
    const int N = 4000;
    for (int i = 1; i <= N; i++) {
      const double s = (double)i / N;
      const double a = a0 * (0.3 + 0.7 * sin(M_PI * s));   /* loading then unloading */
      const dc_patch pa = patch_of(a, a, e1, F0 * pow(a / a0, 3.0));
      const double dx = L * 0.9 * cos(2.0 * M_PI * 3.0 * s) * (2.0 * M_PI * 3.0) / N;   /* 3 shear cycles */
      const double du[3] = {dx * e1[0], dx * e1[1], dx * e1[2]};
      run_step(&r, &pa, n, du, 0.0);
    }
    /* measured 0.094 (the Masing branches while the load changes) */
    printf("Hertz load cycle with 3 shear cycles: max |F - F_exact| = %.3e mu F_n (of the load at the step)\n", r.worst);
    CHECK(!r.bad);
    CHECK(r.worst < 0.1);
  }
}

/* Domain: bad counts, NaN, out-of-range history: DC_EDOM and nothing
   touched; the trusted step gives the same bits as the checked one. */
static void test_domain(void)
{
  double n[3], e1[3], e2[3];
  frame(n, e1, e2);
  dc_cmd_params p;
  memset(&p, 0, sizeof p);
  p.mu = 0.5;
  const dc_mindlin_pair m = {1.0, 0.3};
  const dc_patch pa = patch_of(1e-3, 0.5e-3, e1, 2.0);
  dc_cmdtp_state h, h0;
  memset(&h, 0, sizeof h);
  dc_cmd_out o, o0;
  const double du[3] = {1e-5 * e2[0], 1e-5 * e2[1], 1e-5 * e2[2]};
  CHECK(dc_cmdtp_step(&p, &m, &pa, n, du, 0.0, 1e-6, &h, &o) == DC_OK);
  h0 = h;
  memset(&o0, 0x5a, sizeof o0);
  o = o0;
  const double bad_n[3] = {1.0, 1.0, 0.0};
  CHECK(dc_cmdtp_step(&p, &m, &pa, bad_n, du, 0.0, 1e-6, &h, &o) == DC_EDOM);
  h.nturn = 1.5;
  CHECK(dc_cmdtp_step(&p, &m, &pa, n, du, 0.0, 1e-6, &h, &o) == DC_EDOM);
  h.nturn = 5.0;
  CHECK(dc_cmdtp_step_trusted(&p, &m, &pa, n, du, 0.0, 1e-6, &h, &o) == DC_EDOM);
  h = h0;
  h.c2 = NAN;
  CHECK(dc_cmdtp_step(&p, &m, &pa, n, du, 0.0, 1e-6, &h, &o) == DC_EDOM);
  h = h0;
  const double nan_du[3] = {NAN, 0.0, 0.0};
  CHECK(dc_cmdtp_step(&p, &m, &pa, n, nan_du, 0.0, 1e-6, &h, &o) == DC_EDOM);
  CHECK(!memcmp(&h, &h0, sizeof h) && !memcmp(&o, &o0, sizeof o));
  /* trusted = checked inside the domain */
  dc_cmdtp_state ha = h0, hb = h0;
  dc_cmd_out oa, ob;
  for (int i = 0; i < 200; i++) {
    const double s = 3e-5 * sin(0.05 * i);
    const double d[3] = {s * e1[0] + 0.5 * s * e2[0], s * e1[1] + 0.5 * s * e2[1], s * e1[2] + 0.5 * s * e2[2]};
    const dc_patch pb = patch_of(1e-3 * (1.0 + 0.001 * i), 0.5e-3, e1, 2.0 + 0.01 * i);
    CHECK(dc_cmdtp_step(&p, &m, &pb, n, d, 0.0, 1e-6, &ha, &oa) == DC_OK);
    CHECK(dc_cmdtp_step_trusted(&p, &m, &pb, n, d, 0.0, 1e-6, &hb, &ob) == DC_OK);
  }
  CHECK(!memcmp(&ha, &hb, sizeof ha) && !memcmp(&oa, &ob, sizeof oa));
  /* no friction load: no force, nothing remembered; not formed: fresh */
  const dc_patch p0 = patch_of(1e-3, 0.5e-3, e1, 0.0);
  CHECK(dc_cmdtp_step(&p, &m, &p0, n, du, 0.0, 1e-6, &ha, &oa) == DC_OK);
  CHECK(oa.Ft[0] == 0.0 && oa.Ft[1] == 0.0 && oa.Ft[2] == 0.0 && ha.nturn == 0.0);
  dc_patch pf = pa;
  pf.formed = 0.0;
  CHECK(dc_cmdtp_step(&p, &m, &pf, n, du, 0.0, 1e-6, &ha, &oa) == DC_OK);
  dc_cmdtp_state zero;
  memset(&zero, 0, sizeof zero);
  CHECK(!memcmp(&ha, &zero, DC_CMDTP_FORCE_NFIELDS * sizeof(double)));
}

int main(void)
{
  test_constant_load();
  test_twist_and_dissipation();
  test_turning_plane();
  test_beyond();
  test_domain();
  return check_summary("cmd_turning_points");
}
