/* Unit tests of c_core/src/dissipation_adhesive.c (corrected review Eqs.
   39-40): the w -> 0 limit against review Eq. 37, units (scaling), finiteness
   on the whole JKR branch including delta <= 0, the contact-radius form
   against finite differences of a(t) along a trajectory, and the status
   contract (errors leave the outputs untouched). */
#include "check.h"
#include "dc/dissipation_adhesive.h"
#include "dc/hertz_elliptic.h"
#include "dc/jkr_elliptic.h"
#include "dc/status.h"
#include <math.h>
#include <string.h>

static const double R = 1e-3, E = 1e9, w = 0.05, A = 2e-6;

/* w = 0: F_dis = A ddelta dF_Hertz/d delta (Eq. 37), dF_H/d delta = 2 E* (R delta)^1/2 */
static void test_hertz_limit(void)
{
  for (int i = 0; i < 30; i++) {
    const double delta = 1e-9 * pow(10.0, 0.15 * i), dd = 0.3 * (i % 2 ? 1 : -1);
    dc_jkr_state s;
    double Fd, Ft;
    CHECK(dc_jkr_sphere_viscoelastic(R, E, 0.0, A, delta, dd, &s, &Ft) == DC_OK);
    CHECK(dc_dissip_adhesive_state(A, E, &s, dd, &Fd) == DC_OK);
    const double eq37 = A * dd * 2.0 * E * sqrt(R * delta);
    CHECK_REL(Fd, eq37, 4e-16, "w = 0: Eq. 37");
    CHECK_REL(s.F, 4.0 / 3.0 * E * sqrt(R) * pow(delta, 1.5), 1e-15, "w = 0: Hertz force");
    CHECK(Ft == s.F + Fd);
  }
  /* elliptic Hertz: k_punch = dF/d delta = 3 F/(2 delta) */
  const double ratios[] = {0.9, 0.3, 0.05, 1e-3};
  for (int k = 0; k < 4; k++) {
    dc_hertz_geom H;
    CHECK(dc_hertz_geometry(R, R * ratios[k], &H) == DC_OK);
    dc_hertz_state h;
    CHECK(dc_hertz_contact(&H, E, 1e-6, &h) == DC_OK);
    double Fd;
    CHECK(dc_dissip_adhesive_ab(A, E, h.a, h.b, 0.7, &Fd) == DC_OK);
    CHECK_REL(Fd, A * 0.7 * 1.5 * h.F / 1e-6, 1e-13, "elliptic w = 0: Eq. 37");
  }
  /* w -> 0 through the JKR solution */
  dc_jkr_state s;
  double Fd;
  CHECK(dc_jkr_sphere(R, E, 1e-12, 1e-6, &s) == DC_OK);
  CHECK(dc_dissip_adhesive_state(A, E, &s, 0.5, &Fd) == DC_OK);
  CHECK_REL(Fd, A * 0.5 * 2.0 * E * sqrt(R * 1e-6), 1e-6, "w -> 0 tends to Eq. 37");
}

/* Units: under R, a, delta -> L (.), w -> L w (so that w/(E* R) is fixed)
   and ddelta -> L ddelta, a force scales as L^2. */
static void test_units(void)
{
  const double L = 7.3;
  dc_jkr_state s1, s2;
  const double delta = 3e-9;
  double F1, F2;
  CHECK(dc_jkr_sphere_viscoelastic(R, E, w, A, delta, 0.2, &s1, &F1) == DC_OK);
  CHECK(dc_jkr_sphere_viscoelastic(L * R, E, L * w, A, L * delta, L * 0.2, &s2, &F2) == DC_OK);
  CHECK_REL(s2.a, L * s1.a, 1e-13, "a scales as L");
  CHECK_REL(F2, L * L * F1, 1e-13, "F_total scales as L^2");
  double d1, d2;
  CHECK(dc_dissip_adhesive_state(A, E, &s1, 0.2, &d1) == DC_OK);
  CHECK(dc_dissip_adhesive_state(A, E, &s2, L * 0.2, &d2) == DC_OK);
  CHECK_REL(d2, L * L * d1, 1e-13, "F_dis scales as L^2");
  /* linear in A, E* a, ddelta */
  CHECK(dc_dissip_adhesive_ab(2 * A, E, s1.a, s1.a, 0.2, &d2) == DC_OK);
  CHECK_REL(d2, 2 * d1, 1e-15, "linear in A");
}

