/* The shared bracketed root finder (dc/root_find.h, Brent's method) on
   functions with known roots: cos x = x, x^3 = 2 (both orientations), a
   root at either end of the bracket, a step function (bisection-like
   progress), the slots (the root's evaluation is in the slot named), a
   bad bracket (DC_EDOM, result untouched) and a tolerance below what the
   doubles can give (DC_ENOCONV at the iteration cap, the last iterate
   returned). */
#include "check.h"
#include "dc/root_find.h"
#include "dc/status.h"
#include <float.h>
#include <math.h>

/* Counts the calls and keeps x and f(x) per slot, and checks that no slot
   is written while it is named as held (the finder holds at most three). */
typedef struct {
  int kind, calls;
  double xs[3], fs[3];
  int slot_ok;
} probe;

static double eval(int kind, double x)
{
  switch (kind) {
  case 0: return cos(x) - x;
  case 1: return x * x * x - 2.0;
  case 2: return 2.0 - x * x * x;
  case 3: return x < 0.3 ? -1.0 : 1.0;            /* sign change, no zero */
  case 4: return (x - 0.5) - 1e-17;               /* never exactly 0 in doubles */
  case 5: return x * x + 1.0;                     /* no root */
  case 6: return x - 1.0;
  default: return NAN;
  }
}

static double fn(double x, void *ctx, int slot)
{
  probe *p = ctx;
  p->calls++;
  if (slot < 0 || slot > 2) p->slot_ok = 0;
  else { p->xs[slot] = x; p->fs[slot] = eval(p->kind, x); }
  return eval(p->kind, x);
}

static void init(probe *p, int kind)
{
  p->kind = kind;
  p->calls = 0;
  p->slot_ok = 1;
  for (int i = 0; i < 3; i++) p->xs[i] = p->fs[i] = NAN;
}

/* The result names a slot holding exactly its x and f(x). */
static int slot_holds(const probe *p, const dc_root_result *r)
{
  return p->slot_ok && r->slot >= 0 && r->slot <= 2 && p->xs[r->slot] == r->x && p->fs[r->slot] == r->fx;
}

static void known_roots(void)
{
  const double dottie = 0.73908513321516064166;   /* cos x = x */
  const double cbrt2 = 1.2599210498948731648;
  probe p;
  dc_root_result r;

  init(&p, 0);
  CHECK(dc_root_brent(fn, &p, 0.0, 1.0, 1e-15, 0.0, 100, &r) == DC_OK);
  CHECK_ABS(r.x, dottie, 4e-15, "cos x = x");
  CHECK(slot_holds(&p, &r));
  CHECK(r.evaluations == p.calls && r.evaluations <= 12);

  init(&p, 1);
  CHECK(dc_root_brent(fn, &p, 0.0, 2.0, 1e-14, 0.0, 100, &r) == DC_OK);
  CHECK_REL(r.x, cbrt2, 4e-14, "x^3 = 2");
  CHECK(slot_holds(&p, &r));

  /* decreasing function, bracket given high end first */
  init(&p, 2);
  CHECK(dc_root_brent(fn, &p, 2.0, 0.0, 1e-14, 0.0, 100, &r) == DC_OK);
  CHECK_REL(r.x, cbrt2, 4e-14, "2 - x^3 = 0, reversed bracket");
  CHECK(slot_holds(&p, &r));

  /* absolute tolerance only: |x - root| <= 2 atol */
  init(&p, 1);
  CHECK(dc_root_brent(fn, &p, 1.0, 100.0, 0.0, 1e-9, 100, &r) == DC_OK);
  CHECK_ABS(r.x, cbrt2, 2e-9, "x^3 = 2, atol");

  /* step function: no zero, the bracket still closes on the jump */
  init(&p, 3);
  CHECK(dc_root_brent(fn, &p, 0.0, 1.0, 0.0, 1e-12, 200, &r) == DC_OK);
  CHECK_ABS(r.x, 0.3, 2e-12, "sign change of a step function");
  CHECK(r.evaluations < 120);   /* Brent's bound: a few times bisection's 40 */
  CHECK(slot_holds(&p, &r));
}

