/* GW rough contact with adhesive (JKR) summits: review Eq. 29 with the
   summit law of jkr_elliptic.c, by graded Gauss-Kronrod panels; see
   dc/gw_rough_adhesive.h for the law, the branches and the panels. */
#include "dc/gw_rough_adhesive.h"
#include "dc/gw_rough.h"
#include "dc/jkr_elliptic.h"
#include "dc/status.h"
#include <float.h>
#include <math.h>
#include <stddef.h>

/* 15-point Kronrod nodes on [-1, 1] in increasing order, their weights, and
   the weights of the embedded 7-point Gauss rule (0 at Kronrod-only nodes).
   Computed with mpmath (Stieltjes polynomial of P_7, 40 digits); they agree
   with QUADPACK's qk15. */
static const double XK[15] = {
  -0.991455371120812639207, -0.949107912342758524526, -0.864864423359769072790,
  -0.741531185599394439864, -0.586087235467691130294, -0.405845151377397166907,
  -0.207784955007898467601, 0.0, 0.207784955007898467601, 0.405845151377397166907,
  0.586087235467691130294, 0.741531185599394439864, 0.864864423359769072790,
  0.949107912342758524526, 0.991455371120812639207};
static const double WK[15] = {
  0.0229353220105292249637, 0.0630920926299785532907, 0.104790010322250183840,
  0.140653259715525918745, 0.169004726639267902827, 0.190350578064785409913,
  0.204432940075298892414, 0.209482141084727828013, 0.204432940075298892414,
  0.190350578064785409913, 0.169004726639267902827, 0.140653259715525918745,
  0.104790010322250183840, 0.0630920926299785532907, 0.0229353220105292249637};
static const double WG[15] = {
  0.0, 0.129484966168869693271, 0.0, 0.279705391489276667901, 0.0, 0.381830050505118944950, 0.0,
  0.417959183673469387755, 0.0, 0.381830050505118944950, 0.0, 0.279705391489276667901, 0.0,
  0.129484966168869693271, 0.0};

#define CUT2 90.0       /* phi cut at e^-45 of its largest value on the range */
#define X_FLOOR 1e-6    /* shortest first panel                              */
#define X_TAU 0.5       /* longest first (tau) panel                          */
#define C_TAU 0.5       /* first panel: C_TAU D                               */
#define R_LIN 3.0       /* growth of the linear panels                        */
#define C_Y 8.0         /* y = x^1/4 panels from C_Y D ...                    */
#define X_Y 2.0         /* ... to at most X_Y                                 */
#define R_Y 81.0        /* growth of the y panels in x (3 in y)               */
#define C_G 8.0         /* panel width <= C_G / max(1, s0): phi's decay       */
#define C_GY 1.0        /* y panel width <= C_GY / (phi's slope)               */
#define W_MAX 3.0       /* widest panel                                       */
#define MAX_PANELS 80

enum { MAP_TAU, MAP_LIN, MAP_Y };

typedef struct {
  const dc_jkr_geom *g;
  double uo, so, x_lo;  /* origin of t: compression and height there, x - t */
  double sigma, s0;
  dc_jkr_hint hint;
  double F, A, K;      /* Kronrod sums of F, area, kn                    */
  double E;            /* error estimate of F (unscaled)                */
  int n_eval, status;
} acc_t;

/* phi(so + t) / phi(max(s0, 0)) without cancellation or early underflow
   (s0 > 0 implies so = s0) */
static inline double gauss_factor(double s0, double so, double t)
{
  if (s0 > 0.0) return exp(-t * (s0 + 0.5 * t));
  const double s = so + t;
  return exp(-0.5 * s * s);
}

/* dF/d delta of a circular summit from its contact radius a, (dF/da) /
   (d delta/da) (classical JKR); used instead of dc_jkr_sphere's kn, which
   was pi times dF/d delta on its Halley path when this was written. */
static double sphere_kn(const dc_jkr_geom *g, double a)
{
  const double R = g->Rhat, E = g->Estar, w = g->w;
  const double num = 4.0 * E * a * a / R - 1.5 * sqrt(8.0 * M_PI * w * E * a);
  const double den = 2.0 * a / R - 0.5 * sqrt(2.0 * M_PI * w / (E * a));
  return num / den;
}

/* One panel [ta, tb] in the given map; t is the distance from the origin
   of the integration (x = x_lo + t, x the distance from s0). */
