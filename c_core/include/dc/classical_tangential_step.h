/* The step of the classical tangential laws (dc/classical_tangential.h),
   inline: dc_classical_tangential_step_law is dc_classical_tangential_step
   with the law an argument, so that a caller that knows the law (a
   LIGGGHTS wrapper dispatching once on its setting) gets the law's path
   alone, its values in registers; the same code and the same bits as the
   function (which calls it with checked = 1).
   checked = 0 skips the check of the inputs' domain (a third of the
   step's instructions) and of the increment vt dt: for a caller whose
   inputs lie in the domain by construction (finite, |n| = 1, a, F_bound,
   meff, kn, gamman in range, dt > 0). The results are checked all the
   same (an increment that overflowed shows in the spring): a non-finite
   one gives DC_ERANGE with h and out untouched, and the caller then calls
   the checked step for the status of its inputs. */
#ifndef DC_CLASSICAL_TANGENTIAL_STEP_H
#define DC_CLASSICAL_TANGENTIAL_STEP_H

#include <float.h>
#include <math.h>
#include "dc/classical_tangential.h"
#include "dc/inline.h"
#include "dc/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* |v| of the vector (x, y, z) whose v.v leaves the normal range, scaled
   by its largest component; out of line and by value (rare: the caller's
   vector stays in registers). */
DC_COLD double ct_norm3_scaled(double x, double y, double z)
{
  const double mx = fmax(fabs(x), fmax(fabs(y), fabs(z)));
  if (mx == 0.0 || !isfinite(mx)) return mx;
  const double a = x / mx, b = y / mx, c = z / mx;
  return mx * sqrt(a * a + b * b + c * c);
}

/* |v| without overflow or underflow. */
DC_INLINE double ct_norm3(const double *v)
{
  const double s = dc_dot3(v, v);
  return s >= DBL_MIN && s <= DBL_MAX ? sqrt(s) : ct_norm3_scaled(v[0], v[1], v[2]);
}

/* ct_turn_into_plane where |v|^2, |w|^2 or their ratio leave the normal
   range: v and w by value, the turned v returned. */
typedef struct {
  double v[3];
} ct_vec3;
DC_COLD ct_vec3 ct_turn_scaled(ct_vec3 v, ct_vec3 w)
{
  const double len = ct_norm3(v.v), lw = ct_norm3(w.v);
  ct_vec3 r = {{0.0, 0.0, 0.0}};
  if (!(lw > 0.0)) return r;
  const double f = len / lw;
  for (int k = 0; k < 3; k++) r.v[k] = w.v[k] * f;
  if (!dc_finite3(r.v)) for (int k = 0; k < 3; k++) r.v[k] = w.v[k] / lw * len;
  return r;
}

/* v minus its part along the unit n, scaled back to its former length
   (LIGGGHTS' rotation of the shear history). */
DC_INLINE void ct_turn_into_plane(double *v, const double *n)
{
  const double vn = dc_dot3(v, n);
  if (vn == 0.0) return;   /* in the plane already (or zero) */
  double w[3] = {v[0] - vn * n[0], v[1] - vn * n[1], v[2] - vn * n[2]};
  const double len2 = dc_dot3(v, v), lw2 = dc_dot3(w, w);
  const double q = len2 / lw2;
  if (len2 >= DBL_MIN && len2 <= DBL_MAX && lw2 >= DBL_MIN && lw2 <= DBL_MAX && q <= DBL_MAX) {   /* one root */
    const double f = sqrt(q);
    v[0] = w[0] * f;
    v[1] = w[1] * f;
    v[2] = w[2] * f;
    return;
  }
  const ct_vec3 a = {{v[0], v[1], v[2]}}, b = {{w[0], w[1], w[2]}};
  const ct_vec3 r = ct_turn_scaled(a, b);
  v[0] = r.v[0];
  v[1] = r.v[1];
  v[2] = r.v[2];
}