/* Finite on the whole JKR branch, delta_break <= delta <= 0 included, and
   the contact-radius form against a(t) by central differences along
   delta(t) = d0 + v t. */
static void test_branch_and_radius_form(void)
{
  const double db = dc_jkr_sphere_delta_break(R, E, w);
  int finite = 1;
  double worst = 0;
  for (int i = 0; i <= 400; i++) {
    const double delta = db + (5.0 * fabs(db) - db) * i / 400.0;
    const double vel = 0.1, h = 1e-6 * fabs(db) / vel;
    dc_jkr_state s, sp, sm;
    double Fd, Ft;
    if (dc_jkr_sphere_viscoelastic(R, E, w, A, delta, vel, &s, &Ft) != DC_OK) finite = 0;
    if (dc_dissip_adhesive_state(A, E, &s, vel, &Fd) != DC_OK) finite = 0;
    if (!(isfinite(Fd) && isfinite(Ft) && s.contact == 1 && Fd > 0.0)) finite = 0;
    if (i == 0 || i == 400) continue;
    dc_jkr_sphere(R, E, w, delta + vel * h, &sp);
    dc_jkr_sphere(R, E, w, delta - vel * h, &sm);
    const double adot = (sp.a - sm.a) / (2 * h);
    double Fr;
    CHECK(dc_dissip_adhesive_radius_rate(A, R, E, w, s.a, adot, &Fr) == DC_OK);
    const double e = fabs(Fr / Fd - 1);
    if (i > 20 && e > worst) worst = e;   /* away from the vertical tangent at db */
  }
  printf("contact-radius form vs A ddelta 2 E* a (a(t) by central differences): max rel. diff %.3g\n", worst);
  CHECK(finite);
  CHECK(worst < 1e-6);
  /* at delta = 0 and at the separation point itself */
  dc_jkr_state s;
  double Fd;
  CHECK(dc_jkr_sphere(R, E, w, 0.0, &s) == DC_OK && s.a > 0);
  CHECK(dc_dissip_adhesive_state(A, E, &s, -0.3, &Fd) == DC_OK && isfinite(Fd) && Fd < 0);
  CHECK(dc_jkr_sphere(R, E, w, db, &s) == DC_OK);
  CHECK(dc_dissip_adhesive_state(A, E, &s, -0.3, &Fd) == DC_OK && isfinite(Fd));
  /* elliptic JKR below delta = 0 */
  dc_jkr_geom G;
  CHECK(dc_jkr_geometry(R, 0.1 * R, E, w, &G) == DC_OK);
  CHECK(dc_jkr_contact(&G, 0.5 * G.delta_break, NULL, &s) == DC_OK && s.contact);
  CHECK(dc_dissip_adhesive_state(A, E, &s, 0.1, &Fd) == DC_OK && isfinite(Fd) && Fd > 0);
  /* out of contact: zero; bad input: DC_EDOM */
  CHECK(dc_jkr_sphere(R, E, w, 2 * db, &s) == DC_OK && s.contact == 0);
  CHECK(dc_dissip_adhesive_state(A, E, &s, 0.1, &Fd) == DC_OK && Fd == 0.0);
  CHECK(dc_dissip_adhesive_ab(A, E, 1e-6, 2e-6, 0.1, &Fd) == DC_EDOM);
  CHECK(dc_dissip_adhesive_ab(-1, E, 1e-6, 1e-6, 0.1, &Fd) == DC_EDOM);
  CHECK(dc_dissip_adhesive_ab(A, E, 1e-6, 1e-6, NAN, &Fd) == DC_EDOM);
}

/* Status honesty: an error leaves every output untouched (a viscoelastic
   call used to write the state and then fail on A), a non-finite input is
   DC_EDOM, and overflow is DC_ERANGE, never DC_OK with inf or NaN. */
