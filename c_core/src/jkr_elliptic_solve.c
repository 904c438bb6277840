/* The Johnson-Greenwood contact for a given overlap, dc_jkr_contact (review
   Eqs. 19-21 inverted for e^2 at given delta; dc/jkr_elliptic.h): warm-
   started Newton on ln(delta - delta_break), with the first-order Hertz
   expansion at large overlaps; and the contact hysteresis. */
#include "dc/jkr_elliptic.h"
#include "dc/hertz_elliptic.h"
#include "dc/status.h"
#include "jkr_elliptic_private.h"
#include <float.h>
#include <math.h>

int dc_jkr_in_contact(const dc_jkr_geom *G, int was_in_contact, double delta)
{
  return delta >= 0.0 || (was_in_contact && delta >= G->delta_break);
}

/* The hint after a converged solve at v (ln d = Lt): the slope du/dL of
   u = ln((v - v_b)/(v_H - v)) against L = ln(dbar - dbar_b). */
static void set_hint(dc_jkr_hint *h, double v, double vb, double vH, double Lt, double d, double ddbar)
{
  h->v = v;
  h->L = Lt;
  const double dudv = (vH - vb) / ((v - vb) * (vH - v));
  const double s = dudv * d / ddbar;
  h->dudL = isfinite(s) && s > 0.0 ? s : 0.0;
}

