/* Mindlin-Deresiewicz tangential force with bounded memory
   (dc/cmd_turning_points.h; review Eqs. 59, 66-71, 85). */
#include "dc/cmd_turning_points.h"
#include "dc/elliptic_integrals.h"
#include "dc/inline.h"
#include "dc/status.h"
#include <float.h>
#include <math.h>
#include <string.h>

#define NT DC_CMDTP_MAX_TURNS

_Static_assert(NT == 4, "the field table below lists 4 turning points");
_Static_assert(sizeof(dc_cmdtp_state) == DC_CMDTP_HISTORY_NFIELDS * sizeof(double), "plain doubles");

#define TP_TURN(j) {"cmdtp_T_" #j "_x", 1}, {"cmdtp_T_" #j "_y", 1}, {"cmdtp_T_" #j "_z", 1}
const dc_history_field dc_cmdtp_history[DC_CMDTP_HISTORY_NFIELDS] = {
  {"cmdtp_n_prev_x", 1}, {"cmdtp_n_prev_y", 1}, {"cmdtp_n_prev_z", 1},
  {"cmdtp_F_x", 1}, {"cmdtp_F_y", 1}, {"cmdtp_F_z", 1},
  {"cmdtp_c2", 0}, {"cmdtp_S_prev", 0}, {"cmdtp_nturn", 0},
  TP_TURN(0), TP_TURN(1), TP_TURN(2), TP_TURN(3),
  {"cmdtp_M", 0}, {"cmdtp_c2_t", 0}, {"cmdtp_S_prev_t", 0}, {"cmdtp_nturn_t", 0},
  {"cmdtp_Tt_0", 0}, {"cmdtp_Tt_1", 0}, {"cmdtp_Tt_2", 0}, {"cmdtp_Tt_3", 0},
};

/* ------------------------------------------------------------------ */
/* Vectors of dim components (3: force, 1: twist).                      */

/* |v|, scaled where the squares would leave the normal doubles */
DC_INLINE double vnorm(int dim, const double *v)
{
  if (dim == 1) return fabs(v[0]);
  const double s = dc_dot3(v, v);
  if (s >= 1e-300 && s <= 1e300) return sqrt(s);
  const double a0 = fabs(v[0]), a1 = fabs(v[1]), a2 = fabs(v[2]);
  const double m = a0 > a1 ? (a0 > a2 ? a0 : a2) : (a1 > a2 ? a1 : a2);
  if (!(m > 0.0) || !isfinite(m)) return m;
  const double x = v[0] / m, y = v[1] / m, z = v[2] / m;
  return m * sqrt(x * x + y * y + z * z);
}

/* theta^2 = (1 - q)^2/3 of a branch whose force has used the fraction q
   of its range (theta^3 = 1 - q), given y0 near it (the previous step's
   theta^2): four Newton steps for y^3 = (1 - q)^2 where y0^3 is within
   10 % (a step's load change; the relative error of y squares each step:
   3e-2, 1e-3, 1e-6, 1e-12, 1e-24), the cube root otherwise. */
static inline double theta2_of(double q, double y0)
{
  if (!(q < 1.0)) return 0.0;
  if (!(q > 0.0)) return 1.0;
  const double r = (1.0 - q) * (1.0 - q);
  if (!(fabs(y0 * y0 * y0 - r) <= 0.1 * r)) return cbrt(r);
  double y = y0;
  for (int i = 0; i < 4; i++) y = (2.0 * y * y * y + r) / (3.0 * y * y);
  return y < 1.0 ? y : 1.0;
}

/* One quantity's memory while a step works on it. */
typedef struct {
  double F[3];
  double c2;
  int nt;
  double T[NT][3];
} mem;

/* The current branch's anchor (0 or the newest turning point) and its
   factor m (1 virgin, 2 Masing). */
DC_INLINE double anchor_of(int dim, const mem *s, double *A)
{
  if (!s->nt) {
    DC_UNROLL3 for (int c = 0; c < dim; c++) A[c] = 0.0;
    return 1.0;
  }
  DC_UNROLL3 for (int c = 0; c < dim; c++) A[c] = s->T[s->nt - 1][c];
  return 2.0;
}

