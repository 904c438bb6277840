/* The status contract of dc/status.h for the public c_core functions, by a
   seeded fuzz (every function of the headers included below): random and
   extreme arguments (log-uniform magnitudes over
   1e-320 .. 1e308 of either sign, 0, -0, subnormals, DBL_MAX, +-inf, NaN,
   values at and a few ulps around the domain edges) mixed with typical
   values inside each domain (each call draws how many of its arguments are
   wild), 1e5 calls per function (DC_FUZZ_CALLS=1e7 in the environment
   for the long run; fewer where one call is expensive: the
   full GW solver on small m only, see fuzz_gw_solve; N_GWP, N_TABLE_INIT,
   N_ROLL_MAT, N_KALKER_NU). For every call of a function that returns a status:
   - the status is a dc_status value;
   - DC_OK: every output double is finite (outputs are filled with a NaN
     byte pattern before the call, so an output left unwritten fails too);
   - DC_EDOM, DC_ERANGE: every output is byte for byte untouched;
   - DC_ENOCONV: outputs untouched, or every output double finite (status.h:
     the outputs hold the last iterate);
   - a non-finite input gives DC_EDOM, and inputs inside the documented
     domain never give DC_EDOM (where the domain is simple to state; a
     sufficient subset of it where it is not);
   - where a bound on the true result is cheap, DC_ERANGE only when it can
     overflow (or underflow, where a result can).
   Exceptions the headers document: the parameter checks and inits fill
   their dc_param_error on an error; dc_gw_plastic_summit's w1, w2 may be 0
   or +inf on DC_OK; R_max = +inf is dc_rolling_kinematics_capped's "no cap".
   Struct inputs made by a constructor (dc_hertz_geom, dc_feng_law,
   dc_jkr_geom, dc_gw_solver, dc_classical_normal, dc_classical_tangential,
   dc_gw_plastic_summit, dc_gw_table_law, dc_gw_table_pair,
   dc_gwa_table_pair, dc_rolling_material) come from that constructor under
   the same fuzz; plain-data inputs documented as "any content"
   (dc_jkr_hint) and the fields of dc_jkr_state read by
   dc_dissip_adhesive_state are fuzzed directly, as are the per-contact
   histories within the content their headers allow (the classical laws',
   gw_rough_adhesive_table's) and the plain inputs of gw_rough_plastic.h and
   rolling_kalker.h. The parameter checks must name a bad field with its
   value. Functions without a status (void, double, int) are checked for
   what their headers promise. Prints the calls and statuses per function
   and the time taken. */
#include "check.h"
#include "dc/classical_normal.h"
#include "dc/classical_tangential.h"
#include "dc/cmd_tangential.h"
#include "dc/cmd_turning_points.h"
#include "dc/contract.h"
#include "dc/curvature.h"
#include "dc/damping.h"
#include "dc/dissipation_adhesive.h"
#include "dc/elliptic_integrals.h"
#include "dc/feng_rough.h"
#include "dc/gw_integrals.h"
#include "dc/gw_rough.h"
#include "dc/gw_rough_adhesive.h"
#include "dc/gw_rough_adhesive_table.h"
#include "dc/gw_rough_plastic.h"
#include "dc/gw_rough_table.h"
#include "dc/gw_solver.h"
#include "dc/hertz_elliptic.h"
#include "dc/jamari_ep.h"
#include "dc/jkr_elliptic.h"
#include "dc/mindlin.h"
#include "dc/rolling_kalker.h"
#include "dc/root_find.h"
#include "dc/rough_tangential.h"
#include "dc/maugis_dugdale.h"
#include "dc/scene.h"
#include "dc/status.h"
#include <float.h>
#include <limits.h>
#include <stdarg.h>
#include <time.h>

/* calls per function: 1e5 (ctest), DC_FUZZ_CALLS=1e7 for the long run */
static long N_CALLS = 100000L;

/* ---------------------------------------------------------------- */
/* Bookkeeping: one record per function.                             */

typedef struct {
  const char *name;
  long calls, st[4], fails;
  double seconds;
  const char *why[8];   /* distinct failure reasons seen, and their counts */
  long nwhy[8];
} fz_fn;

static fz_fn fz_all[256];
static int fz_n;
static struct timespec fz_t0;

static double fz_now(void)
{
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)(t.tv_sec - fz_t0.tv_sec) + 1e-9 * (double)(t.tv_nsec - fz_t0.tv_nsec);
}

static fz_fn *fz_new(const char *name)
{
  if (fz_n == (int)(sizeof fz_all / sizeof fz_all[0])) {
    printf("fuzz: more than %d functions: enlarge fz_all\n", fz_n);
    exit(1);
  }
  fz_fn *f = &fz_all[fz_n++];
  f->name = name;
  f->seconds = -fz_now();
  return f;
}

static void fz_done(fz_fn *f) { f->seconds += fz_now(); }

/* A call of a function checked against another (its own statuses counted). */
static void fz_count(fz_fn *f, int st)
{
  f->calls++;
  if (st >= 0 && st <= 3) f->st[st]++;
}

/* Counts a failure; prints the first three of each reason. */
static void fz_fail(fz_fn *f, const char *why, int st, const char *fmt, ...)
{
  f->fails++;
  check_failed_++;
  int i = 0;
  while (i < 8 && f->why[i] && f->why[i] != why) i++;
  if (i < 8) {
    f->why[i] = why;
    if (++f->nwhy[i] > 3) return;   /* counted, not printed */
  }
  printf("FAIL %s: %s (status %d) at ", f->name, why, st);
  va_list ap;
  va_start(ap, fmt);
  vprintf(fmt, ap);
  va_end(ap);
  printf("\n");
}

/* The contract for one call (file comment). in_bad: an input the function
   reads is not finite; in_dom: the inputs lie in the documented domain;
   untouched: the outputs still hold the sentinel; finite: every output
   double is finite (and every other output field valid). */
static const char *fz_verdict(fz_fn *f, int st, int in_bad, int in_dom, int untouched, int finite)
{
  f->calls++;
  if (st < 0 || st > 3) return "status is not a dc_status";
  f->st[st]++;
  if (in_bad && st != DC_EDOM) return "non-finite input without DC_EDOM";
  if (in_dom && st == DC_EDOM) return "DC_EDOM inside the documented domain";
  if (st == DC_OK && !finite) return "DC_OK with a non-finite output";
  if ((st == DC_EDOM || st == DC_ERANGE) && !untouched) return "error status with outputs written";
  if (st == DC_ENOCONV && !untouched && !finite) return "DC_ENOCONV with a non-finite iterate";
  check_passed_++;
  return NULL;
}

#define FZ_CHECK(f, st, in_bad, in_dom, untouched, finite, ...)                              \
  do {                                                                                        \
    const int st_ = (st);                                                                     \
    const char *why_ = fz_verdict((f), st_, (in_bad), (in_dom), (untouched), (finite));       \
    if (why_) fz_fail((f), why_, st_, __VA_ARGS__);                                           \
  } while (0)

/* A further property of one call (not counted as a call). */
#define FZ_EXPECT(f, ok, why, ...)                                                            \
  do {                                                                                        \
    if (ok) check_passed_++;                                                                  \
    else fz_fail((f), (why), -1, __VA_ARGS__);                                                \
  } while (0)

/* Sentinel: a NaN byte pattern (as large as the largest output, the
   tabulated law of dc_gw_table_pair). */
static unsigned char fz_ff[8192];
_Static_assert(sizeof(dc_gw_table_pair) <= sizeof fz_ff && sizeof(dc_rolling_material) <= sizeof fz_ff,
               "fz_ff smaller than an output");
#define SENTINEL(x) memset(&(x), 0xFF, sizeof(x))
#define UNTOUCHED(x) (memcmp(&(x), fz_ff, sizeof(x)) == 0)

static int fin(const double *p, int n)
{
  for (int i = 0; i < n; i++)
    if (!isfinite(p[i])) return 0;
  return 1;
}
/* all-double structs and arrays */
#define FIN(x) fin((const double *)&(x), (int)(sizeof(x) / sizeof(double)))

static int fin_args(int n, const double *a) { return fin(a, n); }
#define ALLFIN(...) fin_args((int)(sizeof((double[]){__VA_ARGS__}) / sizeof(double)), (double[]){__VA_ARGS__})

/* ---------------------------------------------------------------- */
/* Argument generators (fixed seed).                                  */

static unsigned long long fz_x = 0x9E3779B97F4A7C15ull;
static double U(void) { return check_uniform(&fz_x); }
static int UI(int n)
{
  const int k = (int)(U() * n);
  return k < n ? k : n - 1;
}
static double fz_sign(double x) { return U() < 0.5 ? -x : x; }
/* log-uniform in [lo, hi], 0 < lo <= hi */
static double fz_log(double lo, double hi)
{
  const double a = log(lo), b = log(hi), x = exp(a + (b - a) * U());
  return x < lo ? lo : x > hi ? hi : x;
}
static double fz_pos(void) { return fz_log(1e-320, DBL_MAX); }   /* any positive magnitude */
static double fz_wide(void) { return fz_sign(fz_pos()); }
static double fz_special(void)
{
  static const double v[] = {
    0.0, -0.0, 1.0, -1.0, 0.5, -0.5, 2.0, 3.0, DBL_EPSILON, 1.0 - DBL_EPSILON / 2, 1.0 + DBL_EPSILON,
    DBL_MIN, -DBL_MIN, DBL_TRUE_MIN, -DBL_TRUE_MIN, 0x1p-1060, -0x1p-1030, DBL_MAX, -DBL_MAX,
    1e300, -1e300, 1e-300, -1e-300, 1e154, 1e-154, 1e200, 1e-200, INFINITY, -INFINITY, NAN, -NAN};
  if (U() < 0.15) return fz_sign(ldexp(U(), -1022));   /* a subnormal */
  return v[UI((int)(sizeof v / sizeof v[0]))];
}
static double fz_wild(void) { return U() < 0.35 ? fz_special() : fz_wide(); }
/* x, or one to three ulps either side */
static double fz_near(double x)
{
  for (int k = UI(7) - 3; k != 0; k -= (k > 0) - (k < 0)) x = nextafter(x, k > 0 ? INFINITY : -INFINITY);
  return x;
}
#define PICK(...) fz_near(((const double[]){__VA_ARGS__})[UI((int)(sizeof((double[]){__VA_ARGS__}) / sizeof(double)))])

/* How wild this call's arguments are: the probability that an argument is
   replaced by a wild value (0: every argument typical). */
static double fz_pw;
static void fz_call(void)
{
  static const double p[5] = {0.0, 0.0, 0.03, 0.15, 1.0};
  fz_pw = p[UI(5)];
}
static double A(double typical) { return U() < fz_pw ? fz_wild() : typical; }
static int AI(int typical)
{
  static const int v[] = {-1, 0, 1, 2, 3, 4, 5, 7, -2, INT_MIN, INT_MAX, 1000, 1001};
  if (U() >= fz_pw) return typical;
  return U() < 0.8 ? v[UI((int)(sizeof v / sizeof v[0]))] : (int)(U() * 4294967296.0 - 2147483648.0);
}

/* log of a positive bound; -inf for 0 */
static double lg(double x) { return log(fabs(x)); }
#define LOG_MAX 709.78   /* ln DBL_MAX */

/* ---------------------------------------------------------------- */
/* Pools of constructor-made inputs.                                 */

#define POOL 512
static dc_hertz_geom hpool[POOL];
static int nh;
static dc_feng_law lpool[64];
static int nl;
static dc_jkr_geom jpool[POOL];
static int nj;

static void pool_hertz(const dc_hertz_geom *g)
{
  if (nh < POOL) hpool[nh++] = *g;
  else hpool[UI(POOL)] = *g;
}
static void pool_jkr(const dc_jkr_geom *g)
{
  if (nj < POOL) jpool[nj++] = *g;
  else jpool[UI(POOL)] = *g;
}

/* ---------------------------------------------------------------- */
/* status.h, elliptic_integrals.h                                     */

static void fuzz_status_str(void)
{
  fz_fn *f = fz_new("dc_status_str");
  for (long k = 0; k < N_CALLS; k++) {
    const int st = k < 8 ? (int)k - 2 : U() < 0.5 ? UI(8) - 2 : (int)(U() * 4294967296.0 - 2147483648.0);
    const char *s = dc_status_str(st);
    f->calls++;
    FZ_EXPECT(f, s && s[0], "NULL or empty name", "status %d", st);
  }
  fz_done(f);
}

static void fuzz_ellint(void)
{
  fz_fn *f = fz_new("dc_ellint_m");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const double r = U();
    const double m = A(r < 0.3 ? U() : r < 0.6 ? 1.0 - fz_log(1e-17, 1.0) : r < 0.8 ? fz_log(1e-320, 1.0)
                     : PICK(0.0, -0.0, DBL_TRUE_MIN, 0.5, 1.0 / 16, 15.0 / 16, 1.0, 1.0 - 0x1p-53));
    dc_ellint out;
    SENTINEL(out);
    FZ_CHECK(f, dc_ellint_m(m, &out), !isfinite(m), m >= 0.0 && m < 1.0, UNTOUCHED(out), FIN(out),
             "m = %.17g", m);
  }
  fz_done(f);
  f = fz_new("dc_ellint_m1");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const double r = U();
    const double m1 = A(r < 0.3 ? U() : r < 0.7 ? fz_log(1e-320, 1.0)
                        : PICK(0.0, -0.0, DBL_TRUE_MIN, DBL_MIN, 0.5, 1.0 / 16, 1.0, 0x1p-53));
    dc_ellint out;
    SENTINEL(out);
    FZ_CHECK(f, dc_ellint_m1(m1, &out), !isfinite(m1), m1 > 0.0 && m1 <= 1.0, UNTOUCHED(out), FIN(out),
             "m1 = %.17g", m1);
  }
  fz_done(f);
}

/* ---------------------------------------------------------------- */
/* curvature.h                                                        */

/* a random unit vector, or an axis (either sign, -0 components), or one
   near -z (the pole of the tangent-basis construction) */
static void unit_vector(double n[3])
{
  const double r = U();
  if (r < 0.6) {
    const double z = 2.0 * U() - 1.0, ph = 2.0 * M_PI * U(), s = sqrt(fmax(0.0, 1.0 - z * z));
    n[0] = s * cos(ph); n[1] = s * sin(ph); n[2] = z;
  } else if (r < 0.8) {
    n[0] = n[1] = n[2] = U() < 0.5 ? 0.0 : -0.0;
    n[UI(3)] = U() < 0.5 ? 1.0 : -1.0;
  } else {
    const double e = fz_log(1e-300, 1e-3), ph = 2.0 * M_PI * U();
    n[0] = e * cos(ph); n[1] = e * sin(ph); n[2] = (U() < 0.5 ? -1.0 : 1.0) * sqrt(1.0 - e * e);
  }
  const double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (int i = 0; i < 3; i++) n[i] /= l;
}

static double dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static double max_abs3(const double *x) { return fmax(fabs(x[0]), fmax(fabs(x[1]), fabs(x[2]))); }

static void fuzz_tangent_basis(void)
{
  fz_fn *f = fz_new("dc_tangent_basis");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    double n[3], u[3], v[3];
    unit_vector(n);
    int unit = 1;
    for (int i = 0; i < 3; i++) {
      const double t = A(n[i]);
      unit &= t == n[i] || (t == 0.0 && n[i] == 0.0);
      n[i] = t;
    }
    SENTINEL(u);
    SENTINEL(v);
    dc_tangent_basis(n, u, v);
    f->calls++;
    if (!unit) continue;   /* outside the domain (a unit n): no promise */
    double c[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const double err = fmax(fmax(fabs(dot3(u, u) - 1.0), fabs(dot3(v, v) - 1.0)),
                            fmax(fmax(fabs(dot3(u, v)), fabs(dot3(u, n))),
                                 fmax(fabs(dot3(v, n)), fmax(fabs(c[0] - n[0]), fmax(fabs(c[1] - n[1]), fabs(c[2] - n[2]))))));
    FZ_EXPECT(f, FIN(u) && FIN(v) && err < 1e-14, "not a finite right-handed orthonormal basis",
              "n = (%.17g, %.17g, %.17g), error %.3g", n[0], n[1], n[2], err);
  }
  fz_done(f);
}

static void fuzz_curvature_form(void)
{
  fz_fn *f = fz_new("dc_curvature_form");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    double grad[3], hess[9], u[3], v[3], n[3], form[3];
    const double sg = U() < 0.3 ? 1.0 : fz_pos(), sh = U() < 0.3 ? 1.0 : fz_pos();
    for (int i = 0; i < 3; i++) grad[i] = A(U() < 0.1 ? 0.0 : sg * (2.0 * U() - 1.0));
    for (int i = 0; i < 3; i++)
      for (int j = i; j < 3; j++) hess[3 * i + j] = hess[3 * j + i] = U() < 0.1 ? 0.0 : sh * (2.0 * U() - 1.0);
    for (int i = 0; i < 9; i++) hess[i] = A(hess[i]);
    unit_vector(n);
    dc_tangent_basis(n, u, v);
    for (int i = 0; i < 3; i++) { u[i] = A(u[i]); v[i] = A(v[i]); }
    int bad = !fin(grad, 3) || !fin(hess, 9) || !fin(u, 3) || !fin(v, 3);
    int sym = hess[1] == hess[3] && hess[2] == hess[6] && hess[5] == hess[7];
    int dom = !bad && sym && (grad[0] != 0.0 || grad[1] != 0.0 || grad[2] != 0.0);
    SENTINEL(form);
    const int st = dc_curvature_form(grad, hess, u, v, form);
    FZ_CHECK(f, st, bad, dom, UNTOUCHED(form), FIN(form),
             "grad (%.17g, %.17g, %.17g) hess (%.17g %.17g %.17g; %.17g %.17g %.17g; %.17g %.17g %.17g) "
             "u (%.17g, %.17g, %.17g) v (%.17g, %.17g, %.17g)",
             grad[0], grad[1], grad[2], hess[0], hess[1], hess[2], hess[3], hess[4], hess[5], hess[6], hess[7],
             hess[8], u[0], u[1], u[2], v[0], v[1], v[2]);
    /* |form| <= 9 max|H| max(max|u|, max|v|)^2 / max|grad| */
    double mh = 0, mu = 0, mv = 0, mg = 0;
    for (int i = 0; i < 9; i++) mh = fmax(mh, fabs(hess[i]));
    for (int i = 0; i < 3; i++) { mu = fmax(mu, fabs(u[i])); mv = fmax(mv, fabs(v[i])); mg = fmax(mg, fabs(grad[i])); }
    FZ_EXPECT(f, st != DC_ERANGE || lg(9.0) + lg(mh) + 2.0 * lg(fmax(mu, mv)) - lg(mg) > LOG_MAX - 1.0,
              "DC_ERANGE for a representable form", "grad max %.17g hess max %.17g u max %.17g v max %.17g", mg, mh,
              mu, mv);
  }
  fz_done(f);
}

/* dc_superquadric_form: typical bodies and points on their surface (then
   DC_OK is due), some inputs wild */
static void fuzz_superquadric_form(void)
{
  fz_fn *f = fz_new("dc_superquadric_form");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const double scale = fz_log(1e-6, 1e3);
    double s[3], bl[2], d[3], p[3], n[3], u[3], v[3], form[3];
    for (int i = 0; i < 3; i++) s[i] = scale * fz_log(0.1, 10.0);
    for (int i = 0; i < 2; i++) bl[i] = U() < 0.5 ? (double)(2 + (int)(7.0 * U())) : 2.0 + 10.0 * U();
    unit_vector(d);
    /* onto the surface along d: f scales as t^n1 along z, so bisect */
    double lo = 0.0, hi = 4.0 * fmax(s[0], fmax(s[1], s[2]));
    for (int it = 0; it < 56; it++) {
      const double t = 0.5 * (lo + hi);
      const double X = pow(fabs(t * d[0]) / s[0], bl[1]) + pow(fabs(t * d[1]) / s[1], bl[1]);
      if (pow(X, bl[0] / bl[1]) + pow(fabs(t * d[2]) / s[2], bl[0]) < 1.0) lo = t; else hi = t;
    }
    for (int i = 0; i < 3; i++) p[i] = 0.5 * (lo + hi) * d[i];
    unit_vector(n);
    dc_tangent_basis(n, u, v);
    /* off-pole points only count as typical: the gradient is 0 at a pole
       of n1 < n2 (0 * inf) */
    const int typical = fabs(d[0]) > 0.05 && fabs(d[1]) > 0.05 && fabs(d[2]) > 0.05;
    int wild = 0;
    for (int i = 0; i < 3; i++) { const double x = A(s[i]); wild |= x != s[i]; s[i] = x; }
    for (int i = 0; i < 2; i++) { const double x = A(bl[i]); wild |= x != bl[i]; bl[i] = x; }
    for (int i = 0; i < 3; i++) { const double x = A(p[i]); wild |= x != p[i]; p[i] = x; }
    for (int i = 0; i < 3; i++) { u[i] = A(u[i]); v[i] = A(v[i]); }
    const int bad = !fin(s, 3) || !fin(bl, 2) || !fin(p, 3) || !fin(u, 3) || !fin(v, 3) ||
                    !(s[0] > 0.0 && s[1] > 0.0 && s[2] > 0.0) || !(bl[0] >= 2.0 && bl[0] <= 1e3) ||
                    !(bl[1] >= 2.0 && bl[1] <= 1e3);
    const int dom = !bad && !wild && typical && fin(u, 3) && fin(v, 3);
    SENTINEL(form);
    const int st = dc_superquadric_form(s, bl, p, u, v, form);
    FZ_CHECK(f, st, bad, dom, UNTOUCHED(form), FIN(form),
             "shape (%.17g, %.17g, %.17g) blockiness (%.17g, %.17g) p (%.17g, %.17g, %.17g) u (%.17g, %.17g, %.17g) "
             "v (%.17g, %.17g, %.17g)", s[0], s[1], s[2], bl[0], bl[1], p[0], p[1], p[2], u[0], u[1], u[2], v[0], v[1],
             v[2]);
  }
  fz_done(f);
}

/* a relative curvature form: positive definite with principal curvatures
   within 1e6 of each other (clearly inside the domain), random otherwise */
static void random_form(double form[3], int *pd)
{
  const double s = fz_log(1e-310, 1e308);
  double a = s * fz_log(1e-6, 1.0), b = s * fz_log(1e-6, 1.0);
  double c = sqrt(0.5) * sqrt(a) * sqrt(b) * (2.0 * U() - 1.0);
  if (U() < 0.2) c = 0.0;
  if (U() < 0.15) { a = fz_wide(); b = fz_wide(); c = fz_wide(); }
  form[0] = A(a); form[1] = A(c); form[2] = A(b);
  const double lo = fmin(form[0], form[2]), hi = fmax(form[0], form[2]);
  /* the off-diagonal bound on the form scaled to order one (exactly): on
     subnormal entries the products round by up to a whole last place */
  int e = 0;
  if (fin(form, 3)) frexp(fmax(fabs(form[1]), hi), &e);
  const double s0 = ldexp(form[0], -e), s1 = ldexp(form[1], -e), s2 = ldexp(form[2], -e);
  *pd = fin(form, 3) && lo > 0.0 && lo >= 1e-6 * hi && fabs(s1) <= sqrt(0.5) * sqrt(s0) * sqrt(s2);
}

static void fuzz_form_principal(void)
{
  fz_fn *f = fz_new("dc_form_principal");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    double form[3], out[3];
    int pd;
    random_form(form, &pd);
    if (U() < 0.5)
      for (int i = 0; i < 3; i++) form[i] = A(U() < 0.1 ? 0.0 : fz_sign(fz_log(1e-320, 1e307)));
    SENTINEL(out);
    const int want_theta = U() < 0.8;
    dc_form_principal(form, &out[0], &out[1], want_theta ? &out[2] : NULL);
    f->calls++;
    /* promise: eigenvalues k1 >= k2 (and theta); finite when they are
       representable, which |entries| <= 1e307 ensures */
    if (!(fin(form, 3) && fabs(form[0]) <= 1e307 && fabs(form[1]) <= 1e307 && fabs(form[2]) <= 1e307)) continue;
    FZ_EXPECT(f, isfinite(out[0]) && isfinite(out[1]) && out[0] >= out[1] && (!want_theta || isfinite(out[2])) &&
                 (want_theta || isnan(out[2])),
              "eigenvalues not finite, not ordered, or theta wrong",
              "form (%.17g, %.17g, %.17g): k1 %.17g k2 %.17g theta %.17g", form[0], form[1], form[2], out[0], out[1],
              out[2]);
  }
  fz_done(f);
}

static void fuzz_relative_radii(void)
{
  fz_fn *f = fz_new("dc_form_relative_radii");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    double form[3], R[2];
    int pd;
    random_form(form, &pd);
    SENTINEL(R);
    const int st = dc_form_relative_radii(form, &R[0], &R[1]);
    FZ_CHECK(f, st, !fin(form, 3), pd, UNTOUCHED(R), FIN(R) && R[0] >= R[1] && R[1] > 0.0,
             "form (%.17g, %.17g, %.17g)", form[0], form[1], form[2]);
  }
  fz_done(f);
  f = fz_new("dc_relative_radii");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const double s = fz_log(1e-310, 1e308);
    double c[4], R[2];
    for (int i = 0; i < 4; i++) c[i] = A(U() < 0.15 ? 0.0 : U() < 0.1 ? fz_wide() : s * fz_log(1e-6, 1.0));
    const double om = A(U() < 0.3 ? PICK(0.0, -0.0, M_PI / 2, M_PI, -M_PI / 4, 1e10) : 20.0 * U() - 10.0);
    const int bad = !fin(c, 4) || !isfinite(om);
    const double mx = fmax(fmax(c[0], c[1]), fmax(c[2], c[3]));
    const int dom = !bad && c[0] >= 0.0 && c[1] >= 0.0 && c[2] >= 0.0 && c[3] >= 0.0 && mx > 0.0 &&
                    fmin(c[0], c[1]) + fmin(c[2], c[3]) > 0.0 &&
                    fmin(c[0], c[1]) + fmin(c[2], c[3]) >= 1e-6 * mx;
    SENTINEL(R);
    const int st = dc_relative_radii(c[0], c[1], c[2], c[3], om, &R[0], &R[1]);
    FZ_CHECK(f, st, bad, dom, UNTOUCHED(R), FIN(R) && R[0] >= R[1] && R[1] > 0.0,
             "k (%.17g, %.17g, %.17g, %.17g) omega %.17g", c[0], c[1], c[2], c[3], om);
  }
  fz_done(f);
}

static void fuzz_form_major_axis(void)
{
  fz_fn *f = fz_new("dc_form_major_axis");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    double form[3], n[3], u[3], v[3], axis[3];
    int pd;
    random_form(form, &pd);
    if (U() < 0.2) form[2] = form[0] * (1.0 + (U() < 0.5 ? 0.0 : DBL_EPSILON * (UI(5) - 2)));   /* circular */
    if (U() < 0.1) form[1] = 0.0;
    unit_vector(n);
    dc_tangent_basis(n, u, v);
    SENTINEL(axis);
    dc_form_major_axis(form, u, v, axis);
    f->calls++;
    /* promise: the unit direction of the smaller curvature in the plane,
       or zero (circular to rounding, or not finite) */
    const double l = sqrt(dot3(axis, axis));
    if (!fin(form, 3)) {
      FZ_EXPECT(f, axis[0] == 0.0 && axis[1] == 0.0 && axis[2] == 0.0, "not zero for a non-finite form",
                "form (%.17g, %.17g, %.17g)", form[0], form[1], form[2]);
      continue;
    }
    int ok = FIN(axis) && (l == 0.0 || (fabs(l - 1.0) < 1e-14 && fabs(dot3(axis, n)) < 1e-14));
    if (ok && l > 0.0) {
      /* (form - k2 I) x = 0 in the (u, v) coordinates of the axis, to
         rounding of the form's largest entry (backward error) */
      const double sc = fmax(fabs(form[0]), fmax(fabs(form[1]), fabs(form[2])));
      const double fs[3] = {form[0] / sc, form[1] / sc, form[2] / sc};
      double k1, k2;
      dc_form_principal(fs, &k1, &k2, NULL);
      const double x = dot3(axis, u), y = dot3(axis, v);
      const double r0 = (fs[0] - k2) * x + fs[1] * y, r1 = fs[1] * x + (fs[2] - k2) * y;
      ok = fabs(r0) + fabs(r1) < 1e-13;
    }
    FZ_EXPECT(f, ok, "not a unit eigenvector of the smaller curvature in the plane, nor zero",
              "form (%.17g, %.17g, %.17g): axis (%.17g, %.17g, %.17g)", form[0], form[1], form[2], axis[0], axis[1],
              axis[2]);
  }
  fz_done(f);
}

/* ---------------------------------------------------------------- */
/* hertz_elliptic.h                                                   */

static double hertz_ratio(void)
{
  const double r = U();
  return r < 0.4 ? fz_log(DC_HERTZ_RATIO_MIN, 1.0) : r < 0.7 ? 1.0 - fz_log(1e-17, 0.75)
         : PICK(DC_HERTZ_RATIO_MIN, 1.0, 0.25, 0.0, -0.0, 1e-13, 2.0);
}

static void fuzz_hertz_eccentricity(void)
{
  fz_fn *f = fz_new("dc_hertz_eccentricity");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const double r = A(hertz_ratio());
    double out[2];
    SENTINEL(out);
    FZ_CHECK(f, dc_hertz_eccentricity(r, &out[0], &out[1]), !isfinite(r), r >= DC_HERTZ_RATIO_MIN && r <= 1.0,
             UNTOUCHED(out), FIN(out), "ratio %.17g", r);
  }
  fz_done(f);
  f = fz_new("dc_hertz_eccentricity_approx");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const double r = A(hertz_ratio());
    double e2;
    SENTINEL(e2);
    FZ_CHECK(f, dc_hertz_eccentricity_approx(r, &e2), !isfinite(r), r >= DC_HERTZ_RATIO_MIN && r <= 1.0,
             UNTOUCHED(e2), isfinite(e2), "ratio %.17g", r);
  }
  fz_done(f);
}

static void fuzz_hertz_geometry(void)
{
  fz_fn *f = fz_new("dc_hertz_geometry");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    double R1 = U() < 0.3 ? fz_log(1e-6, 1.0) : U() < 0.1 ? PICK(DBL_MAX, DBL_MIN, DBL_TRUE_MIN, 1e308) : fz_pos();
    double R2 = U() < 0.2 ? fz_pos() : R1 * hertz_ratio();
    if (k == 0) { R1 = 2.3e268; R2 = 4.5e256; }   /* the reported case */
    if (U() < 0.5) { const double t = R1; R1 = R2; R2 = t; }
    R1 = A(R1);
    R2 = A(R2);
    const double mx = fmax(R1, R2), mn = fmin(R1, R2);
    const int dom = isfinite(R1) && isfinite(R2) && R1 > 0.0 && R2 > 0.0 && mn / mx >= DC_HERTZ_RATIO_MIN;
    dc_hertz_geom g;
    SENTINEL(g);
    const int st = dc_hertz_geometry(R1, R2, &g);
    FZ_CHECK(f, st, !isfinite(R1) || !isfinite(R2), dom, UNTOUCHED(g),
             FIN(g) && g.R_major >= g.R_minor && g.e2 >= 0.0 && g.e2 < 1.0 && g.m1 > 0.0 && g.m1 <= 1.0,
             "R1 %.17g R2 %.17g", R1, R2);
    if (st == DC_OK) {
      /* Rc = R_minor/(1 + R_minor/R_major) to rounding (a few ulps: both
         forms round three times) wherever it is normal */
      const double rc = mn / (1.0 + mn / mx);
      FZ_EXPECT(f, !(rc >= DBL_MIN) || fabs(g.Rc / rc - 1.0) < 1e-15, "Rc inaccurate",
                "R1 %.17g R2 %.17g: Rc %.17g, want %.17g", R1, R2, g.Rc, rc);
      pool_hertz(&g);
    }
    /* Rc, R_force = Rc gamma^2 and R_area = Rc beta are all <= R_major */
    FZ_EXPECT(f, st != DC_ERANGE, "DC_ERANGE for a representable geometry", "R1 %.17g R2 %.17g", R1, R2);
  }
  fz_done(f);
}

/* log of an upper bound of the largest output of dc_hertz_contact */
static double hertz_bound(const dc_hertz_geom *g, double E, double d)
{
  const double lF = lg(4.0 / 3.0) + lg(E) + 0.5 * (lg(g->R_force) + lg(d)) + lg(d);
  const double lk = lg(2.0) + lg(E) + 0.5 * (lg(g->R_force) + lg(d));
  const double lA = lg(M_PI) + lg(g->R_area) + lg(d);
  const double la = 0.5 * (lg(2.0) + lg(g->R_major) + lg(d) + lg(g->D / g->K));
  return fmax(fmax(lF, lk), fmax(lA, la));
}

static void fuzz_hertz_contact(void)
{
  fz_fn *f = fz_new("dc_hertz_contact");
  fz_fn *fs = fz_new("dc_hertz_stiffness");
  fs->seconds = 0.0;
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const dc_hertz_geom *g = &hpool[UI(nh)];
    const double E = A(U() < 0.3 ? fz_log(1e5, 1e12) : U() < 0.1 ? PICK(DBL_MAX, DBL_TRUE_MIN, DBL_MIN) : fz_pos());
    const double d = A(U() < 0.3 ? g->R_minor * fz_log(1e-12, 1.0) : U() < 0.1 ? PICK(0.0, -0.0, DBL_MAX) : fz_pos());
    dc_hertz_state s;
    SENTINEL(s);
    const int st = dc_hertz_contact(g, E, d, &s);
    FZ_CHECK(f, st, !isfinite(E) || !isfinite(d), isfinite(E) && E > 0.0 && isfinite(d) && d >= 0.0, UNTOUCHED(s),
             FIN(s), "R_major %.17g R_minor %.17g Estar %.17g delta %.17g", g->R_major, g->R_minor, E, d);
    FZ_EXPECT(f, st != DC_ERANGE || hertz_bound(g, E, d) > LOG_MAX - 2.0, "DC_ERANGE for a representable state",
              "R_major %.17g R_minor %.17g Estar %.17g delta %.17g", g->R_major, g->R_minor, E, d);
    /* the inline hot-path kernel (unchecked): the checked contact's kn and
       F = kn delta, bit for bit, wherever its products stay finite */
    fs->seconds -= fz_now();
    double kn, S;
    const double root = dc_hertz_stiffness(E, g->R_force, d, &kn, &S);
    fs->calls++;
    if (st == DC_OK && isfinite(root) && isfinite(kn) && isfinite(kn * d) && isfinite(S))
      FZ_EXPECT(fs, S == s.kn && kn * d == s.F, "differs from dc_hertz_contact",
                "R_force %.17g Estar %.17g delta %.17g: kn %.17g S %.17g vs F %.17g kn %.17g", g->R_force, E, d, kn,
                S, s.F, s.kn);
    fs->seconds += fz_now();
  }
  fz_done(f);
}

static int contact_ok(const dc_contact *c)
{
  return (c->formed == 0 || c->formed == 1) && ALLFIN(c->F, c->kn, c->area, c->a, c->b, c->F_bound);
}

static void fuzz_hertz_normal(void)
{
  fz_fn *f = fz_new("dc_hertz_normal");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const dc_hertz_geom *g = &hpool[UI(nh)];
    const double E = A(U() < 0.3 ? fz_log(1e5, 1e12) : fz_pos());
    const double d = A(U() < 0.4 ? g->R_minor * fz_sign(fz_log(1e-12, 1.0)) : U() < 0.1 ? PICK(0.0, -0.0) : fz_wide());
    dc_contact c;
    SENTINEL(c);
    const int st = dc_hertz_normal(g, E, d, &c);
    FZ_CHECK(f, st, !ALLFIN(E, d), ALLFIN(E, d) && E > 0.0, UNTOUCHED(c), contact_ok(&c),
             "R_major %.17g R_minor %.17g Estar %.17g delta %.17g", g->R_major, g->R_minor, E, d);
  }
  fz_done(f);
}

/* ---------------------------------------------------------------- */
/* gw_integrals.h, gw_rough.h                                         */

static double gw_h(void)
{
  const double r = U();
  return r < 0.4 ? -12.0 + 57.0 * U() : r < 0.7 ? fz_sign(fz_log(1e-320, 1e100))
         : PICK(DC_GW_H_MIN, -10.0, -0.0, 0.0, 20.0, 38.6, 40.0, 1e100, -1e100 * 1.0000001);
}

static void fuzz_gw_integrals(void)
{
  fz_fn *f = fz_new("dc_gw_F");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const int o = AI(UI(4));
    const double h = A(gw_h());
    double F;
    SENTINEL(F);
    FZ_CHECK(f, dc_gw_F(o, h, &F), !isfinite(h), o >= 0 && o <= 3 && isfinite(h) && h >= DC_GW_H_MIN,
             UNTOUCHED(F), isfinite(F), "order %d h %.17g", o, h);
  }
  fz_done(f);
  f = fz_new("dc_gw_F_all");
  fz_fn *f2 = fz_new("dc_gw_F32_F12");
  f2->seconds = 0.0;
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const double h = A(gw_h());
    double F[4];
    SENTINEL(F);
    const int st = dc_gw_F_all(h, F);
    FZ_CHECK(f, st, !isfinite(h), isfinite(h) && h >= DC_GW_H_MIN, UNTOUCHED(F), FIN(F),
             "h %.17g", h);
    /* at the same h (no draws of its own): the same status; F_3/2 and
       F_1/2 within 1e-15 on the pieces, the same bits off them */
    double q[2];
    SENTINEL(q);
    f2->seconds -= fz_now();
    const int s2 = dc_gw_F32_F12(h, &q[0], &q[1]);
    f2->seconds += fz_now();
    f2->calls++;
    const int piece = h >= DC_GW_F32P_LO && h < DC_GW_F32P_HI;
    FZ_EXPECT(f2, s2 == st && (st != DC_OK ? UNTOUCHED(q)
                                           : piece ? fabs(q[0] - F[DC_GW_F32]) <= 1e-15 * F[DC_GW_F32] &&
                                                         fabs(q[1] - F[DC_GW_F12]) <= 1e-15 * F[DC_GW_F12]
                                                   : q[0] == F[DC_GW_F32] && q[1] == F[DC_GW_F12]),
              "differs from dc_gw_F_all", "h %.17g: status %d vs %d, %.17g %.17g", h, s2, st, q[0], q[1]);
  }
  fz_done(f);
  fz_done(f2);
  f = fz_new("dc_gw_F_closed");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const int o = AI(UI(4));
    const double h = A(gw_h());
    double F;
    SENTINEL(F);
    FZ_CHECK(f, dc_gw_F_closed(o, h, &F), !isfinite(h), o >= 0 && o <= 3 && isfinite(h) && h >= DC_GW_H_MIN,
             UNTOUCHED(F), isfinite(F), "order %d h %.17g", o, h);
  }
  fz_done(f);
}

static void fuzz_gw_rough(void)
{
  fz_fn *fc = fz_new("dc_gw_roughness_combine");
  for (long k = 0; k < N_CALLS; k++) {
    const double a = U() < 0.2 ? 0.0 : fz_pos(), b = U() < 0.2 ? 0.0 : fz_pos();
    const double c = dc_gw_roughness_combine(a, b);
    fc->calls++;
    /* (a^2 + b^2)^1/2 in [max, 2^1/2 max]: finite and nonzero where that is */
    const double mx = fmax(a, b);
    FZ_EXPECT(fc, c >= mx && (mx > DBL_MAX / 1.5 || c <= 1.4142135623730951 * mx * (1.0 + 4.0 * DBL_EPSILON)),
              "not (a^2 + b^2)^1/2", "%.17g %.17g: %.17g", a, b, c);
  }
  fz_done(fc);
  fz_fn *fn = fz_new("dc_gw_rough_normal");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const dc_hertz_geom *g = &hpool[UI(nh)];
    const double E = A(U() < 0.3 ? fz_log(1e5, 1e12) : fz_pos());
    const double d = A(U() < 0.4 ? g->R_minor * fz_sign(fz_log(1e-12, 1.0)) : U() < 0.1 ? PICK(0.0, -0.0) : fz_wide());
    const double F = A(U() < 0.5 ? fz_sign(fz_log(1e-12, 1e6)) : fz_wide()), kn = A(fz_wide());
    dc_contact c;
    SENTINEL(c);
    const int st = dc_gw_rough_normal(g, E, d, F, kn, &c);
    FZ_CHECK(fn, st, !ALLFIN(E, d, F, kn), ALLFIN(E, d, F, kn) && E > 0.0, UNTOUCHED(c), contact_ok(&c),
             "R_major %.17g R_minor %.17g Estar %.17g delta %.17g F %.17g kn %.17g", g->R_major, g->R_minor, E, d, F, kn);
  }
  fz_done(fn);
  fz_fn *f = fz_new("dc_gw_rough_elliptic");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const dc_hertz_geom *g = &hpool[UI(nh)];
    const double E = A(U() < 0.3 ? fz_log(1e5, 1e12) : fz_pos());
    const double n = A(U() < 0.3 ? fz_log(1e-2, 1e6) : fz_pos());
    const double sg = A(U() < 0.3 ? g->R_minor * fz_log(1e-9, 1e-3) : U() < 0.2 ? PICK(0.0, DBL_TRUE_MIN, DBL_MIN) : fz_pos());
    const double d = A(U() < 0.5 ? sg * (-12.0 + 60.0 * U()) : U() < 0.1 ? PICK(0.0, -0.0) : fz_wide());
    const int bad = !ALLFIN(E, n, sg, d);
    const int dom = !bad && E > 0.0 && n > 0.0 && sg >= 0.0;
    dc_gw_rough_state s;
    SENTINEL(s);
    const int st = dc_gw_rough_elliptic(g, E, n, sg, d, &s);
    FZ_CHECK(f, st, bad, dom, UNTOUCHED(s), FIN(s),
             "R_major %.17g R_minor %.17g Estar %.17g n_asp %.17g sigma %.17g delta %.17g", g->R_major, g->R_minor,
             E, n, sg, d);
    /* the closed form bound to the geometry: the same status, the same
       result off the pieces of dc_gw_F32_F12, within 1e-14 on them */
    dc_gw_bound b;
    SENTINEL(b);
    const int sb = dc_gw_bound_init(g, E, n, sg, &b);
    FZ_EXPECT(f, sb == DC_OK || UNTOUCHED(b), "dc_gw_bound_init wrote *b on error", "status %d", sb);
    FZ_EXPECT(f, sb != DC_EDOM || !(dom && sg > 0.0), "dc_gw_bound_init: DC_EDOM inside the domain",
              "Estar %.17g n_asp %.17g sigma %.17g", E, n, sg);
    if (sb == DC_OK && !bad) {
      double q[2];
      SENTINEL(q);
      const int sq = dc_gw_bound_force(&b, d, &q[0], &q[1]);
      const double hb = -d * b.inv_sigma;
      const int piece = hb >= DC_GW_F32P_LO && hb < DC_GW_F32P_HI;
      /* (the two form their products in different orders: where sigma^3/2
         is subnormal, sigma below 1e-205, the values are not compared) */
      const int tiny = !(sg > 1e-200);
      /* (a subnormal F is good to its last place, DBL_TRUE_MIN, where
         1e-14 F underflows to 0) */
      /* (dc_gw_rough_elliptic's DC_ERANGE may come from the area alone,
         which the bound form does not compute) */
      FZ_EXPECT(f, (sq == st || (piece && st == DC_ERANGE && sq == DC_OK && FIN(q))) &&
                       (sq != DC_OK ? UNTOUCHED(q)
                        : st != DC_OK || tiny ? 1
                        : piece ? fabs(q[0] - s.F) <= 1e-14 * s.F + 2.0 * DBL_TRUE_MIN &&
                                      fabs(q[1] - s.kn) <= 1e-14 * s.kn + 2.0 * DBL_TRUE_MIN
                                : q[0] == s.F && q[1] == s.kn),
                "dc_gw_bound_force differs from dc_gw_rough_elliptic",
                "R_major %.17g R_minor %.17g Estar %.17g n_asp %.17g sigma %.17g delta %.17g: status %d vs %d, "
                "%.17g %.17g vs %.17g %.17g", g->R_major, g->R_minor, E, n, sg, d, sq, st, q[0], q[1], s.F, s.kn);
    }
    if (st == DC_ERANGE) {
      /* bound: sigma^(3/2) F_3/2(h) <= (sigma + |delta|)^3/2 F_3/2(0) 2^3/2
         and the like; the Hertz bound for the smooth limit */
      const double x = sg + fabs(d);
      const double b = lg(n) + fmax(fmax(hertz_bound(g, E, fabs(d)), lg(M_PI) + lg(g->Rc) + lg(x) + lg(g->beta) + lg(2.0)),
                                    lg(E) + 0.5 * lg(g->Rc) + 0.5 * lg(x) + fmax(lg(x), 0.0) + lg(g->gamma) + lg(4.0));
      FZ_EXPECT(f, b > LOG_MAX - 2.0, "DC_ERANGE for a representable state",
                "R_major %.17g R_minor %.17g Estar %.17g n_asp %.17g sigma %.17g delta %.17g", g->R_major,
                g->R_minor, E, n, sg, d);
    }
  }
  fz_done(f);
}

/* ---------------------------------------------------------------- */
/* feng_rough.h                                                       */

static void fuzz_feng_init(void)
{
  fz_fn *f = fz_new("dc_feng_init");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const double mu = A(U() < 0.6 ? 1.0 + 49.0 * U() : PICK(1.0, 2.0, 4.0, 10.0, 20.0, 35.0, 50.0));
    const int var = AI(UI(2));
    dc_feng_law law;
    SENTINEL(law);
    const int st = dc_feng_init(mu, var, &law);
    FZ_CHECK(f, st, !isfinite(mu), mu >= DC_FENG_MU_MIN && mu <= DC_FENG_MU_MAX && (var == 0 || var == 1),
             UNTOUCHED(law), FIN(law), "mu %.17g variant %d", mu, var);
    if (st == DC_OK) {
      if (nl < 64) lpool[nl++] = law;
      else lpool[UI(64)] = law;
    }
  }
  fz_done(f);
  f = fz_new("dc_feng_P1");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const dc_feng_law *law = &lpool[UI(nl)];
    const double x = A(U() < 0.7 ? U() : PICK(0.0, -0.0, 1.0 / 3, 2.0 / 3, 1.0));
    const double P = dc_feng_P1(law, x);
    f->calls++;
    if (x >= 0.0 && x <= 1.0)
      FZ_EXPECT(f, isfinite(P), "not finite on [0, 1]", "mu %.17g alpha %.17g: %.17g", law->mu, x, P);
  }
  fz_done(f);
  f = fz_new("dc_feng_pstar_sigma");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const dc_feng_law *law = &lpool[UI(nl)];
    const double x = A(U() < 0.6 ? -5.0 + 9.0 * U() : U() < 0.5 ? fz_wide() : PICK(-3.0, -0.0, 0.0, 1.0, 0.5, -0.75));
    const double P = dc_feng_pstar_sigma(law, x);
    f->calls++;
    FZ_EXPECT(f, isnan(x) || (!isnan(P) && (fabs(x) > 1e200 || isfinite(P))), "NaN, or not finite for |alpha'| <= 1e200",
              "mu %.17g alpha' %.17g: %.17g", law->mu, x, P);
  }
  fz_done(f);
}

static void fuzz_feng_force(void)
{
  fz_fn *f = fz_new("dc_feng_force");
  fz_fn *fp = fz_new("dc_feng_pair_init");
  fz_fn *ff = fz_new("dc_feng_pair_force");
  fp->seconds = ff->seconds = 0.0;
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const dc_feng_law *law = &lpool[UI(nl)];
    const double E = A(U() < 0.3 ? fz_log(1e5, 1e12) : fz_pos());
    const double R = A(U() < 0.3 ? fz_log(1e-6, 1.0) : fz_pos());
    double sg = U() < 0.3 ? R * fz_log(1e-9, 1e-2) : U() < 0.3 ? PICK(0.0, DBL_TRUE_MIN, DBL_MIN, 1e-310) : fz_pos();
    if (k < 4) sg = ldexp(1.0, -1030 - (int)k);   /* the reported case: subnormal sigma */
    sg = A(sg);
    const double d = A(U() < 0.6 ? sg * (-4.0 + 8.0 * U()) : U() < 0.1 ? PICK(0.0, -0.0) : fz_wide());
    const int bad = !ALLFIN(E, R, sg, d);
    double out[2];
    SENTINEL(out);
    const int st = dc_feng_force(law, E, R, sg, d, &out[0], &out[1]);
    FZ_CHECK(f, st, bad, !bad && E > 0.0 && R > 0.0 && sg >= 0.0, UNTOUCHED(out), FIN(out),
             "mu %.17g Estar %.17g R %.17g sigma %.17g delta %.17g", law->mu, E, R, sg, d);
    /* |P| <= 4/3 E* R^1/2 max(delta, 3 sigma)^3/2 max |P*| (P* < 4 here), kn likewise */
    const double x = fmax(fabs(d), 3.0 * sg);
    const double b = lg(E) + 0.5 * lg(R) + 0.5 * lg(x) + fmax(lg(x), 0.0) + lg(40.0);
    FZ_EXPECT(f, st != DC_ERANGE || b > LOG_MAX - 2.0, "DC_ERANGE for a representable force",
              "mu %.17g Estar %.17g R %.17g sigma %.17g delta %.17g", law->mu, E, R, sg, d);
    /* the bound pair: same domain without sigma = 0 */
    fp->seconds -= fz_now();
    dc_feng_pair p;
    SENTINEL(p);
    const int sp = dc_feng_pair_init(law, E, sg, &p);
    fp->seconds += fz_now();
    FZ_CHECK(fp, sp, !isfinite(E) || !isfinite(sg), isfinite(E) && isfinite(sg) && E > 0.0 && sg > 0.0,
             UNTOUCHED(p), FIN(p), "mu %.17g Estar %.17g sigma %.17g", law->mu, E, sg);
    if (sp != DC_OK || !(R > 0.0 && isfinite(R) && isfinite(d))) continue;
    /* the unchecked kernel: the checked force's value wherever its
       products stay in range (c R^1/2 and c R^1/2 max(delta, sigma)^3/2) */
    for (int j = 0; j < 3; j++) {   /* three overlaps per bound pair */
      const double dj = j == 0 ? d : U() < 0.7 ? sg * (-4.0 + 8.0 * U()) : fz_wide();
      double o[2] = {out[0], out[1]};
      int sj = st;
      if (j > 0) sj = dc_feng_force(law, E, R, sg, dj, &o[0], &o[1]);
      const double xj = fmax(fabs(dj), 3.0 * sg);
      const double bj = lg(E) + 0.5 * lg(R) + 0.5 * lg(xj) + fmax(lg(xj), 0.0) + lg(40.0);
      ff->seconds -= fz_now();
      double q[2];
      dc_feng_pair_force(&p, sqrt(R), dj, &q[0], &q[1]);
      ff->seconds += fz_now();
      ff->calls++;
      if (bj < LOG_MAX - 5.0 && lg(E) + 0.5 * lg(R) < LOG_MAX - 5.0)
        FZ_EXPECT(ff, sj == DC_OK && q[0] == o[0] && q[1] == o[1], "differs from dc_feng_force",
                  "mu %.17g Estar %.17g R %.17g sigma %.17g delta %.17g: %.17g %.17g vs %.17g %.17g", law->mu, E, R,
                  sg, dj, q[0], q[1], o[0], o[1]);
    }
  }
  fz_done(f);
}

/* ---------------------------------------------------------------- */
/* gw_solver.h                                                        */

static void fuzz_gw_solver(void)
{
  fz_fn *f = fz_new("dc_gw_solve_default_opts");
  for (long k = 0; k < N_CALLS; k++) {
    const dc_gw_solve_opts o = dc_gw_solve_default_opts();
    f->calls++;
    FZ_EXPECT(f, o.domain_scale == 1.0 && o.abar == 0.0 && o.force_mode == DC_GW_FORCE_FULL &&
                 o.f32_mode == DC_GW_F32_EXACT && o.tol == 1e-12 && o.max_iter == 50,
              "not the documented defaults", "call %ld", k);
  }
  fz_done(f);
  /* init: every m, in-range ones mostly small (the m x m influence table
     costs m^2 elliptic integrals), and a few large */
  f = fz_new("dc_gw_solver_init");
  fz_fn *fr = fz_new("dc_gw_solver_free");
  for (long k = 0; f->calls < N_CALLS || fr->calls < N_CALLS; k++) {
    fz_call();
    const double r = U();
    int m = r < 0.5 ? 2 + UI(8) : r < 0.8 ? -3 + UI(16) : r < 0.95 ? (int[]){0, 1, -1, 1001, INT_MIN, INT_MAX}[UI(6)]
            : (int)(U() * 4294967296.0 - 2147483648.0);
    if (k < 3) m = (int[]){1000, 1001, 200}[k];
    dc_gw_solver S;
    SENTINEL(S);
    const int st = dc_gw_solver_init(&S, m);
    int ok = st != DC_OK || (S.m == m && S.x && S.s && S.alpha);
    if (st == DC_OK && ok) {
      ok = fin(S.x, m) && fin(S.s, m) && fin(S.alpha, m * m);
      for (int i = 0; i < m; i++) ok &= S.x[i] > 0.0 && S.x[i] < 1.0 && S.s[i] > 0.0;
    }
    FZ_CHECK(f, st, 0, m >= 2 && m <= 1000, UNTOUCHED(S), ok, "m %d", m);
    if (st == DC_OK) {
      dc_gw_solver_free(&S);
      fr->calls++;
      FZ_EXPECT(fr, !S.x && !S.s && !S.alpha, "pointers not cleared", "m %d", m);
    }
  }
  fz_done(f);
  fz_done(fr);
  fr->seconds = 0.0;   /* inside init's time */
}

/* dc_gw_solve: 1e5 calls like the others, but on small m (2 .. 12, and
   m = 40 every 200th call): each is a Newton solve of up to 50 iterations
   on m points plus the outer force integral, and the tested paths are the
   same for every m. */
static void fuzz_gw_solve(void)
{
  enum { NS = 6 };
  const int ms[NS] = {2, 3, 5, 8, 12, 40};
  dc_gw_solver S[NS];
  for (int i = 0; i < NS; i++) dc_gw_solver_init(&S[i], ms[i]);
  fz_fn *f = fz_new("dc_gw_solve");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const int is = k % 200 == 0 ? NS - 1 : UI(NS - 1);
    const double ap = A(U() < 0.6 ? -10.0 + 30.0 * U() : U() < 0.5 ? fz_log(1e-3, 1e4) : PICK(-10.0, 0.0, -0.0, 1e4, 1.0));
    const double mu = A(U() < 0.6 ? fz_log(0.1, 100.0) : PICK(1e3, DBL_TRUE_MIN, 1e-300, 1.0));
    dc_gw_solve_opts o = dc_gw_solve_default_opts();
    o.domain_scale = A(U() < 0.7 ? 1.0 : fz_log(0.3, 3.0));
    o.abar = A(U() < 0.8 ? 0.0 : fz_log(0.5, 30.0));
    o.force_mode = AI(UI(2));
    o.f32_mode = AI(UI(2));
    o.tol = A(U() < 0.8 ? 1e-12 : PICK(0.0, 1e-15, 1e-6, -1.0));
    o.max_iter = U() < 0.8 ? 50 : U() < 0.5 ? 1 + UI(60) : (int[]){0, -1, INT_MIN}[UI(3)];
    const int bad = !ALLFIN(ap, mu, o.domain_scale, o.abar, o.tol);
    const int dom = !bad && ap >= -10.0 && ap <= 1e4 && mu > 0.0 && mu <= 1e3 && o.domain_scale >= 0.3 &&
                    o.domain_scale <= 3.0 && o.abar >= 0.0 && o.abar <= 30.0 && o.max_iter > 0 &&
                    (o.force_mode == 0 || o.force_mode == 1) && (o.f32_mode == 0 || o.f32_mode == 1) &&
                    o.tol >= 0.0;
    dc_gw_solve_result r;
    SENTINEL(r);
    const int st = dc_gw_solve(&S[is], ap, mu, &o, &r);
    int ok = r.iterations >= 1 && r.iterations <= o.max_iter && isfinite(r.Pstar_sigma) && isfinite(r.Pstar_delta) &&
             isfinite(r.abar) && isfinite(r.p0);
    if (ok) ok = fin(r.hist, r.iterations < DC_GW_SOLVER_MAX_HIST ? r.iterations : DC_GW_SOLVER_MAX_HIST);
    FZ_CHECK(f, st, bad, dom, UNTOUCHED(r), ok,
             "m %d alpha' %.17g mu %.17g domain_scale %.17g abar %.17g force %d f32 %d tol %.17g max_iter %d", ms[is],
             ap, mu, o.domain_scale, o.abar, o.force_mode, o.f32_mode, o.tol, o.max_iter);
    /* inside the domain, only P/P_h(delta) can overflow (alpha' > 0 tiny) */
    FZ_EXPECT(f, st != DC_ERANGE || !dom || (ap > 0.0 && ap < 1e-200), "DC_ERANGE for a representable result",
              "m %d alpha' %.17g mu %.17g domain_scale %.17g abar %.17g force %d f32 %d tol %.17g max_iter %d",
              ms[is], ap, mu, o.domain_scale, o.abar, o.force_mode, o.f32_mode, o.tol, o.max_iter);
  }
  fz_done(f);
  for (int i = 0; i < NS; i++) dc_gw_solver_free(&S[i]);
}

/* ---------------------------------------------------------------- */
/* rough_tangential.h                                                 */

static void fuzz_rough_tangential(void)
{
  fz_fn *f = fz_new("dc_mindlin_chi");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const dc_hertz_geom *g = &hpool[UI(nh)];
    const double nu = A(U() < 0.7 ? 0.5 * U() : PICK(0.0, 0.5, -0.0, -0.1, 0.6));
    const double th = A(U() < 0.7 ? -7.0 + 14.0 * U() : fz_wide());
    double chi;
    SENTINEL(chi);
    FZ_CHECK(f, dc_mindlin_chi(g, nu, th, &chi), !isfinite(nu) || !isfinite(th),
             nu >= 0.0 && nu <= 0.5 && isfinite(th), UNTOUCHED(chi), isfinite(chi) && chi > 0.0,
             "R_major %.17g R_minor %.17g nu %.17g theta %.17g", g->R_major, g->R_minor, nu, th);
  }
  fz_done(f);
  f = fz_new("dc_rough_tangential_stiffness");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const double G = A(U() < 0.3 ? fz_log(1e6, 1e11) : fz_pos());
    const double chi = A(U() < 0.3 ? 0.3 + 0.2 * U() : fz_pos());
    const double n = A(U() < 0.3 ? fz_log(1e-2, 1e6) : fz_pos());
    const double R = A(U() < 0.3 ? fz_log(1e-9, 1e-3) : fz_pos());
    const double sg = A(U() < 0.3 ? R * fz_log(1e-9, 1e-3) : U() < 0.2 ? PICK(0.0, DBL_TRUE_MIN, DBL_MIN) : fz_pos());
    const double d = A(U() < 0.5 ? sg * (-12.0 + 60.0 * U()) : U() < 0.1 ? PICK(0.0, -0.0) : fz_wide());
    const int bad = !ALLFIN(G, chi, n, R, sg, d);
    double kt;
    SENTINEL(kt);
    const int st = dc_rough_tangential_stiffness(G, chi, n, R, sg, d, &kt);
    FZ_CHECK(f, st, bad, !bad && G > 0.0 && chi > 0.0 && n > 0.0 && R > 0.0 && sg >= 0.0, UNTOUCHED(kt),
             isfinite(kt), "G %.17g chi %.17g n_asp %.17g R_asp %.17g sigma %.17g delta %.17g", G, chi, n, R, sg, d);
    /* k_t <= 2 pi n G chi (R_asp (sigma + |delta|))^1/2 F_1/2(0) 2^1/2 */
    const double b = lg(2.0 * M_PI) + lg(n) + lg(G) + lg(chi) + 0.5 * (lg(R) + lg(sg + fabs(d)));
    FZ_EXPECT(f, st != DC_ERANGE || b > LOG_MAX - 2.0, "DC_ERANGE for a representable stiffness",
              "G %.17g chi %.17g n_asp %.17g R_asp %.17g sigma %.17g delta %.17g", G, chi, n, R, sg, d);
  }
  fz_done(f);
  f = fz_new("dc_rough_tangential_axes");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const dc_hertz_geom *g = &hpool[UI(nh)];
    const double n = A(U() < 0.4 ? fz_log(1e-2, 1e6) : U() < 0.1 ? PICK(0.0, -1.0, DBL_TRUE_MIN) : fz_pos());
    const double sg = A(U() < 0.4 ? g->R_major * fz_log(1e-9, 1e-3)
                                  : U() < 0.2 ? PICK(0.0, DBL_TRUE_MIN, DBL_MIN, -1e-9) : fz_pos());
    const double d = A(U() < 0.5 ? sg * (-12.0 + 60.0 * U()) : U() < 0.1 ? PICK(0.0, -0.0) : fz_wide());
    const int bad = !ALLFIN(n, sg, d);
    double a, b;
    SENTINEL(a);
    SENTINEL(b);
    const int st = dc_rough_tangential_axes(g, n, sg, d, &a, &b);
    FZ_CHECK(f, st, bad, !bad && n > 0.0 && sg >= 0.0, UNTOUCHED(a) && UNTOUCHED(b),
             isfinite(a) && isfinite(b) && a >= 0.0 && b >= 0.0 && b <= a,
             "R_major %.17g R_minor %.17g n_asp %.17g sigma %.17g delta %.17g", g->R_major, g->R_minor, n, sg, d);
    /* a_r <= n (2 R_major (sigma + |delta|))^1/2 F_1/2(0) 2^1/2 (D/K <= 1) */
    const double bd = lg(n) + 0.5 * (lg(2.0 * g->R_major) + lg(sg + fabs(d)));
    FZ_EXPECT(f, st != DC_ERANGE || bd > LOG_MAX - 2.0, "DC_ERANGE for representable semi-axes",
              "R_major %.17g n_asp %.17g sigma %.17g delta %.17g", g->R_major, n, sg, d);
    /* the smooth limit is the Hertz semi-axis (dc_hertz_contact) times n_asp */
    if (st == DC_OK && (sg == 0.0 || sg <= 1e-80 * fabs(d)) && d > 0.0 && n == 1.0) {
      dc_hertz_state hs;
      if (dc_hertz_contact(g, 1.0, d, &hs) == DC_OK)
        FZ_EXPECT(f, a == hs.a && b == hs.b, "smooth limit: not the Hertz ellipse", "delta %.17g", d);
    }
  }
  fz_done(f);
}

/* ---------------------------------------------------------------- */
/* maugis_dugdale.h                                                   */

static void fuzz_maugis_dugdale(void)
{
  fz_fn *ft = fz_new("dc_md_lambda_of_tabor");
  for (long k = 0; k < N_CALLS; k++) {
    const double mu = A(U() < 0.7 ? fz_log(1e-4, 1e4) : fz_wild());
    const double l = dc_md_lambda_of_tabor(mu);
    ft->calls++;
    FZ_EXPECT(ft, !isfinite(mu) || fabs(mu) > 0.8 * DBL_MAX || fabs(l - 1.157 * mu) <= 1e-3 * fabs(mu),
              "not 1.1570 mu_T", "mu_T %.17g: %.17g", mu, l);
  }
  fz_done(ft);
  fz_fn *f = fz_new("dc_md_state");
  for (long k = 0; k < N_CALLS / 10; k++) {
    fz_call();
    const double lam = A(U() < 0.7 ? fz_log(1e-10, 1e10) : fz_wild());
    const double ab = A(U() < 0.7 ? fz_log(1e-20, 1e20) : fz_wild());
    const int bad = !ALLFIN(lam, ab);
    double m, P, D;
    SENTINEL(m);
    SENTINEL(P);
    SENTINEL(D);
    const int st = dc_md_state(lam, ab, &m, &P, &D);
    FZ_CHECK(f, st, bad, !bad && lam >= 1e-10 && lam <= 1e10 && ab >= 1e-20 && ab <= 1e20,
             UNTOUCHED(m) && UNTOUCHED(P) && UNTOUCHED(D),
             ALLFIN(m, P, D) && m >= 1.0, "lambda %.17g abar %.17g", lam, ab);
    /* P <= abar^3 and D <= abar^2 (the zone pulls); P >= abar^3 - 2 - ... only near the limits */
    FZ_EXPECT(f, st != DC_OK || (P <= ab * ab * ab * (1.0 + 1e-15) && D <= ab * ab * (1.0 + 1e-15)),
              "the adhesive zone pushes", "lambda %.17g abar %.17g: P %.17g D %.17g", lam, ab, P, D);
    FZ_EXPECT(f, st != DC_ENOCONV, "no convergence in the domain", "lambda %.17g abar %.17g", lam, ab);
  }
  fz_done(f);
  f = fz_new("dc_md_state_zero");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const double lam = A(U() < 0.7 ? fz_log(1e-10, 1e10) : fz_wild());
    const int bad = !isfinite(lam);
    double c, P, D;
    SENTINEL(c);
    SENTINEL(P);
    SENTINEL(D);
    const int st = dc_md_state_zero(lam, &c, &P, &D);
    FZ_CHECK(f, st, bad, !bad && lam >= 1e-10 && lam <= 1e10, UNTOUCHED(c) && UNTOUCHED(P) && UNTOUCHED(D),
             ALLFIN(c, P, D) && c >= 0.0 && P <= 0.0 && P >= -2.0 * (1.0 + 1e-15) && D <= 0.0,
             "lambda %.17g", lam);
  }
  fz_done(f);
  f = fz_new("dc_md_pulloff");
  for (long k = 0; k < N_CALLS / 1000 + 1; k++) {
    fz_call();
    const double lam = A(U() < 0.8 ? fz_log(1e-10, 1e10) : fz_wild());
    const int bad = !isfinite(lam);
    double P, a;
    SENTINEL(P);
    SENTINEL(a);
    const int st = dc_md_pulloff(lam, &P, &a);
    FZ_CHECK(f, st, bad, !bad && lam >= 1e-10 && lam <= 1e10, UNTOUCHED(P) && UNTOUCHED(a), ALLFIN(P, a),
             "lambda %.17g", lam);
    FZ_EXPECT(f, st != DC_OK || (P >= -2.0 - 1e-12 && P <= -1.5 + 1e-12),
              "pull-off outside [-2, -3/2]", "lambda %.17g: %.17g", lam, P);
  }
  fz_done(f);
  f = fz_new("dc_md_separation");
  for (long k = 0; k < N_CALLS / 1000 + 1; k++) {
    fz_call();
    const double lam = A(U() < 0.8 ? fz_log(1e-10, 1e10) : fz_wild());
    const int bad = !isfinite(lam);
    double D, a;
    SENTINEL(D);
    SENTINEL(a);
    const int st = dc_md_separation(lam, &D, &a);
    FZ_CHECK(f, st, bad, !bad && lam >= 1e-10 && lam <= 1e10, UNTOUCHED(D) && UNTOUCHED(a), ALLFIN(D, a) && D < 0.0,
             "lambda %.17g", lam);
  }
  fz_done(f);
  f = fz_new("dc_md_at_overlap");
  for (long k = 0; k < N_CALLS / 1000 + 1; k++) {
    fz_call();
    const double lam = A(U() < 0.8 ? fz_log(1e-6, 1e6) : fz_wild()), D = A(U() < 0.8 ? -3.0 + 10.0 * U() : fz_wild());
    const int bad = !ALLFIN(lam, D);
    double a, m, P;
    int contact;
    SENTINEL(a);
    SENTINEL(m);
    SENTINEL(P);
    SENTINEL(contact);
    const int st = dc_md_at_overlap(lam, D, &contact, &a, &m, &P);
    FZ_CHECK(f, st, bad, !bad && lam >= 1e-10 && lam <= 1e10 && fabs(D) <= 1e30,
             UNTOUCHED(a) && UNTOUCHED(m) && UNTOUCHED(P) && UNTOUCHED(contact),
             (contact == 0 || contact == 1) && ALLFIN(a, P) && !isnan(m) && a >= 0.0,
             "lambda %.17g Dbar %.17g", lam, D);
    /* on the branch the overlap is the one asked for */
    if (st == DC_OK && contact && a > 1e-20) {
      double m2, P2, D2;
      FZ_EXPECT(f, dc_md_state(lam, a, &m2, &P2, &D2) == DC_OK && fabs(D2 - D) <= 1e-12 * (1.0 + fabs(D)),
                "not at the overlap asked for", "lambda %.17g Dbar %.17g: abar %.17g", lam, D, a);
    }
  }
  fz_done(f);
  f = fz_new("dc_md_branch_s");
  for (long k = 0; k < N_CALLS / 10; k++) {
    fz_call();
    const double lam = A(U() < 0.8 ? fz_log(1e-10, 1e10) : fz_wild()), x = A(U() < 0.8 ? fz_log(1e-30, 1e30) : fz_wild());
    const int bad = !ALLFIN(lam, x);
    double a, P, D, dD;
    SENTINEL(a);
    SENTINEL(P);
    SENTINEL(D);
    SENTINEL(dD);
    const int st = dc_md_branch_s(lam, x, &a, &P, &D, &dD);
    FZ_CHECK(f, st, bad, !bad && lam >= 1e-10 && lam <= 1e10 && x >= 1e-30 && x <= 1e30,
             UNTOUCHED(a) && UNTOUCHED(P) && UNTOUCHED(D) && UNTOUCHED(dD), ALLFIN(a, P, D, dD) && a > 0.0,
             "lambda %.17g s %.17g", lam, x);
    /* the branch's state at that abar (the solve in abar, within its domain) */
    if (st == DC_OK && a >= 1e-20 && a <= 1e20 && x >= 1e-6 && x <= 1e6) {
      double m2, P2, D2;
      const double sc = a * a + 4.0 / 3.0 * lam * a * x;
      FZ_EXPECT(f, dc_md_state(lam, a, &m2, &P2, &D2) == DC_OK && fabs(D2 - D) <= 1e-9 * sc &&
                       fabs(P2 - P) <= 1e-9 * (fabs(P) + a * a * a),
                "not the branch's state at abar", "lambda %.17g s %.17g: abar %.17g", lam, x, a);
    }
  }
  fz_done(f);
  f = fz_new("dc_md_zone");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const double lam = A(U() < 0.8 ? fz_log(1e-10, 1e10) : fz_wild()), D = A(U() < 0.8 ? fz_sign(fz_log(1e-6, 1e6)) : fz_wild());
    const int bad = !ALLFIN(lam, D);
    double c, P;
    int zone;
    SENTINEL(c);
    SENTINEL(P);
    SENTINEL(zone);
    const int st = dc_md_zone(lam, D, &zone, &c, &P);
    FZ_CHECK(f, st, bad, !bad && lam >= 1e-10 && lam <= 1e10 && fabs(D) <= 1e30,
             UNTOUCHED(c) && UNTOUCHED(P) && UNTOUCHED(zone), ALLFIN(c, P) && (zone == 0 || zone == 1) && P <= 0.0,
             "lambda %.17g Dbar %.17g", lam, D);
    /* a zone state lies on the zone's curve, on its stable side */
    const double cz = 8.0 * lam / (3.0 * M_PI);
    FZ_EXPECT(f, st != DC_OK || !zone || (c >= cz && fabs(0.5 * c * c - cz * c - 2.0 / (M_PI * lam) - D) <=
                                                         1e-9 * (fabs(D) + 0.5 * c * c + cz * c + 2.0 / (M_PI * lam))),
              "not the zone's stable state", "lambda %.17g Dbar %.17g: cbar %.17g", lam, D, c);
  }
  fz_done(f);
  fz_fn *fr = fz_new("dc_md_reach");
  for (long k = 0; k < N_CALLS; k++) {
    const double lam = A(U() < 0.8 ? fz_log(1e-10, 1e10) : fz_wild()), r = dc_md_reach(lam);
    fr->calls++;
    const int dom = isfinite(lam) && lam >= 1e-10 && lam <= 1e10;
    FZ_EXPECT(fr, dom ? isfinite(r) && r >= 1.0 && r >= 2.0 / (M_PI * lam) * (1.0 - 1e-15) : isnan(r),
              "not a reach >= max(1, 2/(pi lambda)) (NaN outside the domain)", "lambda %.17g: %.17g", lam, r);
  }
  fz_done(fr);
  /* random overlap paths from apart: the states are the zone's or the branch's (the
     reference every 97th contact step) and the force vanishes apart */
  f = fz_new("dc_md_step");
  for (long k = 0; k < N_CALLS / 1000 + 1; k++) {
    const double lam = A(U() < 0.9 ? fz_log(1e-4, 1e4) : fz_wild());
    dc_md_contact h = {0.0, 0.0, 0.0, lam, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    double D = -dc_md_reach(isfinite(lam) && lam >= 1e-10 && lam <= 1e10 ? lam : 1.0) - U();
    for (int i = 0; i < 40; i++) {
      fz_call();
      D = U() < 0.95 ? D + (U() - 0.3) * 0.5 * U() * U() : fz_wild();
      const int bad = !ALLFIN(lam, D);
      double P, a;
      dc_md_contact h0 = h;
      SENTINEL(P);
      SENTINEL(a);
      const int st = dc_md_step(D, &h, &P, &a);
      FZ_CHECK(f, st, bad, !bad && lam >= 1e-10 && lam <= 1e10 && fabs(D) <= 1e30,
               UNTOUCHED(P) && UNTOUCHED(a) && !memcmp(&h, &h0, sizeof h),
               ALLFIN(P, a, h.x, h.s) && a >= 0.0 && (h.phase == DC_MD_APART || h.phase == DC_MD_ZONE || h.phase == DC_MD_CONTACT),
               "lambda %.17g Dbar %.17g step %d", lam, D, i);
      FZ_EXPECT(f, st != DC_ENOCONV, "no convergence in the domain", "lambda %.17g Dbar %.17g step %d", lam, D, i);
      if (st != DC_OK) {
        h = h0;
        if (!isfinite(D) || fabs(D) > 1e30) D = 0.0;
        continue;
      }
      if (h.phase == DC_MD_APART) {
        FZ_EXPECT(f, P == 0.0 && a == 0.0, "a force while apart", "lambda %.17g Dbar %.17g", lam, D);
      } else if (h.phase == DC_MD_ZONE) {
        int zone;
        double c, Pz;
        FZ_EXPECT(f, dc_md_zone(lam, D, &zone, &c, &Pz) == DC_OK && zone && Pz == P && a == 0.0,
                  "not the zone's state", "lambda %.17g Dbar %.17g", lam, D);
      } else if ((k + i) % 97 == 0) {
        int contact;
        double ar, mr, Pr;
        FZ_EXPECT(f, dc_md_at_overlap(lam, D, &contact, &ar, &mr, &Pr) == DC_OK && contact &&
                         fabs(Pr - P) <= 1e-9 * (1.0 + fabs(Pr)) && fabs(ar - a) <= 1e-9 * ar,
                  "not the stable branch's state", "lambda %.17g Dbar %.17g: P %.17g", lam, D, P);
      }
    }
  }
  fz_done(f);
  f = fz_new("dc_md_friction_load");
  for (long k = 0; k < N_CALLS / 1000 + 1; k++) {
    const double lam = A(U() < 0.9 ? fz_log(1e-10, 1e10) : fz_wild()), P = A(U() < 0.9 ? -2.0 + 10.0 * U() : fz_wild());
    dc_md_contact h = {DC_MD_CONTACT, 1.0, 1.0, lam, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    const double L = dc_md_friction_load(&h, P);
    f->calls++;
    const int dom = isfinite(lam) && lam >= 1e-10 && lam <= 1e10;
    FZ_EXPECT(f, !dom ? isnan(L) : !isfinite(P) || (L == P - 2.0 * h.Pc && h.Pc >= -2.0 - 1e-12 && h.Pc <= -1.5 + 1e-12),
              "not F + 2 |F_c| (NaN outside lambda's domain)", "lambda %.17g Pbar %.17g: %.17g", lam, P, L);
  }
  fz_done(f);
  f = fz_new("dc_md_sphere_pair_of");
  fz_fn *fl = fz_new("dc_md_tabor_law");
  fz_fn *fp = fz_new("dc_md_sphere");
  for (long k = 0; k < N_CALLS / 100 + 1; k++) {
    fz_call();
    const double E = A(U() < 0.8 ? fz_log(1e5, 1e12) : fz_wild()), w = A(U() < 0.8 ? fz_log(1e-4, 1.0) : fz_wild());
    const double z0 = A(U() < 0.8 ? fz_log(1e-10, 1e-6) : fz_wild());
    const int bad = !ALLFIN(E, w, z0);
    dc_md_sphere_pair p;
    dc_param_error err;
    SENTINEL(p);
    const int st = dc_md_sphere_pair_of(E, w, z0, &p, &err);
    FZ_CHECK(f, st, bad || !(E > 0.0 && w > 0.0 && z0 > 0.0), 0, UNTOUCHED(p),
             ALLFIN(p.Lam, p.Cd, p.Ca, p.piw, p.h0, p.R_jkr, p.R_dmt) && p.Lam > 0.0 && p.h0 > 0.0 && p.R_dmt > 0.0 &&
                 p.R_dmt < p.R_jkr,
             "E* %.17g w %.17g z0 %.17g", E, w, z0);
    if (st != DC_OK) continue;
    /* the law a radius picks: JKR above R_jkr, DMT below R_dmt */
    const double R = A(U() < 0.8 ? fz_log(1e-9, 1.0) : fz_pos());
    const int law = dc_md_tabor_law(&p, R);
    fl->calls++;
    FZ_EXPECT(fl, law == (R > p.R_jkr ? DC_ADHESION_JKR : R < p.R_dmt ? DC_ADHESION_DMT : DC_ADHESION_MD),
              "not the law of the Tabor parameter", "R %.17g", R);
    /* a short approach and retreat: the force vanishes apart and before -h0 */
    dc_md_contact h = {0};
    double d = -2.0 * p.h0;
    for (int i = 0; i < 6; i++) {
      fz_call();
      d = i < 6 ? d + (i < 3 ? 1.0 : -1.0) * p.h0 * U() * 2.0 : d;
      double F, a;
      dc_md_contact h0 = h;
      SENTINEL(F);
      SENTINEL(a);
      const int s2 = dc_md_sphere(&p, R, d, &h, &F, &a);
      const double lam = h0.phase == DC_MD_APART ? p.Lam * cbrt(R) : h0.lambda;
      FZ_CHECK(fp, s2, 0, R > 0.0 && R <= DBL_MAX && h0.phase == DC_MD_APART && d <= -p.h0, UNTOUCHED(F) && UNTOUCHED(a) && (s2 == DC_ERANGE || !memcmp(&h, &h0, sizeof h)),
               ALLFIN(F, a) && a >= 0.0, "E* %.17g w %.17g z0 %.17g R %.17g delta %.17g", E, w, z0, R, d);
      FZ_EXPECT(fp, s2 != DC_OK || h.phase != DC_MD_APART || (F == 0.0 && a == 0.0), "a force while apart",
                "R %.17g delta %.17g", R, d);
      FZ_EXPECT(fp, s2 != DC_EDOM || !(R > 0.0 && lam >= 1e-10 && lam <= 1e10), "DC_EDOM inside lambda's domain",
                "R %.17g delta %.17g lambda %.17g", R, d, lam);
      if (s2 != DC_OK) break;
    }
  }
  fz_done(fl);
  fz_done(fp);
  fz_done(f);
  /* ellipses: the sphere of elliptic Hertz's force radius; R_force outside (0, DBL_MAX] refused */
  f = fz_new("dc_md_ellipse");
  {
    dc_md_sphere_pair p;
    dc_param_error err;
    dc_md_sphere_pair_of(1e9, 0.05, 4e-10, &p, &err);
    for (long k = 0; k < N_CALLS / 100 + 1; k++) {
      fz_call();
      const double R1 = fz_log(1e-7, 1.0), R2 = fz_log(1e-7, 1.0);
      const double d = A(U() < 0.8 ? fz_sign(fz_log(1e-12, 1e-3)) : fz_wild());
      dc_hertz_geom g;
      if (dc_hertz_geometry(R1 > R2 ? R1 : R2, R1 > R2 ? R2 : R1, &g) != DC_OK) continue;
      if (U() < 0.1) g.R_force = A(fz_wild());
      const int bad = !ALLFIN(d, g.R_force) || !(g.R_force > 0.0);
      dc_md_contact h = {0}, h0 = {0};
      double F, a;
      SENTINEL(F);
      SENTINEL(a);
      const int st = dc_md_ellipse(&p, &g, d, &h, &F, &a);
      FZ_CHECK(f, st, bad, 0, UNTOUCHED(F) && UNTOUCHED(a) && (st == DC_ERANGE || !memcmp(&h, &h0, sizeof h)), ALLFIN(F, a) && a >= 0.0,
               "R_force %.17g delta %.17g", g.R_force, d);
      if (st != DC_OK) continue;
      dc_md_contact hs = {0};
      double Fs, as_;
      FZ_EXPECT(f, dc_md_sphere(&p, g.R_force, d, &hs, &Fs, &as_) == DC_OK && hs.phase == h.phase &&
                       fabs(Fs - F) <= 1e-12 * (fabs(Fs) + p.piw * g.R_force),
                "not the sphere of R_force", "R_force %.17g delta %.17g", g.R_force, d);
    }
  }
  fz_done(f);
  fz_fn *fs = fz_new("dc_dmt_sphere");
  for (long k = 0; k < N_CALLS; k++) {
    const double R = A(U() < 0.8 ? fz_log(1e-7, 1.0) : fz_pos()), E = A(U() < 0.8 ? fz_log(1e5, 1e12) : fz_pos());
    const double w = A(U() < 0.8 ? fz_log(1e-4, 1.0) : fz_pos() * (U() < 0.1 ? 0.0 : 1.0));
    const double d = A(U() < 0.8 ? R * fz_sign(fz_log(1e-12, 1e-1)) : fz_wide());
    double F, kn, root;
    const int ok = dc_dmt_sphere(R, E, w, d, &F, &kn, &root);
    fs->calls++;
    dc_hertz_geom g;
    dc_contact c;
    dc_hertz_geometry_circle(R, &g);
    const int st = dc_dmt_contact(&g, E, w, d, &c);
    /* where both answer, dc_dmt_contact's force and stiffness to the bit (no answer is
       allowed: the caller takes dc_dmt_contact; the unit test has it answer typical contacts) */
    FZ_EXPECT(fs, !ok || (d > 0.0 && (st != DC_OK || (c.formed && F == c.F && kn == c.kn))),
              "not dc_dmt_contact's bits", "R %.17g E %.17g w %.17g delta %.17g", R, E, w, d);
  }
  fz_done(fs);
  fz_fn *fd = fz_new("dc_dmt_pulloff");
  for (long k = 0; k < N_CALLS; k++) {
    const double r1 = A(fz_wild()), r2 = A(fz_wild()), w = A(U() < 0.5 ? fz_log(1e-4, 1.0) : fz_wild());
    const double F = dc_dmt_pulloff(r1, r2, w);
    fd->calls++;
    const int dom = ALLFIN(r1, r2, w) && r1 > 0.0 && r2 > 0.0 && w >= 0.0;
    FZ_EXPECT(fd, dom ? F >= 0.0 && !isnan(F) : isnan(F), "NaN exactly outside the domain",
              "R1 %.17g R2 %.17g w %.17g: %.17g", r1, r2, w, F);
  }
  fz_done(fd);
  f = fz_new("dc_dmt_contact");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const dc_hertz_geom *g = &hpool[UI(nh)];
    const double E = A(U() < 0.7 ? fz_log(1e5, 1e12) : fz_wild()), w = A(U() < 0.7 ? fz_log(1e-4, 1.0) : fz_wild());
    const double d = A(U() < 0.7 ? g->R_minor * fz_sign(fz_log(1e-9, 1e-2)) : fz_wild());
    const int bad = !ALLFIN(E, w, d);
    dc_contact c;
    SENTINEL(c);
    const int st = dc_dmt_contact(g, E, w, d, &c);
    FZ_CHECK(f, st, bad, !bad && E > 0.0 && w >= 0.0, UNTOUCHED(c),
             ALLFIN(c.F, c.kn, c.area, c.a, c.b, c.F_bound) && (c.formed == (d > 0.0)) && c.F_bound >= 0.0,
             "R_major %.17g R_minor %.17g E %.17g w %.17g delta %.17g", g->R_major, g->R_minor, E, w, d);
    /* the force less the friction load is -2 F_po: F = F_bound - 2 F_po (halved: the sum may
       overflow where F_po is near DBL_MAX) */
    const double Fpo = dc_dmt_pulloff(g->R_major, g->R_minor, w);
    FZ_EXPECT(f, st != DC_OK || !c.formed ||
                 fabs(0.5 * c.F_bound - 0.5 * c.F - Fpo) <= 1e-12 * (0.5 * c.F_bound + 0.5 * Fpo) + DBL_TRUE_MIN,
              "friction load not F + 2 F_po", "delta %.17g w %.17g R %.17g %.17g E %.17g", d, w, g->R_major,
              g->R_minor, E);
  }
  fz_done(f);
}

/* ---------------------------------------------------------------- */
/* jkr_elliptic.h                                                     */

static int jkr_state_ok(const dc_jkr_state *s)
{
  return (s->contact == 0 || s->contact == 1) &&
         ALLFIN(s->F, s->delta, s->a, s->b, s->area, s->e2, s->kn);
}

static int jkr_geom_ok(const dc_jkr_geom *g)
{
  return (g->circular == 0 || g->circular == 1) && (g->use_m1 == 0 || g->use_m1 == 1) && FIN(g->hertz) &&
         ALLFIN(g->R_major, g->R_minor, g->Rhat, g->lambda, g->lam2, g->l2c, g->Estar, g->w, g->e2_hertz,
                g->a_scale, g->delta_scale, g->F_scale, g->e2_break, g->delta_break, g->F_break, g->dbar_break,
                g->e2_pull, g->delta_pull, g->F_pull, g->guess_c1, g->guess_c2, g->pert_X0, g->pert_X1,
                g->pert_g0, g->pert_g1, g->pert_P0, g->pert_P1, g->pert_rho0, g->dbar_switch, g->v_hertz,
                g->v_break);
}

#define JS_FMT "F %.17g delta %.17g a %.17g b %.17g area %.17g e2 %.17g kn %.17g contact %d"
#define JS_ARGS(s) (s).F, (s).delta, (s).a, (s).b, (s).area, (s).e2, (s).kn, (s).contact

/* typical work of adhesion for R, E*: the JKR length scale (w R^2/E*)^1/3
   from 1e-12 R to 10 R */
static double jkr_w(double R, double E)
{
  const double r = U();
  if (r < 0.1) return 0.0;
  if (r < 0.4) return fz_log(1e-3, 1.0);
  return E * R * pow(fz_log(1e-12, 10.0), 3.0) * (U() < 0.5 ? 1.0 : fz_log(1e-20, 1.0));
}

/* psi = a/a0 of the Hertz-like end (series, near polynomials, pieces up to
   a little beyond DC_JKR_NU_H): finite, >= 1, and a root of
   psi^2 = 1 + kappa psi^1/2 to 1e-15 of psi^2 (an independent check of
   the tables and of the series' coefficients) */
static void fuzz_jkr_psi(void)
{
  fz_fn *f = fz_new("dc_jkr_psi");
  double worst = 0.0;
  for (long k = 0; k < N_CALLS; k++) {
    const double r = U();
    const double nu = r < 0.3 ? fz_log(1e-30, DC_JKR_NU_S) : r < 0.6 ? DC_JKR_NU_S + (DC_JKR_NU_0 - DC_JKR_NU_S) * U()
                                                          : DC_JKR_NU_0 + (DC_JKR_NU_H + 1.0 - DC_JKR_NU_0) * U();
    const double kappa = sqrt(nu), psi = dc_jkr_psi(nu, kappa);
    f->calls++;
    const double res = fabs((psi * psi - 1.0) - kappa * sqrt(psi)) / (psi * psi);
    worst = fmax(worst, res);
    FZ_EXPECT(f, isfinite(psi) && psi >= 1.0 && res <= 1e-15, "not the root of psi^2 = 1 + kappa psi^1/2",
              "nu %.17g: psi %.17g, residual %.3g of psi^2", nu, psi, res);
  }
  fz_done(f);
  printf("dc_jkr_psi: largest residual %.2g of psi^2\n", worst);
}

static void fuzz_jkr_sphere(void)
{
  fz_fn *f = fz_new("dc_jkr_sphere");
  fz_fn *fa = fz_new("dc_jkr_sphere_at_radius");
  fz_fn *fp = fz_new("dc_jkr_sphere_pulloff");
  fz_fn *fb = fz_new("dc_jkr_sphere_delta_break");
  fz_fn *fh = fz_new("dc_jkr_sphere_near_hertz");
  fa->seconds = fp->seconds = fb->seconds = fh->seconds = 0.0;
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const double R = A(U() < 0.4 ? fz_log(1e-7, 1e-2) : fz_pos());
    const double E = A(U() < 0.4 ? fz_log(1e5, 1e12) : fz_pos());
    const double w = A(jkr_w(R, E));
    const double db = dc_jkr_sphere_delta_break(fabs(R), fabs(E), fabs(w));
    const double d = A(U() < 0.6 && isfinite(db) && db < 0.0 ? db * (U() < 0.3 ? PICK(1.0, 1.0 - 1e-12, 0.999) : -20.0 + 22.0 * U())
                       : U() < 0.1 ? PICK(0.0, -0.0) : fz_wide());
    const int bad = !ALLFIN(R, E, w, d);
    const int dom = !bad && R > 0.0 && E > 0.0 && w >= 0.0;
    dc_jkr_state s;
    SENTINEL(s);
    FZ_CHECK(f, dc_jkr_sphere(R, E, w, d, &s), bad, dom, UNTOUCHED(s), jkr_state_ok(&s),
             "R %.17g Estar %.17g w %.17g delta %.17g: " JS_FMT, R, E, w, d, JS_ARGS(s));
    /* the inline hot path: dc_jkr_sphere's bits wherever it applies, nothing
       written elsewhere */
    fh->seconds -= fz_now();
    {
      const dc_jkr_sphere_pair pr = dc_jkr_sphere_pair_of(E, w);
      double ah = -1.0, Fh = -1.0;
      fh->calls++;
      if (dc_jkr_sphere_near_hertz(&pr, R, d, &ah, &Fh))
        FZ_EXPECT(fh, s.contact == 1 && ah == s.a && Fh == s.F, "not the bits of dc_jkr_sphere",
                  "R %.17g Estar %.17g w %.17g delta %.17g: a %.17g F %.17g", R, E, w, d, ah, Fh);
      else
        FZ_EXPECT(fh, ah == -1.0 && Fh == -1.0, "output written where it does not apply",
                  "R %.17g Estar %.17g w %.17g delta %.17g", R, E, w, d);
    }
    fh->seconds += fz_now();
    /* at a radius: a from the JKR scale */
    fa->seconds -= fz_now();
    const double a = A(U() < 0.6 ? cbrt(fabs(w) * R * R / E) * fz_log(1e-6, 1e6) : fz_pos());
    SENTINEL(s);
    FZ_CHECK(fa, dc_jkr_sphere_at_radius(R, E, w, a, &s), !ALLFIN(R, E, w, a), dom && a > 0.0 && isfinite(a),
             UNTOUCHED(s), jkr_state_ok(&s), "R %.17g Estar %.17g w %.17g a %.17g: " JS_FMT, R, E, w, a, JS_ARGS(s));
    fa->seconds += fz_now();
    /* the two double-valued functions: never NaN inside the domain */
    fp->seconds -= fz_now();
    const double P = dc_jkr_sphere_pulloff(R, w);
    fp->calls++;
    if (dom) FZ_EXPECT(fp, !isnan(P), "NaN inside the domain", "R %.17g w %.17g", R, w);
    fp->seconds += fz_now();
    fb->seconds -= fz_now();
    const double B = dc_jkr_sphere_delta_break(R, E, w);
    fb->calls++;
    /* |delta_break| = 3/4 (pi^2 w^2 R / E*^2)^1/3: finite wherever that is */
    const double lb = lg(0.75) + (2.0 * lg(M_PI) + 2.0 * lg(w) + lg(R) - 2.0 * lg(E)) / 3.0;
    if (dom) FZ_EXPECT(fb, !isnan(B) && (isfinite(B) || lb > LOG_MAX - 1.0), "NaN, or not finite where representable",
                       "R %.17g Estar %.17g w %.17g: %.17g", R, E, w, B);
    fb->seconds += fz_now();
  }
  fz_done(f);
}

/* A law's parameter check (contract.h): DC_OK inside [lo, hi] (open ends
   as flagged), else DC_EDOM with the error report filled, which is its
   documented output for the error (see fuzz_param_check). */
static void fuzz_law_check(const char *name, int (*check)(double, dc_param_error *), double lo, int lo_open,
                           double hi, double typ_lo, double typ_hi)
{
  fz_fn *f = fz_new(name);
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const double x = A(U() < 0.5 ? fz_log(typ_lo, typ_hi) : U() < 0.5 ? fz_wide() : PICK(lo, hi, 0.0, -0.0, DBL_MAX));
    dc_param_error err;
    SENTINEL(err);
    const int st = check(x, &err);
    const int inside = isfinite(x) && (lo_open ? x > lo : x >= lo) && x <= hi;
    FZ_CHECK(f, st, !isfinite(x), inside, 1, UNTOUCHED(err), "value %.17g", x);
    FZ_EXPECT(f, st == (inside ? DC_OK : DC_EDOM) &&
                 (st == DC_OK || (err.name && err.range && memcmp(&err.value, &x, sizeof x) == 0)),
              "wrong status or no error report", "value %.17g: status %d", x, st);
  }
  fz_done(f);
}

static void fuzz_jkr_check(void)
{
  fuzz_law_check("dc_jkr_check", dc_jkr_check, 0.0, 0, DBL_MAX, 1e-6, 1.0);
  fuzz_law_check("dc_feng_check", dc_feng_check, DC_FENG_MU_MIN, 0, DC_FENG_MU_MAX, 1.0, 50.0);
  fuzz_law_check("dc_gw_rough_check", dc_gw_rough_check, 0.0, 1, DBL_MAX, 1e-2, 1e6);
  fz_fn *fl = fz_new("dc_jkr_friction_load");
  for (long k = 0; k < N_CALLS; k++) {
    const double F = fz_wide(), P = fz_wide(), L = dc_jkr_friction_load(F, P);
    fl->calls++;
    FZ_EXPECT(fl, !memcmp(&L, &(double){F + 2.0 * P}, sizeof L), "not F + 2 F_pulloff", "%.17g %.17g", F, P);
  }
  fz_done(fl);
}

static void fuzz_jkr_geometry(void)
{
  fz_fn *f = fz_new("dc_jkr_geometry");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const double R1 = U() < 0.5 ? fz_log(1e-7, 1e-2) : fz_pos();
    const double r = U();
    double R2 = R1 * (r < 0.4 ? fz_log(DC_JKR_RATIO_MIN, 1.0) : r < 0.6 ? 1.0 - fz_log(1e-17, 1e-3)
                      : r < 0.7 ? 1.0 : PICK(DC_JKR_RATIO_MIN, 0.5, 1e-7));
    if (U() < 0.1) R2 = fz_pos();
    const double E = A(U() < 0.5 ? fz_log(1e5, 1e12) : fz_pos());
    const double w = A(jkr_w(R1, E));
    const double a1 = A(R1), a2 = A(R2);
    const int bad = !ALLFIN(a1, a2, E, w);
    const int dom = !bad && a1 > 0.0 && a2 > 0.0 && fmin(a1, a2) / fmax(a1, a2) >= DC_JKR_RATIO_MIN && E > 0.0 && w >= 0.0;
    dc_jkr_geom g;
    SENTINEL(g);
    const int st = dc_jkr_geometry(a1, a2, E, w, &g);
    FZ_CHECK(f, st, bad, dom, UNTOUCHED(g), jkr_geom_ok(&g), "R1 %.17g R2 %.17g Estar %.17g w %.17g", a1, a2, E, w);
    if (st == DC_OK && jkr_geom_ok(&g)) pool_jkr(&g);
  }
  fz_done(f);
}

static void fuzz_jkr_contact(void)
{
  fz_fn *fe = fz_new("dc_jkr_at_eccentricity");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const dc_jkr_geom *g = &jpool[UI(nj)];
    const double r = U();
    double e2 = r < 0.4 ? g->e2_hertz * U() : r < 0.6 ? g->e2_hertz * fz_log(1e-30, 1.0)
                : r < 0.8 ? g->e2_hertz * (1.0 - fz_log(1e-17, 1.0)) : PICK(0.0, g->e2_hertz, g->e2_break, g->e2_pull, 1e-17);
    e2 = A(e2);
    const int dom = !g->circular && g->w > 0.0 && e2 > 0.0 && e2 < g->e2_hertz;
    dc_jkr_state s;
    SENTINEL(s);
    FZ_CHECK(fe, dc_jkr_at_eccentricity(g, e2, &s), !isfinite(e2), dom, UNTOUCHED(s), jkr_state_ok(&s),
             "R_major %.17g R_minor %.17g Estar %.17g w %.17g e2 %.17g (e2_hertz %.17g): " JS_FMT, g->R_major,
             g->R_minor, g->Estar, g->w, e2, g->e2_hertz, JS_ARGS(s));
  }
  fz_done(fe);
  fz_fn *f = fz_new("dc_jkr_contact");
  fz_fn *fi = fz_new("dc_jkr_in_contact");
  fz_fn *fn = fz_new("dc_jkr_normal");
  fi->seconds = fn->seconds = 0.0;
  dc_jkr_hint warm = {0, 0, 0};
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const dc_jkr_geom *g = &jpool[UI(nj)];
    const double sc = g->delta_scale > 0.0 ? g->delta_scale : g->R_minor;
    const double r = U();
    double d = r < 0.5 ? sc * fz_sign(fz_log(1e-20, 1e20)) : r < 0.7 ? g->delta_break * PICK(1.0, 0.5, 2.0, -1.0)
               : r < 0.8 ? PICK(0.0, -0.0, g->delta_pull) : fz_wide();
    d = A(d);
    /* hint: none, zero, the last call's, or any content (documented safe) */
    dc_jkr_hint h = warm, *hp = &h;
    const double rh = U();
    if (rh < 0.25) hp = NULL;
    else if (rh < 0.4) h.v = h.L = h.dudL = 0.0;
    else if (rh < 0.6) { h.v = fz_wild(); h.L = fz_wild(); h.dudL = fz_wild(); }
    else if (rh < 0.7) { h.v = U(); h.L = 60.0 * U() - 30.0; h.dudL = U() < 0.5 ? fz_wide() : 2.0 * U(); }
    const dc_jkr_hint h0 = h;
    struct { dc_jkr_state s; dc_jkr_hint h; } out;
    SENTINEL(out.s);
    const int st = dc_jkr_contact(g, d, hp, &out.s);
    out.h = h;
    const int hint_same = memcmp(&h, &h0, sizeof h) == 0;
    FZ_CHECK(f, st, !isfinite(d), isfinite(d), UNTOUCHED(out.s) && hint_same, jkr_state_ok(&out.s),
             "R_major %.17g R_minor %.17g Estar %.17g w %.17g delta %.17g hint %s (%.17g, %.17g, %.17g): " JS_FMT,
             g->R_major, g->R_minor, g->Estar, g->w, d, hp ? "yes" : "NULL", h0.v, h0.L, h0.dudL, JS_ARGS(out.s));
    if (st == DC_OK && hp) warm = h;
    {
      /* the contract output of the state (or, after a failure, of any state):
         a copy, friction load F + 2 F_pulloff while in contact */
      fn->seconds -= fz_now();
      dc_jkr_state js = out.s;
      double Fp = -g->F_pull;
      if (st != DC_OK) {
        js = (dc_jkr_state){UI(2), fz_wild(), fz_wild(), fz_wild(), fz_wild(), fz_wild(), fz_wild(), fz_wild()};
        Fp = fz_wild();
      }
      dc_contact c;
      SENTINEL(c);
      dc_jkr_normal(&js, Fp, &c);
      fn->calls++;
      const double Fb = js.contact ? js.F + 2.0 * Fp : 0.0;
      FZ_EXPECT(fn, !memcmp(&c.F, &js.F, sizeof c.F) && !memcmp(&c.kn, &js.kn, sizeof c.kn) &&
                    !memcmp(&c.area, &js.area, sizeof c.area) && !memcmp(&c.a, &js.a, sizeof c.a) &&
                    !memcmp(&c.b, &js.b, sizeof c.b) && c.formed == js.contact && !memcmp(&c.F_bound, &Fb, sizeof Fb) &&
                    (st != DC_OK || !isfinite(Fb) || contact_ok(&c)),
                "not the state's contract output", "delta %.17g F_pulloff %.17g", d, Fp);
      fn->seconds += fz_now();
    }
    fi->seconds -= fz_now();
    const int c = dc_jkr_in_contact(g, UI(2), d);
    fi->calls++;
    FZ_EXPECT(fi, c == 0 || c == 1, "not 0 or 1", "delta %.17g", d);
    fi->seconds += fz_now();
  }
  fz_done(f);
}

/* ---------------------------------------------------------------- */
/* gw_rough_adhesive.h                                                */

static void fuzz_gw_rough_adhesive(void)
{
  fz_fn *f = fz_new("dc_gw_rough_adhesive");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const dc_jkr_geom *g = &jpool[UI(nj)];
    const double n = A(U() < 0.5 ? fz_log(1e-2, 1e6) : fz_pos());
    const double Db = fabs(g->delta_break) > 0.0 ? fabs(g->delta_break) : g->R_minor * 1e-6;
    const double sg = A(U() < 0.6 ? Db * fz_log(1e-3, 1e3) : U() < 0.3 ? PICK(0.0, DBL_TRUE_MIN, DBL_MIN) : fz_pos());
    const double d = A(U() < 0.6 ? sg * (-12.0 + 30.0 * U()) : U() < 0.3 ? Db * (-3.0 + 6.0 * U()) : fz_wide());
    const int br = AI(UI(2));
    const int bad = !ALLFIN(n, sg, d);
    dc_gw_adhesive_state s;
    SENTINEL(s);
    const int st = dc_gw_rough_adhesive(g, n, sg, d, br, &s);
    FZ_CHECK(f, st, bad, !bad && n > 0.0 && sg >= 0.0 && (br == 0 || br == 1), UNTOUCHED(s),
             ALLFIN(s.F, s.area, s.kn, s.h, s.err) && s.n_eval >= 0,
             "R_major %.17g R_minor %.17g Estar %.17g w %.17g n_asp %.17g sigma %.17g delta %.17g branch %d",
             g->R_major, g->R_minor, g->Estar, g->w, n, sg, d, br);
  }
  fz_done(f);
}

/* ---------------------------------------------------------------- */
/* dissipation_adhesive.h                                             */

static void fuzz_dissipation(void)
{
  fz_fn *f = fz_new("dc_dissip_adhesive_ab");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const double Am = A(U() < 0.4 ? fz_log(1e-9, 1e-3) : U() < 0.1 ? 0.0 : fz_pos());
    const double E = A(U() < 0.4 ? fz_log(1e5, 1e12) : fz_pos());
    const double a = A(U() < 0.4 ? fz_log(1e-9, 1e-3) : fz_pos());
    const double b = A(U() < 0.2 ? a : a * (U() < 0.5 ? U() : fz_log(1e-300, 1.0)));
    const double dd = A(U() < 0.5 ? fz_sign(fz_log(1e-6, 10.0)) : fz_wide());
    const int bad = !ALLFIN(Am, E, a, b, dd);
    double F;
    SENTINEL(F);
    FZ_CHECK(f, dc_dissip_adhesive_ab(Am, E, a, b, dd, &F), bad, !bad && Am >= 0.0 && E > 0.0 && b > 0.0 && b <= a,
             UNTOUCHED(F), isfinite(F), "A %.17g Estar %.17g a %.17g b %.17g ddelta %.17g", Am, E, a, b, dd);
  }
  fz_done(f);
  f = fz_new("dc_dissip_adhesive_state");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const double Am = A(U() < 0.4 ? fz_log(1e-9, 1e-3) : fz_pos());
    const double E = A(U() < 0.4 ? fz_log(1e5, 1e12) : fz_pos());
    const double dd = A(U() < 0.5 ? fz_sign(fz_log(1e-6, 10.0)) : fz_wide());
    dc_jkr_state s;
    memset(&s, 0, sizeof s);
    if (U() < 0.5 && nj > 0) {
      const dc_jkr_geom *g = &jpool[UI(nj)];
      dc_jkr_contact(g, (g->delta_scale > 0.0 ? g->delta_scale : g->R_minor) * (-2.0 + 10.0 * U()), NULL, &s);
    } else {
      s.contact = U() < 0.8 ? 1 : UI(3) - 1;
      s.a = A(U() < 0.5 ? fz_log(1e-9, 1e-3) : fz_pos());
      s.b = A(U() < 0.3 ? s.a : s.a * U());
    }
    const int bad = !ALLFIN(Am, E, dd) || (s.contact && !ALLFIN(s.a, s.b));
    double F;
    SENTINEL(F);
    FZ_CHECK(f, dc_dissip_adhesive_state(Am, E, &s, dd, &F), bad,
             !bad && Am >= 0.0 && E > 0.0 && (!s.contact || (s.a > 0.0 && s.b > 0.0 && s.b <= s.a)), UNTOUCHED(F),
             isfinite(F), "A %.17g Estar %.17g contact %d a %.17g b %.17g ddelta %.17g", Am, E, s.contact, s.a, s.b, dd);
  }
  fz_done(f);
  f = fz_new("dc_dissip_adhesive_radius_rate");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const double Am = A(U() < 0.4 ? fz_log(1e-9, 1e-3) : fz_pos());
    const double R = A(U() < 0.4 ? fz_log(1e-7, 1e-2) : fz_pos());
    const double E = A(U() < 0.4 ? fz_log(1e5, 1e12) : fz_pos());
    const double w = A(U() < 0.2 ? 0.0 : U() < 0.5 ? fz_log(1e-3, 1.0) : fz_pos());
    const double a = A(U() < 0.4 ? R * fz_log(1e-6, 1.0) : fz_pos());
    const double da = A(U() < 0.5 ? fz_sign(fz_log(1e-6, 10.0)) : fz_wide());
    const int bad = !ALLFIN(Am, R, E, w, a, da);
    double F;
    SENTINEL(F);
    FZ_CHECK(f, dc_dissip_adhesive_radius_rate(Am, R, E, w, a, da, &F), bad,
             !bad && Am >= 0.0 && R > 0.0 && E > 0.0 && w >= 0.0 && a > 0.0, UNTOUCHED(F), isfinite(F),
             "A %.17g R %.17g Estar %.17g w %.17g a %.17g da/dt %.17g", Am, R, E, w, a, da);
  }
  fz_done(f);
  f = fz_new("dc_jkr_sphere_viscoelastic");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const double R = A(U() < 0.5 ? fz_log(1e-7, 1e-2) : fz_pos());
    const double E = A(U() < 0.5 ? fz_log(1e5, 1e12) : fz_pos());
    const double w = A(jkr_w(R, E));
    const double Am = A(U() < 0.5 ? fz_log(1e-9, 1e-3) : U() < 0.2 ? 0.0 : fz_pos());
    const double db = dc_jkr_sphere_delta_break(fabs(R), fabs(E), fabs(w));
    const double d = A(U() < 0.6 && isfinite(db) && db < 0.0 ? db * (-20.0 + 22.0 * U()) : fz_wide());
    const double dd = A(U() < 0.5 ? fz_sign(fz_log(1e-6, 10.0)) : fz_wide());
    const int bad = !ALLFIN(R, E, w, Am, d, dd);
    struct { dc_jkr_state s; double F; } out;
    SENTINEL(out);
    const int st = dc_jkr_sphere_viscoelastic(R, E, w, Am, d, dd, &out.s, &out.F);
    FZ_CHECK(f, st, bad, !bad && R > 0.0 && E > 0.0 && w >= 0.0 && Am >= 0.0, UNTOUCHED(out),
             jkr_state_ok(&out.s) && isfinite(out.F),
             "R %.17g Estar %.17g w %.17g A %.17g delta %.17g ddelta %.17g", R, E, w, Am, d, dd);
  }
  fz_done(f);
}

/* ---------------------------------------------------------------- */
/* contract.h                                                         */

/* dc_param_check and dc_jkr_check fill their dc_param_error on DC_EDOM:
   that report is their documented output for the error (contract.h), an
   exception to status.h's "outputs untouched" that these checks allow and
   verify instead. */
static void fuzz_param_check(void)
{
  fz_fn *f = fz_new("dc_param_check");
  static const char *names[2] = {"youngsModulus", "x"}, *ranges[2] = {"(0, inf)", "[a, b]"};
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    double lo = U() < 0.5 ? PICK(0.0, -1.0, 1.0, -INFINITY, -0.0) : fz_wide();
    double hi = U() < 0.5 ? PICK(1.0, 0.5, 50.0, INFINITY) : fz_wide();
    if (lo > hi) { const double t = lo; lo = hi; hi = t; }
    if (U() < 0.05) lo = NAN;
    const int lo_open = UI(2), hi_open = UI(2);
    const double v = A(U() < 0.3 ? PICK(lo, hi) : isfinite(lo) && isfinite(hi) ? lo + (hi - lo) * U() : fz_wide());
    const char *nm = names[UI(2)], *rg = ranges[UI(2)];
    dc_param_error err;
    SENTINEL(err);
    const int st = dc_param_check(nm, v, lo, lo_open, hi, hi_open, rg, &err);
    const int inside = isfinite(v) && (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
    FZ_CHECK(f, st, !isfinite(v), inside, 1, 1, "value %.17g lo %.17g (%d) hi %.17g (%d)", v, lo, lo_open, hi, hi_open);
    FZ_EXPECT(f, st == (inside ? DC_OK : DC_EDOM) &&
                 (st == DC_OK ? UNTOUCHED(err) : err.name == nm && err.range == rg && memcmp(&err.value, &v, sizeof v) == 0),
              "wrong status or error report", "value %.17g lo %.17g (%d) hi %.17g (%d): status %d", v, lo, lo_open, hi,
              hi_open, st);
  }
  fz_done(f);
  f = fz_new("dc_param_error_format");
  for (long k = 0; k < N_CALLS; k++) {
    dc_param_error err = {names[UI(2)], fz_wild(), ranges[UI(2)]};
    char buf[96];
    const size_t n = (size_t)UI(80);
    memset(buf, 0x5A, sizeof buf);
    dc_param_error_format(&err, UI(20) - 1, UI(20) - 1, buf, n);
    f->calls++;
    int ok = 1;
    for (size_t i = n; i < sizeof buf; i++) ok &= buf[i] == 0x5A;
    if (n > 0) ok &= memchr(buf, 0, n) != NULL;
    FZ_EXPECT(f, ok, "wrote past n or no terminating NUL", "n %zu value %.17g", n, err.value);
  }
  fz_done(f);
}

static void fuzz_patch(void)
{
  fz_fn *f = fz_new("dc_patch_circular");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const double R = A(U() < 0.4 ? fz_log(1e-6, 1.0) : fz_pos());
    const double d = A(U() < 0.4 ? R * fz_sign(fz_log(1e-12, 1.0)) : U() < 0.1 ? PICK(0.0, -0.0) : fz_wide());
    const double F = A(U() < 0.5 ? fz_sign(fz_log(1e-12, 1e6)) : fz_wide());
    dc_patch p;
    SENTINEL(p);
    dc_patch_circular(R, d, F, &p);
    f->calls++;
    if (!(ALLFIN(R, d, F) && R > 0.0)) continue;
    FZ_EXPECT(f, FIN(p) && p.a == p.b && p.a >= 0.0 && (p.a > 0.0) == (d > 0.0) && p.F_elastic == F &&
                 p.F_bound == fmax(F, 0.0) && p.formed == (d > 0.0) && p.axis[0] == 0.0 && p.axis[1] == 0.0 &&
                 p.axis[2] == 0.0,
              "not the finite circular patch", "R %.17g delta %.17g F %.17g: a %.17g", R, d, F, p.a);
  }
  fz_done(f);
  f = fz_new("dc_patch_from_contact");
  for (long k = 0; k < N_CALLS; k++) {
    dc_contact c = {fz_wild(), fz_wild(), fz_wild(), fz_wild(), fz_wild(), fz_wild(), UI(2)};
    double axis[3] = {fz_wild(), fz_wild(), fz_wild()};
    const int null = UI(2);
    dc_patch p;
    SENTINEL(p);
    dc_patch_from_contact(&c, null ? NULL : axis, &p);
    f->calls++;
    const double ax[3] = {null ? 0.0 : axis[0], null ? 0.0 : axis[1], null ? 0.0 : axis[2]};
    FZ_EXPECT(f, !memcmp(&p.a, &c.a, sizeof p.a) && !memcmp(&p.b, &c.b, sizeof p.b) &&
                 !memcmp(&p.F_elastic, &c.F, sizeof c.F) && !memcmp(&p.F_bound, &c.F_bound, sizeof c.F_bound) &&
                 !memcmp(p.axis, ax, sizeof ax) && p.formed == (c.formed ? 1.0 : 0.0),
              "not a copy of the contact", "call %ld", k);
  }
  fz_done(f);
}

/* ---------------------------------------------------------------- */
/* damping.h                                                          */

static void fuzz_damping(void)
{
  fz_fn *f = fz_new("dc_damping_beta");
  fz_fn *fr = fz_new("dc_damping_restitution");
  fr->seconds = 0.0;
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const double e = A(U() < 0.6 ? U() : U() < 0.5 ? fz_log(1e-320, 1.0) : PICK(0.0, 1.0, DBL_TRUE_MIN, 1.0 + DBL_EPSILON));
    double b;
    SENTINEL(b);
    const int st = dc_damping_beta(e, &b);
    FZ_CHECK(f, st, !isfinite(e), e > 0.0 && e <= 1.0, UNTOUCHED(b), isfinite(b) && b <= 0.0 && b > -1.0,
             "e %.17g", e);
    if (st != DC_OK) dc_damping_beta(U() < 0.5 ? 1.0 - U() : fz_log(1e-300, 1.0), &b);
    /* the inline damping coefficient: finite and >= 0 where S m is */
    fr->seconds -= fz_now();
    const double S = U() < 0.5 ? fz_log(1e-3, 1e9) : fz_log(1e-300, 1e300), m = U() < 0.5 ? fz_log(1e-12, 1.0) : fz_log(1e-300, 1e300);
    const double g = dc_damping_restitution(b, S, m);
    fr->calls++;
    if (isfinite(S * m)) FZ_EXPECT(fr, isfinite(g) && g >= 0.0, "not finite and >= 0", "beta %.17g S %.17g m %.17g: %.17g", b, S, m, g);
    fr->seconds += fz_now();
  }
  fz_done(f);
  f = fz_new("dc_damping_viscoelastic");
  fz_fn *fc = fz_new("dc_punch_stiffness_circle");
  for (long k = 0; k < N_CALLS; k++) {
    const double x = fz_wide(), y = fz_wide();
    const double g = dc_damping_viscoelastic(x, y), c = dc_punch_stiffness_circle(x, y);
    f->calls++;
    fc->calls++;
    FZ_EXPECT(f, !memcmp(&g, &(double){x * y}, sizeof g), "not A S", "%.17g %.17g", x, y);
    FZ_EXPECT(fc, !memcmp(&c, &(double){2.0 * x * y}, sizeof c), "not 2 E* a", "%.17g %.17g", x, y);
  }
  fz_done(f);
  fz_done(fc);
  f = fz_new("dc_punch_stiffness");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const double E = A(U() < 0.4 ? fz_log(1e5, 1e12) : fz_pos());
    const double a = A(U() < 0.4 ? fz_log(1e-9, 1e-3) : fz_pos());
    const double b = A(U() < 0.2 ? a : a * (U() < 0.5 ? U() : fz_log(1e-320, 1.0)));
    const int bad = !ALLFIN(E, a, b);
    double kp;
    SENTINEL(kp);
    const int st = dc_punch_stiffness(E, a, b, &kp);
    FZ_CHECK(f, st, bad, !bad && E > 0.0 && b > 0.0 && a >= b, UNTOUCHED(kp), isfinite(kp) && kp >= 0.0,
             "Estar %.17g a %.17g b %.17g", E, a, b);
    /* k <= 2 E* a */
    FZ_EXPECT(f, st != DC_ERANGE || lg(2.0) + lg(E) + lg(a) > LOG_MAX - 1.0, "DC_ERANGE for a representable stiffness",
              "Estar %.17g a %.17g b %.17g", E, a, b);
  }
  fz_done(f);
}

/* ---------------------------------------------------------------- */
/* mindlin.h                                                          */

static void fuzz_mindlin(void)
{
  fz_fn *f = fz_new("dc_mindlin_pair_init");
  fz_fn *fs = fz_new("dc_mindlin_stiffness");
  fz_fn *fk = fz_new("dc_mindlin_kt_circle");
  fz_fn *fg = fz_new("dc_mindlin_pair_gstar");
  fz_fn *fe = fz_new("dc_mindlin_pair_estar");
  fs->seconds = fk->seconds = fg->seconds = fe->seconds = 0.0;
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    double v[4];
    for (int i = 0; i < 2; i++) {
      v[2 * i] = A(U() < 0.5 ? fz_log(1e5, 1e12) : fz_pos());
      v[2 * i + 1] = A(U() < 0.7 ? -1.0 + 1.5 * U() : PICK(-1.0, 0.5, 0.0, -0.0, 0.6));
    }
    const int bad = !fin(v, 4);
    dc_mindlin_pair p;
    SENTINEL(p);
    const int st = dc_mindlin_pair_init(v[0], v[1], v[2], v[3], &p);
    FZ_CHECK(f, st, bad, !bad && v[0] > 0.0 && v[2] > 0.0 && v[1] > -1.0 && v[1] <= 0.5 && v[3] > -1.0 && v[3] <= 0.5,
             UNTOUCHED(p), FIN(p) && p.s0 > 0.0, "E1 %.17g nu1 %.17g E2 %.17g nu2 %.17g", v[0], v[1], v[2], v[3]);
    /* G* and E* of the pair against their sums over the bodies (where the
       compliances stay far from overflow) */
    if (st == DC_OK && p.s0 < 1e300) {
      const double g1 = v[0] / (2.0 * (1.0 + v[1])), g2 = v[2] / (2.0 * (1.0 + v[3]));
      const double gw = 1.0 / ((2.0 - v[1]) / g1 + (2.0 - v[3]) / g2);
      const double ew = 1.0 / ((1.0 - v[1] * v[1]) / v[0] + (1.0 - v[3] * v[3]) / v[2]);
      const double gs = dc_mindlin_pair_gstar(&p), es = dc_mindlin_pair_estar(&p);
      fg->calls++;
      fe->calls++;
      FZ_EXPECT(fg, fabs(gs - gw) <= 1e-12 * gw, "not 1/sum (2 - nu_i)/G_i", "%.17g %.17g %.17g %.17g: %.17g %.17g",
                v[0], v[1], v[2], v[3], gs, gw);
      FZ_EXPECT(fe, fabs(es - ew) <= 1e-12 * ew, "not 1/sum (1 - nu_i^2)/E_i",
                "%.17g %.17g %.17g %.17g: %.17g %.17g", v[0], v[1], v[2], v[3], es, ew);
    }
    /* the stiffnesses on this pair (or on raw values), K and D of an ellipse */
    fs->seconds -= fz_now();
    fz_call();
    if (st != DC_OK || U() < 0.1) { p.s0 = A(fz_pos()); p.s1 = A(fz_wide()); }
    dc_ellint el;
    dc_ellint_m1(U() < 0.5 ? U() : fz_log(1e-300, 1.0), &el);
    const double a = A(U() < 0.5 ? fz_log(1e-9, 1e-3) : U() < 0.1 ? 0.0 : fz_pos());
    const double K = A(el.K), D = A(el.D);
    const int bs = !ALLFIN(a, K, D, p.s0, p.s1);
    double km[2];
    SENTINEL(km);
    const int ss = dc_mindlin_stiffness(&p, a, K, D, &km[0], &km[1]);
    FZ_CHECK(fs, ss, bs, !bs && a >= 0.0 && K > 0.0 && D > 0.0 && p.s0 > 0.0, UNTOUCHED(km), FIN(km),
             "s0 %.17g s1 %.17g a %.17g K %.17g D %.17g", p.s0, p.s1, a, K, D);
    fs->seconds += fz_now();
    fk->seconds -= fz_now();
    const double G = fz_wide(), r = fz_wide(), kt = dc_mindlin_kt_circle(G, r);
    fk->calls++;
    FZ_EXPECT(fk, !memcmp(&kt, &(double){8.0 * G * r}, sizeof kt), "not 8 G* a", "%.17g %.17g", G, r);
    fk->seconds += fz_now();
  }
  fz_done(f);
}

/* ---------------------------------------------------------------- */
/* cmd_tangential.h                                                    */


/* a material pair inside dc_mindlin_pair_init's range (s0 > 0, -s0 < s1 <= s0/2) */
static dc_mindlin_pair cmd_pair(void)
{
  const double s0 = U() < 0.6 ? fz_log(1e-12, 1e-8) : fz_pos();
  return (dc_mindlin_pair){s0, s0 * (U() < 0.1 ? PICK(0.5, -0.999999, 0.0) : -0.9 + 1.4 * U())};
}

static int cmd_pair_ok(const dc_mindlin_pair *m)
{
  return ALLFIN(m->s0, m->s1) && m->s0 > 0.0 && m->s1 > -m->s0 && m->s1 <= 0.5 * m->s0;
}

static int cmd_axes_ok(double a, double b) { return ALLFIN(a, b) && b > 0.0 && b <= a && b >= 1e-150 * a; }

/* One step's inputs of a Cattaneo-Mindlin law along a contact (the normal
   n0 turning slowly, or jumping): bad, a non-finite input; dom, inside the
   documented domain (not with a corrupted history). */
typedef struct {
  dc_cmd_params p;
  dc_mindlin_pair m;
  dc_patch pa;
  double n[3], du[3], dphi, dt;
  int bad, dom;
} cmd_inputs;

static void cmd_fuzz_inputs(double n0[3], int corrupt, cmd_inputs *in)
{
  in->p = (dc_cmd_params){A(U() < 0.9 ? U() : 0.0), A(U() < 0.7 ? fz_log(1e-9, 1e-3) : 0.0), AI(U() < 0.5), AI(U() < 0.5)};
  const dc_cmd_params p = in->p;
  const dc_mindlin_pair m0 = cmd_pair();
  const dc_mindlin_pair m = {A(m0.s0), A(m0.s1)};
  in->m = m;
  /* the normal turns slowly, or jumps */
  double *n = in->n;
  if (U() < 0.05) unit_vector(n0);
  else {
    for (int i = 0; i < 3; i++) n0[i] += 0.01 * (U() - 0.5);
    const double l = sqrt(dot3(n0, n0));
    for (int i = 0; i < 3; i++) n0[i] /= l;
  }
  for (int i = 0; i < 3; i++) n[i] = A(n0[i]);
  dc_patch *pa = &in->pa;
  const double a = A(U() < 0.6 ? fz_log(1e-7, 1e-3) : U() < 0.1 ? 0.0 : fz_pos());
  pa->a = a;
  pa->b = A(U() < 0.3 ? a : a * (U() < 0.7 ? 0.05 + 0.95 * U() : fz_log(1e-160, 1.0)));
  double ax[3];
  unit_vector(ax);
  for (int i = 0; i < 3; i++) pa->axis[i] = A(U() < 0.05 ? 0.0 : ax[i]);
  pa->F_bound = A(U() < 0.05 ? 0.0 : U() < 0.7 ? fz_log(1e-6, 1e3) : fz_pos());
  pa->F_elastic = pa->F_bound;
  pa->formed = A(U() < 0.02 ? 0.0 : 1.0);
  const double scale = 1.5 * p.mu * pa->F_bound * m.s0 / (8.0 * a + 1e-300);
  double *du = in->du;
  for (int i = 0; i < 3; i++) du[i] = A(U() < 0.7 ? scale * fz_sign(fz_log(1e-6, 1e2)) : U() < 0.1 ? 0.0 : fz_wide());
  in->dphi = A(U() < 0.7 ? scale / (a + 1e-300) * fz_sign(fz_log(1e-6, 1e2)) : fz_wide());
  in->dt = A(U() < 0.8 ? fz_log(1e-8, 1e-3) : PICK(0.0, -1e-6));
  const double dphi = in->dphi, dt = in->dt;
  /* the promises */
  const int bad = !ALLFIN(p.mu, a, pa->b, pa->axis[0], pa->axis[1], pa->axis[2], pa->F_bound, pa->formed, n[0], n[1],
                          n[2], du[0], du[1], du[2], m.s0, m.s1) ||
                  (p.twisting && !isfinite(dphi)) || (p.dissipation && !ALLFIN(dt, p.t_visc));
  const double nn = dot3(n, n);
  double axn = 0.0, axl = 0.0;
  if (!bad) { axn = dot3(pa->axis, n); axl = dot3(pa->axis, pa->axis); }
  const int axis_ok = pa->b >= (1.0 - 1e-6) * a || (fabs(axl - 1.0) < 1e-6 && fabs(axn) < 0.99);
  in->bad = bad;
  in->dom = !bad && !corrupt && p.mu >= 0.0 && p.t_visc >= 0.0 && (p.dissipation == 0 || p.dissipation == 1) &&
            (p.twisting == 0 || p.twisting == 1) && cmd_pair_ok(&m) && pa->F_bound >= 0.0 &&
            (a == 0.0 ? pa->b == 0.0 : cmd_axes_ok(a, pa->b)) && fabs(nn - 1.0) <= 1e-6 &&
            (!p.dissipation || dt > 0.0) && axis_ok;
}

static void fuzz_cmd(void)
{
  fz_fn *f = fz_new("dc_cmd_check");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    dc_cmd_params p = {A(U() < 0.7 ? U() : PICK(0.0, -0.0, 1e300, -1e-300)), A(U() < 0.7 ? fz_log(1e-9, 1e-3) : 0.0),
                       AI(UI(2)), AI(UI(2))};
    dc_param_error err;
    SENTINEL(err);
    const int st = dc_cmd_check(&p, &err);
    const int inside = ALLFIN(p.mu, p.t_visc) && p.mu >= 0.0 && p.t_visc >= 0.0 && (p.dissipation == 0 || p.dissipation == 1) &&
                       (p.twisting == 0 || p.twisting == 1);
    FZ_CHECK(f, st, !ALLFIN(p.mu, p.t_visc), inside, 1, 1, "mu %.17g t_visc %.17g flags %d %d", p.mu, p.t_visc,
             p.dissipation, p.twisting);
    FZ_EXPECT(f, st == (inside ? DC_OK : DC_EDOM) && (st == DC_OK ? UNTOUCHED(err) : err.name != NULL && err.range != NULL),
              "wrong status or error report", "mu %.17g t_visc %.17g flags %d %d: status %d", p.mu, p.t_visc,
              p.dissipation, p.twisting, st);
  }
  fz_done(f);

  fz_fn *fs = fz_new("dc_cmd_stiffness");
  fz_fn *ft = fz_new("dc_cmd_twist_stiffness");
  fz_fn *fm = fz_new("dc_cmd_twist_slip_moment");
  ft->seconds = fm->seconds = 0.0;
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    dc_mindlin_pair m = cmd_pair();
    if (U() < 0.05) { m.s0 = A(fz_wide()); m.s1 = A(fz_wide()); }
    m.s0 = A(m.s0);
    const double a = A(U() < 0.5 ? fz_log(1e-9, 1e-2) : fz_pos());
    const double b = A(U() < 0.3 ? a : a * (U() < 0.6 ? U() : fz_log(1e-160, 1.0)));
    const int dom = cmd_pair_ok(&m) && cmd_axes_ok(a, b), bad = !ALLFIN(m.s0, m.s1, a, b);
    double kk[2];
    SENTINEL(kk);
    int st = dc_cmd_stiffness(&m, a, b, &kk[0], &kk[1]);
    FZ_CHECK(fs, st, bad, dom, UNTOUCHED(kk), FIN(kk) && kk[0] >= 0.0 && kk[1] >= 0.0,
             "s0 %.17g s1 %.17g a %.17g b %.17g", m.s0, m.s1, a, b);
    /* k <= 8 a / s0 */
    FZ_EXPECT(fs, st != DC_ERANGE || lg(8.0) + lg(a) - lg(m.s0) > LOG_MAX - 1.0, "DC_ERANGE for a representable stiffness",
              "s0 %.17g a %.17g", m.s0, a);
    ft->seconds -= fz_now();
    double kt;
    SENTINEL(kt);
    st = dc_cmd_twist_stiffness(&m, a, b, &kt);
    FZ_CHECK(ft, st, bad, dom, UNTOUCHED(kt), isfinite(kt) && kt >= 0.0, "s0 %.17g s1 %.17g a %.17g b %.17g", m.s0, m.s1, a, b);
    /* k <= 16/3 a^3 / s0 times a few */
    FZ_EXPECT(ft, st != DC_ERANGE || lg(16.0) + 3.0 * lg(a) - lg(m.s0) > LOG_MAX - 2.0,
              "DC_ERANGE for a representable stiffness", "s0 %.17g a %.17g", m.s0, a);
    ft->seconds += fz_now();
    fm->seconds -= fz_now();
    const double mu = A(U() < 0.8 ? U() : 0.0), F = A(U() < 0.6 ? fz_log(1e-9, 1e3) : fz_pos());
    double M;
    SENTINEL(M);
    st = dc_cmd_twist_slip_moment(mu, F, a, b, &M);
    FZ_CHECK(fm, st, !ALLFIN(mu, F, a, b), ALLFIN(mu, F) && mu >= 0.0 && F >= 0.0 && cmd_axes_ok(a, b), UNTOUCHED(M),
             isfinite(M) && M >= 0.0, "mu %.17g F %.17g a %.17g b %.17g", mu, F, a, b);
    FZ_EXPECT(fm, st != DC_ERANGE || lg(mu) + lg(F) + lg(a) > LOG_MAX - 1.0, "DC_ERANGE for a representable moment",
              "mu %.17g F %.17g a %.17g", mu, F, a);
    fm->seconds += fz_now();
  }
  fz_done(fs);

  /* the step: chains of calls on one history (a contact), its inputs now
     and then wild; now and then a fresh or a corrupted history */
  f = fz_new("dc_cmd_step");
  fz_fn *ftr = fz_new("dc_cmd_step_trusted");
  ftr->seconds = 0.0;
  dc_cmd_state h;
  memset(&h, 0, sizeof h);
  int corrupt = 0;
  double n0[3] = {0.0, 0.0, 1.0};
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    if (U() < 0.01) { memset(&h, 0, sizeof h); corrupt = 0; }
    if (U() < 0.003) {   /* a corrupted history: any status but the promises */
      double *hv = (double *)&h;
      hv[UI(DC_CMD_HISTORY_NFIELDS)] = fz_wild();
      corrupt = 1;
    }
    cmd_inputs in;
    cmd_fuzz_inputs(n0, corrupt, &in);
    const dc_cmd_params p = in.p;
    const dc_mindlin_pair m = in.m;
    const dc_patch pa = in.pa;
    const double *n = in.n, *du = in.du, dphi = in.dphi, dt = in.dt, a = pa.a;
    const int bad = in.bad, dom = in.dom;
    const dc_cmd_state h0 = h;
    dc_cmd_out o;
    SENTINEL(o);
    const int st = dc_cmd_step(&p, &m, &pa, n, du, dphi, dt, &h, &o);
    /* the trusted step (no input-domain check): inside the domain the same
       status and bits */
    if (dom) {
      ftr->seconds -= fz_now();
      dc_cmd_state ht = h0;
      dc_cmd_out ot;
      SENTINEL(ot);
      const int stt = dc_cmd_step_trusted(&p, &m, &pa, n, du, dphi, dt, &ht, &ot);
      fz_count(ftr, stt);
      FZ_EXPECT(ftr, stt == st && (st != DC_OK || (!memcmp(&ot, &o, sizeof o) && !memcmp(&ht, &h, sizeof h))),
                "differs from dc_cmd_step inside the domain", "status %d vs %d", stt, st);
      ftr->seconds += fz_now();
    }
    const int untouched = UNTOUCHED(o) && !memcmp(&h, &h0, sizeof h);
    /* without twisting the twist part of h is neither read nor written */
    /* (the pieces in use: a corrupted unused piece is not read) */
    int fin_ok = FIN(o) && h.nseg >= 0.0 && h.nseg <= DC_CMD_MAX_SEG;
    const int used = (int)(offsetof(dc_cmd_state, seg) / sizeof(double)) + 7 * (fin_ok ? (int)h.nseg : 0);
    for (int k = 0; k < used; k++) fin_ok &= isfinite(((const double *)&h)[k]);
    if (p.twisting) {
      fin_ok &= isfinite(h.nseg_t) && h.nseg_t >= 0.0 && h.nseg_t <= DC_CMD_MAX_SEG;
      for (int j = 0; fin_ok && j < (int)h.nseg_t; j++)
        fin_ok &= isfinite(h.seg_t[j].xi) && isfinite(h.seg_t[j].t0) && isfinite(h.seg_t[j].t1);
    }
    else fin_ok &= !memcmp(&h.nseg_t, &h0.nseg_t, sizeof h - DC_CMD_FORCE_NFIELDS * sizeof(double));
    if (st == DC_OK && !bad && pa.formed != 0.0) {
      /* |Ft| <= mu F_bound, |Mt| <= M_s, Ft in the plane */
      const double lim = p.mu * pa.F_bound, F = hypot(hypot(o.Ft[0], o.Ft[1]), o.Ft[2]);
      fin_ok &= F <= lim * (1.0 + 1e-12) + 4.0 * DBL_TRUE_MIN || !(lim < 1e300);
      /* (a subnormal force has too few bits for its direction) */
      if (fin_ok && F > 1e3 * DBL_MIN) fin_ok &= fabs(o.Ft[0] / F * n[0] + o.Ft[1] / F * n[1] + o.Ft[2] / F * n[2]) <= 1e-12;
    }
    FZ_CHECK(f, st, bad, dom, untouched, fin_ok, "mu %.17g pair %.17g %.17g a %.17g b %.17g F_b %.17g formed %.17g n (%.17g %.17g %.17g) du (%.17g %.17g %.17g) dphi %.17g dt %.17g flags %d %d corrupt %d",
             p.mu, m.s0, m.s1, a, pa.b, pa.F_bound, pa.formed, n[0], n[1], n[2], du[0], du[1], du[2], dphi, dt,
             p.dissipation, p.twisting, corrupt);
    /* DC_ERANGE only where a result can overflow: the force scale mu F_b,
       the stiffnesses ~ a/s0, a^3/s0, the limits ~ mu F_b s0/a, mu F_b s0/a^2,
       the displacements and the stored profile */
    if (st == DC_ERANGE) {
      double big = fmax(lg(p.mu) + lg(pa.F_bound), lg(8.0 * a) - lg(m.s0) + fmax(0.0, lg(p.t_visc) - lg(dt)));
      big = fmax(big, fmax(3.0 * lg(a) - lg(m.s0) + 2.0, lg(p.mu) + lg(pa.F_bound) + lg(m.s0) - 2.0 * lg(a) + 1.0));
      big = fmax(big, fmax(lg(p.mu) + lg(pa.F_bound) + lg(m.s0) - lg(a), fmax(lg(dphi), lg(h0.a_prev) - lg(a))));
      /* the twisting moment: M_s ~ mu F_b a, k_tau dphi ~ a^3 dphi / s0 */
      big = fmax(big, fmax(lg(p.mu) + lg(pa.F_bound) + lg(a), 3.0 * lg(a) - lg(m.s0) + lg(dphi) + 2.0));
      for (int i = 0; i < 3; i++) big = fmax(big, lg(du[i]));
      const double *hv = (const double *)&h0;
      for (int i = 0; i < DC_CMD_HISTORY_NFIELDS; i++) big = fmax(big, lg(hv[i]));
      FZ_EXPECT(f, corrupt || big > LOG_MAX - 6.0, "DC_ERANGE for representable results",
                "mu %.17g pair %.17g %.17g a %.17g b %.17g F_b %.17g du (%.17g %.17g %.17g) dphi %.17g", p.mu, m.s0, m.s1, a,
                pa.b, pa.F_bound, du[0], du[1], du[2], dphi);
    }
    if (st != DC_OK) {
      if (U() < 0.5) { memset(&h, 0, sizeof h); corrupt = 0; }
    } else if (corrupt && U() < 0.2) {
      memset(&h, 0, sizeof h);
      corrupt = 0;
    }
  }
  fz_done(f);
}

/* cmd_turning_points.h: the bounded-memory law on the same inputs as
   dc_cmd_step (a contact stepped along, the normal turning, the patch and
   friction load changing every call); now and then a fresh or a
   corrupted history */
static void fuzz_cmdtp(void)
{
  fz_fn *f = fz_new("dc_cmdtp_step");
  fz_fn *ftr = fz_new("dc_cmdtp_step_trusted");
  ftr->seconds = 0.0;
  dc_cmdtp_state h;
  memset(&h, 0, sizeof h);
  int corrupt = 0;
  double n0[3] = {0.0, 0.0, 1.0};
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    if (U() < 0.01) { memset(&h, 0, sizeof h); corrupt = 0; }
    if (U() < 0.003) {
      double *hv = (double *)&h;
      hv[UI(DC_CMDTP_HISTORY_NFIELDS)] = fz_wild();
      corrupt = 1;
    }
    cmd_inputs in;
    cmd_fuzz_inputs(n0, corrupt, &in);
    const dc_cmd_params p = in.p;
    const dc_mindlin_pair m = in.m;
    const dc_patch pa = in.pa;
    const double *n = in.n, *du = in.du, dphi = in.dphi, dt = in.dt, a = pa.a;
    const int bad = in.bad, dom = in.dom;
    const dc_cmdtp_state h0 = h;
    dc_cmd_out o;
    SENTINEL(o);
    const int st = dc_cmdtp_step(&p, &m, &pa, n, du, dphi, dt, &h, &o);
    if (dom) {
      ftr->seconds -= fz_now();
      dc_cmdtp_state ht = h0;
      dc_cmd_out ot;
      SENTINEL(ot);
      const int stt = dc_cmdtp_step_trusted(&p, &m, &pa, n, du, dphi, dt, &ht, &ot);
      fz_count(ftr, stt);
      FZ_EXPECT(ftr, stt == st && (st != DC_OK || (!memcmp(&ot, &o, sizeof o) && !memcmp(&ht, &h, sizeof h))),
                "differs from dc_cmdtp_step inside the domain", "status %d vs %d", stt, st);
      ftr->seconds += fz_now();
    }
    const int untouched = UNTOUCHED(o) && !memcmp(&h, &h0, sizeof h);
    /* the fields in use finite (the force's, and the twist's with twisting;
       without it the twist's untouched) */
    int fin_ok = FIN(o) && h.nturn >= 0.0 && h.nturn <= DC_CMDTP_MAX_TURNS;
    const int used = (int)(offsetof(dc_cmdtp_state, T) / sizeof(double)) + 3 * (fin_ok ? (int)h.nturn : 0);
    for (int k = 0; k < used; k++) fin_ok &= isfinite(((const double *)&h)[k]);
    if (p.twisting) fin_ok &= ALLFIN(h.M, h.c2_t, h.S_prev_t) && h.nturn_t >= 0.0 && h.nturn_t <= DC_CMDTP_MAX_TURNS;
    else fin_ok &= !memcmp(&h.M, &h0.M, sizeof h - DC_CMDTP_FORCE_NFIELDS * sizeof(double));
    if (st == DC_OK && !bad && pa.formed != 0.0) {
      const double lim = p.mu * pa.F_bound, F = hypot(hypot(o.Ft[0], o.Ft[1]), o.Ft[2]);
      fin_ok &= F <= lim * (1.0 + 1e-12) + 4.0 * DBL_TRUE_MIN || !(lim < 1e300);
      if (fin_ok && F > 1e3 * DBL_MIN) fin_ok &= fabs(o.Ft[0] / F * n[0] + o.Ft[1] / F * n[1] + o.Ft[2] / F * n[2]) <= 1e-12;
    }
    FZ_CHECK(f, st, bad, dom, untouched, fin_ok, "mu %.17g pair %.17g %.17g a %.17g b %.17g F_b %.17g formed %.17g n (%.17g %.17g %.17g) du (%.17g %.17g %.17g) dphi %.17g dt %.17g flags %d %d corrupt %d",
             p.mu, m.s0, m.s1, a, pa.b, pa.F_bound, pa.formed, n[0], n[1], n[2], du[0], du[1], du[2], dphi, dt,
             p.dissipation, p.twisting, corrupt);
    /* DC_ERANGE only where a result can overflow: the force scale mu F_b,
       the stiffnesses ~ a/s0 (a^3/s0 twisting), their products with the
       displacements, the stored values */
    if (st == DC_ERANGE) {
      const double lk = lg(8.0 * a) - lg(m.s0);
      double big = fmax(lg(p.mu) + lg(pa.F_bound), lk + fmax(0.0, lg(p.t_visc) - lg(dt)));
      big = fmax(big, fmax(3.0 * lg(a) - lg(m.s0) + 2.0, lg(p.mu) + lg(pa.F_bound) + lg(a)));
      big = fmax(big, 3.0 * lg(a) - lg(m.s0) + lg(dphi) + 2.0);
      for (int i = 0; i < 3; i++) big = fmax(big, lg(du[i]) + fmax(lk, 0.0));
      const double *hv = (const double *)&h0;
      for (int i = 0; i < DC_CMDTP_HISTORY_NFIELDS; i++) big = fmax(big, lg(hv[i]));
      FZ_EXPECT(f, corrupt || big > LOG_MAX - 6.0, "DC_ERANGE for representable results",
                "mu %.17g pair %.17g %.17g a %.17g b %.17g F_b %.17g du (%.17g %.17g %.17g) dphi %.17g", p.mu, m.s0, m.s1, a,
                pa.b, pa.F_bound, du[0], du[1], du[2], dphi);
    }
    if (st != DC_OK) {
      if (U() < 0.5) { memset(&h, 0, sizeof h); corrupt = 0; }
    } else if (corrupt && U() < 0.2) {
      memset(&h, 0, sizeof h);
      corrupt = 0;
    }
  }
  fz_done(f);
}

/* ---------------------------------------------------------------- */
/* root_find.h                                                        */

typedef struct {
  int kind;
  double c;
  double x_at[3];   /* the point evaluated into each slot */
  int bad_slot;
} root_ctx;

static double root_f(double x, void *vp, int slot)
{
  root_ctx *q = vp;
  if (slot < 0 || slot > 2) q->bad_slot = 1;
  else q->x_at[slot] = x;
  const double t = x - q->c;
  switch (q->kind) {
  case 0: return t;
  case 1: return t * t * t;
  case 2: return t < 0.0 ? -1.0 : 1.0;                          /* a step */
  case 3: return cos(x) - x;
  case 4: return fabs(t) < 0.25 * fabs(q->c) + 1e-300 ? NAN : t;   /* fails near the root */
  case 5: return t == 0.0 ? 0.0 : 1.0 / t;                      /* a pole, no root */
  default: return t > 0.0 ? INFINITY : -1.0;
  }
}

/* ---------------------------------------------------------------- */
/* jamari_ep.h                                                        */

static int jamari_params_in(const dc_jamari_params *p)
{
  return ALLFIN(p->H, p->K_v, p->c_h, p->c_A) && p->H > 0.0 && p->K_v > 0.0 && p->c_h >= 2.0 / 3.0 * p->K_v &&
         p->c_A >= 2.0;
}
/* Parameters: mostly inside the domain, now and then at its edges or wild. */
static dc_jamari_params jamari_params(void)
{
  dc_jamari_params p;
  p.H = U() < 0.8 ? fz_log(1e7, 1e10) : fz_pos();
  p.K_v = U() < 0.7 ? 0.454 + 0.41 * 0.5 * U() : U() < 0.5 ? fz_log(1e-3, 10.0) : fz_pos();
  p.c_h = U() < 0.6 ? fmax(1.0, p.K_v) : U() < 0.3 ? PICK(2.0 / 3.0 * p.K_v) : 2.0 / 3.0 * p.K_v * fz_log(0.5, 100.0);
  p.c_A = U() < 0.6 ? 108.0 : U() < 0.2 ? PICK(2.0) : fz_log(1.0, 1e4);
  p.H = A(p.H); p.K_v = A(p.K_v); p.c_h = A(p.c_h); p.c_A = A(p.c_A);
  return p;
}
/* log of bounds on the loading curve's results at delta (DC_ERANGE is
   allowed beyond them): the Hertz results, c_h H Ap delta, its slope times
   the steepness of Eqs. 45-46 near delta_n2 -> delta_n1, and the yield
   pressures; ld1: log delta_n1 */
static double jamari_bound(const dc_hertz_geom *g, double E, const dc_jamari_params *p, double d, double *ld1)
{
  *ld1 = lg(2.0) + lg(g->Rc) + lg(g->E) + lg(g->K) + 2.0 * (lg(p->K_v) + lg(p->H) - lg(E));
  const double lAp = lg(2.0 * M_PI) + 0.5 * (lg(g->R_major) + lg(g->R_minor));
  const double q = p->c_A * g->R_area / (2.0 * sqrt(g->R_major) * sqrt(g->R_minor));
  const double steep = q > 1.0 ? lg(2.0 + 1.5 * exp(lg(d) - *ld1) / (q - 1.0) + 1.0 / log(q)) : 0.0;
  double b = fmax(hertz_bound(g, E, d), lg(p->c_h) + lg(p->H) + lAp + lg(d));
  b = fmax(b, lg(p->c_h) + lg(p->H) + lAp + steep);
  b = fmax(b, fmax(lg(p->K_v), lg(p->c_h)) + lg(p->H));
  b = fmax(b, 0.5 * (lg(g->R_major) + lg(d)) + lAp);   /* semi-axes */
  return b;
}

static void fuzz_jamari(void)
{
  static const char *names[4] = {"hardness", "plasticityKv", "plasticityCh", "plasticityCa"};
  fz_fn *f = fz_new("dc_jamari_check");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const dc_jamari_params p = jamari_params();
    dc_param_error err;
    SENTINEL(err);
    const int st = dc_jamari_check(&p, &err);
    /* the laws' domain, and the yield pressures K_v H, c_h H doubles */
    const int inside = jamari_params_in(&p) && p.H <= DBL_MAX / fmax(p.K_v, p.c_h);
    FZ_CHECK(f, st, !ALLFIN(p.H, p.K_v, p.c_h, p.c_A), inside, 1, 1, "H %.17g K_v %.17g c_h %.17g c_A %.17g", p.H, p.K_v,
             p.c_h, p.c_A);
    /* the first bad one is named, with its value */
    const double v[4] = {p.H, p.K_v, p.c_h, p.c_A};
    int first = -1;
    if (!(isfinite(p.H) && p.H > 0.0)) first = 0;
    else if (!(isfinite(p.K_v) && p.K_v > 0.0)) first = 1;
    else if (!(isfinite(p.c_h) && p.c_h >= 2.0 / 3.0 * p.K_v)) first = 2;
    else if (!(isfinite(p.c_A) && p.c_A >= 2.0)) first = 3;
    else if (!(p.H <= DBL_MAX / fmax(p.K_v, p.c_h))) first = 0;
    FZ_EXPECT(f, st == (inside ? DC_OK : DC_EDOM) &&
                 (st == DC_OK ? UNTOUCHED(err)
                              : first >= 0 && err.name && !strcmp(err.name, names[first]) && err.range &&
                                    memcmp(&err.value, &v[first], sizeof(double)) == 0),
              "wrong status or error report", "H %.17g K_v %.17g c_h %.17g c_A %.17g: status %d", p.H, p.K_v, p.c_h, p.c_A,
              st);
  }
  fz_done(f);

  f = fz_new("dc_jamari_onsets");
  fz_fn *fl = fz_new("dc_jamari_loading");
  fl->seconds = 0.0;
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const dc_hertz_geom *g = &hpool[UI(nh)];
    const dc_jamari_params p = jamari_params();
    const double E = A(U() < 0.7 ? fz_log(1e9, 1e12) : fz_pos());
    double out[2];
    SENTINEL(out);
    const int inside = jamari_params_in(&p) && isfinite(E) && E > 0.0;
    const int bad = !ALLFIN(p.H, p.K_v, p.c_h, p.c_A, E);
    int st = dc_jamari_onsets(g, E, &p, &out[0], &out[1]);
    FZ_CHECK(f, st, bad, inside, UNTOUCHED(out), FIN(out) && out[0] >= DBL_MIN && out[1] >= out[0],
             "R %.17g %.17g E %.17g H %.17g K_v %.17g c_h %.17g c_A %.17g", g->R_major, g->R_minor, E, p.H, p.K_v, p.c_h,
             p.c_A);
    double ld1;
    jamari_bound(g, E, &p, 1.0, &ld1);
    FZ_EXPECT(f, st != DC_ERANGE || ld1 < log(DBL_MIN) + 2.0 || ld1 + lg(p.c_A) > LOG_MAX - 2.0 ||
                     fmax(lg(p.K_v), lg(p.c_h)) + lg(p.H) > LOG_MAX - 1.0,
              "DC_ERANGE for representable onsets", "R %.17g %.17g E %.17g H %.17g K_v %.17g", g->R_major, g->R_minor, E,
              p.H, p.K_v);
    fl->seconds -= fz_now();
    /* overlaps around the onsets, or anything */
    const double d1 = exp(ld1);
    const double d = A(U() < 0.7 ? d1 * fz_log(1e-3, 1e4) : U() < 0.2 ? PICK(0.0, -0.0, d1, d1 * 54.0) : fz_wide());
    dc_contact c;
    SENTINEL(c);
    st = dc_jamari_loading(g, E, &p, d, &c);
    FZ_CHECK(fl, st, bad || !isfinite(d), inside && isfinite(d), UNTOUCHED(c), contact_ok(&c) && c.F >= 0.0,
             "R %.17g %.17g E %.17g H %.17g K_v %.17g c_h %.17g c_A %.17g delta %.17g", g->R_major, g->R_minor, E, p.H,
             p.K_v, p.c_h, p.c_A, d);
    FZ_EXPECT(fl, st != DC_ERANGE || jamari_bound(g, E, &p, d, &ld1) > LOG_MAX - 4.0 || ld1 < log(DBL_MIN) + 2.0,
              "DC_ERANGE for a representable state", "R %.17g %.17g E %.17g H %.17g K_v %.17g c_h %.17g c_A %.17g delta %.17g",
              g->R_major, g->R_minor, E, p.H, p.K_v, p.c_h, p.c_A, d);
    fl->seconds += fz_now();
  }
  fz_done(f);

  /* the step: chains of calls on one history (a contact) with one geometry
     and material, overlaps wandering up and down through the regimes, now
     and then wild inputs, a fresh or a corrupted history */
  f = fz_new("dc_jamari_step");
  dc_jamari_state h = {0, 0, 0, 0};
  int corrupt = 0;
  const dc_hertz_geom *g = &hpool[0];
  dc_jamari_params p0 = dc_jamari_defaults(2e9, 0.3);
  double E0 = 1e11, x = 0.0;
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    if (U() < 0.01) {   /* a new contact */
      memset(&h, 0, sizeof h);
      corrupt = 0;
      g = &hpool[UI(nh)];
      do p0 = jamari_params(); while (!jamari_params_in(&p0));
      E0 = fz_log(1e9, 1e12);
      x = 0.0;
    }
    if (U() < 0.003) {   /* a corrupted history: any status but the promises */
      ((double *)&h)[UI(DC_JAMARI_HISTORY_NFIELDS)] = U() < 0.5 ? fz_wild() : fz_wide();
      corrupt = 1;
    }
    double ld1;
    jamari_bound(g, E0, &p0, 1.0, &ld1);
    x += exp(ld1) * fz_sign(fz_log(1e-4, 30.0));
    if (U() < 0.02) x = 0.0;
    const dc_jamari_params p = {A(p0.H), A(p0.K_v), A(p0.c_h), A(p0.c_A)};
    const double E = A(E0), d = A(x);
    const int bad = !ALLFIN(p.H, p.K_v, p.c_h, p.c_A, E, d, h.delta_max, h.delta_res, h.F_max, h.area_max);
    const int dom = !bad && jamari_params_in(&p) && E > 0.0;
    const dc_jamari_state h0 = h;
    dc_contact c;
    SENTINEL(c);
    const int st = dc_jamari_step(g, E, &p, d, &h, &c);
    const int untouched = UNTOUCHED(c) && !memcmp(&h, &h0, sizeof h);
    const int fin_ok = contact_ok(&c) && c.F >= 0.0 && FIN(h);
    FZ_CHECK(f, st, bad, dom, untouched, fin_ok,
             "R %.17g %.17g E %.17g H %.17g K_v %.17g c_h %.17g c_A %.17g delta %.17g history %.17g %.17g %.17g %.17g corrupt %d",
             g->R_major, g->R_minor, E, p.H, p.K_v, p.c_h, p.c_A, d, h0.delta_max, h0.delta_res, h0.F_max, h0.area_max,
             corrupt);
    /* DC_ERANGE only where the loading curve's bound or the branch
       (F_max, 1.5 F_max/(delta_max - delta_res), area_max) can overflow */
    if (st == DC_ERANGE) {
      double big = jamari_bound(g, E, &p, d, &ld1);
      big = fmax(big, lg(1.5 * h0.F_max) - lg(h0.delta_max - h0.delta_res));
      big = fmax(big, 0.5 * (lg(h0.area_max) - lg(g->m1)));
      FZ_EXPECT(f, corrupt || big > LOG_MAX - 4.0 || ld1 < log(DBL_MIN) + 2.0, "DC_ERANGE for representable results",
                "R %.17g %.17g E %.17g H %.17g delta %.17g", g->R_major, g->R_minor, E, p.H, d);
    }
    /* the law's promises on a sane contact: never above the loading curve */
    if (st == DC_OK && !corrupt && dom) {
      dc_contact cl;
      if (dc_jamari_loading(g, E, &p, d, &cl) == DC_OK)
        FZ_EXPECT(f, c.F <= cl.F, "above the loading curve", "delta %.17g F %.17g loading %.17g", d, c.F, cl.F);
      FZ_EXPECT(f, h.delta_res >= 0.0 && (h.delta_max == 0.0 || h.delta_res < h.delta_max), "history out of order",
                "delta_max %.17g delta_res %.17g", h.delta_max, h.delta_res);
    }
    if (st != DC_OK) {
      if (U() < 0.5) { memset(&h, 0, sizeof h); corrupt = 0; }
    } else if (corrupt && U() < 0.2) {
      memset(&h, 0, sizeof h);
      corrupt = 0;
    }
  }
  fz_done(f);
}

static void fuzz_root_find(void)
{
  fz_fn *f = fz_new("dc_root_brent");
  fz_fn *fe = fz_new("dc_root_brent_ends");
  fe->seconds = 0.0;
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    root_ctx q = {UI(7), U() < 0.5 ? 2.0 * U() - 1.0 : fz_wide(), {0, 0, 0}, 0};
    if (q.kind == 3) q.c = 0.0;
    const double w = U() < 0.5 ? fz_log(1e-12, 10.0) : fz_log(1e-300, 1e300);
    double a = A(q.c - w * U()), b = A(q.c + w * U());
    if (U() < 0.5) { const double t = a; a = b; b = t; }
    const double rtol = A(U() < 0.5 ? PICK(0.0, 1e-15, 1e-12, 1e-8) : fz_log(1e-20, 1.0));
    const double atol = A(U() < 0.5 ? PICK(0.0, 1e-300, 1e-12) : fz_log(1e-320, 1.0));
    const int mi = U() < 0.9 ? 1 + UI(120) : (int[]){0, -1, INT_MIN}[UI(3)];
    root_ctx q0 = q;
    const double fa = root_f(a, &q0, 0), fb = root_f(b, &q0, 1);
    const int bad = !ALLFIN(a, b, rtol, atol);
    const int dom = !bad && ALLFIN(fa, fb) && ((fa <= 0.0 && fb >= 0.0) || (fa >= 0.0 && fb <= 0.0)) && rtol >= 0.0 &&
                    atol >= 0.0 && mi >= 1;
    dc_root_result r;
    SENTINEL(r);
    const int st = dc_root_brent(root_f, &q, a, b, rtol, atol, mi, &r);
    int ok = isfinite(r.x) && isfinite(r.fx) && r.slot >= 0 && r.slot <= 2 && r.evaluations >= 0 &&
             r.evaluations <= mi + 2 && r.x >= fmin(a, b) && r.x <= fmax(a, b) && !q.bad_slot;
    if (ok) ok = q.x_at[r.slot] == r.x && (st != DC_OK || r.fx == root_f(r.x, &q0, 0));
    FZ_CHECK(f, st, bad, dom, UNTOUCHED(r), ok, "kind %d c %.17g a %.17g b %.17g rtol %.17g atol %.17g max_iter %d", q.kind,
             q.c, a, b, rtol, atol, mi);
    /* with the end values given (any, also non-finite) */
    fe->seconds -= fz_now();
    fz_call();
    q.bad_slot = 0;
    q.x_at[0] = a;
    q.x_at[1] = b;
    const double ga = A(fa), gb = A(fb);
    const int bad2 = !ALLFIN(a, b, ga, gb, rtol, atol);
    const int dom2 = !bad2 && ((ga <= 0.0 && gb >= 0.0) || (ga >= 0.0 && gb <= 0.0)) && rtol >= 0.0 && atol >= 0.0 &&
                     mi >= 1;
    SENTINEL(r);
    const int st2 = dc_root_brent_ends(root_f, &q, a, b, ga, gb, rtol, atol, mi, &r);
    ok = isfinite(r.x) && isfinite(r.fx) && r.slot >= 0 && r.slot <= 2 && r.evaluations >= 0 && r.evaluations <= mi &&
         r.x >= fmin(a, b) && r.x <= fmax(a, b) && !q.bad_slot;
    if (ok) ok = q.x_at[r.slot] == r.x;
    FZ_CHECK(fe, st2, bad2, dom2, UNTOUCHED(r), ok,
             "kind %d c %.17g a %.17g b %.17g fa %.17g fb %.17g rtol %.17g atol %.17g max_iter %d", q.kind, q.c, a, b,
             ga, gb, rtol, atol, mi);
    fe->seconds += fz_now();
  }
  fz_done(f);
}

/* ---------------------------------------------------------------- */
/* Checks of a parameter struct: the error report names a bad field.  */

typedef struct {
  const char *name;  /* as the check reports it */
  double value;
  int bad;           /* read by the check (the settings select it) and outside its range */
} fz_field;

/* err names one of the bad fields, with its value (where the header does
   not give the order of the fields, any bad one). */
static int err_names(const dc_param_error *e, const fz_field *fl, int n)
{
  if (!e->name || !e->range) return 0;
  for (int i = 0; i < n; i++)
    if (fl[i].bad && !strcmp(e->name, fl[i].name) && !memcmp(&e->value, &fl[i].value, sizeof(double))) return 1;
  return 0;
}

/* one field: its name, value, whether the settings have it read, and its range */
typedef struct {
  const char *name;
  double v;
  int used, ok;
} fz_spec;

/* The fields from their specs; inside: no field bad; nonfinite: a read
   double (from index first_double on) is not finite. */
static int fz_fields(const fz_spec *t, int n, int first_double, fz_field *fl, int *nonfinite)
{
  int inside = 1;
  *nonfinite = 0;
  for (int i = 0; i < n; i++) {
    fl[i] = (fz_field){t[i].name, t[i].v, t[i].used && !t[i].ok};
    inside &= !fl[i].bad;
    if (i >= first_double && t[i].used && !isfinite(t[i].v)) *nonfinite = 1;
  }
  return inside;
}

static int pos_fin(double x) { return x > 0.0 && x <= DBL_MAX; }
static int nonneg_fin(double x) { return x >= 0.0 && x <= DBL_MAX; }

/* ---------------------------------------------------------------- */
/* classical_normal.h                                                 */

enum { CN_NF = 11 };

/* The fields of p as the header documents them (unused fields are not
   read; the settings first, then the doubles). */
static int cn_fields(const dc_classical_normal_params *p, fz_field fl[CN_NF], int *nonfinite)
{
  const int law_ok = p->law >= 0 && p->law <= 3, hz = p->law == DC_CLASSICAL_HERTZ, lin = law_ok && !hz;
  const int st_ok = p->stiffness >= 0 && p->stiffness <= 3 &&
                    !(p->law == DC_CLASSICAL_HLS_VARIABLE && p->stiffness == DC_CLASSICAL_K_DURATION);
  const int given = lin && st_ok && p->stiffness == DC_CLASSICAL_K_GIVEN, matched = lin && st_ok && !given;
  const int uses_e = p->law == DC_CLASSICAL_LSD || p->law == DC_CLASSICAL_HLS_CONSTANT ||
                     (hz && (p->damping == DC_DAMPING_RESTITUTION || p->damping == DC_DAMPING_TSUJI));
  const fz_spec t[CN_NF] = {
    {"classicalNormal", p->law, 1, law_ok},
    {"limitForce", p->limit, 1, p->limit == 0 || p->limit == 1},
    {"classicalStiffness", p->stiffness, lin, st_ok},
    {"damping", p->damping, hz, p->damping >= 0 && p->damping <= 4},
    {"kn", p->kn, given, pos_fin(p->kn)},
    {"youngsModulus", p->Estar, hz || matched, pos_fin(p->Estar)},
    {"characteristicVelocity", p->v_char, matched, pos_fin(p->v_char)},
    {"viscoelasticTime", p->A, hz && p->damping == DC_DAMPING_VISCOELASTIC, nonneg_fin(p->A)},
    {"kuwabaraKonoDamping", p->eta_kk, hz && p->damping == DC_DAMPING_KUWABARA_KONO, nonneg_fin(p->eta_kk)},
    {"coefficientRestitution", p->e, uses_e, p->e > 0.0 && p->e <= 1.0},
    {"unloadingStiffnessSlope", p->S, p->law == DC_CLASSICAL_HLS_VARIABLE, nonneg_fin(p->S)}};
  return fz_fields(t, CN_NF, 4, fl, nonfinite);
}

static dc_classical_normal_params cn_params(void)
{
  dc_classical_normal_params p;
  p.law = AI(UI(4));
  p.stiffness = AI(UI(4));
  p.damping = AI(UI(5));
  p.limit = AI(UI(2));
  p.Estar = A(U() < 0.7 ? fz_log(1e5, 1e12) : fz_pos());
  p.kn = A(U() < 0.7 ? fz_log(1e2, 1e10) : fz_pos());
  p.v_char = A(U() < 0.7 ? fz_log(1e-3, 1e2) : fz_pos());
  p.e = A(U() < 0.6 ? U() : U() < 0.5 ? fz_log(1e-320, 1.0) : PICK(1.0, 0.0, 0.5));
  p.A = A(U() < 0.7 ? fz_log(1e-12, 1e-3) : U() < 0.5 ? 0.0 : fz_pos());
  p.eta_kk = A(U() < 0.7 ? fz_log(1e-2, 1e6) : U() < 0.5 ? 0.0 : fz_pos());
  p.S = A(U() < 0.7 ? fz_log(1e-2, 1e8) : U() < 0.5 ? 0.0 : fz_pos());
  return p;
}

#define CN_FMT "law %d stiffness %d damping %d limit %d E* %.17g kn %.17g v %.17g e %.17g A %.17g eta %.17g S %.17g"
#define CN_ARGS(p) (p).law, (p).stiffness, (p).damping, (p).limit, (p).Estar, (p).kn, (p).v_char, (p).e, (p).A, \
                   (p).eta_kk, (p).S

static dc_classical_normal cnpool[64];
static int ncn;

/* log of K (LSD, HLS: K_L; HERTZ: K_HZ) */
static double cn_lK(const dc_classical_normal *m, double R, double meff)
{
  if (m->p.law == DC_CLASSICAL_HERTZ) return lg(4.0 / 3.0) + lg(m->p.Estar) + 0.5 * lg(R);
  return lg(m->kc) + (m->matched ? 0.2 * (2.0 * lg(R) + lg(meff)) : 0.0);
}

/* log of a bound on a step's results and intermediates: K, K_U, the
   elastic force and stiffness, gamma and gamma |ddelta|, the area */
static double cn_bound(const dc_classical_normal *m, double R, double meff, double d, double dd, double dmax)
{
  const dc_classical_normal_params *p = &m->p;
  const double lK = cn_lK(m, R, meff);
  double b = fmax(lK, lg(M_PI) + lg(R) + lg(d)), lgam = -INFINITY;
  if (p->law == DC_CLASSICAL_HERTZ) {
    const double lS = lg(2.0) + lg(p->Estar) + 0.5 * (lg(R) + lg(d));
    b = fmax(b, fmax(lS, lS + lg(d)));
    switch (p->damping) {
    case DC_DAMPING_RESTITUTION: lgam = lg(2.0) + 0.5 * (lS + lg(meff)); break;
    case DC_DAMPING_VISCOELASTIC: lgam = lg(m->dcoef) + lS; break;
    case DC_DAMPING_KUWABARA_KONO: lgam = lg(m->dcoef) + 0.5 * lg(d); break;
    case DC_DAMPING_TSUJI: lgam = lg(m->dcoef) + 0.5 * (lS + lg(meff)); break;
    default: break;
    }
  } else {
    const double ldm = lg(fmax(d, dmax));
    double lKU = lK;
    if (p->law == DC_CLASSICAL_HLS_CONSTANT) lKU += lg(m->ku_ratio);
    if (p->law == DC_CLASSICAL_HLS_VARIABLE) lKU += lg(2.0) + fmax(0.0, lg(p->S) + ldm);
    b = fmax(b, fmax(lKU, lKU + ldm + lg(2.0)));
    if (p->law == DC_CLASSICAL_LSD) lgam = lg(m->zeta) + 0.5 * (lg(meff) + lK);
  }
  return fmax(b, fmax(lgam, lgam + lg(dd)));
}

static void fuzz_classical_normal(void)
{
  /* check and init on the same parameters */
  fz_fn *f = fz_new("dc_classical_normal_check");
  fz_fn *fi = fz_new("dc_classical_normal_init");
  fi->seconds = 0.0;
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const dc_classical_normal_params p = cn_params();
    fz_field fl[CN_NF];
    int bad;
    const int inside = cn_fields(&p, fl, &bad);
    dc_param_error err;
    SENTINEL(err);
    const int st = dc_classical_normal_check(&p, &err);
    FZ_CHECK(f, st, bad, inside, 1, 1, CN_FMT, CN_ARGS(p));
    FZ_EXPECT(f, st == (inside ? DC_OK : DC_EDOM) && (st == DC_OK ? UNTOUCHED(err) : err_names(&err, fl, CN_NF)),
              "wrong status or error report", CN_FMT ": status %d", CN_ARGS(p), st);
    fi->seconds -= fz_now();
    dc_classical_normal m;
    SENTINEL(m);
    SENTINEL(err);
    const int si = dc_classical_normal_init(&p, &m, &err);
    FZ_CHECK(fi, si, bad, inside, UNTOUCHED(m), ALLFIN(m.kc, m.zeta, m.dcoef, m.ku_ratio) && m.zeta >= 0.0,
             CN_FMT, CN_ARGS(p));
    /* DC_EDOM as the check; DC_ERANGE only where kc = c (v E*^2)^2/5
       (c from 0.14 to 1.2 (1 + x^2), x = -ln e / pi) or 1/e^2 can leave
       the range of doubles; both with the error report */
    const int lsd = p.law == DC_CLASSICAL_LSD, matched = inside && p.law != DC_CLASSICAL_HERTZ &&
                                                        p.stiffness != DC_CLASSICAL_K_GIVEN;
    const double x = lsd ? -log(p.e) / M_PI : 0.0, lq = 0.4 * lg(p.v_char) + 0.8 * lg(p.Estar);
    const int range = (matched && (lq + log(1.2 * (1.0 + x * x)) > LOG_MAX - 1.0 || lq + log(0.1) < log(DBL_TRUE_MIN) + 1.0)) ||
                      (inside && p.law == DC_CLASSICAL_HLS_CONSTANT && -2.0 * lg(p.e) > LOG_MAX - 1.0);
    FZ_EXPECT(fi, (si == DC_EDOM) == (st == DC_EDOM) && (si != DC_ERANGE || range) &&
                      (si == DC_OK ? UNTOUCHED(err) : err.name && err.range),
              "not the check's status, DC_ERANGE for representable constants, or no error report",
              CN_FMT ": status %d", CN_ARGS(p), si);
    if (si == DC_OK) {
      if (ncn < 64) cnpool[ncn++] = m;
      else cnpool[UI(64)] = m;
    }
    fi->seconds += fz_now();
  }
  fz_done(f);

  /* the step: chains of calls on one history (a contact) with one model,
     radius and mass, overlaps wandering in and out of contact, now and
     then wild inputs or any history (its domain: delta_max >= 0 finite) */
  f = fz_new("dc_classical_normal_step");
  fz_fn *fs = fz_new("dc_classical_normal_stiffness");
  fs->seconds = 0.0;
  dc_classical_normal_state h = {0.0};
  const dc_classical_normal *m = &cnpool[0];
  double R0 = 1e-3, m0 = 1e-6, x = 0.0, sc = 1e-6;
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    if (U() < 0.01) {   /* a new contact */
      h.delta_max = 0.0;
      m = &cnpool[UI(ncn)];
      R0 = U() < 0.7 ? fz_log(1e-6, 1.0) : fz_pos();
      m0 = U() < 0.7 ? fz_log(1e-12, 1e3) : fz_pos();
      sc = R0 * fz_log(1e-12, 1e-1);
      x = 0.0;
    }
    if (U() < 0.003) h.delta_max = U() < 0.5 ? fz_wild() : fz_wide();
    x += sc * fz_sign(fz_log(1e-3, 1.0));
    if (U() < 0.02) x = -x;
    const double R = A(R0), meff = A(m0), d = A(x), dd = A(U() < 0.8 ? fz_sign(fz_log(1e-4, 1e2)) : PICK(0.0, -0.0));
    const int bad = !ALLFIN(R, meff, d, dd, h.delta_max);
    const int dom = !bad && R > 0.0 && meff > 0.0 && h.delta_max >= 0.0;
    const dc_classical_normal_state h0 = h;
    dc_classical_normal_out o;
    SENTINEL(o);
    const int st = dc_classical_normal_step(m, R, meff, d, dd, &h, &o);
    FZ_CHECK(f, st, bad, dom, UNTOUCHED(o) && !memcmp(&h, &h0, sizeof h),
             contact_ok(&o.c) && ALLFIN(o.gamma, o.F, o.K, h.delta_max),
             CN_FMT " R %.17g meff %.17g delta %.17g ddelta %.17g delta_max %.17g", CN_ARGS(m->p), R, meff, d, dd,
             h0.delta_max);
    if (st == DC_OK && dom) {
      /* sign, formed, the history (HLS: the largest overlap; the others 0),
         limitForce; delta <= 0 gives zeros; HLS never above K_L delta_max */
      const int formed = d > 0.0, hls = m->p.law >= DC_CLASSICAL_HLS_CONSTANT;
      int pr = o.c.formed == formed && o.c.F >= 0.0 && o.c.kn >= 0.0 && o.c.area >= 0.0 && o.c.a == o.c.b &&
               o.c.a >= 0.0 && o.c.F_bound == o.c.F && o.gamma >= 0.0 && (!m->p.limit || o.F >= 0.0) &&
               h.delta_max == (formed && hls ? fmax(h0.delta_max, d) : 0.0);
      if (!formed)
        pr &= o.c.F == 0.0 && o.c.kn == 0.0 && o.c.area == 0.0 && o.c.a == 0.0 && o.gamma == 0.0 && o.F == 0.0 &&
              o.K == 0.0;
      else if (hls && isfinite(o.K * h.delta_max))
        pr &= o.c.F <= o.K * h.delta_max * (1.0 + 1e-14);
      FZ_EXPECT(f, pr, "not the law's promises (sign, formed, history, limit, unloading line)",
                CN_FMT " R %.17g meff %.17g delta %.17g ddelta %.17g delta_max %.17g: F %.17g total %.17g gamma %.17g",
                CN_ARGS(m->p), R, meff, d, dd, h0.delta_max, o.c.F, o.F, o.gamma);
    }
    /* DC_ERANGE where a result can overflow, or a matched K underflow */
    FZ_EXPECT(f, st != DC_ERANGE || cn_bound(m, R, meff, d, dd, h0.delta_max) > LOG_MAX - 3.0 ||
                     (m->matched && cn_lK(m, R, meff) < log(DBL_TRUE_MIN) + 3.0),
              "DC_ERANGE for representable results", CN_FMT " R %.17g meff %.17g delta %.17g ddelta %.17g delta_max %.17g",
              CN_ARGS(m->p), R, meff, d, dd, h0.delta_max);
    if (st != DC_OK && U() < 0.5) h.delta_max = 0.0;
    /* the stiffness alone: the step's K */
    fs->seconds -= fz_now();
    double K;
    SENTINEL(K);
    const int sk = dc_classical_normal_stiffness(m, R, meff, &K);
    FZ_CHECK(fs, sk, !ALLFIN(R, meff), ALLFIN(R, meff) && R > 0.0 && meff > 0.0, UNTOUCHED(K), isfinite(K) && K > 0.0,
             CN_FMT " R %.17g meff %.17g", CN_ARGS(m->p), R, meff);
    const double lK = cn_lK(m, R, meff);
    FZ_EXPECT(fs, sk != DC_ERANGE || lK > LOG_MAX - 1.0 || lK < log(DBL_TRUE_MIN) + 2.0, "DC_ERANGE for a representable K",
              CN_FMT " R %.17g meff %.17g", CN_ARGS(m->p), R, meff);
    if (sk == DC_OK && st == DC_OK && d > 0.0)
      FZ_EXPECT(fs, K == o.K, "not the step's K", CN_FMT " R %.17g meff %.17g: %.17g vs %.17g", CN_ARGS(m->p), R, meff, K,
                o.K);
    fs->seconds += fz_now();
  }
  fz_done(f);

  /* the closed forms of one collision */
  f = fz_new("dc_classical_lsd_collision");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const double K = A(U() < 0.6 ? fz_log(1e2, 1e10) : fz_pos()), meff = A(U() < 0.6 ? fz_log(1e-12, 1e3) : fz_pos());
    const double v0 = A(U() < 0.6 ? fz_log(1e-3, 1e2) : fz_pos());
    /* eta: a fraction q of the critical 2 (m K)^1/2 (in logs: no overflow) */
    const double lcrit = lg(2.0) + 0.5 * (lg(K) + lg(meff));
    const double q = U() < 0.1 ? 0.0 : U() < 0.6 ? U() : U() < 0.5 ? 1.0 - fz_log(1e-16, 0.1) : fz_log(0.5, 2.0);
    const double eta = A(q > 0.0 ? exp(lcrit + log(q)) : 0.0);
    const int limit = AI(UI(2));
    const int bad = !ALLFIN(K, eta, meff, v0);
    const double lq = lg(eta) - lcrit;   /* eta over critical */
    /* underdamped, with a margin for the rounding of the test (wide where
       (m K)^1/2 is subnormal) */
    const int dom = !bad && K > 0.0 && meff > 0.0 && v0 > 0.0 && eta >= 0.0 && (limit == 0 || limit == 1) &&
                    (lq < -0.1 || (lq < -1e-9 && lcrit > log(DBL_MIN) + 2.0));
    dc_classical_collision c;
    SENTINEL(c);
    const int st = dc_classical_lsd_collision(K, eta, meff, v0, limit, &c);
    FZ_CHECK(f, st, bad, dom, UNTOUCHED(c),
             FIN(c) && c.Tc > 0.0 && c.dmax >= 0.0 && c.e >= 0.0 && c.e <= 1.0 && c.Fmax == 0.0 && c.dres == 0.0,
             "K %.17g eta %.17g meff %.17g v0 %.17g limit %d", K, eta, meff, v0, limit);
    /* Tc <= pi/W, dmax <= v0/W, W = (K/m)^1/2 (1 - (eta/crit)^2)^1/2 */
    const double lW = 0.5 * (lg(K) - lg(meff) + log1p(-exp(2.0 * lq)));
    FZ_EXPECT(f, st != DC_ERANGE || fmax(lg(M_PI), lg(v0)) - lW > LOG_MAX - 2.0, "DC_ERANGE for representable figures",
              "K %.17g eta %.17g meff %.17g v0 %.17g limit %d", K, eta, meff, v0, limit);
  }
  fz_done(f);
  f = fz_new("dc_classical_hertz_collision");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const double K = A(U() < 0.6 ? fz_log(1e5, 1e12) : fz_pos()), meff = A(U() < 0.6 ? fz_log(1e-12, 1e3) : fz_pos());
    const double v0 = A(U() < 0.6 ? fz_log(1e-3, 1e2) : fz_pos());
    const int bad = !ALLFIN(K, meff, v0);
    dc_classical_collision c;
    SENTINEL(c);
    const int st = dc_classical_hertz_collision(K, meff, v0, &c);
    FZ_CHECK(f, st, bad, !bad && K > 0.0 && meff > 0.0 && v0 > 0.0, UNTOUCHED(c),
             FIN(c) && c.Tc > 0.0 && c.dmax > 0.0 && c.e == 1.0 && c.Fmax >= 0.0 && c.dres == 0.0,
             "K_HZ %.17g meff %.17g v0 %.17g", K, meff, v0);
    /* dmax = (5/4 m v0^2 / K_HZ)^2/5, Tc = 2.94 dmax / v0, Fmax = K_HZ dmax^3/2 */
    const double ld = 0.4 * (log(1.25) + lg(meff) + 2.0 * lg(v0) - lg(K));
    const double b = fmax(ld, fmax(ld + log(2.95) - lg(v0), lg(K) + 1.5 * ld));
    FZ_EXPECT(f, st != DC_ERANGE || b > LOG_MAX - 1.0 || ld < log(DBL_MIN) + 1.0, "DC_ERANGE for representable figures",
              "K_HZ %.17g meff %.17g v0 %.17g", K, meff, v0);
  }
  fz_done(f);
  f = fz_new("dc_classical_hls_collision");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const int law = AI(DC_CLASSICAL_HLS_CONSTANT + UI(2));
    const double K = A(U() < 0.6 ? fz_log(1e2, 1e10) : fz_pos()), meff = A(U() < 0.6 ? fz_log(1e-12, 1e3) : fz_pos());
    const double v0 = A(U() < 0.6 ? fz_log(1e-3, 1e2) : fz_pos());
    const double xv = A(law == DC_CLASSICAL_HLS_CONSTANT ? (U() < 0.7 ? U() : PICK(1.0, 0.0, 1e-300))
                                                          : (U() < 0.7 ? fz_log(1e-2, 1e8) : U() < 0.3 ? 0.0 : fz_pos()));
    const int bad = !ALLFIN(K, xv, meff, v0);
    const int dom = !bad && K > 0.0 && meff > 0.0 && v0 > 0.0 &&
                    (law == DC_CLASSICAL_HLS_CONSTANT ? xv > 0.0 && xv <= 1.0 : law == DC_CLASSICAL_HLS_VARIABLE && xv >= 0.0);
    dc_classical_collision c;
    SENTINEL(c);
    const int st = dc_classical_hls_collision(law, K, xv, meff, v0, &c);
    FZ_CHECK(f, st, bad, dom, UNTOUCHED(c),
             FIN(c) && c.Tc >= 0.0 && c.dmax >= 0.0 && c.e > 0.0 && c.e <= 1.0 && c.Fmax >= 0.0 && c.dres >= 0.0 &&
                 c.dres <= c.dmax && (law != DC_CLASSICAL_HLS_CONSTANT || c.e == xv),
             "law %d K_L %.17g x %.17g meff %.17g v0 %.17g", law, K, xv, meff, v0);
    /* Tc <= pi (m/K)^1/2, dmax = v0 (m/K)^1/2, Fmax = v0 (m K)^1/2 */
    const double lw = 0.5 * (lg(meff) - lg(K));
    const double b = fmax(fmax(lg(M_PI) + lw, lg(v0) + lw), lg(v0) + 0.5 * (lg(meff) + lg(K)));
    FZ_EXPECT(f, st != DC_ERANGE || b > LOG_MAX - 2.0, "DC_ERANGE for representable figures",
              "law %d K_L %.17g x %.17g meff %.17g v0 %.17g", law, K, xv, meff, v0);
  }
  fz_done(f);
}

/* ---------------------------------------------------------------- */
/* classical_tangential.h                                             */

enum { CT_NF = 11 };

static int ct_fields(const dc_classical_tangential_params *p, fz_field fl[CT_NF], int *nonfinite)
{
  const int law = p->law, law_ok = law >= 0 && law <= 9;
  const int uses_st = law == DC_CT_SPRING_SLIDING || law == DC_CT_SPRING_DASHPOT_SLIDING || law == DC_CT_INCREMENTAL;
  const int st_ok = p->stiffness >= 0 && p->stiffness <= 2;
  const int uses_d = law == DC_CT_SPRING_DASHPOT_SLIDING || law == DC_CT_DI_RENZO;
  const int gstar = (uses_st && st_ok && p->stiffness != DC_CT_KT_GIVEN) || law == DC_CT_DI_RENZO ||
                    law == DC_CT_LANGSTON || law == DC_CT_ZHENG || law == DC_CT_TSUJI;
  const fz_spec t[CT_NF] = {
    {"classicalTangential", law, 1, law_ok},
    {"classicalTangentialStiffness", p->stiffness, uses_st, st_ok},
    {"classicalTangentialDamping", p->damping, uses_d, p->damping >= 0 && p->damping <= 3},
    {"coefficientFriction", p->mu, law_ok && law != DC_CT_VISCOUS, nonneg_fin(p->mu)},
    {"kt", p->kt, uses_st && p->stiffness == DC_CT_KT_GIVEN, pos_fin(p->kt)},
    {"youngsModulus", p->Gstar, gstar, pos_fin(p->Gstar)},
    {"youngsModulus", p->Estar, uses_st && p->stiffness == DC_CT_KT_RATIO, pos_fin(p->Estar)},
    {"gammat", p->gammat, law == DC_CT_VISCOUS || law == DC_CT_VISCOUS_SLIDING || (uses_d && p->damping == DC_CT_DAMP_GIVEN),
     nonneg_fin(p->gammat)},
    {"coefficientRestitutionTangential", p->e_t, uses_d && p->damping == DC_CT_DAMP_RESTITUTION,
     p->e_t >= 0.0 && p->e_t <= 1.0},
    {"langstonDamping", p->eta_l, law == DC_CT_LANGSTON, nonneg_fin(p->eta_l)},
    {"tangentialViscoelasticTime", p->t_visc, law == DC_CT_ZHENG, nonneg_fin(p->t_visc)}};
  return fz_fields(t, CT_NF, 3, fl, nonfinite);
}

static dc_classical_tangential_params ct_params(void)
{
  dc_classical_tangential_params p;
  p.law = AI(UI(10));
  p.stiffness = AI(UI(3));
  p.damping = AI(UI(4));
  p.mu = A(U() < 0.8 ? 2.0 * U() : PICK(0.0, 1.0));
  p.kt = A(U() < 0.7 ? fz_log(1e2, 1e9) : fz_pos());
  p.gammat = A(U() < 0.7 ? fz_log(1e-6, 1e2) : U() < 0.5 ? 0.0 : fz_pos());
  p.e_t = A(U() < 0.7 ? U() : PICK(0.0, 1.0));
  p.Gstar = A(U() < 0.7 ? fz_log(1e6, 1e11) : fz_pos());
  p.Estar = A(U() < 0.7 ? fz_log(1e6, 1e11) : fz_pos());
  p.eta_l = A(U() < 0.7 ? fz_log(1e-3, 2.0) : U() < 0.5 ? 0.0 : fz_pos());
  p.t_visc = A(U() < 0.7 ? fz_log(1e-12, 1e-3) : U() < 0.5 ? 0.0 : fz_pos());
  return p;
}

#define CT_FMT "law %d stiffness %d damping %d mu %.17g kt %.17g gammat %.17g e_t %.17g G* %.17g E* %.17g eta_l %.17g A_t %.17g"
#define CT_ARGS(p) (p).law, (p).stiffness, (p).damping, (p).mu, (p).kt, (p).gammat, (p).e_t, (p).Gstar, (p).Estar, \
                   (p).eta_l, (p).t_visc

static dc_classical_tangential ctpool[64];
static int nct;

/* log of the spring stiffness of a law (-inf: none) */
static double ct_lK(const dc_classical_tangential *m, const dc_patch *pa, const dc_classical_tangential_contact *c)
{
  const dc_classical_tangential_params *p = &m->p;
  switch (p->law) {
  case DC_CT_SPRING_SLIDING: case DC_CT_SPRING_DASHPOT_SLIDING: case DC_CT_INCREMENTAL:
    return p->stiffness == DC_CT_KT_GIVEN ? lg(p->kt) : p->stiffness == DC_CT_KT_RATIO ? lg(m->ratio) + lg(c->kn)
                                                                                        : lg(8.0) + lg(p->Gstar) + lg(pa->a);
  case DC_CT_DI_RENZO: return lg(16.0 / 3.0) + lg(p->Gstar) + lg(pa->a);
  case DC_CT_LANGSTON: case DC_CT_ZHENG: case DC_CT_TSUJI: return lg(8.0) + lg(p->Gstar) + lg(pa->a);
  default: return -INFINITY;
  }
}

/* log of a bound on the dashpot (-inf: none) for a spring of log stiffness lK */
static double ct_leta(const dc_classical_tangential *m, const dc_classical_tangential_contact *c, double lK)
{
  const dc_classical_tangential_params *p = &m->p;
  return fmax(fmax(lg(p->gammat), lg(c->gamman)),
              fmax(lg(2.0) + 0.5 * (lg(c->meff) + lK) + fmax(lg(p->eta_l), lg(m->zeta_t)), lg(p->t_visc) + lK));
}

/* log of a bound on a step's results and intermediates: mu F_b, the
   spring stiffness, the dashpots times the velocity, the spring times its
   stiffness, the spring a sliding step leaves ((F - eta v)/K), the
   displacements and velocities */
static double ct_bound(const dc_classical_tangential *m, const dc_patch *pa, const dc_classical_tangential_contact *c,
                       const double *du, const double *vt, double dt, const dc_classical_tangential_state *h)
{
  const dc_classical_tangential_params *p = &m->p;
  const double lK = ct_lK(m, pa, c);
  double lv = -INFINITY, ld = -INFINITY, ls = -INFINITY;
  for (int i = 0; i < 3; i++) {
    lv = fmax(lv, lg(vt[i]));
    ld = fmax(ld, du ? lg(du[i]) : lg(vt[i]) + lg(dt));
    ls = fmax(ls, lg(h->spring[i]));
    if (p->law == DC_CT_INCREMENTAL) ls = fmax(ls, lg(h->rev[i]));
  }
  const double leta = ct_leta(m, c, lK);
  const double llim = lg(p->mu) + lg(pa->F_bound);
  /* (the damping coefficient used is an output of its own: eta alone) */
  double b = fmax(fmax(llim, leta), fmax(lK, leta + lv));
  b = fmax(b, fmax(lK + fmax(ld, ls) + 1.0, fmax(fmax(ld, ls), lv)));
  return fmax(b, fmax(llim, leta + lv) - lK + 1.0);
}

/* |x| over its part in the plane of the unit n (1 for x = 0): how much
   the rounding of the projection is amplified */
static double plane_cond(const double *x, const double *n)
{
  const double mx = max_abs3(x);
  if (!(mx > 0.0) || !isfinite(mx)) return 1.0;
  const double y[3] = {x[0] / mx, x[1] / mx, x[2] / mx}, yn = dot3(y, n);
  const double p[3] = {y[0] - yn * n[0], y[1] - yn * n[1], y[2] - yn * n[2]};
  return fmax(1.0, sqrt(dot3(y, y)) / sqrt(dot3(p, p)));
}

static void fuzz_classical_tangential(void)
{
  fz_fn *f = fz_new("dc_classical_tangential_check");
  fz_fn *fi = fz_new("dc_classical_tangential_init");
  fi->seconds = 0.0;
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const dc_classical_tangential_params p = ct_params();
    fz_field fl[CT_NF];
    int bad;
    const int inside = ct_fields(&p, fl, &bad);
    dc_param_error err;
    SENTINEL(err);
    const int st = dc_classical_tangential_check(&p, &err);
    FZ_CHECK(f, st, bad, inside, 1, 1, CT_FMT, CT_ARGS(p));
    FZ_EXPECT(f, st == (inside ? DC_OK : DC_EDOM) && (st == DC_OK ? UNTOUCHED(err) : err_names(&err, fl, CT_NF)),
              "wrong status or error report", CT_FMT ": status %d", CT_ARGS(p), st);
    fi->seconds -= fz_now();
    dc_classical_tangential m;
    SENTINEL(m);
    SENTINEL(err);
    const int si = dc_classical_tangential_init(&p, &m, &err);
    FZ_CHECK(fi, si, bad, inside, UNTOUCHED(m), ALLFIN(m.zeta_t, m.ratio) && m.zeta_t >= 0.0 && m.ratio >= 0.0,
             CT_FMT, CT_ARGS(p));
    /* DC_EDOM as the check; DC_ERANGE only where 4 G* / E* leaves the doubles */
    const double lr = lg(4.0) + lg(p.Gstar) - lg(p.Estar);
    const int range = inside && (p.law == DC_CT_SPRING_SLIDING || p.law == DC_CT_SPRING_DASHPOT_SLIDING ||
                                 p.law == DC_CT_INCREMENTAL) &&
                      p.stiffness == DC_CT_KT_RATIO && (lr > LOG_MAX - 1.0 || lr < log(DBL_TRUE_MIN) + 1.0);
    FZ_EXPECT(fi, (si == DC_EDOM) == (st == DC_EDOM) && (si != DC_ERANGE || range) &&
                      (si == DC_OK ? UNTOUCHED(err) : err.name && err.range),
              "not the check's status, DC_ERANGE for a representable ratio, or no error report",
              CT_FMT ": status %d", CT_ARGS(p), si);
    if (si == DC_OK) {
      if (nct < 64) ctpool[nct++] = m;
      else ctpool[UI(64)] = m;
    }
    fi->seconds += fz_now();
  }
  fz_done(f);

  /* the step: chains of calls on one history (a contact) with one model,
     the normal turning slowly, stick and slip, now and then wild inputs,
     any finite history (its domain), a patch that is not formed; the
     laws other than INCREMENTAL get any reversal force (they neither read
     nor write it: a wrapper may store only the spring) */
  f = fz_new("dc_classical_tangential_step");
  dc_classical_tangential_state h;
  memset(&h, 0, sizeof h);
  const dc_classical_tangential *m = &ctpool[0];
  double n0[3] = {0.0, 0.0, 1.0}, a0 = 1e-4, F0 = 1.0, m0 = 1e-6, dt0 = 1e-6;
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    if (U() < 0.01) {   /* a new contact */
      memset(&h, 0, sizeof h);
      m = &ctpool[UI(nct)];
      a0 = U() < 0.8 ? fz_log(1e-8, 1e-2) : fz_pos();
      F0 = U() < 0.8 ? fz_log(1e-9, 1e4) : fz_pos();
      m0 = U() < 0.8 ? fz_log(1e-12, 1e3) : fz_pos();
      dt0 = fz_log(1e-8, 1e-4);
    }
    const int inc = m->p.law == DC_CT_INCREMENTAL;
    if (!inc && U() < 0.2)
      for (int i = 0; i < 3; i++) h.rev[i] = fz_wild();
    if (U() < 0.003) ((double *)&h)[UI(inc ? DC_CT_HISTORY_NFIELDS : DC_CT_SPRING_NFIELDS)] = U() < 0.5 ? fz_wild() : fz_wide();
    double n[3];
    if (U() < 0.05) unit_vector(n0);
    else {
      for (int i = 0; i < 3; i++) n0[i] += 0.01 * (U() - 0.5);
      const double l = sqrt(dot3(n0, n0));
      for (int i = 0; i < 3; i++) n0[i] /= l;
    }
    for (int i = 0; i < 3; i++) n[i] = A(n0[i]);
    dc_patch pa;
    pa.a = A(U() < 0.02 ? 0.0 : a0 * fz_log(0.5, 2.0));
    pa.b = pa.a * U();
    double ax[3];
    unit_vector(ax);
    memcpy(pa.axis, ax, sizeof ax);
    pa.F_bound = A(U() < 0.02 ? 0.0 : F0 * fz_log(0.5, 2.0));
    pa.F_elastic = pa.F_bound;
    pa.formed = A(U() < 0.03 ? 0.0 : 1.0);
    const dc_classical_tangential_contact c = {A(m0), A(U() < 0.8 ? fz_log(1e1, 1e10) : fz_pos()),
                                               A(U() < 0.8 ? fz_log(1e-6, 1e2) : U() < 0.5 ? 0.0 : fz_pos())};
    /* displacements from far below to far above the sliding distance */
    const double us = a0 * fz_log(1e-12, 1e-1);
    double du[3], vt[3];
    for (int i = 0; i < 3; i++) {
      du[i] = A(us * (2.0 * U() - 1.0));
      vt[i] = A(us / dt0 * (2.0 * U() - 1.0));
    }
    const int pass_du = U() < 0.8;
    const double dt = A(U() < 0.9 ? dt0 : PICK(0.0, -1e-7, 1e-300));
    const int bad = !ALLFIN(pa.a, pa.F_bound, pa.formed, n[0], n[1], n[2], vt[0], vt[1], vt[2], c.meff, c.kn, c.gamman) ||
                    !fin(h.spring, 3) || (inc && !fin(h.rev, 3)) || (pass_du ? !fin(du, 3) : !isfinite(dt));
    const double nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    const int dom = !bad && pa.a >= 0.0 && pa.F_bound >= 0.0 && fabs(nn - 1.0) <= 1e-6 && (pass_du || dt > 0.0) &&
                    c.meff > 0.0 && c.kn >= 0.0 && c.gamman >= 0.0;
    const dc_classical_tangential_state h0 = h;
    dc_classical_tangential_out o;
    SENTINEL(o);
    const int st = dc_classical_tangential_step(m, &pa, &c, n, pass_du ? du : NULL, vt, dt, &h, &o);
    FZ_CHECK(f, st, bad, dom, UNTOUCHED(o) && !memcmp(&h, &h0, sizeof h),
             FIN(o.Ft) && ALLFIN(o.kt, o.gammat) && (o.sliding == 0 || o.sliding == 1) && fin(h.spring, 3) &&
                 (!inc || fin(h.rev, 3)),
             CT_FMT " a %.17g F_b %.17g formed %.17g n (%.17g %.17g %.17g) meff %.17g kn %.17g gamman %.17g "
             "du %s(%.17g %.17g %.17g) vt (%.17g %.17g %.17g) dt %.17g spring (%.17g %.17g %.17g)",
             CT_ARGS(m->p), pa.a, pa.F_bound, pa.formed, n[0], n[1], n[2], c.meff, c.kn, c.gamman, pass_du ? "" : "NULL ",
             du[0], du[1], du[2], vt[0], vt[1], vt[2], dt, h0.spring[0], h0.spring[1], h0.spring[2]);
    if (!inc)
      FZ_EXPECT(f, !memcmp(h.rev, h0.rev, sizeof h.rev), "reversal force read or written by a law without one",
                CT_FMT " status %d rev (%.17g %.17g %.17g)", CT_ARGS(m->p), st, h0.rev[0], h0.rev[1], h0.rev[2]);
    if (st == DC_OK && dom) {
      int pr;
      if (pa.formed == 0.0) {
        pr = o.Ft[0] == 0.0 && o.Ft[1] == 0.0 && o.Ft[2] == 0.0 && o.kt == 0.0 && o.gammat == 0.0 && o.sliding == 0 &&
             h.spring[0] == 0.0 && h.spring[1] == 0.0 && h.spring[2] == 0.0 &&
             (!inc || (h.rev[0] == 0.0 && h.rev[1] == 0.0 && h.rev[2] == 0.0));
      } else {
        /* |Ft| <= mu F_b (but VISCOUS), kt 0 when sliding, Ft in the plane
           to rounding (a subnormal spring or velocity: to its last place
           times the spring and dashpot) */
        const double lim = m->p.mu * pa.F_bound, F = hypot(hypot(o.Ft[0], o.Ft[1]), o.Ft[2]);
        pr = o.kt >= 0.0 && o.gammat >= 0.0 && (!o.sliding || o.kt == 0.0) &&
             (m->p.law == DC_CT_VISCOUS || F <= lim * (1.0 + 1e-12) + 4.0 * DBL_TRUE_MIN);
        const double lK = ct_lK(m, &pa, &c), amp = 1.0 + exp(fmax(lK, 0.0)) + exp(fmax(ct_leta(m, &c, lK), 0.0));
        const double cond = fmax(fmax(plane_cond(pass_du ? du : vt, n), plane_cond(vt, n)), plane_cond(h0.spring, n));
        if (fabs(nn - 1.0) < 1e-14)
          pr &= fabs(o.Ft[0] * n[0] + o.Ft[1] * n[1] + o.Ft[2] * n[2]) <=
                (F > 0.0 ? 1e-12 * (F * cond) : 0.0) + 16.0 * DBL_TRUE_MIN * amp;   /* F cond first: 1e-12 F may underflow to 0 while cond is inf */
      }
      FZ_EXPECT(f, pr, "not the law's promises (limit, plane, zeros when not formed)",
                CT_FMT " a %.17g F_b %.17g formed %.17g n (%.17g %.17g %.17g) du %s(%.17g %.17g %.17g) "
                "vt (%.17g %.17g %.17g) dt %.17g: Ft (%.17g %.17g %.17g) kt %.17g gammat %.17g sliding %d",
                CT_ARGS(m->p), pa.a, pa.F_bound, pa.formed, n[0], n[1], n[2], pass_du ? "" : "NULL ", du[0], du[1], du[2],
                vt[0], vt[1], vt[2], dt, o.Ft[0], o.Ft[1], o.Ft[2], o.kt, o.gammat, o.sliding);
    }
    FZ_EXPECT(f, st != DC_ERANGE || ct_bound(m, &pa, &c, pass_du ? du : NULL, vt, dt, &h0) > LOG_MAX - 3.0,
              "DC_ERANGE for representable results",
              CT_FMT " a %.17g F_b %.17g meff %.17g kn %.17g gamman %.17g du %s(%.17g %.17g %.17g) vt (%.17g %.17g %.17g) "
              "dt %.17g spring (%.17g %.17g %.17g)",
              CT_ARGS(m->p), pa.a, pa.F_bound, c.meff, c.kn, c.gamman, pass_du ? "" : "NULL ", du[0], du[1], du[2], vt[0],
              vt[1], vt[2], dt, h0.spring[0], h0.spring[1], h0.spring[2]);
    if (st != DC_OK && U() < 0.5) memset(&h, 0, sizeof h);
  }
  fz_done(f);
}

/* ---------------------------------------------------------------- */
/* gw_rough_plastic.h                                                 */

/* The rough sums take ~1.6 us where the regimes meet (11 panels of
   Gauss-Legendre; test_gw_rough_plastic times them): 3e4 calls of each
   function that sums them. */
#define N_GWP 30000L

static int gwp_params_in(const dc_gw_plastic_params *p)
{
  return ALLFIN(p->hardness, p->K_v, p->c_h, p->c_A) && p->hardness > 0.0 && p->K_v > 0.0 &&
         p->c_h >= 2.0 / 3.0 * p->K_v && p->c_A >= 2.0 &&
         (p->plastic_area == DC_GW_PLASTIC_AREA_JW || p->plastic_area == DC_GW_PLASTIC_AREA_TRUNCATED);
}
/* the four numbers of jamari_ep's parameters (same names and ranges), the area setting */
static dc_gw_plastic_params gwp_params(void)
{
  const dc_jamari_params j = jamari_params();
  return (dc_gw_plastic_params){j.H, j.K_v, j.c_h, j.c_A, AI(UI(2))};
}

#define GWP_FMT "H %.17g K_v %.17g c_h %.17g c_A %.17g area %d"
#define GWP_ARGS(p) (p).hardness, (p).K_v, (p).c_h, (p).c_A, (p).plastic_area

static dc_gw_plastic_summit spool[POOL];
static int nsp;

/* log of a bound on the summit law's f, area, df at omega > 0 (elastic
   and plastic forms both; df's factor from the elastic-plastic branch) */
static double gwp_summit_bound(const dc_gw_plastic_summit *s, double w)
{
  const double lw = lg(w), lRf = lg(s->R_force), lRa = lg(M_PI) + lg(s->R_area), r = s->ratio;
  double b = fmax(lg(4.0 / 3.0) + lg(s->Estar) + 0.5 * (lRf + lw) + lw, lg(2.0) + lg(s->Estar) + 0.5 * (lRf + lw));
  b = fmax(b, lRa + lw + lg(s->lambda));
  const double fac = s->lambda * s->c_h * (r > 1.0 ? 1.0 + 1.5 * r / (r - 1.0) + 1.0 / log(r) : 1.0);
  return fmax(b, lRa + lg(s->H) + lg(fac) + fmax(lw, 0.0));
}

/* the same for n summits spread by sigma at overlap delta (x = sigma +
   |delta| bounds the mean compression), and the point mass of kn where
   w2 = w1 */
static double gwp_rough_bound(const dc_hertz_geom *g, const dc_gw_plastic_summit *s, double n, double sg, double d)
{
  const double x = sg + fabs(d), lx = lg(x);
  double b = fmax(hertz_bound(g, s->Estar, x), gwp_summit_bound(s, x));
  b = fmax(b, lg(s->Estar) + 0.5 * lg(g->Rc) + 0.5 * lx + fmax(lx, 0.0) + lg(g->gamma) + lg(4.0));
  if (s->ratio == 1.0) b = fmax(b, lg(M_PI) + lg(s->R_area) + lg(s->H) + lg(s->lambda * s->c_h) + lg(s->w1) - lg(sg));
  return lg(n) + b + 2.0;
}

static void fuzz_gw_rough_plastic(void)
{
  fz_fn *f = fz_new("dc_gw_plastic_default_params");
  for (long k = 0; k < N_CALLS; k++) {
    const double H = U() < 0.5 ? fz_log(1e7, 1e10) : fz_wild(), nu = U() < 0.7 ? -1.0 + 1.5 * U() : fz_wild();
    dc_gw_plastic_params p = dc_gw_plastic_default_params(H, nu);
    f->calls++;
    const double Kv = 0.454 + 0.41 * nu;
    FZ_EXPECT(f, !memcmp(&p.hardness, &H, sizeof H) && !memcmp(&p.K_v, &Kv, sizeof Kv) && p.c_h == 1.0 &&
                 p.c_A == 108.0 && p.plastic_area == DC_GW_PLASTIC_AREA_JW,
              "not the documented defaults", "H %.17g nu %.17g", H, nu);
    dc_param_error err;
    if (isfinite(H) && H > 0.0 && nu >= -1.0 && nu <= 0.5)
      FZ_EXPECT(f, dc_gw_plastic_check(&p, &err) == DC_OK, "defaults fail the check", "H %.17g nu %.17g", H, nu);
  }
  fz_done(f);

  static const char *names[5] = {"hardness", "plasticityKv", "plasticityCh", "plasticityCa", "plasticArea"};
  f = fz_new("dc_gw_plastic_check");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const dc_gw_plastic_params p = gwp_params();
    dc_param_error err;
    SENTINEL(err);
    const int st = dc_gw_plastic_check(&p, &err);
    const int inside = gwp_params_in(&p);
    FZ_CHECK(f, st, !ALLFIN(p.hardness, p.K_v, p.c_h, p.c_A), inside, 1, 1, GWP_FMT, GWP_ARGS(p));
    /* the first bad one in the documented order, with its value */
    const double v[5] = {p.hardness, p.K_v, p.c_h, p.c_A, p.plastic_area};
    int first = -1;
    if (!(isfinite(p.hardness) && p.hardness > 0.0)) first = 0;
    else if (!(isfinite(p.K_v) && p.K_v > 0.0)) first = 1;
    else if (!(isfinite(p.c_h) && p.c_h >= 2.0 / 3.0 * p.K_v)) first = 2;
    else if (!(isfinite(p.c_A) && p.c_A >= 2.0)) first = 3;
    else if (!inside) first = 4;
    FZ_EXPECT(f, st == (inside ? DC_OK : DC_EDOM) &&
                 (st == DC_OK ? UNTOUCHED(err)
                              : first >= 0 && err.name && !strcmp(err.name, names[first]) && err.range &&
                                    memcmp(&err.value, &v[first], sizeof(double)) == 0),
              "wrong status or error report", GWP_FMT ": status %d", GWP_ARGS(p), st);
  }
  fz_done(f);

  /* a summit bound to a geometry (w1, w2 may be 0 or +inf on DC_OK: the
     header's limits of all-plastic and all-elastic summits), and its law */
  f = fz_new("dc_gw_plastic_summit_init");
  fz_fn *fl = fz_new("dc_gw_plastic_summit_law");
  fl->seconds = 0.0;
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const dc_hertz_geom *g = &hpool[UI(nh)];
    const dc_gw_plastic_params p = gwp_params();
    const double E = A(U() < 0.7 ? fz_log(1e9, 1e12) : fz_pos());
    dc_gw_plastic_summit s;
    SENTINEL(s);
    int st = dc_gw_plastic_summit_init(g, E, &p, &s);
    const int ok = !isnan(s.w1) && s.w1 >= 0.0 && s.w2 >= s.w1 && s.lambda >= 1.0 && s.ratio >= 1.0 &&
                   ALLFIN(s.ratio, s.lambda, s.Km, s.c_h, s.inv_log_ratio, s.H, s.Estar, s.R_force, s.R_area);
    FZ_CHECK(f, st, !ALLFIN(p.hardness, p.K_v, p.c_h, p.c_A, E), gwp_params_in(&p) && isfinite(E) && E > 0.0,
             UNTOUCHED(s), ok, "R %.17g %.17g E* %.17g " GWP_FMT, g->R_major, g->R_minor, E, GWP_ARGS(p));
    FZ_EXPECT(f, st != DC_ERANGE, "DC_ERANGE (not among its statuses)", "R %.17g %.17g E* %.17g " GWP_FMT, g->R_major,
              g->R_minor, E, GWP_ARGS(p));
    if (st == DC_OK && ok) {
      if (nsp < POOL) spool[nsp++] = s;
      else spool[UI(POOL)] = s;
    }
    fl->seconds -= fz_now();
    const dc_gw_plastic_summit *sp = st == DC_OK ? &s : &spool[UI(nsp)];
    const double w = sp->w1 > 0.0 && sp->w1 < 1e300 ? sp->w1 : sp->R_force * 1e-6;
    const double om = A(U() < 0.7 ? w * fz_log(1e-3, 1e4) : U() < 0.3 ? PICK(0.0, -0.0, sp->w1, sp->w2) : fz_wide());
    double out[3];
    SENTINEL(out);
    st = dc_gw_plastic_summit_law(sp, om, &out[0], &out[1], &out[2]);
    FZ_CHECK(fl, st, !isfinite(om), isfinite(om), UNTOUCHED(out),
             FIN(out) && out[0] >= 0.0 && out[1] >= 0.0 && out[2] >= 0.0 &&
                 (om > 0.0 || (out[0] == 0.0 && out[1] == 0.0 && out[2] == 0.0)),
             "w1 %.17g w2 %.17g lambda %.17g omega %.17g", sp->w1, sp->w2, sp->lambda, om);
    FZ_EXPECT(fl, st != DC_ERANGE || gwp_summit_bound(sp, om) > LOG_MAX - 2.0, "DC_ERANGE for representable results",
              "w1 %.17g w2 %.17g lambda %.17g E* %.17g H %.17g omega %.17g", sp->w1, sp->w2, sp->lambda, sp->Estar, sp->H, om);
    fl->seconds += fz_now();
  }
  fz_done(f);

  f = fz_new("dc_gw_plastic_integrals");
  for (long k = 0; k < N_GWP; k++) {
    fz_call();
    dc_gw_plastic_shape sh;
    sh.a = A(U() < 0.7 ? fz_log(1e-4, 100.0) : U() < 0.5 ? fz_log(1e-300, 1e300) : PICK(DBL_TRUE_MIN, DBL_MIN, 1.0));
    const double r = U() < 0.6 ? fz_log(1.0, 1e3) : U() < 0.5 ? PICK(1.0, 1e6) : fz_log(1.0, 1e6);
    sh.b = A(sh.a * r);
    sh.lambda = A(U() < 0.5 ? 2.0 : U() < 0.8 ? 1.0 + 15.6 * U() : PICK(1.0));
    sh.Km = A(2.0 / 3.0 * (0.454 + 0.205 * U()) * (U() < 0.8 ? 1.0 : fz_log(1e-3, 1e3)));
    sh.c_h = A(U() < 0.6 ? fmax(1.0, sh.Km) : sh.Km * (U() < 0.3 ? 1.0 : fz_log(1.0, 100.0)));
    const double h = A(gw_h());
    const int bad = !ALLFIN(sh.a, sh.b, sh.lambda, sh.Km, sh.c_h, h);
    const int dom = !bad && sh.a > 0.0 && sh.b > sh.a && sh.b / sh.a <= 1e6 && sh.lambda >= 1.0 && sh.Km > 0.0 &&
                    sh.c_h >= sh.Km && h >= DC_GW_H_MIN;
    dc_gw_plastic_sums J;
    SENTINEL(J);
    const int st = dc_gw_plastic_integrals(&sh, h, &J);
    FZ_CHECK(f, st, bad, dom, UNTOUCHED(J),
             ALLFIN(J.Je, J.Je12, J.Jp, J.Jdp, J.JA) && J.Je >= 0.0 && J.Je12 >= 0.0 && J.Jp >= 0.0 && J.Jdp >= 0.0 &&
                 J.JA >= 0.0 && J.n_panels >= 0,
             "a %.17g b %.17g lambda %.17g Km %.17g c_h %.17g h %.17g", sh.a, sh.b, sh.lambda, sh.Km, sh.c_h, h);
    /* the sums <= lambda c_h (1 + 1.5 rho/(rho - 1) + 1/ln rho) max(b + |h|, 1)^3/2 (rho = b/a) */
    const double rho = sh.b / sh.a, fac = 1.0 + 1.5 * rho / (rho - 1.0) + 1.0 / log(rho);
    FZ_EXPECT(f, st != DC_ERANGE || !dom || lg(sh.lambda) + lg(sh.c_h) + lg(fac) + 1.5 * fmax(lg(sh.b + fabs(h)), 0.0) > LOG_MAX - 3.0,
              "DC_ERANGE for representable sums", "a %.17g b %.17g lambda %.17g Km %.17g c_h %.17g h %.17g", sh.a, sh.b,
              sh.lambda, sh.Km, sh.c_h, h);
  }
  fz_done(f);

  /* the rough contact: sigma around the yield compression w1, so that the
     regimes meet on the summits' Gaussian */
  f = fz_new("dc_gw_rough_plastic");
  for (long k = 0; k < N_GWP; k++) {
    fz_call();
    const dc_hertz_geom *g = &hpool[UI(nh)];
    const double E = A(U() < 0.6 ? fz_log(1e9, 1e12) : fz_pos());
    const dc_gw_plastic_params p = gwp_params();
    const double n = A(U() < 0.6 ? fz_log(1e-2, 1e6) : fz_pos());
    dc_gw_plastic_summit sm;
    const int si = dc_gw_plastic_summit_init(g, E, &p, &sm);
    const double w1 = si == DC_OK && sm.w1 > 0.0 && sm.w1 < 1e300 ? sm.w1 : g->R_minor * 1e-6;
    const double sg = A(U() < 0.5 ? w1 * fz_log(1e-3, 1e3) : U() < 0.4 ? g->R_minor * fz_log(1e-9, 1e-3)
                        : U() < 0.3 ? PICK(0.0, DBL_TRUE_MIN, DBL_MIN) : fz_pos());
    const double d = A(U() < 0.5 ? sg * (-12.0 + 60.0 * U()) : U() < 0.4 ? w1 * fz_log(1e-2, 1e3)
                       : U() < 0.2 ? PICK(0.0, -0.0) : fz_wide());
    const int bad = !ALLFIN(E, n, sg, d, p.hardness, p.K_v, p.c_h, p.c_A);
    dc_gw_rough_state s;
    SENTINEL(s);
    const int st = dc_gw_rough_plastic(g, E, &p, n, sg, d, &s);
    FZ_CHECK(f, st, bad, !bad && E > 0.0 && n > 0.0 && sg >= 0.0 && gwp_params_in(&p), UNTOUCHED(s),
             FIN(s) && s.F >= 0.0 && s.kn >= 0.0 && s.area >= 0.0,
             "R %.17g %.17g E* %.17g " GWP_FMT " n_asp %.17g sigma %.17g delta %.17g", g->R_major, g->R_minor, E,
             GWP_ARGS(p), n, sg, d);
    FZ_EXPECT(f, st != DC_ERANGE || (si == DC_OK && gwp_rough_bound(g, &sm, n, sg, d) > LOG_MAX - 3.0),
              "DC_ERANGE for a representable state", "R %.17g %.17g E* %.17g " GWP_FMT " n_asp %.17g sigma %.17g delta %.17g",
              g->R_major, g->R_minor, E, GWP_ARGS(p), n, sg, d);
  }
  fz_done(f);

  /* the rough flat: its domain ends at h = -delta/sigma >= DC_GW_H_MIN */
  f = fz_new("dc_gw_plastic_flat");
  for (long k = 0; k < N_GWP; k++) {
    fz_call();
    const dc_gw_plastic_params p = gwp_params();
    const double E = A(U() < 0.6 ? fz_log(1e9, 1e12) : fz_pos()), Rs = A(U() < 0.6 ? fz_log(1e-8, 1e-3) : fz_pos());
    const double eta = A(U() < 0.6 ? fz_log(1e8, 1e14) : fz_pos());
    const double sg = A(U() < 0.6 ? fabs(Rs) * fz_log(1e-7, 1e-2) : U() < 0.2 ? PICK(DBL_TRUE_MIN, DBL_MIN) : fz_pos());
    const double d = A(U() < 0.6 ? sg * (-12.0 + 60.0 * U()) : U() < 0.2 ? PICK(0.0, -0.0) : fz_wide());
    const int bad = !ALLFIN(E, Rs, eta, sg, d, p.hardness, p.K_v, p.c_h, p.c_A);
    const double h = -d / sg;
    const int dom = !bad && E > 0.0 && Rs > 0.0 && eta > 0.0 && sg > 0.0 && gwp_params_in(&p) && h >= DC_GW_H_MIN;
    dc_gw_plastic_flat_state s;
    SENTINEL(s);
    const int st = dc_gw_plastic_flat(&p, E, Rs, eta, sg, d, &s);
    FZ_CHECK(f, st, bad, dom, UNTOUCHED(s), FIN(s) && s.p >= 0.0 && s.area_ratio >= 0.0 && s.dp >= 0.0 && s.h == h,
             GWP_FMT " E* %.17g R_s %.17g eta %.17g sigma %.17g delta %.17g", GWP_ARGS(p), E, Rs, eta, sg, d);
    if (st == DC_ERANGE) {
      dc_hertz_geom gs;
      dc_gw_plastic_summit sm;
      const int known = dc_hertz_geometry(Rs, Rs, &gs) == DC_OK && dc_gw_plastic_summit_init(&gs, E, &p, &sm) == DC_OK;
      FZ_EXPECT(f, !known || gwp_rough_bound(&gs, &sm, eta, sg, d) > LOG_MAX - 3.0 || lg(h) > LOG_MAX - 1.0,
                "DC_ERANGE for a representable state", GWP_FMT " E* %.17g R_s %.17g eta %.17g sigma %.17g delta %.17g",
                GWP_ARGS(p), E, Rs, eta, sg, d);
    }
  }
  fz_done(f);
}

/* ---------------------------------------------------------------- */
/* gw_rough_table.h                                                   */

/* dc_gw_table_init builds a spline through 209 nodes (~20 us): 5000 calls. */
#define N_TABLE_INIT 5000L

static dc_gw_table_law tlpool[8];
static int ntl;
static dc_gw_table_law tl_out;     /* 6.7 kB each: static */
static dc_gw_table_pair tp_out;

static void fuzz_gw_table(void)
{
  fuzz_law_check("dc_gw_table_check", dc_gw_table_check, DC_GW_TABLE_MU_MIN, 0, DC_GW_TABLE_MU_MAX, 1.0, 50.0);
  fz_fn *f = fz_new("dc_gw_table_node");
  for (long k = 0; k < N_CALLS; k++) {
    const int i = UI(DC_GW_TABLE_NNODE);
    const double x = dc_gw_table_node(i), y = i + 1 < DC_GW_TABLE_NNODE ? dc_gw_table_node(i + 1) : INFINITY;
    f->calls++;
    FZ_EXPECT(f, isfinite(x) && x < y && (i != 0 || x == DC_GW_TABLE_X_LO) &&
                 (i != DC_GW_TABLE_NNODE - 1 || x == DC_GW_TABLE_X_HI),
              "not increasing from X_LO to X_HI", "node %d: %.17g, next %.17g", i, x, y);
  }
  fz_done(f);

  f = fz_new("dc_gw_table_init");
  for (long k = 0; k < N_TABLE_INIT; k++) {
    fz_call();
    const double mu = A(U() < 0.6 ? 1.0 + 49.0 * U() : U() < 0.5 ? fz_log(1.0, 50.0) : PICK(1.0, 50.0, 2.0, 4.0, 25.0));
    SENTINEL(tl_out);
    const int st = dc_gw_table_init(mu, &tl_out);
    FZ_CHECK(f, st, !isfinite(mu), mu >= DC_GW_TABLE_MU_MIN && mu <= DC_GW_TABLE_MU_MAX, UNTOUCHED(tl_out),
             FIN(tl_out) && tl_out.mu == mu, "mu %.17g", mu);
    if (st == DC_OK) {
      if (ntl < 8) tlpool[ntl++] = tl_out;
      else if (U() < 0.05) tlpool[UI(8)] = tl_out;
    }
  }
  fz_done(f);

  /* P* >= 0, nondecreasing; DC_ERANGE only where alpha'^3/2 overflows */
  f = fz_new("dc_gw_table_pstar");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const dc_gw_table_law *L = &tlpool[UI(ntl)];
    const double ap = A(U() < 0.5 ? -8.0 + 20.0 * U() : U() < 0.4 ? fz_sign(fz_log(1e-3, 1e5))
                        : U() < 0.5 ? PICK(-6.0, -6.0 + 1.0 / 16, 0.0, -0.0, 1.0, 4096.0) : fz_wide());
    double P[2];
    SENTINEL(P);
    const int st = dc_gw_table_pstar(L, ap, &P[0], &P[1]);
    FZ_CHECK(f, st, !isfinite(ap), isfinite(ap), UNTOUCHED(P), FIN(P) && P[0] >= 0.0 && P[1] >= 0.0,
             "mu %.17g alpha' %.17g: %.17g %.17g", L->mu, ap, P[0], P[1]);
    FZ_EXPECT(f, st != DC_ERANGE || 1.5 * lg(ap) > LOG_MAX - 1.0, "DC_ERANGE for a representable P*",
              "mu %.17g alpha' %.17g", L->mu, ap);
  }
  fz_done(f);

  f = fz_new("dc_gw_table_force");
  fz_fn *fp = fz_new("dc_gw_table_pair_init");
  fz_fn *ff = fz_new("dc_gw_table_pair_force");
  fp->seconds = ff->seconds = 0.0;
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const dc_gw_table_law *L = &tlpool[UI(ntl)];
    const double E = A(U() < 0.3 ? fz_log(1e5, 1e12) : fz_pos());
    const double R = A(U() < 0.3 ? fz_log(1e-6, 1.0) : fz_pos());
    const double sg = A(U() < 0.3 ? fabs(R) * fz_log(1e-9, 1e-2) : U() < 0.3 ? PICK(0.0, DBL_TRUE_MIN, DBL_MIN, 1e-310) : fz_pos());
    const double d = A(U() < 0.6 ? sg * (-8.0 + 16.0 * U()) : U() < 0.2 ? sg * fz_log(1.0, 1e5)
                       : U() < 0.1 ? PICK(0.0, -0.0) : fz_wide());
    const int bad = !ALLFIN(E, R, sg, d);
    double out[2];
    SENTINEL(out);
    const int st = dc_gw_table_force(L, E, R, sg, d, &out[0], &out[1]);
    FZ_CHECK(f, st, bad, !bad && E > 0.0 && R > 0.0 && sg >= 0.0, UNTOUCHED(out),
             FIN(out) && out[0] >= 0.0 && out[1] >= 0.0, "mu %.17g E* %.17g R %.17g sigma %.17g delta %.17g", L->mu, E, R,
             sg, d);
    /* P <= 4/3 E* R^1/2 max(|delta|, 6 sigma)^3/2 max P* (P* < 30 there), kn likewise */
    const double x = fmax(fabs(d), 6.0 * sg);
    const double b = lg(E) + 0.5 * lg(R) + 0.5 * lg(x) + fmax(lg(x), 0.0) + lg(40.0);
    FZ_EXPECT(f, st != DC_ERANGE || b > LOG_MAX - 2.0, "DC_ERANGE for a representable force",
              "mu %.17g E* %.17g R %.17g sigma %.17g delta %.17g", L->mu, E, R, sg, d);
    /* the bound pair: sigma > 0; DC_ERANGE only where its constants do not fit */
    fp->seconds -= fz_now();
    SENTINEL(tp_out);
    const int sp = dc_gw_table_pair_init(L, E, sg, &tp_out);
    fp->seconds += fz_now();
    FZ_CHECK(fp, sp, !isfinite(E) || !isfinite(sg), isfinite(E) && isfinite(sg) && E > 0.0 && sg > 0.0,
             UNTOUCHED(tp_out), FIN(tp_out) && !memcmp(&tp_out.law, L, sizeof *L), "mu %.17g E* %.17g sigma %.17g",
             L->mu, E, sg);
    const double lc = lg(4.0 / 3.0) + lg(E), lcs = lc + 1.5 * lg(sg);
    FZ_EXPECT(fp, sp != DC_ERANGE || lc > LOG_MAX - 1.0 || -lg(sg) > LOG_MAX - 1.0 || lcs > LOG_MAX - 1.0 ||
                      lcs < log(DBL_MIN) + 1.0,
              "DC_ERANGE for representable constants", "E* %.17g sigma %.17g", E, sg);
    if (sp != DC_OK || !(R > 0.0 && isfinite(R))) continue;
    /* the unchecked kernel: the checked force's value wherever it is
       finite (the force evaluates the same kernel first); NaN delta: 0 */
    for (int j = 0; j < 3; j++) {
      const double dj = j == 0 ? d : U() < 0.7 ? sg * (-8.0 + 16.0 * U()) : U() < 0.2 ? NAN : fz_wide();
      double o[2] = {out[0], out[1]};
      int sj = st;
      if (j > 0) sj = dc_gw_table_force(L, E, R, sg, dj, &o[0], &o[1]);
      ff->seconds -= fz_now();
      double q[2];
      dc_gw_table_pair_force(&tp_out, sqrt(R), dj, &q[0], &q[1]);
      ff->seconds += fz_now();
      ff->calls++;
      if (isnan(dj))
        FZ_EXPECT(ff, q[0] == 0.0 && q[1] == 0.0, "not 0 for NaN delta", "mu %.17g E* %.17g R %.17g sigma %.17g", L->mu, E,
                  R, sg);
      else if (isfinite(dj) && FIN(q))
        FZ_EXPECT(ff, sj == DC_OK && q[0] == o[0] && q[1] == o[1], "differs from dc_gw_table_force",
                  "mu %.17g E* %.17g R %.17g sigma %.17g delta %.17g: %.17g %.17g vs %.17g %.17g", L->mu, E, R, sg, dj,
                  q[0], q[1], o[0], o[1]);
    }
  }
  fz_done(f);
}

/* ---------------------------------------------------------------- */
/* gw_rough_adhesive_table.h                                          */

static dc_gwa_table_pair gapool[64];
static int nga;

/* log of a bound on the force and stiffness: |G| < 1, |dG/dx| < e^12
   (tau <= e^8 after the clamp) */
static double gwa_bound(const dc_gwa_table_pair *p, double R)
{
  return lg(p->F_coef) + lg(R) + fmax(0.0, lg(p->inv_sigma) + 12.0);
}

#define GWA_FMT "E* %.17g w %.17g sigma %.17g n_asp %.17g R %.17g"
#define GWA_ARGS(p, R) (p)->Estar, (p)->w, (p)->sigma, (p)->n_asp, (R)

/* The step fuzz's contact, now and then a new one: history cleared, pair,
   radius R0 (rho given: the ratio of its radii too), the overlap x 10
   scales sc apart (sc: sigma or one summit's |delta_break|) */
static void gwa_new_contact(double *hist, const dc_gwa_table_pair **p, double *R0, double *rho, double *sc, double *x)
{
  if (!(U() < 0.01)) return;
  hist[0] = hist[1] = 0.0;
  *p = &gapool[UI(nga)];
  *R0 = U() < 0.8 ? fz_log(1e-6, 1e-1) : fz_pos();
  if (rho) *rho = U() < 0.8 ? fz_log(1e-4, 1.0) : fz_log(1e-14, 1.0);
  *sc = fmax((*p)->sigma, -(*p)->ub * (*p)->dc_coef * cbrt(*R0));
  *x = -10.0 * *sc;
}

static void fuzz_gwa_table(void)
{
  fz_fn *f = fz_new("dc_gwa_table_x_near, _x_deep");
  for (long k = 0; k < N_CALLS; k++) {
    const int i = UI(DC_GWA_TABLE_NNEAR), kd = DC_GWA_TABLE_K_MIN + UI(DC_GWA_TABLE_NDEEP - 1);
    const double x = dc_gwa_table_x_near(i), y = dc_gwa_table_x_near(i + 1);
    const double u = dc_gwa_table_x_deep(kd + 1), v = dc_gwa_table_x_deep(kd);
    f->calls++;
    FZ_EXPECT(f, isfinite(x) && x < y && (i != 0 || x == DC_GWA_TABLE_X_LO) &&
                 (i + 1 != DC_GWA_TABLE_NNEAR || y == DC_GWA_TABLE_X_HI) && isfinite(u) && u < v && v < 0.0,
              "nodes not increasing from X_LO to X_HI, or deep nodes not decreasing below 0",
              "near node %d: %.17g, next %.17g; deep node %d: %.17g, next %.17g", i, x, y, kd, v, u);
  }
  fz_done(f);

  f = fz_new("dc_gwa_table_check");
  fz_fn *fp = fz_new("dc_gwa_table_pair_init");
  fp->seconds = 0.0;
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const double E = A(U() < 0.6 ? fz_log(1e5, 1e12) : fz_pos());
    const double w = A(U() < 0.1 ? 0.0 : U() < 0.6 ? fz_log(1e-3, 1.0) : fz_pos());
    const double sg = A(U() < 0.6 ? fz_log(1e-10, 1e-5) : U() < 0.2 ? PICK(DBL_TRUE_MIN, DBL_MIN, 0.0) : fz_pos());
    const double n = A(U() < 0.6 ? fz_log(1e-2, 1e6) : fz_pos());
    const fz_spec t[4] = {{"youngsModulus (E*)", E, 1, pos_fin(E)},
                          {"workOfAdhesion", w, 1, nonneg_fin(w)},
                          {"roughness", sg, 1, pos_fin(sg)},
                          {"asperityCount", n, 1, pos_fin(n)}};
    fz_field fl[4];
    int bad;
    const int inside = fz_fields(t, 4, 0, fl, &bad);
    dc_param_error err;
    SENTINEL(err);
    const int st = dc_gwa_table_check(E, w, sg, n, &err);
    FZ_CHECK(f, st, bad, inside, 1, 1, "E* %.17g w %.17g sigma %.17g n_asp %.17g", E, w, sg, n);
    FZ_EXPECT(f, st == (inside ? DC_OK : DC_EDOM) && (st == DC_OK ? UNTOUCHED(err) : err_names(&err, fl, 4)),
              "wrong status or error report", "E* %.17g w %.17g sigma %.17g n_asp %.17g: status %d", E, w, sg, n, st);
    fp->seconds -= fz_now();
    dc_gwa_table_pair p;
    SENTINEL(p);
    const int sp = dc_gwa_table_pair_init(E, w, sg, n, &p);
    FZ_CHECK(fp, sp, bad, inside, UNTOUCHED(p),
             FIN(p) && p.Estar == E && p.w == w && p.sigma == sg && p.n_asp == n && (w == 0.0 || (p.ub < 0.0 && p.dc_coef > 0.0)),
             "E* %.17g w %.17g sigma %.17g n_asp %.17g", E, w, sg, n);
    /* DC_ERANGE only where 8 w n_asp, 1/sigma or delta_c = (8 w/(pi E*))^2/3 / 2 leave the doubles */
    const double ldc = log(0.5) + 2.0 / 3.0 * (lg(8.0 / M_PI) + lg(w) - lg(E));
    FZ_EXPECT(fp, sp != DC_ERANGE || lg(8.0) + lg(w) + lg(n) > LOG_MAX - 1.0 || -lg(sg) > LOG_MAX - 1.0 ||
                      (w > 0.0 && (ldc > LOG_MAX - 1.0 || ldc < log(DBL_MIN) + 1.0)),
              "DC_ERANGE for representable constants", "E* %.17g w %.17g sigma %.17g n_asp %.17g", E, w, sg, n);
    if (sp == DC_OK) {
      if (nga < 64) gapool[nga++] = p;
      else gapool[UI(64)] = p;
    }
    fp->seconds += fz_now();
  }
  fz_done(f);

  /* G <= 0 and bounded (-pi/8 deep in compression, -> 0 apart): no overflow */
  f = fz_new("dc_gwa_table_reduced");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const int br = AI(UI(2));
    const double x = A(U() < 0.4 ? -300.0 + 320.0 * U() : U() < 0.4 ? fz_sign(fz_log(1e-3, 1e6))
                       : U() < 0.5 ? PICK(-256.0, -8.0, -8.0 + 1.0 / 16, 8.0, 0.0, -0.0) : fz_wide());
    const double eta = A(U() < 0.7 ? -6.0 + 16.0 * U() : U() < 0.5 ? PICK(-4.5, 8.0, 0.0) : fz_wide());
    double out[2];
    SENTINEL(out);
    const int st = dc_gwa_table_reduced(br, x, eta, &out[0], &out[1]);
    FZ_CHECK(f, st, !ALLFIN(x, eta), ALLFIN(x, eta) && (br == DC_GW_LOADING || br == DC_GW_UNLOADING), UNTOUCHED(out),
             FIN(out) && out[0] <= 0.0, "branch %d x %.17g eta %.17g", br, x, eta);
    FZ_EXPECT(f, st != DC_ERANGE, "DC_ERANGE for a bounded G", "branch %d x %.17g eta %.17g", br, x, eta);
  }
  fz_done(f);

  f = fz_new("dc_gwa_table_force");
  fz_fn *fr = fz_new("dc_gwa_table_reach");
  fr->seconds = 0.0;
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const dc_gwa_table_pair *p = &gapool[UI(nga)];
    const double R = A(U() < 0.6 ? fz_log(1e-6, 1e-1) : fz_pos());
    const double db = -p->ub * p->dc_coef * cbrt(fabs(R));   /* |delta_break| */
    const double d = A(U() < 0.4 ? p->sigma * (-20.0 + 30.0 * U()) : U() < 0.5 ? db * (-3.0 + 6.0 * U())
                       : U() < 0.2 ? PICK(0.0, -0.0) : fz_wide());
    const int br = AI(UI(2));
    const int bad = !ALLFIN(R, d);
    double out[2];
    SENTINEL(out);
    const int st = dc_gwa_table_force(p, R, br, d, &out[0], &out[1]);
    FZ_CHECK(f, st, bad, !bad && R > 0.0 && (br == DC_GW_LOADING || br == DC_GW_UNLOADING), UNTOUCHED(out),
             FIN(out) && out[0] <= 0.0 && (p->w != 0.0 || (out[0] == 0.0 && out[1] == 0.0)),
             GWA_FMT " branch %d delta %.17g", GWA_ARGS(p, R), br, d);
    FZ_EXPECT(f, st != DC_ERANGE || gwa_bound(p, R) > LOG_MAX - 3.0, "DC_ERANGE for representable results",
              GWA_FMT " branch %d delta %.17g", GWA_ARGS(p, R), br, d);
    /* the reach (D + 8) sigma >= 8 sigma, finite where representable */
    fr->seconds -= fz_now();
    const double Rr = fabs(R), r = dc_gwa_table_reach(p, Rr);
    fr->calls++;
    if (Rr > 0.0 && isfinite(Rr))
      FZ_EXPECT(fr, r >= 8.0 * p->sigma && (isfinite(r) || fmax(lg(-p->ub * p->dc_coef) + lg(Rr) / 3.0, lg(8.0 * p->sigma)) > LOG_MAX - 1.0),
                "not (D + 8) sigma", GWA_FMT ": %.17g", GWA_ARGS(p, Rr), r);
    fr->seconds += fz_now();
  }
  fz_done(f);

  /* the step: chains of calls on one history (a contact), overlaps
     wandering through loading, the blend and unloading, now and then wild
     inputs or a corrupted history (its content: touched 0 or 1, the
     largest overlap finite) */
  f = fz_new("dc_gwa_table_step");
  double hist[2] = {0.0, 0.0}, R0 = 1e-3, x = 0.0, sc = 1e-8;
  const dc_gwa_table_pair *p = &gapool[0];
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    gwa_new_contact(hist, &p, &R0, NULL, &sc, &x);
    if (U() < 0.003) hist[UI(2)] = U() < 0.5 ? fz_wild() : fz_wide();
    x += sc * fz_sign(fz_log(1e-3, 3.0));
    if (U() < 0.01) x = -10.0 * sc;
    const double R = A(R0), d = A(x), h0[2] = {hist[0], hist[1]};
    const int bad = !ALLFIN(R, d, hist[0], hist[1]);
    const int dom = !bad && R > 0.0 && (hist[0] == 0.0 || hist[0] == 1.0);
    dc_gwa_table_out o;
    SENTINEL(o);
    /* the same step with the radius set up once (the DEM path) */
    dc_gwa_table_radius rr;
    dc_gwa_table_out o2;
    double hist2[2] = {h0[0], h0[1]};
    SENTINEL(o2);
    const int sr = dc_gwa_table_radius_init(p, R, &rr);
    const int st2 = sr == DC_OK ? dc_gwa_table_step_radius(p, &rr, d, hist2, &o2) : sr;
    /* and with the contact's record (one per contact: set up again when
       the contact's R or pair changes, its last cell kept across steps) */
    static dc_gwa_table_contact con;
    static const dc_gwa_table_pair *con_p;
    dc_gwa_table_out o3;
    double hist3[2] = {h0[0], h0[1]};
    SENTINEL(o3);
    int st3 = sr;
    if (sr == DC_OK && (con.R != R || con_p != p)) {
      const int si = dc_gwa_table_contact_init(p, R, &con);
      FZ_EXPECT(f, si == DC_OK && con.cell[0] == 0.0, "dc_gwa_table_contact_init fails where _radius_init does not",
                GWA_FMT ": status %d", GWA_ARGS(p, R), si);
      con_p = p;
    }
    if (sr == DC_OK) st3 = dc_gwa_table_step_contact(p, &con, d, hist3, &o3);
    FZ_EXPECT(f, st3 == st2 && !memcmp(&o3, &o2, sizeof o2) && !memcmp(hist3, hist2, sizeof hist2),
              "dc_gwa_table_step_contact differs from dc_gwa_table_step_radius",
              GWA_FMT " delta %.17g: status %d vs %d", GWA_ARGS(p, R), d, st3, st2);
    const int st = dc_gwa_table_step(p, R, d, hist, &o);
    FZ_CHECK(f, st, bad, dom, UNTOUCHED(o) && !memcmp(hist, h0, sizeof hist),
             FIN(o) && o.F <= 0.0 && o.weight >= 0.0 && o.weight <= 1.0 && fin(hist, 2),
             GWA_FMT " delta %.17g history %.17g %.17g", GWA_ARGS(p, R), d, h0[0], h0[1]);
    FZ_EXPECT(f, sr != DC_OK ? st != DC_OK || !dom
                             : st2 == st && (st != DC_OK || (!memcmp(&o2, &o, sizeof o) && !memcmp(hist2, hist, sizeof hist))),
              "dc_gwa_table_radius_init + _step_radius differ from dc_gwa_table_step",
              GWA_FMT " delta %.17g: status %d vs %d", GWA_ARGS(p, R), d, st2, st);
    if (st == DC_OK && dom) {
      if (p->w == 0.0 || dc_gwa_table_apart(p, d, h0))
        FZ_EXPECT(f, o.F == 0.0 && o.kn == 0.0 && o.weight == 0.0 && !memcmp(hist, h0, sizeof hist),
                  "w = 0 or apart: not zero, or the history written", GWA_FMT " delta %.17g", GWA_ARGS(p, R), d);
      else {
        /* loading while delta >= the largest overlap; the history holds it */
        FZ_EXPECT(f, (hist[0] == 0.0 || (hist[0] == 1.0 && hist[1] >= d)) && ((h0[0] != 0.0 && d < h0[1]) || o.weight == 0.0),
                  "history or branch rule broken", GWA_FMT " delta %.17g history %.17g %.17g: weight %.17g, %.17g %.17g",
                  GWA_ARGS(p, R), d, h0[0], h0[1], o.weight, hist[0], hist[1]);
        /* loading, or clearly past the blend (2 |delta_break| below the
           largest overlap): dc_gwa_table_force's value on that branch */
        const int loading = h0[0] == 0.0 || d >= h0[1];
        if (loading || d <= h0[1] + 2.0 * p->ub * p->dc_coef * cbrt(R)) {
          double q[2];
          const int sq = dc_gwa_table_force(p, R, loading ? DC_GW_LOADING : DC_GW_UNLOADING, d, &q[0], &q[1]);
          FZ_EXPECT(f, sq == DC_OK && q[0] == o.F && q[1] == o.kn, "differs from dc_gwa_table_force on its branch",
                    GWA_FMT " delta %.17g weight %.17g: %.17g %.17g vs %.17g %.17g (status %d)", GWA_ARGS(p, R), d,
                    o.weight, o.F, o.kn, q[0], q[1], sq);
        }
      }
    }
    /* the band adds dw/d delta (F_U - F_L), |dw/d delta| up to about
       1/|delta_break| = 1/(D sigma): a further factor 1/D */
    const double Dr = -p->ub * p->dc_coef * cbrt(fabs(R)) * p->inv_sigma;
    FZ_EXPECT(f, st != DC_ERANGE || gwa_bound(p, R) + fmax(0.0, -lg(Dr)) > LOG_MAX - 3.0,
              "DC_ERANGE for representable results", GWA_FMT " delta %.17g", GWA_ARGS(p, R), d);
    if (st != DC_OK && U() < 0.5) hist[0] = hist[1] = 0.0;
  }
  fz_done(f);
}

/* Elliptic summits (dc_gwa_table_radius_init_elliptic): a contact's
   radii wander (ratio 1 to 1e-14, now and then wild), the overlap through
   loading, the band and unloading; the step's contract as for circles,
   and the set-up untouched on error. */
static void fuzz_gwa_elliptic(void)
{
  fz_fn *fi = fz_new("dc_gwa_table_radius_init_elliptic");
  fz_fn *f = fz_new("dc_gwa_table_step_radius (elliptic)");
  double hist[2] = {0.0, 0.0}, R0 = 1e-3, rho = 0.5, x = 0.0, sc = 1e-8;
  const dc_gwa_table_pair *p = &gapool[0];
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    gwa_new_contact(hist, &p, &R0, &rho, &sc, &x);
    x += sc * fz_sign(fz_log(1e-3, 3.0));
    if (U() < 0.01) x = -10.0 * sc;
    const double Rmaj = A(R0), Rmin = A(rho * R0), d = A(x), h0[2] = {hist[0], hist[1]};
    dc_gwa_table_radius r;
    SENTINEL(r);
    const int si = dc_gwa_table_radius_init_elliptic(p, Rmaj, Rmin, &r);
    const int dom_i = ALLFIN(Rmaj, Rmin) && Rmin > 0.0 && Rmaj >= Rmin;
    FZ_CHECK(fi, si, !ALLFIN(Rmaj, Rmin), dom_i, UNTOUCHED(r),
             isfinite(r.R) && isfinite(r.Fs) && isfinite(r.db) && !isnan(r.D) && isfinite(r.reach) &&
                 isfinite(r.ell.ke) && (p->w == 0.0 || (r.ell.rho >= DC_GWAE_RHO_MIN && r.ell.rho <= 1.0)),
             GWA_FMT " R_minor %.17g", GWA_ARGS(p, Rmaj), Rmin);
    if (si != DC_OK) continue;
    dc_gwa_table_out o;
    SENTINEL(o);
    const int bad = !ALLFIN(d, hist[0], hist[1]);
    const int st = dc_gwa_table_step_radius(p, &r, d, hist, &o);
    FZ_CHECK(f, st, bad, !bad, UNTOUCHED(o) && !memcmp(hist, h0, sizeof hist),
             FIN(o) && o.F <= 0.0 && o.weight >= 0.0 && o.weight <= 1.0 && fin(hist, 2),
             GWA_FMT " R_minor %.17g delta %.17g history %.17g %.17g", GWA_ARGS(p, Rmaj), Rmin, d, h0[0], h0[1]);
    /* an overflow only where the circle's products are near the doubles'
       end, or the blend's slope term (FU - FL) dw/d delta, dw/d delta of
       order 1/|delta_break|: an ellipse's |delta_break| (from R_minor) may
       lie far below sigma */
    FZ_EXPECT(f, st != DC_ERANGE || lg(p->F_coef) + lg(Rmaj) + fmax(0.0, fmax(lg(p->inv_sigma), -lg(r.db)) + 12.0) > LOG_MAX - 12.0,
              "DC_ERANGE for representable results",
              GWA_FMT " R_minor %.17g delta %.17g", GWA_ARGS(p, Rmaj), Rmin, d);
    if (st != DC_OK) hist[0] = hist[1] = 0.0;
  }
  fz_done(fi);
  fz_done(f);
}

/* ---------------------------------------------------------------- */
/* rolling_kalker.h                                                   */

/* dc_rolling_material_init sums the creep coefficient series on 129
   points (~60 us), dc_kalker_coefficients_nu the series at every node
   (~25 us): 2000 and 5000 calls. */
#define N_ROLL_MAT 2000L
#define N_KALKER_NU 5000L

static dc_rolling_material rmpool[8];
static int nrm;
static dc_rolling_material rm_out;   /* 4.3 kB */

/* four coefficients c11, c22, c23, c33: finite and positive */
static int coef4_ok(const double *c) { return fin(c, 4) && c[0] > 0.0 && c[1] > 0.0 && c[2] > 0.0 && c[3] > 0.0; }
static int kalker_ok(const dc_kalker_coef *c) { return coef4_ok((const double[]){c->c11, c->c22, c->c23, c->c33}); }

/* one body's curvatures in the plane (u, v): a flat, a sphere or any
   ellipse, now and then concave or wild; d1 unit in the plane */
static void rolling_curvature(const double *u, const double *v, dc_rolling_curvature *c)
{
  const double s = U() < 0.7 ? fz_log(1e-1, 1e4) : fz_log(1e-300, 1e300), r = U();
  c->k1 = r < 0.15 ? 0.0 : s;
  c->k2 = r < 0.15 ? 0.0 : r < 0.4 ? c->k1 : c->k1 * (U() < 0.8 ? U() : fz_log(1e-15, 1.0));
  if (U() < 0.05) c->k2 = -0.5 * U() * c->k1;
  if (U() < 0.3) { const double t = c->k1; c->k1 = c->k2; c->k2 = t; }
  const double th = 2.0 * M_PI * U();
  for (int i = 0; i < 3; i++) c->d1[i] = cos(th) * u[i] + sin(th) * v[i];
  c->k1 = A(c->k1);
  c->k2 = A(c->k2);
  for (int i = 0; i < 3; i++) c->d1[i] = c->k1 == c->k2 && U() < 0.1 ? fz_wild() : A(c->d1[i]);
}

/* the kinematics' promises: V >= 0, ex unit and in the plane as n is
   (within 1e-6) for V > 0, zero for V = 0, all finite */
/* (the header: where the normal part of dv exceeds its tangential part by
   1e12 and more, rounding of the normal part rules the slip and the
   direction; then only finite outputs are promised) */
static int rolling_kin_ok(const dc_rolling_kin *k, const double *n, const double *dv)
{
  const double ee = dot3(k->ex, k->ex), nn = dot3(n, n), dvn = dot3(dv, n);
  const double t[3] = {dv[0] - dvn * n[0], dv[1] - dvn * n[1], dv[2] - dvn * n[2]};
  if (!(max_abs3(t) >= 1e-12 * max_abs3(dv))) return FIN(*k) && k->V >= 0.0;
  return FIN(*k) && k->V >= 0.0 &&
         (k->V > 0.0 ? fabs(ee - 1.0) <= 1e-14 + 4.0 * fabs(nn - 1.0) && fabs(dot3(k->ex, n)) <= 2e-6 : ee == 0.0);
}

/* its tensor in the plane (u, v) */
static void rolling_tensor(const dc_rolling_curvature *c, const double *u, const double *v, double K[3])
{
  if (c->k1 == c->k2) {
    K[0] = K[2] = c->k1;
    K[1] = 0.0;
    return;
  }
  const double x = dot3(c->d1, u), y = dot3(c->d1, v), d = c->k1 - c->k2;
  K[0] = c->k2 + d * x * x;
  K[1] = d * x * y;
  K[2] = c->k2 + d * y * y;
}

/* d1 as the domain asks (unit, in the plane within 1e-6), or better than
   tol; a sphere's is not read */
static int rolling_d1_ok(const dc_rolling_curvature *c, const double *n, double tol)
{
  return c->k1 == c->k2 || (fabs(dot3(c->d1, c->d1) - 1.0) <= tol && fabs(dot3(c->d1, n)) <= tol);
}

static void fuzz_rolling(void)
{
  static const char *names[3] = {"coefficientFriction", "rollingVelocityMin", "rollingCreepModel"};
  fz_fn *f = fz_new("dc_rolling_check");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const dc_rolling_params p = {A(U() < 0.8 ? U() : PICK(0.0, -0.0, 1e300)),
                                 A(U() < 0.8 ? fz_log(1e-9, 1e-1) : PICK(0.0, DBL_TRUE_MIN, -1e-6)), AI(UI(2)), 0.0};
    const fz_spec t[3] = {{names[0], p.mu, 1, nonneg_fin(p.mu)},
                          {names[1], p.v_min, 1, pos_fin(p.v_min)},
                          {names[2], p.model, 1, p.model == DC_ROLLING_KALKER || p.model == DC_ROLLING_VJ}};
    fz_field fl[3];
    int bad;
    const int inside = fz_fields(t, 3, 0, fl, &bad);
    dc_param_error err;
    SENTINEL(err);
    const int st = dc_rolling_check(&p, &err);
    FZ_CHECK(f, st, !ALLFIN(p.mu, p.v_min), inside, 1, 1, "mu %.17g v_min %.17g model %d", p.mu, p.v_min, p.model);
    FZ_EXPECT(f, st == (inside ? DC_OK : DC_EDOM) && (st == DC_OK ? UNTOUCHED(err) : err_names(&err, fl, 3)),
              "wrong status or error report", "mu %.17g v_min %.17g model %d: status %d", p.mu, p.v_min, p.model, st);
  }
  fz_done(f);

  f = fz_new("dc_rolling_material_init");
  for (long k = 0; k < N_ROLL_MAT; k++) {
    fz_call();
    const double s0 = U() < 0.6 ? fz_log(1e-12, 1e-8) : fz_pos(), nu = U() < 0.8 ? -0.1 + 0.7 * U() : PICK(0.0, 0.5, -0.0);
    const dc_mindlin_pair m = {A(s0), A(s0 * nu)};
    const double q = m.s1 / m.s0;
    const int inside = isfinite(m.s0) && m.s0 > 0.0 && 2.0 / m.s0 <= DBL_MAX && q >= 0.0 && q <= 0.5;
    dc_param_error err;
    SENTINEL(err);
    SENTINEL(rm_out);
    const int st = dc_rolling_material_init(&m, &rm_out, &err);
    int ok = FIN(rm_out) && rm_out.G > 0.0 && rm_out.nu >= 0.0 && rm_out.nu <= 0.5;
    for (int i = 0; ok && i < DC_KALKER_FINE; i++) ok &= coef4_ok(rm_out.fine[i]);
    ok &= coef4_ok(rm_out.circle);
    FZ_CHECK(f, st, !ALLFIN(m.s0, m.s1), inside, UNTOUCHED(rm_out), ok, "s0 %.17g s1 %.17g", m.s0, m.s1);
    FZ_EXPECT(f, st == DC_OK ? UNTOUCHED(err)
                             : err.name && err.range && (!strcmp(err.name, "poissonsRatio") || !strcmp(err.name, "youngsModulus")),
              "no error report", "s0 %.17g s1 %.17g: status %d", m.s0, m.s1, st);
    if (st == DC_OK && ok) {
      if (nrm < 8) rmpool[nrm++] = rm_out;
      else if (U() < 0.1) rmpool[UI(8)] = rm_out;
    }
  }
  fz_done(f);

  f = fz_new("dc_kalker_coefficients");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const dc_rolling_material *rm = &rmpool[UI(nrm)];
    const double g = A(U() < 0.5 ? fz_log(1e-3, 1e3) : U() < 0.5 ? fz_log(1e-150, 1e150)
                       : PICK(1.0, 0.1, 10.0, 1e-150, 1e150, 0.0));
    dc_kalker_coef c;
    SENTINEL(c);
    const int st = dc_kalker_coefficients(rm, g, &c);
    FZ_CHECK(f, st, !isfinite(g), g >= 1e-150 && g <= 1e150, UNTOUCHED(c), kalker_ok(&c), "nu %.17g g %.17g", rm->nu, g);
    FZ_EXPECT(f, st == DC_OK || st == DC_EDOM, "neither DC_OK nor DC_EDOM (its statuses)", "nu %.17g g %.17g", rm->nu, g);
  }
  fz_done(f);
  /* the series; at a material's nu the material's table is within 5e-7 of it */
  f = fz_new("dc_kalker_coefficients_nu");
  for (long k = 0; k < N_KALKER_NU; k++) {
    fz_call();
    const dc_rolling_material *rm = &rmpool[UI(nrm)];
    const double g = A(U() < 0.5 ? fz_log(1e-3, 1e3) : U() < 0.5 ? fz_log(1e-150, 1e150) : PICK(1.0, 0.1, 10.0, 1e-150, 1e150));
    const int same = U() < 0.5;
    const double nu = same ? rm->nu : A(U() < 0.7 ? 0.5 * U() : PICK(0.0, 0.5, -0.0));
    dc_kalker_coef c;
    SENTINEL(c);
    const int st = dc_kalker_coefficients_nu(g, nu, &c);
    FZ_CHECK(f, st, !ALLFIN(g, nu), isfinite(g) && g >= 1e-150 && g <= 1e150 && nu >= 0.0 && nu <= 0.5, UNTOUCHED(c),
             kalker_ok(&c), "g %.17g nu %.17g", g, nu);
    dc_kalker_coef t;
    if (same && st == DC_OK && dc_kalker_coefficients(rm, g, &t) == DC_OK) {
      const double e = fmax(fmax(fabs(t.c11 / c.c11 - 1.0), fabs(t.c22 / c.c22 - 1.0)),
                            fmax(fabs(t.c23 / c.c23 - 1.0), fabs(t.c33 / c.c33 - 1.0)));
      FZ_EXPECT(f, e <= 2e-6, "the material's table differs from the series", "g %.17g nu %.17g: %.3g", g, nu, e);
    }
  }
  fz_done(f);

  /* kinematics: two bodies' curvatures with K_i + K_j positive definite
     (a subset of the domain: the smaller eigenvalue above 1e-11 of the
     larger, d1 exact), or anything */
  f = fz_new("dc_rolling_kinematics");
  fz_fn *fc = fz_new("dc_rolling_kinematics_capped");
  fc->seconds = 0.0;
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    double n[3], u[3], v[3], dv[3], dw[3];
    unit_vector(n);
    dc_tangent_basis(n, u, v);
    dc_rolling_curvature ci, cj;
    rolling_curvature(u, v, &ci);
    rolling_curvature(u, v, &cj);
    const double vs = U() < 0.7 ? fz_log(1e-3, 10.0) : fz_pos(), ws = vs * (U() < 0.7 ? fz_log(1e-1, 1e4) : fz_pos());
    for (int i = 0; i < 3; i++) {
      dv[i] = A(vs * (2.0 * U() - 1.0));
      dw[i] = A(ws * (2.0 * U() - 1.0));
    }
    for (int i = 0; i < 3; i++) n[i] = A(n[i]);
    const int bad = !fin(n, 3) || !fin(dv, 3) || !fin(dw, 3) || !ALLFIN(ci.k1, ci.k2, cj.k1, cj.k2) ||
                    (ci.k1 != ci.k2 && !fin(ci.d1, 3)) || (cj.k1 != cj.k2 && !fin(cj.d1, 3));
    /* the relative curvature in the plane of the n given (A() may have
       turned it): its basis from n normalised */
    double Ki[3], Kj[3], S[3], l1 = NAN, l2 = NAN;
    const double nl = sqrt(dot3(n, n));
    if (fin(n, 3) && nl > 0.0) {
      const double nu[3] = {n[0] / nl, n[1] / nl, n[2] / nl};
      dc_tangent_basis(nu, u, v);
    }
    rolling_tensor(&ci, u, v, Ki);
    rolling_tensor(&cj, u, v, Kj);
    for (int i = 0; i < 3; i++) S[i] = Ki[i] + Kj[i];
    if (fin(S, 3)) dc_form_principal(S, &l1, &l2, NULL);
    const int exact = rolling_d1_ok(&ci, n, 1e-14) && rolling_d1_ok(&cj, n, 1e-14);
    const double nn = dot3(n, n);
    const int dom = !bad && fabs(nn - 1.0) <= 1e-6 && rolling_d1_ok(&ci, n, 1e-6) && rolling_d1_ok(&cj, n, 1e-6) &&
                    l2 > 0.0 && l2 > (exact ? 1e-11 : 1e-4) * l1 && l2 >= DBL_MIN;
    dc_rolling_kin kk;
    SENTINEL(kk);
    const int st = dc_rolling_kinematics(n, &ci, &cj, dv, dw, &kk);
    FZ_CHECK(f, st, bad, dom, UNTOUCHED(kk), rolling_kin_ok(&kk, n, dv),
             "n (%.17g %.17g %.17g) k_i %.17g %.17g d1 (%.17g %.17g %.17g) k_j %.17g %.17g d1 (%.17g %.17g %.17g) "
             "dv (%.17g %.17g %.17g) dw (%.17g %.17g %.17g)", n[0], n[1], n[2], ci.k1, ci.k2, ci.d1[0], ci.d1[1], ci.d1[2],
             cj.k1, cj.k2, cj.d1[0], cj.d1[1], cj.d1[2], dv[0], dv[1], dv[2], dw[0], dw[1], dw[2]);
    /* V <= (|dw| + max|k| |dv|) / l2, slip <= |dv| and spin <= |dw| (times a few) */
    const double kmax = fmax(fmax(fabs(ci.k1), fabs(ci.k2)), fmax(fabs(cj.k1), fabs(cj.k2)));
    const double lV = fmax(lg(max_abs3(dw)), lg(kmax) + lg(max_abs3(dv))) + lg(8.0) - lg(l2);
    const double lsv = fmax(lg(max_abs3(dv)), lg(max_abs3(dw)));
    const double ksum = fabs(ci.k1) + fabs(ci.k2) + fabs(cj.k1) + fabs(cj.k2);
    FZ_EXPECT(f, st != DC_ERANGE || !dom || lV > LOG_MAX - 2.0 || lsv > LOG_MAX - 2.0 || !(ksum <= DBL_MAX),
              "DC_ERANGE for a representable V", "n (%.17g %.17g %.17g) k_i %.17g %.17g k_j %.17g %.17g dv max %.17g dw max %.17g",
              n[0], n[1], n[2], ci.k1, ci.k2, cj.k1, cj.k2, max_abs3(dv), max_abs3(dw));
    /* capped at R_max (+inf: no cap, a documented input; NaN, <= 0:
       DC_EDOM); a relative curvature not positive definite gives V = 0 */
    fc->seconds -= fz_now();
    const double Rm = A(U() < 0.3 ? INFINITY : U() < 0.3 && l2 > 0.0 ? fz_log(2.0, 1e6) / l2 : fz_log(1e-6, 1e2));
    const int badc = bad || isnan(Rm) || Rm == -INFINITY;
    /* a subset of the domain: curvatures and 1/R_max up to 1e300 (sums of
       them stay finite) */
    const int domc = !badc && fabs(nn - 1.0) <= 1e-6 && rolling_d1_ok(&ci, n, 1e-6) && rolling_d1_ok(&cj, n, 1e-6) &&
                     Rm >= 1e-300 && kmax <= 1e300;
    dc_rolling_kin kc;
    SENTINEL(kc);
    const int sc = dc_rolling_kinematics_capped(n, &ci, &cj, dv, dw, Rm, &kc);
    FZ_CHECK(fc, sc, badc, domc, UNTOUCHED(kc), rolling_kin_ok(&kc, n, dv),
             "n (%.17g %.17g %.17g) k_i %.17g %.17g k_j %.17g %.17g dv (%.17g %.17g %.17g) dw (%.17g %.17g %.17g) R_max %.17g",
             n[0], n[1], n[2], ci.k1, ci.k2, cj.k1, cj.k2, dv[0], dv[1], dv[2], dw[0], dw[1], dw[2], Rm);
    /* no cap, or a cap above the relative radii: the plain kinematics bit for bit */
    if (st == DC_OK && (Rm == INFINITY || (exact && Rm > 0.0 && 1.0 / Rm <= 0.5 * l2)))
      FZ_EXPECT(fc, sc == DC_OK && !memcmp(&kc, &kk, sizeof kk), "differs from dc_rolling_kinematics without a cap",
                "n (%.17g %.17g %.17g) k_i %.17g %.17g k_j %.17g %.17g R_max %.17g", n[0], n[1], n[2], ci.k1, ci.k2, cj.k1,
                cj.k2, Rm);
    /* the raised relative curvature is at least 1/R_max (DC_ERANGE also
       where that bound on V underflows) */
    const double lVc = fmax(lg(max_abs3(dw)), lg(kmax) + lg(max_abs3(dv))) + lg(8.0) - lg(fmax(l2, 1.0 / Rm));
    FZ_EXPECT(fc, sc != DC_ERANGE || !domc || !(lVc < LOG_MAX - 2.0) || lVc < log(DBL_TRUE_MIN) || lsv > LOG_MAX - 2.0,
              "DC_ERANGE for a representable V",
              "n (%.17g %.17g %.17g) k_i %.17g %.17g k_j %.17g %.17g dv max %.17g dw max %.17g R_max %.17g", n[0], n[1],
              n[2], ci.k1, ci.k2, cj.k1, cj.k2, max_abs3(dv), max_abs3(dw), Rm);
    fc->seconds += fz_now();
  }
  fz_done(f);

  /* the force: creepages from tiny to saturated, patches circular to
     slender, rolling speeds around v_min */
  f = fz_new("dc_rolling_force");
  fz_fn *fa = fz_new("dc_rolling_acts");
  fa->seconds = 0.0;
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const dc_rolling_material *rm = &rmpool[UI(nrm)];
    const dc_rolling_params p = {A(U() < 0.8 ? U() : PICK(0.0, 1.0)), A(U() < 0.8 ? fz_log(1e-9, 1e-3) : fz_pos()),
                                 AI(UI(2)), 0.0};
    double n[3], u[3], v[3];
    unit_vector(n);
    dc_tangent_basis(n, u, v);
    dc_patch pa;
    const double a = U() < 0.05 ? 0.0 : U() < 0.7 ? fz_log(1e-7, 1e-2) : fz_pos();
    const double r = U() < 0.3 ? 1.0 : U() < 0.8 ? 0.05 + 0.95 * U() : fz_log(1e-160, 1.0);
    pa.a = A(a);
    pa.b = A(a * r);
    const double th = 2.0 * M_PI * U(), ph = 2.0 * M_PI * U();
    for (int i = 0; i < 3; i++) pa.axis[i] = A(r == 1.0 ? 0.0 : cos(th) * u[i] + sin(th) * v[i]);
    pa.F_bound = A(U() < 0.05 ? 0.0 : U() < 0.7 ? fz_log(1e-6, 1e3) : fz_pos());
    pa.F_elastic = pa.F_bound;
    pa.formed = A(U() < 0.03 ? 0.0 : 1.0);
    dc_rolling_kin kk;
    kk.V = A(U() < 0.1 ? PICK(0.0, p.v_min) : U() < 0.7 ? fz_log(1e-6, 10.0) : fz_pos());
    const double cr = U() < 0.7 ? fz_log(1e-8, 1e-1) : fz_log(1e-300, 1e300), sa = 2.0 * U() - 1.0, sb = 2.0 * U() - 1.0;
    for (int i = 0; i < 3; i++) {
      kk.ex[i] = A(cos(ph) * u[i] + sin(ph) * v[i]);
      kk.slip[i] = A(kk.V * cr * (sa * u[i] + sb * v[i]));
    }
    kk.spin = A(kk.V * cr * (2.0 * U() - 1.0) / (a > 0.0 ? a : 1.0));
    for (int i = 0; i < 3; i++) n[i] = A(n[i]);
    const int bad = !ALLFIN(p.mu, p.v_min, n[0], n[1], n[2], kk.V, kk.ex[0], kk.ex[1], kk.ex[2], kk.slip[0], kk.slip[1],
                            kk.slip[2], kk.spin, pa.a, pa.b, pa.F_bound, pa.formed, pa.axis[0], pa.axis[1], pa.axis[2]);
    /* the header's domain: p checked, n unit, a >= b (b > 0 and b >= 1e-150
       a formed), F_b >= 0, a unit axis in the plane for a > b, ex unit in
       the plane when the law acts (from the kinematics) */
    const int acts = pa.formed != 0.0 && pa.a != 0.0 && kk.V > p.v_min;
    const double nn = dot3(n, n), ee = dot3(kk.ex, kk.ex), en = dot3(kk.ex, n);
    const double xx = dot3(pa.axis, pa.axis), xn = dot3(pa.axis, n);
    const int dom = !bad && p.mu >= 0.0 && p.v_min > 0.0 && (p.model == DC_ROLLING_KALKER || p.model == DC_ROLLING_VJ) &&
                    fabs(nn - 1.0) <= 1e-6 && kk.V >= 0.0 && pa.a >= pa.b && pa.b >= 0.0 && pa.F_bound >= 0.0 &&
                    (pa.formed == 0.0 || (pa.b > 0.0 && pa.b >= 1e-150 * pa.a)) && (pa.a == pa.b || (fabs(xx - 1.0) <= 1e-6 && fabs(xn) <= 1e-6)) &&
                    (!acts || (fabs(ee - 1.0) <= 1e-6 && fabs(en) <= 1e-6));
    dc_rolling_out o;
    SENTINEL(o);
    const int st = dc_rolling_force(&p, rm, &pa, n, &kk, &o);
    /* the hand-over rule: any input (no domain check), the force's flag */
    fa->seconds -= fz_now();
    const int act = dc_rolling_acts(&p, &pa, &kk);
    fa->calls++;
    FZ_EXPECT(fa, act == !(pa.formed == 0.0 || pa.a == 0.0 || kk.V <= p.v_min) && (st != DC_OK || act == o.rolling),
              "not the zero rule, or not the force's flag", "v_min %.17g a %.17g formed %.17g V %.17g: %d (force %d, status %d)",
              p.v_min, pa.a, pa.formed, kk.V, act, o.rolling, st);
    fa->seconds += fz_now();
    /* every input of the failing call */
#define RF_FMT "mu %.17g v_min %.17g model %d G %.17g nu %.17g a %.17g b %.17g axis (%.17g %.17g %.17g) F_b %.17g " \
               "formed %.17g n (%.17g %.17g %.17g) V %.17g ex (%.17g %.17g %.17g) slip (%.17g %.17g %.17g) spin %.17g"
#define RF_ARGS p.mu, p.v_min, p.model, rm->G, rm->nu, pa.a, pa.b, pa.axis[0], pa.axis[1], pa.axis[2], pa.F_bound, \
                pa.formed, n[0], n[1], n[2], kk.V, kk.ex[0], kk.ex[1], kk.ex[2], kk.slip[0], kk.slip[1], kk.slip[2], kk.spin
    FZ_CHECK(f, st, bad, dom, UNTOUCHED(o),
             FIN(o.F) && ALLFIN(o.Mz, o.Fx, o.Fy, o.xi_x, o.xi_y, o.phi, o.saturation) && FIN(o.c) &&
                 (o.rolling == 0 || o.rolling == 1),
             RF_FMT, RF_ARGS);
    if (st == DC_OK && dom) {
      int pr = o.rolling == acts;
      if (!acts) {
        dc_rolling_out z;
        memset(&z, 0, sizeof z);
        pr &= !memcmp(&o, &z, sizeof z);
      } else {
        /* |F| <= mu F_b, |Mz| <= M_s = 3/8 mu F_b a E(e^2), F in the plane */
        const double muF = p.mu * pa.F_bound, F = hypot(hypot(o.F[0], o.F[1]), o.F[2]);
        double Ms = 3.0 * M_PI / 16.0 * muF * pa.a;
        dc_ellint el;
        if (pa.b < pa.a && dc_ellint_m1((pa.b / pa.a) * (pa.b / pa.a), &el) == DC_OK) Ms = 0.375 * muF * pa.a * el.E;
        /* (a subnormal mu F_b has too few bits for the bounds to hold to
           1e-12; F = Fx ex + Fy (n x ex) is as long as n and ex, each
           unit within 1e-6) */
        const double lv = fmax(1.0, sqrt(nn * ee));
        pr &= o.saturation >= 0.0 && o.saturation <= 1.0 && kalker_ok(&o.c) &&
              (muF < DBL_MIN || (F <= muF * lv * (1.0 + 1e-12) + 4.0 * DBL_TRUE_MIN &&
                                 (!isfinite(Ms) || fabs(o.Mz) <= Ms * (1.0 + 1e-12) + 4.0 * DBL_TRUE_MIN)));
        if (F > 1e3 * DBL_MIN) pr &= fabs(o.F[0] / F * n[0] + o.F[1] / F * n[1] + o.F[2] / F * n[2]) <= 4e-6;
      }
      FZ_EXPECT(f, pr, "not the law's promises (acting, zeros, bounds, plane)",
                RF_FMT ": rolling %d F (%.17g %.17g %.17g) Mz %.17g", RF_ARGS, o.rolling, o.F[0], o.F[1], o.F[2], o.Mz);
    }
    /* DC_ERANGE where mu F_b, a creepage (slip/V, spin/V) or the moment
       (the linear G c^3 (c23 xi + c c33 phi), c = (a b)^1/2, the
       coefficients below 10 (a/b)^3/2, capped at M_s ~ mu F_b a) can
       overflow */
    const double lxi = lg(max_abs3(kk.slip)) - lg(kk.V), lphi = lg(kk.spin) - lg(kk.V), lc = 0.5 * (lg(pa.a) + lg(pa.b));
    const double lcoef = 1.5 * (lg(pa.a) - lg(pa.b)) + lg(10.0);
    const double lM = fmin(lg(rm->G) + 3.0 * lc + lcoef + fmax(lxi, lc + lphi) + 2.0, lg(p.mu) + lg(pa.F_bound) + lg(pa.a));
    /* (and a slip beyond DBL_MAX/4, whose dot product with ex may overflow) */
    const double big = fmax(fmax(fmax(lg(p.mu) + lg(pa.F_bound), lM), fmax(lxi, lphi)),
                            lg(max_abs3(kk.slip)) + log(4.0));
    FZ_EXPECT(f, st != DC_ERANGE || big > LOG_MAX - 2.0, "DC_ERANGE for representable results", RF_FMT, RF_ARGS);
  }
#undef RF_FMT
#undef RF_ARGS
  fz_done(f);
}

/* ---------------------------------------------------------------- */
/* The inline hot-path forms and the remaining constructors (run last, so
   that the cases drawn for the blocks above stay what they were).       */

/* x made >= 0 (-0 kept) and finite; > 0: and not 0 (PICK's ulps step
   across 0 and DBL_MAX) */
static double fz_nonneg(double x) { return x < 0.0 ? fmin(-x, DBL_MAX) : fmin(x, DBL_MAX); }
static double fz_positive(double x) { return x == 0.0 ? DBL_TRUE_MIN : fz_nonneg(x); }

/* hertz_elliptic.h: dc_hertz_geometry_circle is dc_hertz_geometry(R, R)
   bit for bit for every R > 0 finite (subnormal to DBL_MAX) */
static void fuzz_hertz_geometry_circle(void)
{
  fz_fn *f = fz_new("dc_hertz_geometry_circle");
  for (long k = 0; k < N_CALLS; k++) {
    const double r = U();
    const double R = r < 0.3 ? fz_log(1e-6, 1.0) : r < 0.85 ? fz_pos()
                     : fz_positive(PICK(DBL_TRUE_MIN, DBL_MIN, 0x1p-511, 0x1p-512, 0x1p-537, 0x1p-538, 0x1p511, 0x1p512,
                                        DBL_MAX / 2, DBL_MAX, 1.0));
    dc_hertz_geom g, h;
    SENTINEL(g);
    SENTINEL(h);
    dc_hertz_geometry_circle(R, &g);
    const int st = dc_hertz_geometry(R, R, &h);
    f->calls++;
    FZ_EXPECT(f, FIN(g) && g.Rc >= 0.0 && g.Rc <= R, "not finite, or Rc not in [0, R]", "R %.17g: Rc %.17g", R, g.Rc);
    FZ_EXPECT(f, st == DC_OK && !memcmp(&g, &h, sizeof g), "differs from dc_hertz_geometry(R, R)",
              "R %.17g: Rc %.17g vs %.17g (status %d)", R, g.Rc, h.Rc, st);
  }
  fz_done(f);
}

/* damping.h: the Tsuji coefficient (checked) and the inline laws (domains
   in the header; finite and >= 0 wherever their exact values and the
   product S m are finite, as dc_damping_restitution above); the dispatch
   dc_damping_gamma is the law's own function bit for bit, 0 for another
   law */
static double damping_law_fn(int law, double coef, double S, double delta, double m)
{
  switch (law) {
  case DC_DAMPING_RESTITUTION: return dc_damping_restitution(coef, S, m);
  case DC_DAMPING_VISCOELASTIC: return dc_damping_viscoelastic(coef, S);
  case DC_DAMPING_KUWABARA_KONO: return dc_damping_kuwabara_kono(coef, delta);
  case DC_DAMPING_TSUJI: return dc_damping_tsuji(coef, S, m);
  default: return 0.0;
  }
}

static void fuzz_damping_laws(void)
{
  fz_fn *f = fz_new("dc_damping_tsuji_alpha");
  fz_fn *ft = fz_new("dc_damping_tsuji");
  ft->seconds = 0.0;
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const double e = A(U() < 0.6 ? U() : U() < 0.5 ? fz_log(1e-320, 1.0) : PICK(0.0, 1.0, DBL_TRUE_MIN, 1.0 + DBL_EPSILON, 0.1));
    double al;
    SENTINEL(al);
    const int st = dc_damping_tsuji_alpha(e, &al);
    /* |ln e| / (ln^2 e + 10.1354)^1/2 < 1 */
    FZ_CHECK(f, st, !isfinite(e), e > 0.0 && e <= 1.0, UNTOUCHED(al), isfinite(al) && al >= 0.0 && al < 2.2664,
             "e %.17g: alpha %.17g", e, al);
    if (st != DC_OK) dc_damping_tsuji_alpha(U() < 0.5 ? 1.0 - U() : fz_log(1e-300, 1.0), &al);
    /* the inline law with the coefficient it is made for, and with any
       alpha >= 0 */
    ft->seconds -= fz_now();
    if (U() < 0.3) al = U() < 0.2 ? fz_nonneg(PICK(0.0, DBL_TRUE_MIN, DBL_MAX)) : fz_pos();
    const double S = U() < 0.5 ? fz_log(1e-3, 1e9) : U() < 0.1 ? fz_nonneg(PICK(0.0, -0.0, DBL_MAX, DBL_TRUE_MIN)) : fz_pos();
    const double m = U() < 0.5 ? fz_log(1e-12, 1.0) : U() < 0.1 ? fz_positive(PICK(DBL_TRUE_MIN, DBL_MAX)) : fz_pos();
    const double g = dc_damping_tsuji(al, S, m);
    ft->calls++;
    const double sm = 2.0 / 3.0 * S * m;
    if (isfinite(sm) && !(lg(al) + 0.5 * lg(sm) > LOG_MAX - 1.0))
      FZ_EXPECT(ft, isfinite(g) && g >= 0.0, "not finite and >= 0", "alpha %.17g S %.17g m %.17g: %.17g", al, S, m, g);
    ft->seconds += fz_now();
  }
  fz_done(f);

  f = fz_new("dc_damping_kuwabara_kono");
  for (long k = 0; k < N_CALLS; k++) {
    const double eta = U() < 0.4 ? fz_log(1e-3, 1e6) : U() < 0.1 ? fz_nonneg(PICK(0.0, -0.0, DBL_TRUE_MIN, DBL_MAX)) : fz_pos();
    const double d = U() < 0.4 ? fz_log(1e-12, 1e-3) : U() < 0.1 ? fz_nonneg(PICK(0.0, -0.0, DBL_TRUE_MIN, DBL_MAX)) : fz_pos();
    const double g = dc_damping_kuwabara_kono(eta, d);
    f->calls++;
    FZ_EXPECT(f, !memcmp(&g, &(double){eta * sqrt(d)}, sizeof g), "not eta delta^1/2", "%.17g %.17g", eta, d);
    if (!(lg(eta) + 0.5 * lg(d) > LOG_MAX - 1.0))
      FZ_EXPECT(f, isfinite(g) && g >= 0.0, "not finite and >= 0", "eta %.17g delta %.17g: %.17g", eta, d, g);
  }
  fz_done(f);

  f = fz_new("dc_damping_gamma");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const int law = AI(UI(5));
    /* each law's coefficient as its setting makes it, or wild */
    double coef;
    const double e = U() < 0.1 ? PICK(1.0, DBL_TRUE_MIN) : 1.0 - U();
    switch (UI(4)) {
    case 0: dc_damping_beta(e, &coef); break;
    case 1: coef = fz_log(1e-9, 1e-2); break;
    case 2: coef = fz_log(1e-3, 1e6); break;
    default: dc_damping_tsuji_alpha(e, &coef); break;
    }
    coef = A(coef);
    const double S = A(U() < 0.5 ? fz_log(1e-3, 1e9) : fz_pos()), d = A(U() < 0.5 ? fz_log(1e-12, 1e-3) : fz_pos());
    const double m = A(U() < 0.5 ? fz_log(1e-12, 1.0) : fz_pos());
    const double g = dc_damping_gamma(law, coef, S, d, m), w = damping_law_fn(law, coef, S, d, m);
    f->calls++;
    /* (a NaN's sign bit may differ between two inlined copies) */
    FZ_EXPECT(f, (!memcmp(&g, &w, sizeof g) || (isnan(g) && isnan(w))) && (law >= 0 && law <= 3 ? 1 : g == 0.0),
              "not the law's own function",
              "law %d coef %.17g S %.17g delta %.17g m %.17g: %.17g vs %.17g", law, coef, S, d, m, g, w);
  }
  fz_done(f);
}

/* gw_rough.h: the rough-sphere pair (Feng or tabulated) */
#define N_GWS 20000L
static dc_gw_sphere_pair gs_out;
static dc_gw_table_law gs_tl;
static dc_gw_table_pair gs_tp;
static const unsigned char fz_zero[sizeof(dc_gw_table_pair)];
_Static_assert(sizeof(dc_gw_sphere_pair) <= sizeof fz_ff, "fz_ff smaller than an output");

static void fuzz_gw_sphere(void)
{
  fz_fn *f = fz_new("dc_gw_sphere_pair_init");
  fz_fn *ff = fz_new("dc_gw_sphere_pair_force");
  fz_fn *fr = fz_new("dc_gw_sphere_reach");
  ff->seconds = fr->seconds = 0.0;
  for (long k = 0; k < N_GWS; k++) {
    fz_call();
    const int law = AI(UI(2)), var = AI(UI(2));
    const double mu = A(U() < 0.6 ? 1.0 + 49.0 * U() : PICK(1.0, 2.0, 4.0, 25.0, 50.0));
    const double E = A(U() < 0.5 ? fz_log(1e5, 1e12) : fz_pos());
    const double sg = A(U() < 0.5 ? fz_log(1e-9, 1e-4) : U() < 0.2 ? PICK(0.0, DBL_TRUE_MIN, DBL_MIN, 1e-310) : fz_pos());
    const int bad = !ALLFIN(mu, E, sg);
    const int dom = !bad && E > 0.0 && sg > 0.0 &&
                    ((law == DC_GW_SPHERE_FENG && (var == DC_FENG_TABLE || var == DC_FENG_FITTED) &&
                      mu >= DC_FENG_MU_MIN && mu <= DC_FENG_MU_MAX) ||
                     (law == DC_GW_SPHERE_TABULATED && mu >= DC_GW_TABLE_MU_MIN && mu <= DC_GW_TABLE_MU_MAX));
    /* what the law's own constructors give */
    dc_feng_law fl;
    dc_feng_pair fp;
    int want = DC_EDOM;
    if (law == DC_GW_SPHERE_FENG) {
      want = dc_feng_init(mu, var, &fl);
      if (want == DC_OK) want = dc_feng_pair_init(&fl, E, sg, &fp);
    } else if (law == DC_GW_SPHERE_TABULATED) {
      want = dc_gw_table_init(mu, &gs_tl);
      if (want == DC_OK) want = dc_gw_table_pair_init(&gs_tl, E, sg, &gs_tp);
    }
    SENTINEL(gs_out);
    const int st = dc_gw_sphere_pair_init(law, var, mu, E, sg, &gs_out);
    const int feng = law == DC_GW_SPHERE_FENG;
    const int fin_ok = gs_out.law == law && (feng ? FIN(gs_out.feng) && !memcmp(&gs_out.table, fz_zero, sizeof gs_out.table)
                                                  : FIN(gs_out.table) && !memcmp(&gs_out.feng, fz_zero, sizeof gs_out.feng));
    FZ_CHECK(f, st, bad, dom, UNTOUCHED(gs_out), fin_ok, "law %d variant %d mu %.17g Estar %.17g sigma %.17g", law, var,
             mu, E, sg);
    FZ_EXPECT(f, st == want && (st != DC_OK || (feng ? !memcmp(&gs_out.feng, &fp, sizeof fp)
                                                     : !memcmp(&gs_out.table, &gs_tp, sizeof gs_tp))),
              "not the law's own constructor", "law %d variant %d mu %.17g Estar %.17g sigma %.17g: status %d, want %d", law,
              var, mu, E, sg, st, want);
    /* the reach of any law setting: -3 (Feng) or X_LO (tabulated) */
    fr->seconds -= fz_now();
    const int lr = U() < 0.5 ? law : AI(UI(2));
    const double reach = dc_gw_sphere_reach(lr);
    fr->calls++;
    FZ_EXPECT(fr, reach == (lr == DC_GW_SPHERE_TABULATED ? DC_GW_TABLE_X_LO : -3.0), "not -3 or X_LO", "law %d: %.17g",
              lr, reach);
    fr->seconds += fz_now();
    if (st != DC_OK) continue;
    /* the force: the bound law's own kernel, unchanged, for any sqrtR and
       delta; zero at and below the reach (sqrtR > 0 finite) */
    ff->seconds -= fz_now();
    const double rs = dc_gw_sphere_reach(law);
    for (int j = 0; j < 4; j++) {
      const double sR = U() < 0.7 ? sqrt(fz_log(1e-6, 1.0)) : U() < 0.5 ? fz_pos() : fz_wild();
      const double r = U();
      const double d = j == 3 ? (U() < 0.5 ? rs * sg : rs * sg * fz_log(1.0, 1e6))
                       : r < 0.6 ? sg * (-8.0 + 16.0 * U()) : r < 0.8 ? sg * fz_log(1.0, 1e5) : fz_wild();
      double q[2], w[2];
      dc_gw_sphere_pair_force(&gs_out, sR, d, &q[0], &q[1]);
      if (feng) dc_feng_pair_force(&gs_out.feng, sR, d, &w[0], &w[1]);
      else dc_gw_table_pair_force(&gs_out.table, sR, d, &w[0], &w[1]);
      ff->calls++;
      FZ_EXPECT(ff, !memcmp(q, w, sizeof q), "not the bound law's kernel",
                "law %d mu %.17g Estar %.17g sigma %.17g sqrtR %.17g delta %.17g: %.17g %.17g vs %.17g %.17g", law, mu, E,
                sg, sR, d, q[0], q[1], w[0], w[1]);
      /* the law scales delta by its rounded 1/sigma: exactly 0 from a few
         ulps below reach x sigma on; within those ulps, rounding-level:
         h is off the reach by up to 8 ulps of 6 (1e-14), times the law's
         slope there (below 4/3 E* R^1/2 sigma^3/2 per unit of h): < 1e-14
         of 4/3 E* R^1/2 sigma^3/2 (1.1e-15 seen at mu 25.7; the bound was
         1e-15 until a shifted random stream met that case) */
      const double lph = lg(4.0 / 3.0) + lg(E) + lg(sR) + 1.5 * lg(sg);
      if (!(lph < LOG_MAX - 5.0)) continue;   /* the kernel's products leave the doubles */
      if (d <= rs * sg * (1.0 + 8.0 * DBL_EPSILON) && sR > 0.0 && isfinite(sR))
        FZ_EXPECT(ff, q[0] == 0.0, "force beyond the reach",
                  "law %d mu %.17g Estar %.17g sigma %.17g sqrtR %.17g delta %.17g (reach %.17g sigma): P %.17g", law, mu,
                  E, sg, sR, d, rs, q[0]);
      else if (d <= rs * sg && sR > 0.0 && isfinite(sR))
        FZ_EXPECT(ff, !(lg(q[0]) > lph - 14.0 * M_LN10), "force at the reach above rounding",
                  "law %d mu %.17g Estar %.17g sigma %.17g sqrtR %.17g delta %.17g (reach %.17g sigma): P %.17g", law, mu,
                  E, sg, sR, d, rs, q[0]);
    }
    ff->seconds += fz_now();
  }
  fz_done(f);
}

/* jamari_ep.h: the default K_v and parameters, the circular yield ratio */
static void fuzz_jamari_inline(void)
{
  fz_fn *f = fz_new("dc_jamari_kv_default");
  fz_fn *fd = fz_new("dc_jamari_defaults");
  fd->seconds = 0.0;
  for (long k = 0; k < N_CALLS; k++) {
    /* Poisson's ratio in [-1, 1/2], or any finite value */
    const double nu = U() < 0.6 ? -1.0 + 1.5 * U() : U() < 0.5 ? PICK(-1.0, 0.0, 0.5, -0.0) : fz_wide();
    const double kv = dc_jamari_kv_default(nu);
    f->calls++;
    FZ_EXPECT(f, isfinite(kv) && (!(nu >= -1.0 && nu <= 0.5) || kv > 0.0), "not finite, or not > 0 for nu in [-1, 1/2]",
              "nu %.17g: %.17g", nu, kv);
    /* the defaults pass the parameter check for any hardness > 0 and nu in [-1, 1/2] */
    fd->seconds -= fz_now();
    const double H = U() < 0.5 ? fz_log(1e7, 1e10) : fz_pos();
    const dc_jamari_params p = dc_jamari_defaults(H, nu);
    dc_param_error err;
    const int st = dc_jamari_check(&p, &err);
    fd->calls++;
    if (nu >= -1.0 && nu <= 0.5)
      FZ_EXPECT(fd, st == DC_OK && p.H == H && p.K_v == kv, "defaults fail the parameter check", "H %.17g nu %.17g: status %d",
                H, nu, st);
    fd->seconds += fz_now();
  }
  fz_done(f);

  /* (pi K_v H/(2 E*))^2 for inputs in the domain of dc_jamari_onsets: never
     NaN, >= 0, finite wherever that value is; delta_n1 / R of the circular
     geometry wherever both are normal numbers */
  f = fz_new("dc_jamari_circle_yield_ratio");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    if (fz_pw > 0.15) fz_pw = 0.15;   /* in the domain often */
    dc_jamari_params p;
    do p = jamari_params(); while (!jamari_params_in(&p));
    const double E = U() < 0.6 ? fz_log(1e9, 1e12) : U() < 0.1 ? fz_positive(PICK(DBL_TRUE_MIN, DBL_MIN, DBL_MAX)) : fz_pos();
    const double R = U() < 0.6 ? fz_log(1e-6, 1e-1) : fz_pos();
    const double q = dc_jamari_circle_yield_ratio(E, &p);
    f->calls++;
    const double lq = 2.0 * (lg(M_PI / 2.0) + lg(p.K_v) + lg(p.H) - lg(E));
    FZ_EXPECT(f, !isnan(q) && q >= 0.0, "NaN or negative", "E* %.17g H %.17g K_v %.17g: %.17g", E, p.H, p.K_v, q);
    if (lq < LOG_MAX - 1.0)
      FZ_EXPECT(f, isfinite(q), "not finite where its value is", "E* %.17g H %.17g K_v %.17g: %.17g", E, p.H, p.K_v, q);
    dc_hertz_geom g;
    dc_hertz_geometry_circle(R, &g);
    double d[2];
    if (dc_jamari_onsets(&g, E, &p, &d[0], &d[1]) == DC_OK && g.Rc >= DBL_MIN && q * R >= DBL_MIN && q * R <= DBL_MAX &&
        q >= DBL_MIN)
      FZ_EXPECT(f, fabs(q * R / d[0] - 1.0) < 1e-14, "not delta_n1 / R", "E* %.17g H %.17g K_v %.17g R %.17g: %.17g vs %.17g",
                E, p.H, p.K_v, R, q * R, d[0]);
  }
  fz_done(f);
}

/* ---------------------------------------------------------------- */
/* The reported cases, by name (the sweeps above find them too).     */

static void known_cases(void)
{
  /* Rc = R1 R2/(R1 + R2) overflowed to inf with DC_OK */
  dc_hertz_geom g;
  CHECK(dc_hertz_geometry(2.3e268, 4.5e256, &g) == DC_OK && FIN(g));
  CHECK_REL(g.Rc, 4.5e256 / (1.0 + 4.5e256 / 2.3e268), 4e-16, "Rc(2.3e268, 4.5e256)");
  /* a subnormal sigma gave NaN with DC_OK */
  dc_feng_law law;
  dc_feng_init(4.0, DC_FENG_TABLE, &law);
  double P[2];
  for (int e = 1030; e <= 1074; e += 4)
    for (int k = -2; k <= 2; k++) {
      CHECK(dc_feng_force(&law, 1e9, 1e-3, ldexp(1.0, -e), k * ldexp(1.0, -e), &P[0], &P[1]) == DC_OK && FIN(P));
    }
  /* a non-finite Hessian was accepted */
  const double grad[3] = {0.0, 0.0, 1.0}, u[3] = {1.0, 0.0, 0.0}, v[3] = {0.0, 1.0, 0.0};
  for (int i = 0; i < 9; i++) {
    double hess[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, form[3];
    hess[i] = i % 2 ? NAN : INFINITY;
    SENTINEL(form);
    CHECK(dc_curvature_form(grad, hess, u, v, form) == DC_EDOM && UNTOUCHED(form));
  }
  /* E* = inf was accepted */
  dc_hertz_state hs;
  dc_hertz_geometry(1e-3, 2e-4, &g);
  SENTINEL(hs);
  CHECK(dc_hertz_contact(&g, INFINITY, 1e-6, &hs) == DC_EDOM && UNTOUCHED(hs));
  /* jkr_elliptic (owned elsewhere, checked here): NaN for e^2 <= 1e-17, and
     dc_jkr_sphere_viscoelastic wrote its outputs before failing */
  dc_jkr_geom jg;
  CHECK(dc_jkr_geometry(1e-3, 2e-4, 1e9, 0.05, &jg) == DC_OK);
  for (double e2 = 1e-30; e2 <= 1e-15; e2 *= 10.0) {
    dc_jkr_state s;
    SENTINEL(s);
    const int st = dc_jkr_at_eccentricity(&jg, e2, &s);
    if (!CHECK(st == DC_OK ? jkr_state_ok(&s) : st != DC_EDOM && UNTOUCHED(s)))
      printf("  dc_jkr_at_eccentricity(R 1e-3/2e-4, E* 1e9, w 0.05, e2 = %g): status %d, F %g\n", e2, st, s.F);
  }
  struct { dc_jkr_state s; double F; } out;
  SENTINEL(out);
  CHECK(dc_jkr_sphere_viscoelastic(1e-3, 1e9, 0.05, -1.0, 1e-7, 0.1, &out.s, &out.F) == DC_EDOM && UNTOUCHED(out));
  SENTINEL(out);
  CHECK(dc_jkr_sphere_viscoelastic(1e-3, 1e9, 0.05, 1e-6, 1e-7, NAN, &out.s, &out.F) == DC_EDOM && UNTOUCHED(out));
}

/* ---------------------------------------------------------------- */

/* ---------------------------------------------------------------- */
/* The stable step and the rolled-distance hand-over of rolling_kalker.h,
   the bound forms split from their constructors (gw_rough.h), the adhesive
   table's parts (gw_rough_adhesive_table.h), the inline speed bound and
   sphere patch: run after the blocks above.                          */

/* A rolling contact inside the force law's domain now and then made wild:
   p, patch, unit n, kinematics; *bad: a non-finite input. */
static void draw_rolling(dc_rolling_params *p, dc_patch *pa, double n[3], dc_rolling_kin *kk, int *bad)
{
  p->mu = A(U() < 0.8 ? U() : PICK(0.0, 1.0));
  p->v_min = A(U() < 0.8 ? fz_log(1e-9, 1e-3) : fz_pos());
  p->model = AI(UI(2));
  p->roll_min = A(U() < 0.3 ? 0.0 : 4.0 * U());
  double u[3], v[3];
  unit_vector(n);
  dc_tangent_basis(n, u, v);
  const double a = U() < 0.05 ? 0.0 : fz_log(1e-7, 1e-2), r = U() < 0.3 ? 1.0 : 0.05 + 0.95 * U();
  pa->a = A(a);
  pa->b = A(a * r);
  const double th = 2.0 * M_PI * U(), ph = 2.0 * M_PI * U();
  for (int i = 0; i < 3; i++) pa->axis[i] = A(r == 1.0 ? 0.0 : cos(th) * u[i] + sin(th) * v[i]);
  pa->F_bound = pa->F_elastic = A(U() < 0.05 ? 0.0 : fz_log(1e-6, 1e3));
  pa->formed = A(U() < 0.03 ? 0.0 : 1.0);
  kk->V = A(U() < 0.1 ? PICK(0.0, p->v_min) : fz_log(1e-6, 10.0));
  const double cr = fz_log(1e-8, 1e-1), sa = 2.0 * U() - 1.0, sb = 2.0 * U() - 1.0;
  for (int i = 0; i < 3; i++) {
    kk->ex[i] = A(cos(ph) * u[i] + sin(ph) * v[i]);
    kk->slip[i] = A(kk->V * cr * (sa * u[i] + sb * v[i]));
  }
  kk->spin = A(kk->V * cr * (2.0 * U() - 1.0) / (a > 0.0 ? a : 1.0));
  *bad = !ALLFIN(p->mu, p->v_min, n[0], n[1], n[2], kk->V, kk->ex[0], kk->ex[1], kk->ex[2], kk->slip[0],
                 kk->slip[1], kk->slip[2], kk->spin, pa->a, pa->b, pa->F_bound, pa->formed, pa->axis[0], pa->axis[1],
                 pa->axis[2]);
}

static void fuzz_rolling_step(void)
{
  /* the factor: (0, 1], x phi(x) <= 1, 1 for x <= 0 or NaN */
  fz_fn *f = fz_new("dc_rolling_step_factor");
  for (long k = 0; k < N_CALLS; k++) {
    const double x = U() < 0.3 ? fz_special() : fz_wide(), s = dc_rolling_step_factor(x);
    f->calls++;
    FZ_EXPECT(f, (s > 0.0 || x == INFINITY) && s <= 1.0 &&
                     (!(x > 0.0) ? s == 1.0 : x == INFINITY ? s == 0.0 : x * s <= 1.0 + 4.0 * DBL_EPSILON),
              "not in (0, 1] (0 at +inf), or x phi(x) > 1", "x %.17g: %.17g", x, s);
  }
  fz_done(f);

  /* the stepped force: the force law's contract with the step's inputs;
     dt = 0 the plain law's bits; the bounds and the factor's range */
  f = fz_new("dc_rolling_force_step");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    dc_rolling_params p;
    dc_patch pa;
    double n[3];
    dc_rolling_kin kk;
    int bad;
    draw_rolling(&p, &pa, n, &kk, &bad);
    const dc_rolling_material *rm = &rmpool[UI(nrm)];
    const dc_rolling_step sp = {A(U() < 0.2 ? 0.0 : fz_log(1e-9, 1e-3)), A(fz_log(1e-3, 1e9)), A(fz_log(1e3, 1e15))};
    const int sbad = !ALLFIN(sp.dt, sp.inv_m, sp.inv_I);
    dc_rolling_out o, o0;
    SENTINEL(o);
    const int st = dc_rolling_force_step(&p, rm, &pa, n, &kk, &sp, &o);
    const int s0 = dc_rolling_force(&p, rm, &pa, n, &kk, &o0);
    const int sok = !sbad && sp.dt >= 0.0 && sp.inv_m >= 0.0 && sp.inv_I >= 0.0;
    /* inside: where the plain law is DC_OK and the step's inputs are valid */
    FZ_CHECK(f, st, bad || sbad, s0 == DC_OK && sok, UNTOUCHED(o),
             FIN(o.F) && ALLFIN(o.Mz, o.Fx, o.Fy, o.saturation, o.step_factor), "mu %.17g a %.17g V %.17g dt %.17g "
             "inv_m %.17g inv_I %.17g", p.mu, pa.a, kk.V, sp.dt, sp.inv_m, sp.inv_I);
    FZ_EXPECT(f, !sok || st == DC_OK || st == s0, "fails where the plain law does not", "status %d vs %d", st, s0);
    if (st == DC_OK) {
      const double F = hypot(o.Fx, o.Fy), muF = p.mu * pa.F_bound;
      FZ_EXPECT(f, (o.rolling == 0 || (o.step_factor >= 0.0 && o.step_factor <= 1.0)) &&
                       F <= muF * (1.0 + 1e-12) + 4.0 * DBL_TRUE_MIN &&
                       (sp.dt != 0.0 || (o.Fx == o0.Fx && o.Fy == o0.Fy && o.Mz == o0.Mz)),
                "factor out of [0, 1], above mu F_b, or dt = 0 not the plain law",
                "dt %.17g factor %.17g |F| %.17g mu F_b %.17g", sp.dt, o.step_factor, F, muF);
    }
  }
  fz_done(f);

  /* the hand-over: 0 or 1; the distance cleared where the contact does
     not act; roll_min = 0 from zero is dc_rolling_acts; finite inputs keep
     it finite */
  f = fz_new("dc_rolling_acts_rolled");
  double rolled[3] = {0.0, 0.0, 0.0};
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    dc_rolling_params p;
    dc_patch pa;
    double n[3];
    dc_rolling_kin kk;
    int bad;
    draw_rolling(&p, &pa, n, &kk, &bad);
    if (U() < 0.01) rolled[0] = rolled[1] = rolled[2] = 0.0;
    const double dt = A(fz_log(1e-9, 1e-3));
    const int acts = dc_rolling_acts(&p, &pa, &kk);
    const int r = dc_rolling_acts_rolled(&p, &pa, &kk, dt, rolled);
    double z[3] = {0.0, 0.0, 0.0};
    dc_rolling_params p0 = p;
    p0.roll_min = 0.0;
    const int r0 = dc_rolling_acts_rolled(&p0, &pa, &kk, dt, z);
    /* (no domain check: the finite-input promises for finite inputs, and
       for rolled distances below 1e100 m) */
    const int fine = !bad && isfinite(p.roll_min) && isfinite(dt) && fabs(kk.V * dt) < 1e90 && max_abs3(rolled) < 1e95;
    f->calls++;
    FZ_EXPECT(f, (r == 0 || r == 1) && (acts || (rolled[0] == 0.0 && rolled[1] == 0.0 && rolled[2] == 0.0 && !r)) &&
                     (!fine || (r0 == acts && FIN(rolled))) && (!r || acts),
              "not 0/1, not cleared, not dc_rolling_acts at roll_min 0, or not finite",
              "V %.17g v_min %.17g a %.17g roll_min %.17g: %d (acts %d)", kk.V, p.v_min, pa.a, p.roll_min, r, acts);
    if (!FIN(rolled) || max_abs3(rolled) >= 1e95) rolled[0] = rolled[1] = rolled[2] = 0.0;
  }
  fz_done(f);

  /* the speed bound: never below the kinematics' V for spheres */
  f = fz_new("dc_rolling_speed_bound_isotropic");
  for (long k = 0; k < N_CALLS; k++) {
    double n[3], dv[3], dw[3];
    unit_vector(n);
    const double ki = fz_log(1e-6, 1e6), kj = U() < 0.3 ? 0.0 : fz_log(1e-6, 1e6);
    const double sv = fz_log(1e-300, 1e300), sw = fz_log(1e-300, 1e300);
    for (int i = 0; i < 3; i++) {
      dv[i] = sv * (2.0 * U() - 1.0);
      dw[i] = sw * (2.0 * U() - 1.0);
    }
    const dc_rolling_curvature ci = {ki, ki, {0.0, 0.0, 0.0}}, cj = {kj, kj, {0.0, 0.0, 0.0}};
    dc_rolling_kin kk;
    const double b = dc_rolling_speed_bound_isotropic(ki, kj, dv, dw);
    const int st = dc_rolling_kinematics(n, &ci, &cj, dv, dw, &kk);
    f->calls++;
    FZ_EXPECT(f, b >= 0.0 && (st != DC_OK || b >= kk.V), "below the rolling speed, or negative / NaN",
              "k %.17g %.17g |dv| %.17g |dw| %.17g: bound %.17g V %.17g", ki, kj, sv, sw, b, kk.V);
  }
  fz_done(f);
}

static void fuzz_bound_parts(void)
{
  /* dc_gw_bound_material then dc_gw_bound_bind: dc_gw_bound_init's bits */
  fz_fn *f = fz_new("dc_gw_bound_material");
  fz_fn *fb = fz_new("dc_gw_bound_bind");
  fb->seconds = 0.0;
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const dc_hertz_geom *g = &hpool[UI(nh)];
    const double E = A(fz_log(1e5, 1e12)), n = A(fz_log(1e-2, 1e6)), sg = A(g->R_minor * fz_log(1e-9, 1e-3));
    const int bad = !ALLFIN(E, n, sg);
    dc_gw_bound b, bi;
    SENTINEL(b);
    SENTINEL(bi);
    const int st = dc_gw_bound_material(E, n, sg, &b);
    FZ_CHECK(f, st, bad, !bad && E > 0.0 && n > 0.0 && sg > 0.0 && 1.0 / sg < DBL_MAX, UNTOUCHED(b), 1,
             "Estar %.17g n_asp %.17g sigma %.17g", E, n, sg);
    const int si = dc_gw_bound_init(g, E, n, sg, &bi);
    if (st == DC_OK) {
      fb->seconds -= fz_now();
      const int sbd = dc_gw_bound_bind(&b, g);
      fz_count(fb, sbd);
      FZ_EXPECT(fb, sbd == si && (si != DC_OK || !memcmp(&b, &bi, sizeof b)), "not dc_gw_bound_init's bits",
                "Estar %.17g n_asp %.17g sigma %.17g: %d vs %d", E, n, sg, sbd, si);
      fb->seconds += fz_now();
    }
  }
  fz_done(f);

  /* the sphere patch: dc_hertz_normal's bits on the circle, or 0 */
  f = fz_new("dc_hertz_patch_circle");
  for (long k = 0; k < N_CALLS; k++) {
    const double R = fz_log(1e-9, 1e3), E = fz_log(1e3, 1e12), d = R * fz_log(1e-12, 1e-1);
    double kn, Sn;
    dc_hertz_stiffness(E, R, d, &kn, &Sn);
    dc_patch pc;
    const int ok = dc_hertz_patch_circle(R, d, kn * d, &pc);
    dc_hertz_geom g;
    dc_contact c;
    dc_hertz_geometry_circle(R, &g);
    const int sc = dc_hertz_normal(&g, E, d, &c);
    f->calls++;
    FZ_EXPECT(f, !ok || (sc == DC_OK && pc.a == c.a && pc.b == c.b && pc.F_bound == c.F_bound),
              "not dc_hertz_normal's patch", "R %.17g E* %.17g delta %.17g", R, E, d);
  }
  fz_done(f);
}

/* the circle's values for the correction's deep tail (as the step gives them) */
static void fuzz_circle_at(int b, double x, double eta, double *G, double *Gx, double *C, double *Cx)
{
  *C = *Cx = 0.0;
  if (b == DC_GW_UNLOADING) dc_gwa_table_kink(x, eta, C, Cx);
  dc_gwa_table_reduced(b, x, eta, G, Gx);
}

static void fuzz_gwa_parts(void)
{
  /* the eta cell: clamped to the table's rows for any finite eta; the
     kink: finite for |eta| <= 50 (the step passes the table's eta) and
     any finite x */
  fz_fn *f = fz_new("dc_gwa_table_eta_cell");
  fz_fn *fk = fz_new("dc_gwa_table_kink");
  fk->seconds = 0.0;
  const double eta_hi = DC_GWA_TABLE_ETA_LO + (DC_GWA_TABLE_NETA - 1.0) / DC_GWA_TABLE_ETA_PER_UNIT;
  for (long k = 0; k < N_CALLS; k++) {
    const double eta = U() < 0.8 ? -8.0 + 20.0 * U() : U() < 0.5 ? PICK(DC_GWA_TABLE_ETA_LO, eta_hi) : fz_wide();
    const double x = U() < 0.8 ? -20.0 + 30.0 * U() : fz_wide();
    dc_gwa_table_eta c;
    SENTINEL(c);
    dc_gwa_table_eta_cell(eta, &c);
    f->calls++;
    FZ_EXPECT(f, c.j >= 0 && c.j < DC_GWA_TABLE_NETA && c.ue >= 0.0 && c.ue <= 1.0 && c.eta >= DC_GWA_TABLE_ETA_LO &&
                     c.eta <= eta_hi && fin(c.w, 4), "not a cell of the table's rows", "eta %.17g: row %d ue %.17g",
              eta, c.j, c.ue);
    fk->seconds -= fz_now();
    double C, Cx;
    const double ek = fabs(eta) <= 50.0 ? eta : -50.0 + 100.0 * U();
    dc_gwa_table_kink(x, ek, &C, &Cx);
    fk->calls++;
    FZ_EXPECT(fk, isfinite(C) && isfinite(Cx), "not finite", "x %.17g eta %.17g: %.17g %.17g", x, ek, C, Cx);
    fk->seconds += fz_now();
  }
  fz_done(f);

  /* the elliptic correction: finite G, Gx for a set-up from radii */
  f = fz_new("dc_gwa_table_ell_apply");
  for (long k = 0; k < N_CALLS; k++) {
    const dc_gwa_table_pair *p = &gapool[UI(nga)];
    if (p->w == 0.0) continue;
    const double Rm = fz_log(1e-6, 1e-1), rho = fz_log(1e-7, 1.0);
    dc_gwa_table_radius r;
    if (dc_gwa_table_radius_init_elliptic(p, Rm, Rm * rho, &r) != DC_OK) continue;
    const int b = UI(2);
    const double x = U() < 0.2 ? -fz_log(1e4, 1e6) : -20.0 + 30.0 * U();   /* (the deep tail below x_lo = -13642) */
    double kc[2] = {0.0, 0.0}, G = -fz_log(1e-12, 0.5), Gx = fz_sign(fz_log(1e-12, 1.0));
    if (b == DC_GW_UNLOADING) dc_gwa_table_kink(x, r.cell.eta, &kc[0], &kc[1]);
    dc_gwa_table_ell_apply(&r.ell, b, x, r.cell.eta, kc, fuzz_circle_at, &G, &Gx);
    f->calls++;
    FZ_EXPECT(f, isfinite(G) && isfinite(Gx), "not finite", "rho %.17g branch %d x %.17g: %.17g %.17g", rho, b, x, G, Gx);
  }
  fz_done(f);

  /* a contact's record stepped by _step_contact_any and, where it applies,
     _step_settled: dc_gwa_table_step_radius's status and bits; the reach
     from the record is the set-up's */
  f = fz_new("dc_gwa_table_step_contact_any");
  fz_fn *fs = fz_new("dc_gwa_table_step_settled");
  fz_fn *fr = fz_new("dc_gwa_table_contact_reach");
  fs->seconds = fr->seconds = 0.0;
  dc_gwa_table_contact con;
  memset(&con, 0, sizeof con);
  double hc[2] = {0.0, 0.0}, hr[2] = {0.0, 0.0}, x = 0.0;
  const dc_gwa_table_pair *p = &gapool[0];
  dc_gwa_table_radius rr;
  for (long k = 0; k < N_CALLS; k++) {
    if (k == 0 || U() < 0.002) {
      p = &gapool[UI(nga)];
      const double R = fz_log(1e-6, 1e-1);
      if (dc_gwa_table_contact_init(p, R, &con) != DC_OK || dc_gwa_table_radius_init(p, R, &rr) != DC_OK) {
        k--;
        continue;
      }
      hc[0] = hc[1] = hr[0] = hr[1] = 0.0;
      x = 4.0 * p->sigma;
      fr->seconds -= fz_now();
      fr->calls++;
      FZ_EXPECT(fr, dc_gwa_table_contact_reach(p, &con) == rr.reach || p->w == 0.0, "not the set-up's reach",
                "R %.17g: %.17g vs %.17g", R, dc_gwa_table_contact_reach(p, &con), rr.reach);
      fr->seconds += fz_now();
    }
    x += p->sigma * fz_sign(fz_log(1e-3, 0.5));
    dc_gwa_table_out oc, orr, os;
    SENTINEL(oc);
    double hs[2] = {hc[0], hc[1]};
    dc_gwa_table_contact cs = con;
    fs->seconds -= fz_now();
    const int settled = dc_gwa_table_step_settled(p, &cs, x, hs, &os);
    fs->calls++;
    fs->seconds += fz_now();
    const int st = dc_gwa_table_step_contact_any(p, &con, x, hc, &oc);
    const int sr = dc_gwa_table_step_radius(p, &rr, x, hr, &orr);
    FZ_CHECK(f, st, 0, 1, UNTOUCHED(oc), FIN(oc), "delta %.17g", x);
    FZ_EXPECT(f, st == sr && (st != DC_OK || (!memcmp(&oc, &orr, sizeof oc) && !memcmp(hc, hr, sizeof hc))),
              "not dc_gwa_table_step_radius's bits", "delta %.17g: %d vs %d", x, st, sr);
    FZ_EXPECT(fs, !settled || (st == DC_OK && !memcmp(&os, &oc, sizeof os) && !memcmp(hs, hc, sizeof hs)),
              "a settled step not the full step's bits", "delta %.17g", x);
    if (st != DC_OK) hc[0] = hc[1] = hr[0] = hr[1] = 0.0;
  }
  fz_done(f);
}

/* ---------------------------------------------------------------- */
/* scene.h: the advisor's measures                                    */

/* A value against its long double reference: within 1e-14 where the
   reference is a normal double, DC_ERANGE (only) where it is not. */
static int scene_value_ok(int st, double v, long double ref)
{
  const int normal = ref >= DBL_MIN * (1.0L + 1e-12L) && ref <= DBL_MAX * (1.0L - 1e-12L);
  const int edge = ref >= DBL_MIN * (1.0L - 1e-12L) && ref <= DBL_MAX * (1.0L + 1e-12L);
  if (st == DC_OK) return edge && fabsl(v / ref - 1.0L) <= 1e-14L;
  return st == DC_ERANGE && !normal;
}

static void fuzz_scene(void)
{
  fz_fn *f = fz_new("dc_scene_rayleigh_time");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const double R = A(U() < 0.8 ? fz_log(1e-6, 1e-1) : fz_pos()), rho = A(U() < 0.8 ? fz_log(1e2, 2e4) : fz_pos());
    const double E = A(U() < 0.8 ? fz_log(1e5, 1e12) : fz_pos()), nu = A(U() < 0.9 ? 0.5 * U() : fz_sign(U()));
    const int bad = !ALLFIN(R, rho, E, nu), dom = !bad && R > 0.0 && rho > 0.0 && E > 0.0 && nu >= 0.0 && nu <= 0.5;
    double T;
    SENTINEL(T);
    const int st = dc_scene_rayleigh_time(R, rho, E, nu, &T);
    FZ_CHECK(f, st, bad, dom, UNTOUCHED(T), isfinite(T) && T > 0.0, "R %.17g rho %.17g E %.17g nu %.17g", R, rho, E, nu);
    /* against long double (no overflow there): DC_ERANGE exactly where T leaves the normal doubles */
    const long double Tl = (long double)M_PI * R * sqrtl((long double)rho * (2.0L * (1.0L + nu)) / E) /
                           (0.1631L * nu + 0.8766L);
    if (dom) FZ_EXPECT(f, scene_value_ok(st, T, Tl), "not pi R (rho/G)^1/2 / (0.1631 nu + 0.8766)",
                       "R %.17g rho %.17g E %.17g nu %.17g: status %d", R, rho, E, nu, st);
  }
  fz_done(f);

  f = fz_new("dc_scene_tabor");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const double R = A(U() < 0.8 ? fz_log(1e-6, 1e-1) : fz_pos()), w = A(U() < 0.1 ? 0.0 : U() < 0.8 ? fz_log(1e-3, 1.0) : fz_pos());
    const double E = A(U() < 0.8 ? fz_log(1e5, 1e12) : fz_pos()), z0 = A(U() < 0.8 ? fz_log(1e-10, 1e-9) : fz_pos());
    const int bad = !ALLFIN(R, w, E, z0), dom = !bad && R > 0.0 && w >= 0.0 && E > 0.0 && z0 > 0.0;
    double mu;
    SENTINEL(mu);
    const int st = dc_scene_tabor(R, w, E, z0, &mu);
    FZ_CHECK(f, st, bad, dom, UNTOUCHED(mu), isfinite(mu) && mu >= 0.0, "R %.17g w %.17g E* %.17g z0 %.17g", R, w, E, z0);
    const long double ml = cbrtl((long double)R * w * w / ((long double)E * E * z0 * z0 * z0));
    if (dom && w > 0.0) FZ_EXPECT(f, scene_value_ok(st, mu, ml), "not (R w^2 / (E*^2 z0^3))^1/3",
                                  "R %.17g w %.17g E* %.17g z0 %.17g: status %d", R, w, E, z0, st);
  }
  fz_done(f);

  f = fz_new("dc_scene_hertz_overlap");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const dc_hertz_geom *g = &hpool[UI(nh)];
    const double E = A(U() < 0.8 ? fz_log(1e5, 1e12) : fz_pos()), F = A(U() < 0.05 ? 0.0 : U() < 0.8 ? fz_log(1e-6, 1e3) : fz_wide());
    const int bad = !ALLFIN(E, F), dom = !bad && E > 0.0 && F >= 0.0;
    double d;
    SENTINEL(d);
    const int st = dc_scene_hertz_overlap(g, E, F, &d);
    FZ_CHECK(f, st, bad, dom, UNTOUCHED(d), isfinite(d) && d >= 0.0, "R_force %.17g E* %.17g F %.17g", g->R_force, E, F);
    const long double dl = cbrtl(0.5625L * F * F / ((long double)E * E * g->R_force));
    if (dom && F > 0.0) FZ_EXPECT(f, scene_value_ok(st, d, dl), "not (3 F / (4 E* R_force^1/2))^2/3",
                                  "R_force %.17g E* %.17g F %.17g: status %d", g->R_force, E, F, st);
    /* the round trip through dc_hertz_contact (delta^3/2 and R_force delta
       normal: its root of a subnormal product has lost digits) */
    dc_hertz_state hs;
    if (st == DC_OK && d > 1e-200 && d < 1e200 && E >= 1e-290 && g->R_force * d >= DBL_MIN && E * sqrt(g->R_force * d) >= DBL_MIN && dc_hertz_contact(g, E, d, &hs) == DC_OK && hs.F > 1e-290 && hs.F < 1e290)
      FZ_EXPECT(f, fabs(hs.F / F - 1.0) <= 1e-14, "dc_hertz_contact at the overlap is not F",
                "R_force %.17g E* %.17g F %.17g: delta %.17g gives %.17g", g->R_force, E, F, d, hs.F);
  }
  fz_done(f);

  f = fz_new("dc_scene_superquadric_radius");
  fz_fn *fs = fz_new("dc_scene_shape_error");
  for (long k = 0; k < N_CALLS; k++) {
    fz_call();
    const double L = U() < 0.8 ? fz_log(1e-5, 1e-1) : fz_pos();
    double sh[3], bl[2];
    for (int i = 0; i < 3; i++) sh[i] = A(L * fz_log(0.2, 1.0));
    const int sphere = U() < 0.2;
    for (int i = 0; i < 2; i++) bl[i] = A(sphere ? 2.0 : U() < 0.8 ? 2.0 + 8.0 * U() : U() < 0.5 ? fz_log(2.0, 1e3) : fz_wide());
    const int bad = !fin(sh, 3) || !fin(bl, 2);
    const int dom = !bad && sh[0] > 0.0 && sh[1] > 0.0 && sh[2] > 0.0 && bl[0] >= 2.0 && bl[0] <= 1e3 && bl[1] >= 2.0 &&
                    bl[1] <= 1e3;
    double R;
    SENTINEL(R);
    const int st = dc_scene_superquadric_radius(sh, bl, &R);
    FZ_CHECK(f, st, bad, dom, UNTOUCHED(R), isfinite(R) && R > 0.0,
             "shape %.17g %.17g %.17g blockiness %.17g %.17g", sh[0], sh[1], sh[2], bl[0], bl[1]);
    /* between the inscribed ellipsoid's and the box's volume-equivalent radii */
    const long double rl = cbrtl((long double)sh[0] * sh[1] * sh[2]);
    if (st == DC_OK)
      FZ_EXPECT(f, R >= rl * (1.0L - 1e-13L) && R <= rl * cbrtl(6.0L / (long double)M_PI) * (1.0L + 1e-13L) &&
                       (bl[0] != 2.0 || bl[1] != 2.0 || fabsl(R / rl - 1.0L) <= 1e-13L),
                "not between the ellipsoid's and the box's radii", "shape %.17g %.17g %.17g blockiness %.17g %.17g: %.17g",
                sh[0], sh[1], sh[2], bl[0], bl[1], R);
    if (k % 200 != 0) continue;   /* the sampling: 1 call in 200, m up to 6 */
    const int m = U() < 0.9 ? 2 + UI(5) : AI(4);
    const double cap = A(U() < 0.8 ? fz_log(1.0, 1e3) : fz_wide());
    dc_scene_shape s;
    SENTINEL(s);
    fs->seconds -= fz_now();
    const int ss = dc_scene_shape_error(sh, bl, m, cap, &s);
    fs->seconds += fz_now();
    const int doms = dom && m >= 2 && m <= 64 && cap >= 1.0 && cap <= 1e6;
    FZ_CHECK(fs, ss, bad || !isfinite(cap), doms, UNTOUCHED(s),
             FIN(s) && s.err_pair_max >= s.err_pair_rms && s.err_pair_rms >= 0.0 && s.err_wall_max >= s.err_wall_rms &&
                 s.err_wall_rms >= 0.0 && s.R_body_min > 0.0 && s.R_body_min <= s.R_body_max &&
                 s.R_body_max <= cap * s.R_eq * (1.0 + 1e-12) && (ss != DC_OK || st != DC_OK || s.R_eq == R ||
                                                                 fabs(s.R_eq / R - 1.0) <= 1e-14),
             "shape %.17g %.17g %.17g blockiness %.17g %.17g m %d cap %.17g", sh[0], sh[1], sh[2], bl[0], bl[1], m, cap);
  }
  fz_done(f);
  fz_done(fs);
}

int main(void)
{
  clock_gettime(CLOCK_MONOTONIC, &fz_t0);
  if (getenv("DC_FUZZ_CALLS")) N_CALLS = (long)atof(getenv("DC_FUZZ_CALLS"));
  if (N_CALLS < 1) N_CALLS = 1;
  memset(fz_ff, 0xFF, sizeof fz_ff);
  /* constructor pools start with ordinary members */
  dc_hertz_geom g;
  dc_hertz_geometry(1e-3, 1e-3, &g); pool_hertz(&g);
  dc_hertz_geometry(1e-3, 2e-4, &g); pool_hertz(&g);
  dc_feng_law law;
  dc_feng_init(4.0, DC_FENG_TABLE, &law); lpool[nl++] = law;
  dc_jkr_geom jg;
  dc_jkr_geometry(1e-3, 1e-3, 1e9, 0.05, &jg); pool_jkr(&jg);
  dc_jkr_geometry(1e-3, 2e-4, 1e9, 0.05, &jg); pool_jkr(&jg);
  dc_param_error err;
  dc_classical_normal_params cn = {DC_CLASSICAL_LSD, DC_CLASSICAL_K_GIVEN, DC_DAMPING_NONE, 0, 1e11, 1e5, 1.0, 0.5, 0.0, 0.0, 0.0};
  dc_classical_normal_init(&cn, &cnpool[ncn++], &err);
  cn.law = DC_CLASSICAL_HERTZ;
  cn.damping = DC_DAMPING_RESTITUTION;
  dc_classical_normal_init(&cn, &cnpool[ncn++], &err);
  cn.law = DC_CLASSICAL_HLS_CONSTANT;
  cn.stiffness = DC_CLASSICAL_K_ENERGY;
  dc_classical_normal_init(&cn, &cnpool[ncn++], &err);
  const dc_classical_tangential_params ct = {DC_CT_SPRING_DASHPOT_SLIDING, DC_CT_KT_MINDLIN, DC_CT_DAMP_RESTITUTION, 0.5, 1e5,
                                             0.0, 0.5, 3e10, 1e11, 0.0, 0.0};
  dc_classical_tangential_init(&ct, &ctpool[nct++], &err);
  const dc_gw_plastic_params gp = dc_gw_plastic_default_params(2e9, 0.3);
  dc_gw_plastic_summit_init(&hpool[0], 1e11, &gp, &spool[nsp++]);
  dc_gw_table_init(4.0, &tlpool[ntl++]);
  dc_gwa_table_pair_init(1e9, 0.05, 1e-8, 1e4, &gapool[nga++]);
  dc_gwa_table_pair_init(1e9, 0.0, 1e-8, 1e4, &gapool[nga++]);
  const dc_mindlin_pair mp = {1e-10, 2e-11};
  dc_rolling_material_init(&mp, &rmpool[nrm++], &err);

  /* DC_FUZZ_ONLY=word: only the blocks whose function name holds it (a
     failure's neighbourhood, at many calls, in a fraction of the time;
     the draws then differ from the whole run's) */
  const char *only = getenv("DC_FUZZ_ONLY");
#define FZ_RUN(block) if (!only || strstr(#block, only)) block()
  FZ_RUN(known_cases);
  FZ_RUN(fuzz_status_str);
  FZ_RUN(fuzz_ellint);
  FZ_RUN(fuzz_tangent_basis);
  FZ_RUN(fuzz_curvature_form);
  FZ_RUN(fuzz_superquadric_form);
  FZ_RUN(fuzz_form_principal);
  FZ_RUN(fuzz_relative_radii);
  FZ_RUN(fuzz_form_major_axis);
  FZ_RUN(fuzz_hertz_eccentricity);
  FZ_RUN(fuzz_hertz_geometry);
  FZ_RUN(fuzz_hertz_contact);
  FZ_RUN(fuzz_hertz_normal);
  FZ_RUN(fuzz_gw_integrals);
  FZ_RUN(fuzz_gw_rough);
  FZ_RUN(fuzz_feng_init);
  FZ_RUN(fuzz_feng_force);
  FZ_RUN(fuzz_gw_solver);
  FZ_RUN(fuzz_gw_solve);
  FZ_RUN(fuzz_rough_tangential);
  FZ_RUN(fuzz_maugis_dugdale);
  FZ_RUN(fuzz_jkr_psi);
  FZ_RUN(fuzz_jkr_sphere);
  FZ_RUN(fuzz_jkr_geometry);
  FZ_RUN(fuzz_jkr_contact);
  FZ_RUN(fuzz_gw_rough_adhesive);
  FZ_RUN(fuzz_dissipation);
  FZ_RUN(fuzz_jkr_check);
  FZ_RUN(fuzz_param_check);
  FZ_RUN(fuzz_patch);
  FZ_RUN(fuzz_damping);
  FZ_RUN(fuzz_mindlin);
  FZ_RUN(fuzz_cmd);
  FZ_RUN(fuzz_cmdtp);
  FZ_RUN(fuzz_jamari);
  FZ_RUN(fuzz_root_find);
  FZ_RUN(fuzz_classical_normal);
  FZ_RUN(fuzz_classical_tangential);
  FZ_RUN(fuzz_gw_rough_plastic);
  FZ_RUN(fuzz_gw_table);
  FZ_RUN(fuzz_gwa_table);
  FZ_RUN(fuzz_gwa_elliptic);
  FZ_RUN(fuzz_rolling);
  FZ_RUN(fuzz_hertz_geometry_circle);
  FZ_RUN(fuzz_damping_laws);
  FZ_RUN(fuzz_gw_sphere);
  FZ_RUN(fuzz_jamari_inline);
  FZ_RUN(fuzz_rolling_step);
  FZ_RUN(fuzz_bound_parts);
  FZ_RUN(fuzz_gwa_parts);
  FZ_RUN(fuzz_scene);
#undef FZ_RUN

  printf("\n%-32s %9s %9s %8s %8s %8s %6s %8s\n", "function", "calls", "OK", "EDOM", "ENOCONV", "ERANGE", "fails",
         "seconds");
  for (int i = 0; i < fz_n; i++) {
    const fz_fn *f = &fz_all[i];
    printf("%-32s %9ld %9ld %8ld %8ld %8ld %6ld %8.3f\n", f->name, f->calls, f->st[0], f->st[1], f->st[2], f->st[3],
           f->fails, f->seconds);
    for (int j = 0; j < 8 && f->why[j]; j++) printf("    %ld x %s\n", f->nwhy[j], f->why[j]);
  }
  printf("total %.2f s\n", fz_now());
  return check_summary("fuzz");
}