/* The history back: the laws other than INCREMENTAL own only the spring. */
DC_INLINE void ct_store(int law, const dc_classical_tangential_state *s, dc_classical_tangential_state *h)
{
  h->spring[0] = s->spring[0];
  h->spring[1] = s->spring[1];
  h->spring[2] = s->spring[2];
  if (law == DC_CT_INCREMENTAL) {
    h->rev[0] = s->rev[0];
    h->rev[1] = s->rev[1];
    h->rev[2] = s->rev[2];
  }
}

DC_INLINE void ct_project_plane(double *v, const double *n)
{
  const double vn = dc_dot3(v, n);
  v[0] -= vn * n[0];
  v[1] -= vn * n[1];
  v[2] -= vn * n[2];
}

/* Scales F onto |F| = lim when it exceeds it; 1 if it did. */
DC_INLINE int ct_limit_force(double *F, double lim)
{
  const double f2 = dc_dot3(F, F), lim2 = lim * lim;
  if (f2 <= lim2 && lim2 <= DBL_MAX && (f2 >= DBL_MIN || f2 == 0.0) && lim2 >= DBL_MIN) return 0;   /* no root */
  const double f = ct_norm3(F);
  if (!(f > lim)) return 0;
  if (lim == 0.0) { F[0] = F[1] = F[2] = 0.0; return 1; }
  F[0] = F[0] / f * lim;
  F[1] = F[1] / f * lim;
  F[2] = F[2] / f * lim;
  return 1;
}

/* K_t of the stiffness setting (the default, MINDLIN, tested first). */
DC_INLINE double ct_spring_stiffness(const dc_classical_tangential *m, const dc_patch *patch,
                                     const dc_classical_tangential_contact *c)
{
  if (m->p.stiffness == DC_CT_KT_MINDLIN) return 8.0 * m->p.Gstar * patch->a;
  return m->p.stiffness == DC_CT_KT_GIVEN ? m->p.kt : m->ratio * c->kn;
}

/* eta_t of the damping setting for a spring of stiffness K. */
DC_INLINE double ct_dashpot(const dc_classical_tangential *m, int damping, double K,
                      const dc_classical_tangential_contact *c)
{
  switch (damping) {
  case DC_CT_DAMP_GIVEN: return m->p.gammat;
  case DC_CT_DAMP_RESTITUTION: {
    double g = m->zeta_t * sqrt(2.0 / 7.0 * c->meff * K);
    if (!isfinite(g)) g = m->zeta_t * (sqrt(2.0 / 7.0 * c->meff) * sqrt(K));
    return g;
  }
  case DC_CT_DAMP_NORMAL: return c->gamman;
  default: return 0.0;
  }
}

/* Notes 4.5: F = K s, |F| <= lim; a sliding spring is set to F/K. */
DC_INLINE void ct_spring(double K, double lim, const double *du, double *s, double *F, double *kt, int *sliding)
{
  s[0] += du[0];
  s[1] += du[1];
  s[2] += du[2];
  F[0] = K * s[0];
  F[1] = K * s[1];
  F[2] = K * s[2];
  *sliding = ct_limit_force(F, lim);
  *kt = *sliding ? 0.0 : K;
  if (*sliding) {
    if (K > 0.0) {
      s[0] = F[0] / K;
      s[1] = F[1] / K;
      s[2] = F[2] / K;
    } else {
      s[0] = s[1] = s[2] = 0.0;
    }
  }
}

/* Notes 4.6, 4.7: F = K s + eta v, |F| <= lim; a sliding spring is set to
   (F - eta v)/K. */