static void test_status(void)
{
  dc_jkr_state s, s0;
  memset(&s0, 0xA5, sizeof s0);
  double Ft, Fd;
  const double F0 = -123.0;
  /* bad A after a good state: DC_EDOM, state and total untouched */
  const double bad_A[] = {-1.0, NAN, INFINITY};
  for (int i = 0; i < 3; i++) {
    s = s0;
    Ft = F0;
    CHECK(dc_jkr_sphere_viscoelastic(R, E, w, bad_A[i], 1e-9, 0.1, &s, &Ft) == DC_EDOM);
    CHECK(memcmp(&s, &s0, sizeof s) == 0 && Ft == F0);
  }
  s = s0;
  Ft = F0;
  CHECK(dc_jkr_sphere_viscoelastic(R, E, w, A, 1e-9, NAN, &s, &Ft) == DC_EDOM);
  CHECK(dc_jkr_sphere_viscoelastic(-R, E, w, A, 1e-9, 0.1, &s, &Ft) == DC_EDOM);
  CHECK(dc_jkr_sphere_viscoelastic(R, E, w, A, NAN, 0.1, &s, &Ft) == DC_EDOM);
  CHECK(memcmp(&s, &s0, sizeof s) == 0 && Ft == F0);
  /* a finite state whose dissipative force overflows: DC_ERANGE, untouched */
  CHECK(dc_jkr_sphere_viscoelastic(R, E, w, 1e300, 1e-6, 1e300, &s, &Ft) == DC_ERANGE);
  CHECK(memcmp(&s, &s0, sizeof s) == 0 && Ft == F0);
  Fd = F0;
  CHECK(dc_dissip_adhesive_ab(1e300, E, 1e-3, 1e-3, 1e300, &Fd) == DC_ERANGE && Fd == F0);
  CHECK(dc_dissip_adhesive_radius_rate(1e300, R, E, w, 1e-3, 1e300, &Fd) == DC_ERANGE && Fd == F0);
  /* a state in contact with a non-finite size is not a state: DC_EDOM */
  CHECK(dc_jkr_sphere(R, E, w, 1e-9, &s) == DC_OK);
  s.b = NAN;
  CHECK(dc_dissip_adhesive_state(A, E, &s, 0.1, &Fd) == DC_EDOM && Fd == F0);
  s.b = s.a;
  s.a = NAN;
  CHECK(dc_dissip_adhesive_state(A, E, &s, 0.1, &Fd) == DC_EDOM && Fd == F0);
  s.a = 0.0;   /* touching (Hertz at delta = 0): no punch stiffness */
  CHECK(dc_dissip_adhesive_state(A, E, &s, 0.1, &Fd) == DC_OK && Fd == 0.0);
  /* b/a so small that (b/a)^2 is not a normal number (was DC_EDOM, from
     the elliptic integral at m1 = 0): K = ln(4 a/b), continuous with the
     elliptic-integral path, which K(m1) = ln(4/m1^1/2) + O(m1) matches */
  const double a = 1e-4;
  const double gs[] = {1e-150, 1e-160, 1e-200, 1e-300};
  for (int i = 0; i < 4; i++) {
    CHECK(dc_dissip_adhesive_ab(A, E, a, a * gs[i], 0.3, &Fd) == DC_OK);
    CHECK_REL(Fd, A * 0.3 * M_PI * E * a / log(4.0 / gs[i]), 2e-15, "F_dis for b/a -> 0: K = ln(4 a/b)");
  }
  CHECK(dc_dissip_adhesive_ab(A, E, 1e100, 1e-300, 0.3, &Fd) == DC_OK);   /* b/a underflows to 0 */
  CHECK_REL(Fd, A * 0.3 * M_PI * E * 1e100 / (log(4.0) + log(1e100) - log(1e-300)), 1e-15, "F_dis at b/a < DBL_TRUE_MIN");
}

int main(void)
{
  test_hertz_limit();
  test_units();
  test_branch_and_radius_form();
  test_status();
  return check_summary("test_dissipation_adhesive");
}