int dc_jkr_contact(const dc_jkr_geom *G, double delta, dc_jkr_hint *hint, dc_jkr_state *s)
{
  if (!isfinite(delta)) return DC_EDOM;
  if (G->w == 0.0) {
    if (delta < 0.0) { dc_jkr_zero_state_(delta, s); return DC_OK; }
    dc_hertz_state h;
    int st = dc_hertz_contact(&G->hertz, G->Estar, delta, &h);
    if (st != DC_OK) return st;
    if (!(isfinite(h.F) && isfinite(h.a) && isfinite(h.b) && isfinite(h.area) && isfinite(h.kn))) return DC_ERANGE;
    s->contact = 1; s->F = h.F; s->delta = delta; s->a = h.a; s->b = h.b;
    s->area = h.area; s->e2 = G->e2_hertz; s->kn = h.kn;
    return DC_OK;
  }
  if (G->circular) return dc_jkr_sphere(G->Rhat, G->Estar, G->w, delta, s);
  if (delta < G->delta_break) { dc_jkr_zero_state_(delta, s); return DC_OK; }
  const double dbar_t = delta / G->delta_scale;
  if (dbar_t > G->dbar_switch) {
    /* first order in rho ~ dbar^-3/4 < 3e-8: the neglected O(rho^2) is
       below rounding */
    const double rho = G->pert_rho0 / (sqrt(dbar_t) * sqrt(sqrt(dbar_t)));
    const double X = G->pert_X0 + G->pert_X1 * rho;
    const double g = G->pert_g0 + G->pert_g1 * rho;
    const double Fd = G->F_scale * dbar_t * sqrt(dbar_t);
    dc_jkr_state t;
    t.contact = 1;
    t.delta = delta;
    t.F = Fd * (G->pert_P0 + G->pert_P1 * rho);
    t.a = G->a_scale * sqrt(dbar_t / X);
    t.b = g * t.a;
    t.area = M_PI * t.a * t.b;
    t.e2 = (1.0 - g) * (1.0 + g);
    t.kn = (1.5 * t.F - 0.75 * Fd * G->pert_P1 * rho) / delta;
    if (!dc_jkr_state_finite_(&t)) return DC_ERANGE;
    *s = t;
    if (hint) { hint->v = G->use_m1 ? g * g : t.e2; hint->dudL = 0.0; }
    return DC_OK;
  }
  const double vH = G->v_hertz, vb = G->v_break;
  jg_point p;
  const double dbar_b = G->dbar_break;
  const double dtarget = dbar_t - dbar_b;
  dc_jkr_state t;
  /* at the separation point, or above it by less than the rounding of the
     map there: dbar_b is the exact minimum (jkr_geometry_poly.h), the
     map's own minimum can lie above it by ~1e-14 relative (slender
     contacts), and a target between the two has no root */
  int at_break = !(dtarget > 0.0);
  if (!at_break && dtarget < 1e-10 * fabs(dbar_b)) {
    jg_eval(G, vb, &p);
    at_break = !(p.dbar < dbar_t);
  }
  if (at_break) {
    jg_eval(G, vb, &p);
    dc_jkr_elliptic_fill_(G, &p, 0.0, &t);
    t.delta = delta;
    if (!dc_jkr_state_finite_(&t)) return DC_ERANGE;
    *s = t;
    if (hint) { hint->v = vb; hint->dudL = 0.0; }
    return DC_OK;
  }
  double v;
  const double Lt = log(dtarget);
  if (hint && (hint->v - vb) * (hint->v - vH) < 0.0) {
    v = hint->v;
    /* predictor: u linear in L from the previous solve (u(L) is close to
       linear, so this is usually within the 1e-8 tolerance below and one
       evaluation suffices) */
    if (hint->dudL > 0.0 && isfinite(hint->L)) {
      const double du = hint->dudL * (Lt - hint->L);
      if (fabs(du) < 1.0) {
        const double rn = (v - vb) / (vH - v) * exp(du);
        const double vn = (vb + vH * rn) / (1.0 + rn);
        if ((vn - vb) * (vn - vH) < 0.0) v = vn;
      }
    }
  } else {
    const double sd = sqrt(dtarget);
    v = vH - (vH - vb) / (1.0 + sd * (G->guess_c1 + G->guess_c2 * sqrt(sd)));
  }
  /* Newton on ln(dbar(v) - dbar_b) = ln(dtarget): dbar - dbar_b grows like
     (v - v_b)^2 at the separation point and like |v_H - v|^-4/3 at the
     Hertz end, so its logarithm is close to linear in ln of either
     distance and the iteration neither stalls at the vertical tangent nor
     jumps past the pole. Bracketed: lo has dbar < target, hi dbar > target. */
  double lo = vb, hi = vH;
  for (int it = 0; it < 60; it++) {
    jg_eval(G, v, &p);
    const double d = p.dbar - dbar_b;
    const double sgn = vH > vb ? 1.0 : -1.0;   /* dbar increases along sgn */
    if (!(d > 0.0) || !(sgn * p.ddbar > 0.0) || !(p.rho > 0.0)) {
      /* rounding at either end of the bracket: bisect */
      if (!(p.rho > 0.0)) hi = v; else lo = v;
      v = 0.5 * (lo + hi);
      continue;
    }
    if (p.dbar > dbar_t) hi = v; else lo = v;
    const double lin = (dbar_t - p.dbar) / p.ddbar;  /* plain Newton step */
    const double step = -(log(d) - Lt) * d / p.ddbar;
    const double scale = fmin(fabs(vH - v), fabs(v - vb));
    const double tol_v = fmax(1e-8 * scale, 16.0 * DBL_EPSILON * (fabs(vH) + fabs(dbar_b / p.ddbar)));
    if (fabs(step) <= tol_v || fabs(hi - lo) <= 4.0 * DBL_EPSILON * fabs(v)) {
      dc_jkr_elliptic_fill_(G, &p, lin, &t);
      t.delta = delta;
      if (!dc_jkr_state_finite_(&t)) return DC_ERANGE;
      *s = t;
      if (hint) set_hint(hint, v + lin, vb, vH, Lt, dtarget, p.ddbar);
      return DC_OK;
    }
    /* the step is taken in u = ln((v - v_b)/(v_H - v)), in which ln d is
       close to linear at both ends (slope 2 at the separation point, 4/3
       at the Hertz end), so Newton's quadratic error term is small and a
       warm start usually converges in two evaluations (plain Newton steps
       in v, even within a few per cent of the root, need three); to first
       order this is the step above */
    const double r = (v - vb) / (vH - v);
    const double du = step * (vH - vb) / ((v - vb) * (vH - v));
    const double rn = r * exp(du);
    double vn = (vb + vH * rn) / (1.0 + rn);
    if (!((vn - lo) * (vn - hi) < 0.0)) vn = 0.5 * (lo + hi);
    v = vn;
  }
  /* not converged: the last iterate (status.h), if it is finite */
  jg_eval(G, v, &p);
  dc_jkr_elliptic_fill_(G, &p, (dbar_t - p.dbar) / p.ddbar, &t);
  t.delta = delta;
  if (dc_jkr_state_finite_(&t)) {
    *s = t;
    if (hint) { hint->v = v; hint->dudL = 0.0; }
  }
  return DC_ENOCONV;
}