DC_INLINE void ct_spring_dashpot(double K, double eta, double lim, const double *du, const double *v, double *s,
                           double *F, double *kt, int *sliding)
{
  double Fv[3];
  s[0] += du[0];
  s[1] += du[1];
  s[2] += du[2];
  Fv[0] = eta * v[0];
  Fv[1] = eta * v[1];
  Fv[2] = eta * v[2];
  F[0] = K * s[0] + Fv[0];
  F[1] = K * s[1] + Fv[1];
  F[2] = K * s[2] + Fv[2];
  *sliding = ct_limit_force(F, lim);
  *kt = *sliding ? 0.0 : K;
  if (*sliding) {
    if (K > 0.0) {
      s[0] = (F[0] - Fv[0]) / K;
      s[1] = (F[1] - Fv[1]) / K;
      s[2] = (F[2] - Fv[2]) / K;
    } else {
      s[0] = s[1] = s[2] = 0.0;
    }
  }
}

/* Notes 4.7, LTH and ZZYt: the elastic force of the spring s (capped at
   d = 3 lim / (2 K0)) and its stiffness K0 (1 - x)^1/2. */
DC_INLINE void ct_langston_spring(double K0, double lim, const double *du, double *s, double *Fe, double *kt,
                            double *d, int *at_limit)
{
  s[0] += du[0];
  s[1] += du[1];
  s[2] += du[2];
  *at_limit = 0;
  if (!(K0 > 0.0) || !(lim > 0.0)) {
    s[0] = s[1] = s[2] = 0.0;
    Fe[0] = Fe[1] = Fe[2] = 0.0;
    *kt = 0.0;
    *d = 0.0;
    *at_limit = lim == 0.0;
    return;
  }
  *d = 1.5 * (lim / K0);
  const double r = ct_norm3(s), x = r > 0.0 ? r / *d : 0.0;
  if (x >= 1.0) {
    /* at the limit (d may underflow to 0: the direction from s itself) */
    const double e[3] = {s[0] / r, s[1] / r, s[2] / r};
    s[0] = e[0] * *d;
    s[1] = e[1] * *d;
    s[2] = e[2] * *d;
    Fe[0] = e[0] * lim;
    Fe[1] = e[1] * lim;
    Fe[2] = e[2] * lim;
    *kt = 0.0;
    *at_limit = 1;
    return;
  }
  /* mu F_n (1 - (1 - x)^3/2) */
  const double f = -lim * expm1(1.5 * log1p(-x));
  Fe[0] = r > 0.0 ? s[0] / r * f : 0.0;
  Fe[1] = r > 0.0 ? s[1] / r * f : 0.0;
  Fe[2] = r > 0.0 ? s[2] / r * f : 0.0;
  *kt = K0 * sqrt(1.0 - x);
}

/* Notes 4.8, Walton-Braun, integrated exactly along the step: F the force,
   R the force at the last reversal, lim = mu F_n. */