static void bracket_ends(void)
{
  probe p;
  dc_root_result r;
  /* root at a: f(a) = 0 given, no evaluation */
  init(&p, 6);
  CHECK(dc_root_brent_ends(fn, &p, 1.0, 3.0, 0.0, 2.0, 1e-12, 0.0, 50, &r) == DC_OK);
  CHECK(r.x == 1.0 && r.fx == 0.0 && r.slot == 0 && r.evaluations == 0 && p.calls == 0);
  /* root at b */
  init(&p, 6);
  CHECK(dc_root_brent_ends(fn, &p, -1.0, 1.0, -2.0, 0.0, 1e-12, 0.0, 50, &r) == DC_OK);
  CHECK(r.x == 1.0 && r.fx == 0.0 && r.slot == 1 && r.evaluations == 0);
  /* the same through dc_root_brent, which evaluates the ends (counted) */
  init(&p, 6);
  CHECK(dc_root_brent(fn, &p, 1.0, 3.0, 1e-12, 0.0, 50, &r) == DC_OK);
  CHECK(r.x == 1.0 && r.evaluations == 2 && p.calls == 2 && slot_holds(&p, &r));
}

static void failures(void)
{
  probe p;
  dc_root_result r, keep;
  keep.x = keep.fx = -7.0;
  keep.slot = keep.evaluations = -7;
  /* no sign change: DC_EDOM, result untouched */
  init(&p, 5);
  r = keep;
  CHECK(dc_root_brent(fn, &p, -1.0, 1.0, 1e-12, 0.0, 50, &r) == DC_EDOM);
  CHECK(r.x == -7.0 && r.fx == -7.0 && r.slot == -7 && r.evaluations == -7);
  r = keep;
  CHECK(dc_root_brent_ends(fn, &p, 0.0, 1.0, 1.0, 2.0, 1e-12, 0.0, 50, &r) == DC_EDOM);
  CHECK(dc_root_brent_ends(fn, &p, 0.0, 1.0, -1.0, -2.0, 1e-12, 0.0, 50, &r) == DC_EDOM);
  CHECK(dc_root_brent_ends(fn, &p, 0.0, 1.0, NAN, 2.0, 1e-12, 0.0, 50, &r) == DC_EDOM);
  CHECK(dc_root_brent_ends(fn, &p, 0.0, INFINITY, -1.0, 2.0, 1e-12, 0.0, 50, &r) == DC_EDOM);
  CHECK(dc_root_brent_ends(fn, &p, 0.0, 1.0, -1.0, 2.0, -1e-12, 0.0, 50, &r) == DC_EDOM);
  CHECK(dc_root_brent_ends(fn, &p, 0.0, 1.0, -1.0, 2.0, 1e-12, NAN, 50, &r) == DC_EDOM);
  CHECK(dc_root_brent_ends(fn, &p, 0.0, 1.0, -1.0, 2.0, 1e-12, 0.0, 0, &r) == DC_EDOM);
  CHECK(r.x == -7.0 && r.slot == -7);
  init(&p, 7);   /* f = NaN at the ends */
  CHECK(dc_root_brent(fn, &p, 0.0, 1.0, 1e-12, 0.0, 50, &r) == DC_EDOM);
  CHECK(r.x == -7.0 && r.slot == -7);

  /* rtol = atol = 0 with a root that is not a double: the bracket shrinks
     to neighbouring doubles and the steps can no longer move; DC_ENOCONV
     at the cap, r holds the last iterate, still in the bracket */
  init(&p, 4);
  CHECK(dc_root_brent(fn, &p, 0.0, 1.0, 0.0, 0.0, 60, &r) == DC_ENOCONV);
  CHECK(r.evaluations == 62 && p.calls == 62);
  CHECK(fabs(r.x - 0.5) <= 4 * DBL_EPSILON);
  CHECK(slot_holds(&p, &r));
  /* the same with a tolerance it can meet */
  init(&p, 4);
  CHECK(dc_root_brent(fn, &p, 0.0, 1.0, 0.0, 1e-15, 60, &r) == DC_OK);
  CHECK_ABS(r.x, 0.5, 2e-15, "(x - 1/2) - 1e-17 = 0");
  /* a cap too small for the tolerance asked */
  init(&p, 0);
  CHECK(dc_root_brent(fn, &p, 0.0, 1.0, 1e-15, 0.0, 3, &r) == DC_ENOCONV);
  CHECK(r.evaluations == 5 && slot_holds(&p, &r));
}

int main(void)
{
  known_roots();
  bracket_ends();
  failures();
  return check_summary("root_find");
}
