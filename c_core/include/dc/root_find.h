/* Bracketed root finding shared by the laws: Brent's method (Brent,
   Algorithms for Minimization without Derivatives, 1973, Ch. 4, "zeroin"):
   inverse quadratic or secant steps while they stay well inside the
   bracket and shrink it fast enough, bisection otherwise, so the bracket
   always holds a sign change and the number of evaluations is at most
   about (log2((b - a)/tol))^2 (in practice a few more than the secant
   method needs).

   Evaluation slots: a caller whose function computes more than the value
   (a state it wants at the root, without evaluating there again) stores
   that side data in one of three slots, 0, 1, 2, named by the finder in
   each call; the finder never holds more than three points (the bracket
   ends and the previous iterate) and never reuses a slot it still holds.
   The caller's evaluations at the given ends are slots 0 (at a) and 1 (at
   b); the result names the slot of the root's evaluation. Callers without
   side data ignore the slot. */
#ifndef DC_ROOT_FIND_H
#define DC_ROOT_FIND_H

#ifdef __cplusplus
extern "C" {
#endif

/* The function, evaluated at x; slot: where to keep side data (above). */
typedef double (*dc_root_fn)(double x, void *ctx, int slot);

typedef struct {
  double x;        /* the root: the bracket end with the smaller |f|        */
  double fx;       /* f(x)                                                   */
  int slot;        /* the slot of the evaluation at x                        */
  int evaluations; /* calls of f made by the finder (given ends not counted) */
} dc_root_result;

/* Brent's method on [a, b] (either order) with fa = f(a), fb = f(b)
   already evaluated (slots 0 and 1). Stops when f(x) == 0 or half the
   width of the bracket is <= tol = rtol |x| + atol; steps shorter than tol
   are lengthened to tol.
   Domain: a, b, fa, fb finite with fa, fb of opposite signs or one of them
   zero (that end is the root, no evaluation); rtol, atol >= 0 finite;
   max_iter >= 1. DC_EDOM outside (a bad bracket), *r untouched.
   DC_ENOCONV after max_iter evaluations without meeting the tolerance
   (rtol = atol = 0 asks for more than the doubles can give, and ends
   there unless f hits 0 exactly), or when f is not finite inside the
   bracket: *r holds the last iterate (after a non-finite f, the last point
   where f was finite, so *r is always finite). */
int dc_root_brent_ends(dc_root_fn f, void *ctx, double a, double b, double fa, double fb, double rtol,
                       double atol, int max_iter, dc_root_result *r);

/* The same, evaluating f at a (slot 0) and b (slot 1) first; those two
   evaluations are counted in r->evaluations. DC_EDOM also when f is not
   finite at an end. */
int dc_root_brent(dc_root_fn f, void *ctx, double a, double b, double rtol, double atol, int max_iter,
                  dc_root_result *r);

#ifdef __cplusplus
}
#endif
#endif