static void panel(acc_t *q, int map, double ta, double tb)
{
  double F = 0.0, A = 0.0, K = 0.0, FG = 0.0, fv[15];
  /* tau: x = xa + (xb - xa) tau^2, tau in [0, 1]; y: x = y^4, y in
     [xa^1/4, xb^1/4]; lin: t itself */
  const double xa = q->x_lo + ta, xb = q->x_lo + tb;
  double c, hw;
  if (map == MAP_TAU) { c = 0.5; hw = 0.5; }
  else if (map == MAP_Y) { const double ya = sqrt(sqrt(xa)), yb = sqrt(sqrt(xb)); c = 0.5 * (ya + yb); hw = 0.5 * (yb - ya); }
  else { c = 0.5 * (ta + tb); hw = 0.5 * (tb - ta); }
  for (int i = 0; i < 15; i++) {
    const double p = c + hw * XK[i];
    double t, dt;
    if (map == MAP_TAU) { t = ta + (tb - ta) * p * p; dt = 2.0 * (tb - ta) * p; }
    else if (map == MAP_Y) { const double p2 = p * p; t = p2 * p2 - q->x_lo; dt = 4.0 * p2 * p; }
    else { t = p; dt = 1.0; }
    dc_jkr_state st = {0};   /* read below even when the summit failed (status kept) */
    const int r = dc_jkr_contact(q->g, q->uo + q->sigma * t, &q->hint, &st);
    q->n_eval++;
    /* a summit's failure; its compression can only be non-finite (EDOM
       from the summit law) by overflowing */
    if (r != DC_OK && q->status != DC_ERANGE) q->status = r == DC_EDOM ? DC_ERANGE : r;
    const double wgt = dt * gauss_factor(q->s0, q->so, t);
    fv[i] = wgt * st.F;
    F += WK[i] * fv[i];
    A += WK[i] * wgt * st.area;
    K += WK[i] * wgt * (q->g->circular ? sphere_kn(q->g, st.a) : st.kn);
    FG += WG[i] * fv[i];
  }
  /* QUADPACK's qk15 error estimate: resasc min(1, (200 |K - G| /
     resasc)^1.5), resasc = int |f - mean f|, at least 50 eps int |f| */
  double asc = 0.0, abs_ = 0.0;
  for (int i = 0; i < 15; i++) {
    asc += WK[i] * fabs(fv[i] - 0.5 * F);
    abs_ += WK[i] * fabs(fv[i]);
  }
  const double dif = fabs(F - FG);
  double err = asc > 0.0 ? asc * fmin(1.0, pow(200.0 * dif / asc, 1.5)) : dif;
  err = fmax(err, 50.0 * DBL_EPSILON * abs_);
  q->F += hw * F;
  q->A += hw * A;
  q->K += hw * K;
  q->E += hw * err;
}

/* The state is written on DC_OK and DC_ENOCONV (the last iterate), and
   only if finite: otherwise DC_ERANGE, output untouched. */
static int finish(int st, const dc_gw_adhesive_state *s, dc_gw_adhesive_state *out)
{
  if (!(isfinite(s->F) && isfinite(s->area) && isfinite(s->kn) && isfinite(s->h) && isfinite(s->err)))
    st = DC_ERANGE;
  if (st != DC_OK && st != DC_ENOCONV) return st;
  *out = *s;
  return st;
}