/* One quantity's step (header): the limit's change, the displacement d of
   the stuck springs (k the no-slip stiffness, S > 0 the limit now, Sp the
   previous step's), the friction bound. Returns theta, the stuck
   fraction. */
DC_INLINE double mem_step(int dim, mem *s, const double *d, double k, double S, double Sp)
{
  if (!(S > 0.0)) {   /* no friction: nothing sticks, nothing is remembered */
    memset(s, 0, sizeof *s);
    s->c2 = 1.0;
    return 0.0;
  }
  double A[3], X[3];
  double m = anchor_of(dim, s, A);
  DC_UNROLL3 for (int c = 0; c < dim; c++) X[c] = s->F[c] - A[c];
  double xm = vnorm(dim, X), th2 = 1.0 - s->c2;
  if (S != Sp) {
    if (S < Sp) {
      /* a smaller limit clips the slipping annulus: the force falls by
         (S_prev - S)(1 - theta) along its branch (Eq. 70), and turning
         points outside the new limit are drawn onto it */
      const double red = (Sp - S) * (1.0 - sqrt(th2));
      double f = xm > red ? (xm - red) / xm : 0.0;
      if (f * xm > m * S) f = m * S / xm;   /* within the branch's range */
      DC_UNROLL3 for (int c = 0; c < dim; c++) {
        X[c] *= f;
        s->F[c] = A[c] + X[c];
      }
      xm *= f;
      int clipped = 0;
      for (int j = 0; j < s->nt; j++) {
        const double t2 = dim == 1 ? s->T[j][0] * s->T[j][0] : dc_dot3(s->T[j], s->T[j]);
        if (t2 <= S * S && t2 >= 1e-300 && S * S <= 1e300) continue;   /* inside, decided by the squares */
        const double tm = vnorm(dim, s->T[j]);
        if (tm > S) {
          DC_UNROLL3 for (int c = 0; c < dim; c++) s->T[j][c] *= S / tm;
          clipped = 1;
        }
      }
      if (clipped) {
        anchor_of(dim, s, A);
        DC_UNROLL3 for (int c = 0; c < dim; c++) X[c] = s->F[c] - A[c];
        xm = vnorm(dim, X);
      }
    }
    th2 = theta2_of(xm / (m * S), th2);   /* the state is the force */
  }
  /* a subnormal displacement has too few bits for a direction: none */
  if (dim == 1 ? fabs(d[0]) >= DBL_MIN : (fabs(d[0]) >= DBL_MIN || fabs(d[1]) >= DBL_MIN || fabs(d[2]) >= DBL_MIN)) {
    double e[3] = {0.0, 0.0, 0.0}, sa, dp = 0.0;
    /* a subnormal force has too few bits for a direction: a fresh branch */
    if (!(xm >= DBL_MIN)) xm = 0.0;
    if (xm > 0.0) {   /* the branch's direction, and the displacement along it */
      DC_UNROLL3 for (int c = 0; c < dim; c++) e[c] = X[c] / xm;
      dp = dim == 1 ? d[0] * e[0] : dc_dot3(d, e);
    }
    if (dp < 0.0) {
      /* reversal: F pushed (the newest turning point forgotten with the
         one before when the memory is full) */
      if (s->nt == NT) s->nt -= 2;
      DC_UNROLL3 for (int c = 0; c < dim; c++) s->T[s->nt][c] = A[c] = s->F[c];
      s->nt++;
      m = 2.0;
      xm = 0.0;
      th2 = 1.0;
    }
    if (xm > 0.0) {
      sa = dp;
      if (dim == 3) {   /* the part across X turns it with the stuck core's stiffness */
        const double kth = k * sqrt(th2);
        double Y[3];
        DC_UNROLL3 for (int c = 0; c < 3; c++) Y[c] = X[c] + kth * (d[c] - dp * e[c]);
        const double ym = vnorm(3, Y);
        if (ym > 0.0)
          DC_UNROLL3 for (int c = 0; c < 3; c++) e[c] = Y[c] / ym;
      }
    } else {
      const double dm = vnorm(dim, d);
      DC_UNROLL3 for (int c = 0; c < dim; c++) e[c] = d[c] / dm;
      sa = dm;
    }
    for (;;) {
      const double g = 2.0 * k / (3.0 * m * S);   /* -d theta^2 / ds */
      double t2 = th2 - sa * g;
      if (!(t2 > 0.0)) t2 = 0.0;
      const double t3 = t2 * sqrt(t2);
      if (s->nt == 0) {   /* virgin branch */
        th2 = t2;
        xm = S * (1.0 - t3);
        break;
      }
      /* the range of the branch before: |previous turning point - anchor| */
      const double mb = s->nt >= 2 ? 2.0 : 1.0;
      double R[3];
      DC_UNROLL3 for (int c = 0; c < dim; c++) R[c] = A[c] - (s->nt >= 2 ? s->T[s->nt - 2][c] : 0.0);
      const double qr = vnorm(dim, R) / (mb * S), qe = qr < 1.0 ? qr : 1.0, q = 1.0 - t3;
      if (q < qe) {
        th2 = t2;
        xm = 2.0 * S * q;
        break;
      }
      /* the previous turning point reached: the rest of the displacement on
         the branch before (Madelung; at nt = 1 the virgin curve at -T_1) */
      const double te2 = theta2_of(qe, t2);
      sa -= (th2 - te2) / g;
      if (sa < 0.0) sa = 0.0;
      double Fp[3];
      DC_UNROLL3 for (int c = 0; c < dim; c++) Fp[c] = A[c] + e[c] * (2.0 * S * qe);
      s->nt = s->nt >= 2 ? s->nt - 2 : 0;
      m = anchor_of(dim, s, A);
      DC_UNROLL3 for (int c = 0; c < dim; c++) X[c] = Fp[c] - A[c];
      xm = vnorm(dim, X);
      if (xm > 0.0)
        DC_UNROLL3 for (int c = 0; c < dim; c++) e[c] = X[c] / xm;
      th2 = theta2_of(xm / (m * S), te2);
    }
    DC_UNROLL3 for (int c = 0; c < dim; c++) s->F[c] = A[c] + e[c] * xm;
  }
  s->c2 = th2 < 1.0 ? 1.0 - th2 : 0.0;
  if (s->nt) {   /* |F| <= S; full slip clears the memory (the virgin branch is within it) */
    const double fm = vnorm(dim, s->F);
    if (fm >= S) {
      DC_UNROLL3 for (int c = 0; c < dim; c++) s->F[c] *= S / fm;
      s->nt = 0;
      s->c2 = 1.0;
      return 0.0;
    }
  }
  return sqrt(th2);
}