DC_INLINE void ct_incremental_step(double K0, double lim, const double *du, double *F, double *R, double *kt,
                             int *sliding)
{
  if (!(lim > 0.0) || !(K0 > 0.0)) {
    /* no friction, or no spring: nothing can be held */
    F[0] = F[1] = F[2] = 0.0;
    R[0] = R[1] = R[2] = 0.0;
    *kt = 0.0;
    *sliding = lim == 0.0;
    return;
  }
  ct_limit_force(F, lim);   /* a smaller normal force clips the state */
  ct_limit_force(R, lim);
  const double L = ct_norm3(du);
  double e[3];
  if (L > 0.0) {
    e[0] = du[0] / L;
    e[1] = du[1] / L;
    e[2] = du[2] / L;
    const double rev = du[0] * (F[0] - R[0]) + du[1] * (F[1] - R[1]) + du[2] * (F[2] - R[2]);
    if (rev < 0.0) {
      R[0] = F[0];
      R[1] = F[1];
      R[2] = F[2];
    }
  } else {
    const double f = ct_norm3(F);
    if (f > 0.0) {
      e[0] = F[0] / f;
      e[1] = F[1] / f;
      e[2] = F[2] / f;
    } else {
      e[0] = e[1] = e[2] = 0.0;
    }
  }
  const double T = F[0] * e[0] + F[1] * e[1] + F[2] * e[2];
  const double Ts = R[0] * e[0] + R[1] * e[1] + R[2] * e[2];
  const double D = lim - Ts;   /* >= 0 since |R| <= lim */
  double u0;                   /* 1 - (T - T*)/D in [0, 1] */
  if (T - Ts <= 0.0) u0 = 1.0;
  else if (D > 0.0) u0 = fmax(0.0, 1.0 - (T - Ts) / D);
  else u0 = 0.0;
  /* du/dx = -K0 u^1/3 / D: u^2/3 = u0^2/3 - 2 K0 x / (3 D); dT = D (u0 - u) */
  double dT = 0.0, u1 = u0;
  if (L > 0.0 && u0 > 0.0 && D > 0.0) {
    const double c23 = cbrt(u0 * u0);
    const double y = 2.0 * K0 * (L / D) / (3.0 * c23);   /* fraction of u0^2/3 used */
    if (y >= 1.0 || !isfinite(y)) { dT = D * u0; u1 = 0.0; }
    else {
      dT = -D * u0 * expm1(1.5 * log1p(-y));
      u1 = u0 * (1.0 - y) * sqrt(1.0 - y);
    }
  }
  F[0] += dT * e[0];
  F[1] += dT * e[1];
  F[2] += dT * e[2];
  *sliding = ct_limit_force(F, lim) || u1 == 0.0;
  *kt = *sliding ? 0.0 : K0 * cbrt(u1);
}

/* The inputs' domain (dc_classical_tangential_step): every input finite
   (one sum, dc/inline.h), then the ranges. */
DC_INLINE int dc_classical_tangential_domain(int law, const dc_patch *patch, const dc_classical_tangential_contact *c,
                                             const double n[3], const double du[3], const double vt[3], double dt,
                                             const dc_classical_tangential_state *h)
{
  const double *sp = h->spring;
  double chk = ((dc_nf(patch->a) + dc_nf(patch->F_bound)) + (dc_nf(patch->formed) + dc_nf(c->meff))) +
               ((dc_nf(n[0]) + dc_nf(n[1])) + (dc_nf(n[2]) + dc_nf(vt[0]))) +
               ((dc_nf(vt[1]) + dc_nf(vt[2])) + (dc_nf(sp[0]) + dc_nf(sp[1]))) +
               (dc_nf(sp[2]) + (dc_nf(c->kn) + dc_nf(c->gamman)));
  if (du) chk += (dc_nf(du[0]) + dc_nf(du[1])) + dc_nf(du[2]);
  if (law == DC_CT_INCREMENTAL) chk += (dc_nf(h->rev[0]) + dc_nf(h->rev[1])) + dc_nf(h->rev[2]);
  if (chk != 0.0) return DC_EDOM;
  if (!(patch->a >= 0.0 && patch->F_bound >= 0.0 && c->meff > 0.0 && c->kn >= 0.0 && c->gamman >= 0.0))
    return DC_EDOM;
  const double nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
  if (!(fabs(nn - 1.0) <= 1e-6)) return DC_EDOM;
  if (!du && !(dt > 0.0 && dt <= DBL_MAX)) return DC_EDOM;
  return DC_OK;
}

/* Whether the law reads the projected velocity (COULOMB scales its own). */
DC_INLINE int ct_uses_velocity(int law)
{
  return law == DC_CT_VISCOUS || law == DC_CT_VISCOUS_SLIDING || law == DC_CT_SPRING_DASHPOT_SLIDING ||
         law == DC_CT_DI_RENZO || law == DC_CT_TSUJI || law == DC_CT_LANGSTON || law == DC_CT_ZHENG;
}