int dc_gw_rough_adhesive(const dc_jkr_geom *g, double n_asp, double sigma, double delta,
                         int branch, dc_gw_adhesive_state *out)
{
  if (!(n_asp > 0.0 && isfinite(n_asp) && sigma >= 0.0 && isfinite(sigma) && isfinite(delta) &&
        (branch == DC_GW_LOADING || branch == DC_GW_UNLOADING)))
    return DC_EDOM;
  if (g->w == 0.0) {
    /* no adhesion: the closed form (review Eqs. 31-36) */
    dc_gw_rough_state rs;
    const int r = dc_gw_rough_elliptic(&g->hertz, g->Estar, n_asp, sigma, delta, &rs);
    if (r != DC_OK) return r;
    out->F = rs.F; out->area = rs.area; out->kn = rs.kn; out->h = rs.h;
    out->err = 0.0; out->n_eval = 0;
    return DC_OK;
  }
  dc_gw_adhesive_state res, *s = &res;
  const double u0 = branch == DC_GW_LOADING ? 0.0 : g->delta_break;
  const double s0 = (u0 - delta) / sigma;
  if (sigma == 0.0 || !isfinite(s0)) {
    /* all summits at one height (or sigma so small that |s0| overflows) */
    s->F = s->area = s->kn = s->err = 0.0;
    s->h = delta > 0.0 ? -1e300 : 1e300;
    s->n_eval = 0;
    if (delta < u0) return finish(DC_OK, s, out);
    dc_jkr_state st;
    const int r = dc_jkr_contact(g, delta, NULL, &st);
    if (r != DC_OK && r != DC_ENOCONV) return r;
    s->n_eval = 1;
    s->F = n_asp * st.F; s->area = n_asp * st.area; s->kn = n_asp * st.kn;
    return finish(r, s, out);
  }
  const double h = -delta / sigma;
  s->h = isfinite(h) ? h : (h > 0.0 ? 1e300 : -1e300);
  s->F = s->area = s->kn = s->err = 0.0;
  s->n_eval = 0;
  const double sr = s0 > 0.0 ? s0 : 0.0;
  const double scale = exp(-0.5 * sr * sr) * 0.39894228040143267794;   /* phi(sr) */
  if (!(scale > 0.0)) return finish(DC_OK, s, out);   /* every summit far apart */
  const double cut = sqrt(CUT2);
  const double x_hi = sqrt(sr * sr + CUT2) - s0;
  const double x_lo = s0 < -cut ? -cut - s0 : 0.0;
  const double D = -g->delta_break / sigma;
  /* origin: the lowest attached summit, or the cut of phi below it (then
     u = delta + sigma s from there, free of the cancellation in s0 + x
     when |s0| is large) */
  acc_t q;
  q.g = g;
  q.x_lo = x_lo;
  q.so = x_lo == 0.0 ? s0 : -cut;
  q.uo = x_lo == 0.0 ? u0 : delta - sigma * cut;
  q.sigma = sigma;
  q.s0 = s0;
  q.hint.v = q.hint.L = q.hint.dudL = 0.0;
  q.F = q.A = q.K = q.E = 0.0;
  q.n_eval = 0;
  q.status = DC_OK;

  /* panels (header comment), laid out in x = x_lo + t, abutting in t */
  const double t_hi = x_lo == 0.0 ? x_hi : 2.0 * cut;
  const double x1 = fmin(X_TAU, fmax(C_TAU * D, X_FLOOR));
  const double xy = C_Y * D;
  const double wg = fmin(W_MAX, C_G / fmax(1.0, s0));   /* phi's scale */
  double t = 0.0;
  int np = 0;
  while (t < t_hi && np < MAX_PANELS) {
    const double x = x_lo + t;
    double dt;
    int map = MAP_LIN;
    if (x < x1) {
      dt = fmin(x1 - x, wg);
      map = MAP_TAU;
    } else {
      dt = fmin(x * (R_LIN - 1.0), wg);
      if (x >= xy && x < X_Y) {
        const double lam = fmax(1.0, fmax(s0, -(s0 + x)));   /* phi's slope */
        const double dty = fmin(fmin(x * (R_Y - 1.0), X_Y - x), C_GY / lam);
        if (dty > dt) { dt = dty; map = MAP_Y; }
      }
    }
    double tb = t + dt;
    if (!(tb < t_hi) || t_hi - tb < 0.25 * dt) tb = t_hi;   /* no sliver at the end */
    panel(&q, map, t, tb);
    t = tb;
    np++;
  }
  s->F = n_asp * scale * q.F;
  s->area = n_asp * scale * q.A;
  s->kn = n_asp * scale * q.K;
  s->err = n_asp * scale * q.E;
  if (t < t_hi) q.status = DC_ENOCONV;   /* MAX_PANELS: not reached */
  if (x_lo == 0.0) {
    /* attachment term f(u0) phi(s0)/sigma */
    double f0 = g->F_break;
    if (branch == DC_GW_LOADING) {
      dc_jkr_state st = {0};
      const int r = dc_jkr_contact(g, 0.0, NULL, &st);
      q.n_eval++;
      if (r != DC_OK && q.status != DC_ERANGE) q.status = r;
      f0 = st.F;
    }
    s->kn += n_asp * scale * gauss_factor(s0, s0, 0.0) * f0 / sigma;
  }
  s->n_eval = q.n_eval;
  return finish(q.status, s, out);
}