/* ------------------------------------------------------------------ */
/* The step.                                                            */

/* v <- M v, M the 3x3 matrix of turn_plane */
DC_INLINE void apply3(const double M[9], double *v)
{
  const double x = v[0], y = v[1], z = v[2];
  v[0] = M[0] * x + M[1] * y + M[2] * z;
  v[1] = M[3] * x + M[4] * y + M[5] * z;
  v[2] = M[6] * x + M[7] * y + M[8] * z;
}

/* Projects v onto the plane normal to b keeping |v| (a turn by nearly pi). */
DC_INLINE void project_keep(const double *b, double *v)
{
  const double l = vnorm(3, v), vn = dc_dot3(v, b);
  double r[3] = {v[0] - vn * b[0], v[1] - vn * b[1], v[2] - vn * b[2]};
  const double lr = vnorm(3, r);
  DC_UNROLL3 for (int k = 0; k < 3; k++) v[k] = lr > 0.0 ? l * (r[k] / lr) : 0.0;
}

/* The stored vectors turned with the contact plane (as the exact law's
   profile). */
DC_INLINE void turn_plane(const double *np0, const double *nh, mem *s)
{
  if (np0[0] == nh[0] && np0[1] == nh[1] && np0[2] == nh[2]) return;
  if (np0[0] == 0.0 && np0[1] == 0.0 && np0[2] == 0.0) return;   /* fresh */
  const double c = dc_dot3(np0, nh);
  if (c > -0.999) {
    /* the rotation taking np0 to nh (Rodrigues: R = c I + [w]x + w w^T / (1 + c),
       w = np0 x nh) followed by the projection onto the new plane, one
       matrix for all vectors: (I - nh nh^T) R = R - nh np0^T */
    const double w0 = np0[1] * nh[2] - np0[2] * nh[1], w1 = np0[2] * nh[0] - np0[0] * nh[2],
                 w2 = np0[0] * nh[1] - np0[1] * nh[0], ic = 1.0 / (1.0 + c);
    const double M[9] = {c + ic * w0 * w0 - nh[0] * np0[0], -w2 + ic * w0 * w1 - nh[0] * np0[1],
                         w1 + ic * w0 * w2 - nh[0] * np0[2],
                         w2 + ic * w1 * w0 - nh[1] * np0[0], c + ic * w1 * w1 - nh[1] * np0[1],
                         -w0 + ic * w1 * w2 - nh[1] * np0[2],
                         -w1 + ic * w2 * w0 - nh[2] * np0[0], w0 + ic * w2 * w1 - nh[2] * np0[1],
                         c + ic * w2 * w2 - nh[2] * np0[2]};
    apply3(M, s->F);
    for (int j = 0; j < s->nt; j++) apply3(M, s->T[j]);
  } else {
    project_keep(nh, s->F);
    for (int j = 0; j < s->nt; j++) project_keep(nh, s->T[j]);
  }
}