DC_INLINE int dc_classical_tangential_step_law(int law, int checked, const dc_classical_tangential *m,
                                               const dc_patch *patch, const dc_classical_tangential_contact *c,
                                               const double n[3], const double du[3], const double vt[3], double dt,
                                               dc_classical_tangential_state *h, dc_classical_tangential_out *out)
{
  if (checked && dc_classical_tangential_domain(law, patch, c, n, du, vt, dt, h) != DC_OK) return DC_EDOM;
  double d[3], v[3] = {vt[0], vt[1], vt[2]};
  if (du) {
    d[0] = du[0]; d[1] = du[1]; d[2] = du[2];
  } else {
    d[0] = vt[0] * dt;
    d[1] = vt[1] * dt;
    d[2] = vt[2] * dt;
    if (checked && !dc_finite3(d)) return DC_ERANGE;
  }

  dc_classical_tangential_out o;
  dc_classical_tangential_state s;   /* the laws but INCREMENTAL neither read nor write h->rev */
  s.spring[0] = h->spring[0];
  s.spring[1] = h->spring[1];
  s.spring[2] = h->spring[2];
  if (law == DC_CT_INCREMENTAL) {
    s.rev[0] = h->rev[0];
    s.rev[1] = h->rev[1];
    s.rev[2] = h->rev[2];
  } else {
    s.rev[0] = s.rev[1] = s.rev[2] = 0.0;
  }
  o.Ft[0] = o.Ft[1] = o.Ft[2] = 0.0;
  o.kt = o.gammat = 0.0;
  o.sliding = 0;
  if (!(patch->formed != 0.0)) {
    s.spring[0] = s.spring[1] = s.spring[2] = 0.0;
    s.rev[0] = s.rev[1] = s.rev[2] = 0.0;
    ct_store(law, &s, h);
    *out = o;
    return DC_OK;
  }
  ct_project_plane(d, n);
  if (ct_uses_velocity(law)) ct_project_plane(v, n);
  ct_turn_into_plane(s.spring, n);
  if (law == DC_CT_INCREMENTAL) ct_turn_into_plane(s.rev, n);
  const double lim = m->p.mu * patch->F_bound;
  if (!(lim <= DBL_MAX)) return DC_ERANGE;

  switch (law) {
  case DC_CT_COULOMB: {
    /* notes 4.2: F = mu F_n v/|v|, v from vt scaled to order one (exactly:
       a subnormal vt has too few bits to give a direction), and again
       after the projection (a vt mostly along n leaves a subnormal v, whose
       rounded |v| is off by up to 1e-11) */
    int e;
    frexp(fmax(fabs(vt[0]), fmax(fabs(vt[1]), fabs(vt[2]))), &e);
    v[0] = ldexp(vt[0], -e);
    v[1] = ldexp(vt[1], -e);
    v[2] = ldexp(vt[2], -e);
    ct_project_plane(v, n);
    if (dc_dot3(v, v) < 1e-270) {   /* |v| below ~1e-135: scaled to order one again */
      frexp(fmax(fabs(v[0]), fmax(fabs(v[1]), fabs(v[2]))), &e);
      v[0] = ldexp(v[0], -e);
      v[1] = ldexp(v[1], -e);
      v[2] = ldexp(v[2], -e);
    }
    const double vv = ct_norm3(v);
    if (vv > 0.0) {
      o.Ft[0] = v[0] / vv * lim;
      o.Ft[1] = v[1] / vv * lim;
      o.Ft[2] = v[2] / vv * lim;
      o.sliding = 1;
    }
    break;
  }
  case DC_CT_VISCOUS:
  case DC_CT_VISCOUS_SLIDING:
    /* notes 4.3, 4.4: F = eta_t v (|F| <= mu F_n) */
    o.gammat = m->p.gammat;
    o.Ft[0] = o.gammat * v[0];
    o.Ft[1] = o.gammat * v[1];
    o.Ft[2] = o.gammat * v[2];
    if (law == DC_CT_VISCOUS_SLIDING) o.sliding = ct_limit_force(o.Ft, lim);
    break;
  case DC_CT_SPRING_SLIDING:
  case DC_CT_SPRING_DASHPOT_SLIDING:
  case DC_CT_DI_RENZO:
  case DC_CT_TSUJI: {
    /* notes 4.5-4.7: F = K s + eta v, |F| <= mu F_n */
    double K, eta;
    if (law == DC_CT_DI_RENZO) K = 16.0 / 3.0 * m->p.Gstar * patch->a;
    else if (law == DC_CT_TSUJI) K = 8.0 * m->p.Gstar * patch->a;
    else K = ct_spring_stiffness(m, patch, c);
    if (law == DC_CT_TSUJI) eta = c->gamman;
    else if (law == DC_CT_SPRING_SLIDING) eta = 0.0;
    else eta = ct_dashpot(m, m->p.damping, K, c);
    if (!(fabs(K) <= DBL_MAX) || !(fabs(eta) <= DBL_MAX)) return DC_ERANGE;   /* kt, gammat finite */
    o.gammat = eta;
    if (law == DC_CT_SPRING_SLIDING) ct_spring(K, lim, d, s.spring, o.Ft, &o.kt, &o.sliding);
    else ct_spring_dashpot(K, eta, lim, d, v, s.spring, o.Ft, &o.kt, &o.sliding);
    break;
  }
  case DC_CT_LANGSTON:
  case DC_CT_ZHENG: {
    /* notes 4.7: LTH elastic force; LTH or ZZYt viscous force */
    const double K0 = 8.0 * m->p.Gstar * patch->a;
    if (!(K0 <= DBL_MAX)) return DC_ERANGE;
    double Fe[3], kt, dlim;
    int at_limit;
    ct_langston_spring(K0, lim, d, s.spring, Fe, &kt, &dlim, &at_limit);
    double eta = 0.0;
    if (law == DC_CT_LANGSTON) {
      eta = m->p.eta_l * sqrt(4.0 * c->meff * kt);
      if (!isfinite(eta)) eta = m->p.eta_l * 2.0 * (sqrt(c->meff) * sqrt(kt));
    } else if (dlim > 0.0) {
      const double A = m->p.t_visc;
      const double f = 1.0 - 0.4 * A * (ct_norm3(v) / dlim);
      eta = f > 0.0 ? A * f * kt : 0.0;
    }
    o.gammat = eta;
    o.Ft[0] = Fe[0] + eta * v[0];
    o.Ft[1] = Fe[1] + eta * v[1];
    o.Ft[2] = Fe[2] + eta * v[2];
    o.sliding = ct_limit_force(o.Ft, lim) || at_limit;
    o.kt = o.sliding ? 0.0 : kt;
    break;
  }
  default: {
    /* notes 4.8, corrected: Walton-Braun incremental slip */
    const double K0 = ct_spring_stiffness(m, patch, c);
    if (!(K0 <= DBL_MAX)) return DC_ERANGE;
    ct_incremental_step(K0, lim, d, s.spring, s.rev, &o.kt, &o.sliding);
    o.Ft[0] = s.spring[0];
    o.Ft[1] = s.spring[1];
    o.Ft[2] = s.spring[2];
    break;
  }
  }
  /* the results finite, by their sum (finite unless one is not, or they
     come within a factor 11 of DBL_MAX): force and spring; kt and gammat
     where they are not a checked K and eta or a constant; rev for
     INCREMENTAL (0 otherwise) */
  double sum = ((o.Ft[0] + o.Ft[1]) + (o.Ft[2] + s.spring[0])) + (s.spring[1] + s.spring[2]);
  if (law == DC_CT_LANGSTON || law == DC_CT_ZHENG || law == DC_CT_INCREMENTAL) sum += o.kt + o.gammat;
  if (law == DC_CT_INCREMENTAL) sum += (s.rev[0] + s.rev[1]) + s.rev[2];
  if (dc_nf(sum) != 0.0) return DC_ERANGE;
  ct_store(law, &s, h);
  *out = o;
  return DC_OK;
}

#ifdef __cplusplus
}
#endif
#endif