/* Counts as whole numbers in range: DC_EDOM otherwise. */
DC_INLINE int tp_counts(const dc_cmd_params *p, const dc_cmdtp_state *h, int *nf, int *nt)
{
  if (!(h->nturn >= 0.0 && h->nturn <= NT && (!p->twisting || (h->nturn_t >= 0.0 && h->nturn_t <= NT))))
    return DC_EDOM;
  *nf = (int)h->nturn;
  *nt = p->twisting ? (int)h->nturn_t : 0;
  if (!(h->nturn == (double)*nf && (!p->twisting || h->nturn_t == (double)*nt))) return DC_EDOM;
  return DC_OK;
}

/* Inputs finite and in their domain (the counts apart). */
DC_INLINE int tp_check(const dc_cmd_params *p, const dc_mindlin_pair *m, const dc_patch *patch, const double n[3],
                       const double du[3], double dphi, double dt, const dc_cmdtp_state *h)
{
  const double a = patch->a, b = patch->b, Fb = patch->F_bound;
  double chk = dc_nf(a) + dc_nf(b) + dc_nf(Fb) + dc_nf(patch->formed) + dc_nf(p->mu) + dc_nf(m->s0) + dc_nf(m->s1);
  chk += dc_nf(patch->axis[0]) + dc_nf(patch->axis[1]) + dc_nf(patch->axis[2]);
  chk += dc_nf(n[0]) + dc_nf(n[1]) + dc_nf(n[2]) + dc_nf(du[0]) + dc_nf(du[1]) + dc_nf(du[2]);
  const int nf = DC_CMDTP_FORCE_NFIELDS, nall = p->twisting ? DC_CMDTP_HISTORY_NFIELDS : nf;
  const double *hv = &h->n_prev[0];
  for (int j = 0; j < nall; j++) chk += dc_nf(hv[j]);
  if (p->twisting) chk += dc_nf(dphi);
  if (p->dissipation) chk += dc_nf(dt) + dc_nf(p->t_visc);
  if (chk != 0.0) return DC_EDOM;
  const double s0 = m->s0, s1 = m->s1;
  if (!(p->mu >= 0.0 && p->t_visc >= 0.0 && (p->dissipation == 0 || p->dissipation == 1) &&
        (p->twisting == 0 || p->twisting == 1) && s0 > 0.0 && s1 > -s0 && s1 <= 0.5 * s0 && Fb >= 0.0 &&
        b >= 0.0 && a >= b && (a == 0.0 || b >= 1e-150 * a) && (!p->dissipation || dt > 0.0)))
    return DC_EDOM;
  if (!(fabs(dc_dot3(n, n) - 1.0) <= 1e-6)) return DC_EDOM;
  if (!(h->c2 >= 0.0 && h->c2 <= 1.0 && h->S_prev >= 0.0)) return DC_EDOM;
  if (p->twisting && !(h->c2_t >= 0.0 && h->c2_t <= 1.0 && h->S_prev_t >= 0.0)) return DC_EDOM;
  return DC_OK;
}

DC_INLINE int tp_step(int checked, const dc_cmd_params *restrict p, const dc_mindlin_pair *restrict m,
                      const dc_patch *restrict patch, const double *restrict n, const double *restrict du, double dphi,
                      double dt, dc_cmdtp_state *restrict h, dc_cmd_out *restrict out)
{
  int nf, ntw;
  if (tp_counts(p, h, &nf, &ntw) != DC_OK) return DC_EDOM;
  if (checked && tp_check(p, m, patch, n, du, dphi, dt, h) != DC_OK) return DC_EDOM;
  const double a = patch->a, b = patch->b;
  const double axl = a > b ? dc_dot3(patch->axis, patch->axis) : 0.0;
  if (a > b && !(axl > 0.0) && b < (1.0 - 1e-6) * a) return DC_EDOM;   /* an ellipse needs its axis */
  if (patch->formed == 0.0 || a == 0.0) {   /* the history starts afresh */
    memset(h, 0, p->twisting ? sizeof *h : DC_CMDTP_FORCE_NFIELDS * sizeof(double));
    memset(out, 0, sizeof *out);
    return DC_OK;
  }

  /* frame: unit normal, no-slip stiffness along the major axis, d = M du_t */
  const double in = 1.0 / sqrt(dc_dot3(n, n));
  const double nh[3] = {n[0] * in, n[1] * in, n[2] * in};
  double rho = 1.0, ax[3] = {0.0, 0.0, 0.0};
  /* circle: k = 8 a / (2 s0 - s1) (Eq. 56 with K = pi/2, D = pi/4) */
  double k = 8.0 * a / (2.0 * m->s0 - m->s1);
  dc_ellint el;
  const int ell = a > b && axl > 0.0;
  if (ell) {
    const double g = b / a, t = m->s1 / m->s0;
    if (dc_ellint_m1(g * g, &el) != DC_OK) return DC_EDOM;
    const double cm = (1.0 - t) * el.K + t * el.D;
    k = 2.0 * M_PI * a / (m->s0 * cm);
    rho = cm / (el.K - t * el.D);   /* k_minor / k_major */
    const double an = dc_dot3(patch->axis, nh);
    DC_UNROLL3 for (int c = 0; c < 3; c++) ax[c] = patch->axis[c] - an * nh[c];
    const double al = vnorm(3, ax);
    if (!(al > 0.0)) return DC_EDOM;   /* axis along n */
    DC_UNROLL3 for (int c = 0; c < 3; c++) ax[c] /= al;
  }
  const double dn = dc_dot3(du, nh);
  double dut[3], d[3];
  DC_UNROLL3 for (int c = 0; c < 3; c++) dut[c] = du[c] - dn * nh[c];
  if (ell) {
    const double da = (1.0 - rho) * dc_dot3(ax, dut);
    DC_UNROLL3 for (int c = 0; c < 3; c++) d[c] = rho * dut[c] + da * ax[c];
  } else {
    DC_UNROLL3 for (int c = 0; c < 3; c++) d[c] = dut[c];
  }

  /* the force's memory */
  const double S = p->mu * patch->F_bound;
  mem f;
  DC_UNROLL3 for (int c = 0; c < 3; c++) f.F[c] = h->F[c];
  f.c2 = h->c2;
  f.nt = nf;
  for (int j = 0; j < nf; j++)
    DC_UNROLL3 for (int c = 0; c < 3; c++) f.T[j][c] = h->T[j][c];
  turn_plane(h->n_prev, nh, &f);
  const double th = mem_step(3, &f, d, k, S, h->S_prev);
  {   /* in the plane and within the limit to rounding (an anchor and an
         excess that nearly cancel, a displacement that dwarfs the normal,
         a subnormal force) */
    const double fn = dc_dot3(f.F, nh);
    DC_UNROLL3 for (int c = 0; c < 3; c++) f.F[c] -= fn * nh[c];
    const double fm = vnorm(3, f.F);
    if (fm > S)
      DC_UNROLL3 for (int c = 0; c < 3; c++) f.F[c] *= S / fm;
  }
  double F[3] = {f.F[0], f.F[1], f.F[2]};
  double kt = th * k;
  if (ell) {
    double dir[3];
    double l = vnorm(3, dut);
    const double *v = dut;
    if (!(l > 0.0)) { l = vnorm(3, F); v = F; }
    DC_UNROLL3 for (int c = 0; c < 3; c++) dir[c] = l > 0.0 ? v[c] / l : 0.0;
    const double ea = dc_dot3(dir, ax);
    kt *= l > 0.0 ? rho + (1.0 - rho) * ea * ea : 0.5 * (1.0 + rho);
  }
  if (p->dissipation && th > 0.0 && p->t_visc > 0.0) {
    /* Eq. 85: A_t (theta K0) d(delta)/dt, not stored */
    const double fd = p->t_visc / dt * th * k;
    double G[3];
    DC_UNROLL3 for (int c = 0; c < 3; c++) G[c] = F[c] + fd * d[c];
    const double gn = dc_dot3(G, nh);
    DC_UNROLL3 for (int c = 0; c < 3; c++) G[c] -= gn * nh[c];
    const double gm = vnorm(3, G);
    if (isfinite(gm)) {
      const double s = gm > S ? S / gm : 1.0;
      DC_UNROLL3 for (int c = 0; c < 3; c++) F[c] = s * G[c];
    } else {   /* the viscous part dominates: at the limit along d (a subnormal d has no direction) */
      const double dm = vnorm(3, d);
      if (dm >= DBL_MIN)
        DC_UNROLL3 for (int c = 0; c < 3; c++) F[c] = S * (d[c] / dm);
    }
  }

  /* the twist's memory */
  mem tw;
  double Mt = 0.0, kr = 0.0, Ms = 0.0;
  if (p->twisting) {
    double ktw;
    if (dc_cmd_twist_stiffness(m, a, b, &ktw) != DC_OK || dc_cmd_twist_slip_moment(p->mu, patch->F_bound, a, b, &Ms) != DC_OK)
      return DC_ERANGE;
    tw.F[0] = h->M;
    tw.c2 = h->c2_t;
    tw.nt = ntw;
    for (int j = 0; j < ntw; j++) tw.T[j][0] = h->Tt[j];
    const double tht = mem_step(1, &tw, &dphi, ktw, Ms, h->S_prev_t);
    Mt = tw.F[0];
    kr = tht * ktw;
  }

  /* the turning points are earlier forces (turned, or scaled down): finite
     when the force is */
  const double fin = ((dc_nf(F[0]) + dc_nf(F[1])) + (dc_nf(F[2]) + dc_nf(kt))) +
                     ((dc_nf(f.F[0]) + dc_nf(f.F[1])) + (dc_nf(f.F[2]) + dc_nf(f.c2))) + ((dc_nf(Mt) + dc_nf(kr)) + dc_nf(th));
  if (fin != 0.0) return DC_ERANGE;

  DC_UNROLL3 for (int c = 0; c < 3; c++) out->Ft[c] = F[c];
  out->kt = kt;
  out->stick = th;
  out->Mt = Mt;
  out->kr = kr;
  DC_UNROLL3 for (int c = 0; c < 3; c++) {
    h->n_prev[c] = nh[c];
    h->F[c] = f.F[c];
  }
  h->c2 = f.c2;
  h->S_prev = S;
  h->nturn = f.nt;
  for (int j = 0; j < f.nt; j++)
    DC_UNROLL3 for (int c = 0; c < 3; c++) h->T[j][c] = f.T[j][c];
  for (int j = f.nt; j < nf; j++)
    DC_UNROLL3 for (int c = 0; c < 3; c++) h->T[j][c] = 0.0;
  if (p->twisting) {
    h->M = tw.F[0];
    h->c2_t = tw.c2;
    h->S_prev_t = Ms;
    h->nturn_t = tw.nt;
    for (int j = 0; j < NT; j++) h->Tt[j] = j < tw.nt ? tw.T[j][0] : 0.0;
  }
  return DC_OK;
}

int dc_cmdtp_step(const dc_cmd_params *p, const dc_mindlin_pair *m, const dc_patch *patch, const double n[3],
                  const double du[3], double dphi, double dt, dc_cmdtp_state *h, dc_cmd_out *out)
{
  return tp_step(1, p, m, patch, n, du, dphi, dt, h, out);
}

int dc_cmdtp_step_trusted(const dc_cmd_params *p, const dc_mindlin_pair *m, const dc_patch *patch, const double n[3],
                          const double du[3], double dphi, double dt, dc_cmdtp_state *h, dc_cmd_out *out)
{
  return tp_step(0, p, m, patch, n, du, dphi, dt, h, out);
}
