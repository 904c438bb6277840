/* Cattaneo-Mindlin-Deresiewicz tangential force and Mindlin twisting with
   full load history (dc/cmd_tangential.h, review Eqs. 56-77, 85). */
#include "dc/cmd_tangential.h"
#include "dc/elliptic_integrals.h"
#include "dc/inline.h"
#include "dc/status.h"
#include <float.h>
#include <math.h>
#include <string.h>

_Static_assert(DC_CMD_MAX_SEG == 8, "the field table below lists 8 pieces");
_Static_assert(sizeof(dc_cmd_state) == DC_CMD_HISTORY_NFIELDS * sizeof(double), "plain doubles");
_Static_assert(sizeof(dc_cmd_piece) == 7 * sizeof(double) && sizeof(dc_cmd_twist_piece) == 3 * sizeof(double),
               "pieces of 1 + 2 dim doubles");

#define CMD_PIECE(j) {"cmd_xi_" #j, 0}, {"cmd_u0_" #j "_x", 1}, {"cmd_u0_" #j "_y", 1}, {"cmd_u0_" #j "_z", 1}, \
    {"cmd_u1_" #j "_x", 1}, {"cmd_u1_" #j "_y", 1}, {"cmd_u1_" #j "_z", 1}
#define CMD_TWIST_PIECE(j) {"cmd_xi_t_" #j, 0}, {"cmd_t0_" #j, 0}, {"cmd_t1_" #j, 0}
const dc_history_field dc_cmd_history[DC_CMD_HISTORY_NFIELDS] = {
  {"cmd_n_prev_x", 1}, {"cmd_n_prev_y", 1}, {"cmd_n_prev_z", 1}, {"cmd_a_prev", 0}, {"cmd_nseg", 0},
  CMD_PIECE(0), CMD_PIECE(1), CMD_PIECE(2), CMD_PIECE(3), CMD_PIECE(4), CMD_PIECE(5), CMD_PIECE(6), CMD_PIECE(7),
  {"cmd_nseg_t", 0},
  CMD_TWIST_PIECE(0), CMD_TWIST_PIECE(1), CMD_TWIST_PIECE(2), CMD_TWIST_PIECE(3),
  CMD_TWIST_PIECE(4), CMD_TWIST_PIECE(5), CMD_TWIST_PIECE(6), CMD_TWIST_PIECE(7),
};

int dc_cmd_check(const dc_cmd_params *p, dc_param_error *err)
{
  if (dc_param_check("coefficientFriction", p->mu, 0.0, 0, HUGE_VAL, 1, "[0, inf)", err)) return DC_EDOM;
  if (dc_param_check("tangentialViscoelasticTime", p->t_visc, 0.0, 0, HUGE_VAL, 1, "[0, inf) s", err))
    return DC_EDOM;
  if (p->dissipation != 0 && p->dissipation != 1) {
    err->name = "cmdDissipation"; err->value = (double)p->dissipation; err->range = "{0 (off), 1 (on)}";
    return DC_EDOM;
  }
  if (p->twisting != 0 && p->twisting != 1) {
    err->name = "cmdTwisting"; err->value = (double)p->twisting; err->range = "{0 (off), 1 (on)}";
    return DC_EDOM;
  }
  return DC_OK;
}

/* ------------------------------------------------------------------ */
/* Range-safe products (plain when the result is a normal double).      */

/* c x y z / (d1 d2) by exponent and mantissa, for when the plain product
   is not a normal double */
static double pq_scaled(double c, double x, double y, double z, double d1, double d2)
{
  if (c == 0.0 || x == 0.0 || y == 0.0 || z == 0.0) return 0.0;
  const double f[4] = {c, x, y, z};
  double m = 1.0;
  int e = 0, k;
  for (int i = 0; i < 4; i++) {
    m *= frexp(f[i], &k);
    e += k;
    m = frexp(m, &k);
    e += k;
  }
  m /= frexp(d1, &k);
  e -= k;
  m /= frexp(d2, &k);
  e -= k;
  return ldexp(m, e);
}

/* c x y z / (d1 d2), factors >= 0, d1, d2 > 0 */
static inline double pq(double c, double x, double y, double z, double d1, double d2)
{
  const double p = c * x * y * z / (d1 * d2);
  if (p >= DBL_MIN && p <= DBL_MAX) return p;
  return pq_scaled(c, x, y, z, d1, d2);
}

/* ------------------------------------------------------------------ */
/* No-slip stiffnesses (review Eqs. 56-58 via dc/mindlin.h; Eq. 77).   */

static int pair_ok(const dc_mindlin_pair *m)
{
  /* what dc_mindlin_pair_init gives: s0 > 0, -s0 < s1 <= s0/2 */
  return isfinite(m->s0) && isfinite(m->s1) && m->s0 > 0.0 && m->s1 > -m->s0 && m->s1 <= 0.5 * m->s0;
}

static int axes_ok(double a, double b) { return isfinite(a) && isfinite(b) && b > 0.0 && b <= a && b >= 1e-150 * a; }

/* Eqs. 56-57 per unit s0 (t = s1/s0): compliances along the axes,
   c = 2 pi a / (s0 k); circle (K = pi/2, D = pi/4): (2 - t) pi/4 */
static void axis_compliances(double t, const dc_ellint *el, double *c_major, double *c_minor)
{
  *c_major = (1.0 - t) * el->K + t * el->D;
  *c_minor = el->K - t * el->D;
}

int dc_cmd_stiffness(const dc_mindlin_pair *m, double a, double b, double *k_major, double *k_minor)
{
  if (!pair_ok(m) || !axes_ok(a, b)) return DC_EDOM;
  const double t = m->s1 / m->s0;
  double cm = (2.0 - t) * (M_PI / 4.0), cn = cm;
  if (a != b) {
    const double g = b / a;
    dc_ellint el;
    if (dc_ellint_m1(g * g, &el) != DC_OK) return DC_EDOM;
    axis_compliances(t, &el, &cm, &cn);
  }
  const double km = pq(2.0 * M_PI, a, 1.0, 1.0, m->s0, cm), kn = pq(2.0 * M_PI, a, 1.0, 1.0, m->s0, cn);
  if (!isfinite(km) || !isfinite(kn)) return DC_ERANGE;
  *k_major = km;
  *k_minor = kn;
  return DC_OK;
}

/* Eq. 77 generalised to two bodies (header), per unit s0: the stiffness
   is 2 pi/3 a^3 / s0 times the factor returned; 4 for a circle */
static double twist_factor(double t, double g, const dc_ellint *el)
{
  const double B = el->B, C = el->C, D = el->D;
  const double a11 = (1.0 - t) * B + t * (D - C), a22 = (1.0 - t) * D + t * (D - C);
  const double det = a11 * a22 - t * t * C * (B - D + C);
  return ((B - 2.0 * t * (B - D + C)) + g * g * (D - 2.0 * t * C)) / det;
}

int dc_cmd_twist_stiffness(const dc_mindlin_pair *m, double a, double b, double *k)
{
  if (!pair_ok(m) || !axes_ok(a, b)) return DC_EDOM;
  double f = 8.0 / M_PI;   /* circle: 2 pi/3 f = 16/3 */
  if (a != b) {
    const double g = b / a;
    dc_ellint el;
    if (dc_ellint_m1(g * g, &el) != DC_OK) return DC_EDOM;
    f = twist_factor(m->s1 / m->s0, g, &el);
  }
  const double kt = pq(2.0 * M_PI / 3.0 * f, a, a, a, m->s0, 1.0);
  if (!isfinite(kt)) return DC_ERANGE;
  *k = kt;
  return DC_OK;
}

int dc_cmd_twist_slip_moment(double mu, double F, double a, double b, double *M)
{
  if (!(isfinite(mu) && isfinite(F) && mu >= 0.0 && F >= 0.0) || !axes_ok(a, b)) return DC_EDOM;
  double E = M_PI / 2.0;
  if (a != b) {
    const double g = b / a;
    dc_ellint el;
    if (dc_ellint_m1(g * g, &el) != DC_OK) return DC_EDOM;
    E = el.E;
  }
  const double Ms = pq(0.375 * E, mu, F, a, 1.0, 1.0);
  if (!isfinite(Ms)) return DC_ERANGE;
  *M = Ms;
  return DC_OK;
}

/* ------------------------------------------------------------------ */
/* The spring profile: pieces [x0, x1] of xi, each linear in xi^2 and  */
/* given by its end values v0, v1.                                     */

#define MAXP (3 * (DC_CMD_MAX_SEG + 1) + 4)
#define SLIVER 1e-13   /* narrower pieces (in xi) join a neighbour */

typedef struct {
  double x0, x1;
  double v0[3], v1[3];   /* x1, v0, v1: a dc_cmd_piece's layout (force) */
  double e[3];   /* slip direction (slipping pieces) */
  int slip;
} piece;
_Static_assert(offsetof(piece, v1) + 3 * sizeof(double) - offsetof(piece, x1) == sizeof(dc_cmd_piece) &&
               offsetof(dc_cmd_piece, u1) - offsetof(dc_cmd_piece, xi) == offsetof(piece, v1) - offsetof(piece, x1),
               "a force piece is stored with one copy");

static inline double max2(double a, double b) { return a > b ? a : b; }


/* The profile functions below take the number of components (3: force,
   1: twist) as a constant through two instantiations of profile_step. */

/* weight of v1 in the mean of a piece: int = (x1 - x0) [(1 - w) v0 + w v1] */
static inline double piece_w(double x0, double x1)
{
  const double s = x0 + x1;
  return s > 0.0 ? (x1 + 2.0 * x0) / (3.0 * s) : 0.5;
}

/* The Coulomb limit L0 (1 - xi^2) at xi */
static inline double limit_at(double L0, double x) { return L0 * ((1.0 - x) * (1.0 + x)); }

/* |v|^2 */
DC_INLINE double sq(int dim, const double *v)
{
  double s = 0.0;
  DC_UNROLL3 for (int k = 0; k < dim; k++) s += v[k] * v[k];
  return s;
}

/* Splits the trial piece [x0, x1] (end values p0, p1, their squares n0,
   n1; limits l0, l1 = limit_at(L0, x0 or x1)) where it leaves the
   Coulomb limit L0 (1 - xi^2): |p(t)|^2 = l(t)^2 is a quadratic in
   t = (xi^2 - x0^2)/(x1^2 - x0^2), both sides being linear in t. Appends
   the parts (slip parts with their trial values; group() puts them on
   the limit). */
DC_INLINE void clamp_piece(int dim, double x0, double x1, double l0, double l1, const double *p0, const double *p1,
                           double n0, double n1, piece *out, int *nout)
{
  {
    /* Pre-test: both ends inside by tau. |p(t)| - l(t) is convex (l is
       linear in t), so it is <= -c on [0, 1], c = tau / (2 max l), and the
       margins give min l >= 1e-3 max l: g = (|p| - l)(|p| + l) <= -c min l
       <= -5e-10 max l^2. The full test below (iS = 1 for l0 in this range)
       rounds g, its vertex and A C - B^2 by less than 1e-13 max l^2 (times
       |A|), so it finds the same: the whole piece inside. */
    const double s0 = l0 * l0, s1 = l1 * l1, tau = 1e-6 * (s0 + s1);
    if (n0 <= s0 - tau && n1 <= s1 - tau && l0 >= 1e-137 && l0 <= 1e137) {
      piece *o = &out[(*nout)++];
      o->x0 = x0;
      o->x1 = x1;
      DC_UNROLL3 for (int k = 0; k < dim; k++) {
        o->v0[k] = p0[k];
        o->v1[k] = p1[k];
      }
      o->slip = 0;
      return;
    }
  }
  double q[3];
  DC_UNROLL3 for (int k = 0; k < dim; k++) q[k] = p1[k] - p0[k];
  /* g(t) = |p(t)|^2 - l(t)^2 = A t^2 + 2 B t + C, scaled by 1/S^2 only
     where the squares could leave the doubles: S = max(l0, |p0|, |p1|)
     (max norm) outside [1e-150, 1e150]; it lies there (scale 1) when l0
     does and n0, n1 <= 1e298 (so every |p_k| < 1e150) */
  double S = 1.0, iS = 1.0;
  if (!(l0 >= 1e-150 && l0 <= 1e150 && n0 <= 1e298 && n1 <= 1e298)) {
    S = l0;
    DC_UNROLL3 for (int k = 0; k < dim; k++) S = max2(S, max2(fabs(p0[k]), fabs(p1[k])));
    iS = S > 0.0 && (S < 1e-150 || S > 1e150) ? 1.0 / S : 1.0;
  }
  const double la = l0 * iS, dl = (l1 - l0) * iS;
  double A = -dl * dl, B = -la * dl, C = -la * la;
  DC_UNROLL3 for (int k = 0; k < dim; k++) {
    const double ps = p0[k] * iS, qs = q[k] * iS;
    A += qs * qs;
    B += ps * qs;
    C += ps * ps;
  }
  /* the whole piece inside its limit, or the whole piece beyond it: from
     g(0), g(1) and, when it lies in (0, 1), the vertex -B/A */
  const double g1 = A + 2.0 * B + C;
  const int vertex = A != 0.0 && (A > 0.0 ? (B < 0.0 && -B < A) : (B > 0.0 && B < -A));
  int whole = -1;
  if (S == 0.0 || (C <= 0.0 && g1 <= 0.0 && (A >= 0.0 || !vertex || A * C >= B * B))) whole = 0;
  else if (C > 0.0 && g1 > 0.0 && (A <= 0.0 || !vertex || A * C > B * B)) whole = 1;
  if (whole >= 0) {
    piece *o = &out[(*nout)++];
    o->x0 = x0;
    o->x1 = x1;
    DC_UNROLL3 for (int k = 0; k < dim; k++) {
      o->v0[k] = p0[k];
      o->v1[k] = p1[k];
    }
    o->slip = whole;
    return;
  }
  double t[4] = {0.0, 1.0, 1.0, 1.0};
  int nt = 1;
  {
    double r[2];
    int nr = 0;
    if (A != 0.0) {
      const double disc = B * B - A * C;
      if (disc > 0.0) {
        const double qq = -(B + copysign(sqrt(disc), B));
        if (qq != 0.0) { r[0] = qq / A; r[1] = C / qq; nr = 2; }
      }
    } else if (B != 0.0) {
      r[0] = -C / (2.0 * B);
      nr = 1;
    }
    if (nr == 2 && r[1] < r[0]) { const double tmp = r[0]; r[0] = r[1]; r[1] = tmp; }
    for (int i = 0; i < nr; i++)
      if (r[i] > 0.0 && r[i] < 1.0 && r[i] > t[nt - 1]) t[nt++] = r[i];
  }
  t[nt++] = 1.0;
  const double s0 = x0 * x0, ds = (x1 - x0) * (x1 + x0);
  for (int i = 0; i + 1 < nt; i++) {
    const double ta = t[i], tb = t[i + 1], tm = 0.5 * (ta + tb);
    piece *o = &out[(*nout)++];
    o->x0 = i == 0 ? x0 : sqrt(s0 + ta * ds);
    o->x1 = i + 2 == nt ? x1 : sqrt(s0 + tb * ds);
    double g = 0.0;
    DC_UNROLL3 for (int k = 0; k < dim; k++) {
      o->v0[k] = i == 0 ? p0[k] : p0[k] + q[k] * ta;
      o->v1[k] = i + 2 == nt ? p1[k] : p0[k] + q[k] * tb;
      const double v = (p0[k] + q[k] * tm) * iS;
      g += v * v;
    }
    const double l = la + dl * tm;
    o->slip = g > l * l;
  }
}

DC_INLINE double norm_dir(int dim, const double *I, double *e)
{
  if (dim == 1) {
    e[0] = I[0] > 0.0 ? 1.0 : I[0] < 0.0 ? -1.0 : 0.0;
    return fabs(I[0]);
  }
  const double m = max2(fabs(I[0]), max2(fabs(I[1]), fabs(I[2])));
  if (!(m > 0.0) || !isfinite(m)) { e[0] = e[1] = e[2] = 0.0; return m; }
  const double x = I[0] / m, y = I[1] / m, z = I[2] / m, l = sqrt(x * x + y * y + z * z);
  e[0] = x / l; e[1] = y / l; e[2] = z / l;
  return m * l;
}

/* Puts each contiguous slipping zone on its limit with one direction, that
   of its integrated trial values, in place (a zone's piece takes the slot
   of its first); returns the stuck length (sum of the stuck widths, theta
   of Eqs. 70-71). */
DC_INLINE double group(int dim, piece *pc, int np, double L0, int *nout)
{
  double stick = 0.0;
  int no = 0;
  for (int i = 0; i < np;) {
    if (!pc[i].slip) {
      stick += pc[i].x1 - pc[i].x0;
      if (no != i) pc[no] = pc[i];
      no++;
      i++;
      continue;
    }
    double I[3] = {0.0, 0.0, 0.0};
    const double xa = pc[i].x0;
    double xb = xa;
    int j = i;
    do {
      const double h = pc[j].x1 - pc[j].x0, w = piece_w(pc[j].x0, pc[j].x1);
      double Ij[3], dot = 0.0;
      DC_UNROLL3 for (int k = 0; k < dim; k++) {
        Ij[k] = h * ((1.0 - w) * pc[j].v0[k] + w * pc[j].v1[k]);
        dot += Ij[k] * I[k];
      }
      if (j > i && dot < 0.0) break;   /* opposite slip: a zone of its own */
      DC_UNROLL3 for (int k = 0; k < dim; k++) I[k] += Ij[k];
      xb = pc[j].x1;
      j++;
    } while (j < np && pc[j].slip);
    piece *o = &pc[no++];
    o->x0 = xa;
    o->x1 = xb;
    o->slip = 1;
    norm_dir(dim, I, o->e);
    const double la = L0 * ((1.0 - xa) * (1.0 + xa)), lb = L0 * ((1.0 - xb) * (1.0 + xb));
    DC_UNROLL3 for (int k = 0; k < dim; k++) {
      o->v0[k] = la * o->e[k];
      o->v1[k] = lb * o->e[k];
    }
    i = j;
  }
  *nout = no;
  return stick;
}

/* Removes slivers (into a neighbour), joins neighbouring slip zones of one
   direction and neighbouring stuck pieces that form one function to
   rounding (|difference| <= 1e-14 L0: turning points that drifted together). */
DC_INLINE int tidy(int dim, piece *pc, int np, double L0)
{
  const double tol = 1e-14 * L0;
  int no = 0;
  for (int i = 0; i < np; i++) {
    const piece *p = &pc[i];
    if (p->x1 - p->x0 < SLIVER && np > 1) {
      if (no > 0) { pc[no - 1].x1 = p->x1; continue; }
      if (i + 1 < np) { pc[i + 1].x0 = p->x0; continue; }
    }
    if (no > 0) {
      piece *q = &pc[no - 1];
      if (p->slip && q->slip) {
        double d = 0.0;
        DC_UNROLL3 for (int k = 0; k < dim; k++) d += p->e[k] * q->e[k];
        if (d > 1.0 - 1e-14) {
          q->x1 = p->x1;
          const double lb = L0 * ((1.0 - q->x1) * (1.0 + q->x1));
          DC_UNROLL3 for (int k = 0; k < dim; k++) q->v1[k] = lb * q->e[k];
          continue;
        }
      } else if (!p->slip && !q->slip) {
        /* q continued linearly in xi^2 to p's outer end */
        int same = 1;
        DC_UNROLL3 for (int k = 0; k < dim && same; k++) same = fabs(q->v1[k] - p->v0[k]) <= tol;
        if (same) {
          const double f = (p->x1 - q->x0) * (p->x1 + q->x0) / ((q->x1 - q->x0) * (q->x1 + q->x0));
          DC_UNROLL3 for (int k = 0; k < dim && same; k++)
            same = fabs(q->v0[k] + (q->v1[k] - q->v0[k]) * f - p->v1[k]) <= tol;
        }
        if (same) {
          q->x1 = p->x1;
          DC_UNROLL3 for (int k = 0; k < dim; k++) q->v1[k] = p->v1[k];
          continue;
        }
      }
    }
    if (no != i) pc[no] = *p;
    no++;
  }
  return no;
}

/* int_x0^x1 phi^k dxi, phi = (xi^2 - x0^2)/(x1^2 - x0^2), k = 1, 2 */
static inline void moments(double x0, double x1, double *J1, double *J2)
{
  const double h = x1 - x0, d = h + 2.0 * x0;
  if (!(d > 0.0)) { *J1 = *J2 = 0.0; return; }
  *J1 = h * (h / 3.0 + x0) / d;
  *J2 = h * (h * h / 5.0 + x0 * h + 4.0 / 3.0 * x0 * x0) / (d * d);
}

/* One piece (linear in xi^2) in place of pieces i, i+1: it keeps their
   force int u dxi and their value at the outer end (where the limit is
   least, so that a merge does not make the rim slip), u = c0 + c1 phi,
   phi = (xi^2 - xa^2)/(xb^2 - xa^2). Returns the squared L2 change; the
   piece in *f. */
DC_INLINE double merge_fit(int dim, const piece *pc, int i, piece *f)
{
  const double xa = pc[i].x0, xb = pc[i + 1].x1, S = (xb - xa) * (xb + xa);
  double g01, g11;
  moments(xa, xb, &g01, &g11);
  const double g00 = xb - xa;
  double m0[3] = {0, 0, 0}, m1[3] = {0, 0, 0}, e2 = 0.0;
  memset(f, 0, sizeof *f);
  for (int j = i; j <= i + 1; j++) {
    const piece *p = &pc[j];
    double J1, J2;
    moments(p->x0, p->x1, &J1, &J2);
    const double J0 = p->x1 - p->x0;
    const double lam = (p->x0 - xa) * (p->x0 + xa) / S, kap = (p->x1 - p->x0) * (p->x1 + p->x0) / S;
    DC_UNROLL3 for (int k = 0; k < dim; k++) {
      const double dv = p->v1[k] - p->v0[k];
      const double I0 = p->v0[k] * J0 + dv * J1, Ip = p->v0[k] * J1 + dv * J2;
      m0[k] += I0;
      m1[k] += lam * I0 + kap * Ip;
      e2 += p->v0[k] * p->v0[k] * J0 + 2.0 * p->v0[k] * dv * J1 + dv * dv * J2;
    }
  }
  const double w = g00 - g01;   /* int (1 - phi) > 0 */
  double cross = 0.0, self = 0.0;
  f->x0 = xa;
  f->x1 = xb;
  f->slip = 0;
  DC_UNROLL3 for (int k = 0; k < dim; k++) {
    const double vb = pc[i + 1].v1[k];
    const double c0 = w > 0.0 ? (m0[k] - vb * g01) / w : vb, c1 = vb - c0;
    f->v0[k] = c0;
    f->v1[k] = vb;
    cross += c0 * m0[k] + c1 * m1[k];
    self += c0 * c0 * g00 + 2.0 * c0 * c1 * g01 + c1 * c1 * g11;
  }
  return e2 - 2.0 * cross + self;
}

/* Per-piece moments for merge costs: width, int phi, int phi^2, int u,
   int u phi, int |u|^2 (phi the piece's own variable). */
typedef struct {
  double J0, J1, J2, I0[3], Ip[3], e2;
} pmom;

DC_INLINE void piece_moments(int dim, const piece *p, pmom *m)
{
  moments(p->x0, p->x1, &m->J1, &m->J2);
  m->J0 = p->x1 - p->x0;
  m->e2 = 0.0;
  DC_UNROLL3 for (int k = 0; k < dim; k++) {
    const double dv = p->v1[k] - p->v0[k];
    m->I0[k] = p->v0[k] * m->J0 + dv * m->J1;
    m->Ip[k] = p->v0[k] * m->J1 + dv * m->J2;
    m->e2 += p->v0[k] * p->v0[k] * m->J0 + 2.0 * p->v0[k] * dv * m->J1 + dv * dv * m->J2;
  }
}

/* The change of merge_fit(i) from the moments (same formulas). */
DC_INLINE double merge_cost(int dim, const piece *pc, const pmom *pm, int i)
{
  const double xa = pc[i].x0, xm = pc[i].x1, xb = pc[i + 1].x1, S = (xb - xa) * (xb + xa);
  double g01, g11;
  moments(xa, xb, &g01, &g11);
  const double g00 = xb - xa, w = g00 - g01;
  const double iS = 1.0 / S, kap0 = (xm - xa) * (xm + xa) * iS, lam1 = kap0, kap1 = (xb - xm) * (xb + xm) * iS;
  double cross = 0.0, self = 0.0;
  DC_UNROLL3 for (int k = 0; k < dim; k++) {
    const double m0 = pm[i].I0[k] + pm[i + 1].I0[k];
    const double m1 = kap0 * pm[i].Ip[k] + lam1 * pm[i + 1].I0[k] + kap1 * pm[i + 1].Ip[k];
    const double vb = pc[i + 1].v1[k];
    const double c0 = w > 0.0 ? (m0 - vb * g01) / w : vb, c1 = vb - c0;
    cross += c0 * m0 + c1 * m1;
    self += c0 * c0 * g00 + 2.0 * c0 * c1 * g01 + c1 * c1 * g11;
  }
  return pm[i].e2 + pm[i + 1].e2 - 2.0 * cross + self;
}

/* The piece of merge_fit(i) from the moments (the same arithmetic). */
DC_INLINE void merged_piece(int dim, const piece *pc, const pmom *pm, int i, piece *f)
{
  const double xa = pc[i].x0, xb = pc[i + 1].x1;
  double g01, g11;
  moments(xa, xb, &g01, &g11);
  const double w = (xb - xa) - g01;
  f->x0 = xa;
  f->x1 = xb;
  f->slip = 0;
  DC_UNROLL3 for (int k = 0; k < dim; k++) {
    const double vb = pc[i + 1].v1[k], m0 = (0.0 + pm[i].I0[k]) + pm[i + 1].I0[k];
    f->v0[k] = w > 0.0 ? (m0 - vb * g01) / w : vb;
    f->v1[k] = vb;
  }
}

/* Over DC_CMD_MAX_SEG pieces: merges the cheapest neighbours (least change,
   merge_fit) down to DC_CMD_MAX_SEG - 1, which leaves room for the next
   step's new piece (a growing patch makes one per step). A merge changes
   the costs of the merged piece's two pairs only. */
DC_INLINE int cap(int dim, piece *pc, int np)
{
  if (np <= DC_CMD_MAX_SEG) return np;
  pmom pm[MAXP];
  double cost[MAXP];
  for (int i = 0; i < np; i++) piece_moments(dim, &pc[i], &pm[i]);
  for (int i = 0; i + 1 < np; i++) cost[i] = merge_cost(dim, pc, pm, i);
  while (np > DC_CMD_MAX_SEG - 1) {
    int best = 0;
    double bc = cost[0];
    for (int i = 1; i + 1 < np; i++)
      if (cost[i] < bc) { bc = cost[i]; best = i; }
    piece f;
    merged_piece(dim, pc, pm, best, &f);
    pc[best] = f;
    piece_moments(dim, &pc[best], &pm[best]);
    for (int i = best + 1; i + 1 < np; i++) {
      pc[i] = pc[i + 1];
      pm[i] = pm[i + 1];
      cost[i] = cost[i + 1];
    }
    np--;
    if (best > 0) cost[best - 1] = merge_cost(dim, pc, pm, best - 1);
    if (best + 1 < np) cost[best] = merge_cost(dim, pc, pm, best);
  }
  return np;
}

/* Projects v onto the plane normal to b, keeping |v| (a turn by nearly pi). */
static inline void project_keep(const double *b, double *v)
{
  double e[3];
  const double l = norm_dir(3, v, e), en = dc_dot3(e, b);
  double r[3] = {e[0] - en * b[0], e[1] - en * b[1], e[2] - en * b[2]};
  const double lr = norm_dir(3, r, r);
  DC_UNROLL3 for (int k = 0; k < 3; k++) v[k] = lr > 0.0 ? l * r[k] : 0.0;
}

/* The turn of the stored force profile with the contact plane (the
   three-dimensional rule): the rotation R taking the unit a to the unit b
   (Rodrigues without a square root: R v = c v + w x v + (w.v)/(1+c) w,
   c = a.b, w = a x b) followed by the removal of what is left along b,
   as one matrix for the whole profile: (I - b b^T) R = R - b a^T (as
   R^T b = a); for a turn by nearly pi, the projection keeping |v|. */
typedef struct {
  double M[3][3];
  const double *nh;   /* b, the new unit normal */
  int keep;           /* 1: project_keep */
} cmd_turn;

DC_INLINE void turn_apply(const cmd_turn *tr, const double *v, double *out)
{
  if (tr->keep) {
    DC_UNROLL3 for (int k = 0; k < 3; k++) out[k] = v[k];
    project_keep(tr->nh, out);
  } else {
    const double v0 = v[0], v1 = v[1], v2 = v[2];
    out[0] = tr->M[0][0] * v0 + tr->M[0][1] * v1 + tr->M[0][2] * v2;
    out[1] = tr->M[1][0] * v0 + tr->M[1][1] * v1 + tr->M[1][2] * v2;
    out[2] = tr->M[2][0] * v0 + tr->M[2][1] * v1 + tr->M[2][2] * v2;
  }
}

/* out = turned v + d, rounded as turn_apply then the sum */
DC_INLINE void turn_add(const cmd_turn *tr, const double *v, const double *d, double *out)
{
  if (tr->keep) {
    turn_apply(tr, v, out);
    DC_UNROLL3 for (int k = 0; k < 3; k++) out[k] += d[k];
  } else {
    const double v0 = v[0], v1 = v[1], v2 = v[2];
    out[0] = tr->M[0][0] * v0 + tr->M[0][1] * v1 + tr->M[0][2] * v2 + d[0];
    out[1] = tr->M[1][0] * v0 + tr->M[1][1] * v1 + tr->M[1][2] * v2 + d[1];
    out[2] = tr->M[2][0] * v0 + tr->M[2][1] * v1 + tr->M[2][2] * v2 + d[2];
  }
}

/* One step of a profile with dim components: the stored pieces (xi, u0,
   u1: 1 + 2 dim doubles each) turned by tr (dim 3; NULL: not turned) and
   rescaled by r = a_prev / a, the increment d for the stuck springs,
   entering rim, clamp, group, tidy, cap. Returns the number of pieces in
   out; *stick and I = int_0^1 u dxi. */
DC_INLINE int profile_step(int dim, int n, const double *seg, const cmd_turn *tr, double r, const double *d,
                           double L0, piece *out, double *stick, double *I)
{
  int np = 0, entered = 0;
  const double nd = sq(dim, d);
  if (n == 0) {
    clamp_piece(dim, 0.0, 1.0, limit_at(L0, 0.0), limit_at(L0, 1.0), d, d, nd, nd, out, &np);
  } else {
    double x0 = 0.0, l0 = limit_at(L0, 0.0);   /* a piece's inner end and its limit */
    for (int j = 0; j < n; j++) {
      const double xs = x0;
      const double *sj = seg + (1 + 2 * dim) * j;
      double xe = sj[0] * r;
      x0 = xe;
      if (xs >= 1.0) break;
      double p0[3], p1[3];
      const double *a0 = sj + 1, *a1 = sj + 1 + dim;
      if (xe > 1.0) {
        double t0[3], t1[3];
        if (tr) {
          turn_apply(tr, a0, t0);
          turn_apply(tr, a1, t1);
          a0 = t0;
          a1 = t1;
        }
        const double t = (1.0 - xs) * (1.0 + xs) / ((xe - xs) * (xe + xs));
        DC_UNROLL3 for (int k = 0; k < dim; k++) {
          p0[k] = a0[k] + d[k];
          p1[k] = a0[k] + (a1[k] - a0[k]) * t + d[k];
        }
        xe = 1.0;
        x0 = 1.0;
      } else if (tr) {
        turn_add(tr, a0, d, p0);
        turn_add(tr, a1, d, p1);
      } else {
        DC_UNROLL3 for (int k = 0; k < dim; k++) {
          p0[k] = a0[k] + d[k];
          p1[k] = a1[k] + d[k];
        }
      }
      const double l1 = limit_at(L0, xe);
      if (xe > xs) clamp_piece(dim, xs, xe, l0, l1, p0, p1, sq(dim, p0), sq(dim, p1), out, &np);
      l0 = l1;
    }
    if (x0 < 1.0) {
      /* the rim entered during the step (linearly in xi^2): loaded by the
         part of d after its entry */
      const double z[3] = {0.0, 0.0, 0.0};
      clamp_piece(dim, x0, 1.0, l0, limit_at(L0, 1.0), d, z, nd, 0.0, out, &np);
      entered = 1;
    }
  }
  int no;
  *stick = group(dim, out, np, L0, &no);
  no = tidy(dim, out, no, L0);
  if (entered && no >= 2 && !out[no - 1].slip && !out[no - 2].slip) {
    /* a stuck rim grown in this step joins its neighbour when the profile
       barely changes (mean square change <= (1e-9 L0)^2, the force kept):
       steady growth makes one piece per step otherwise */
    piece f;
    const double c = merge_fit(dim, out, no - 2, &f);
    if (c <= 1e-18 * L0 * L0 * (out[no - 1].x1 - out[no - 2].x0)) {
      out[no - 2] = f;
      no--;
    }
  }
  no = cap(dim, out, no);
  DC_UNROLL3 for (int k = 0; k < dim; k++) I[k] = 0.0;
  for (int j = 0; j < no; j++) {
    const double h = out[j].x1 - out[j].x0, w = piece_w(out[j].x0, out[j].x1);
    DC_UNROLL3 for (int k = 0; k < dim; k++) I[k] += h * ((1.0 - w) * out[j].v0[k] + w * out[j].v1[k]);
  }
  return no;
}

static int profile_step3(int n, const dc_cmd_piece *seg, const cmd_turn *tr, double r, const double *d, double L0,
                         piece *out, double *stick, double *I)
{
  return profile_step(3, n, &seg[0].xi, tr, r, d, L0, out, stick, I);
}

static int profile_step1(int n, const dc_cmd_twist_piece *seg, double r, const double *d, double L0, piece *out,
                         double *stick, double *I)
{
  return profile_step(1, n, &seg[0].xi, NULL, r, d, L0, out, stick, I);
}

/* ------------------------------------------------------------------ */
/* The step in parts (each inlined: one function's code).              */

/* The stored piece counts in *ns, *nt (nt 0 without twisting, whose part
   of h is neither read nor written): DC_EDOM unless whole numbers in
   [0, DC_CMD_MAX_SEG]. The counts are range-checked as doubles before the
   conversion to int (a corrupted count beyond int's range would make it
   undefined). */
DC_INLINE int cmd_counts(const dc_cmd_params *p, const dc_cmd_state *h, int *ns_out, int *nt_out)
{
  if (!(h->nseg >= 0.0 && h->nseg <= DC_CMD_MAX_SEG && (!p->twisting || (h->nseg_t >= 0.0 && h->nseg_t <= DC_CMD_MAX_SEG))))
    return DC_EDOM;
  const int ns = (int)h->nseg, nt = p->twisting ? (int)h->nseg_t : 0;
  if (!(h->nseg == (double)ns && (!p->twisting || h->nseg_t == (double)nt))) return DC_EDOM;
  *ns_out = ns;
  *nt_out = nt;
  return DC_OK;
}

/* Inputs finite and in their domain (the counts apart: cmd_counts). */
DC_INLINE int cmd_check(const dc_cmd_params *p, const dc_mindlin_pair *m, const dc_patch *patch, const double n[3],
                        const double du[3], double dphi, double dt, const dc_cmd_state *h, int ns, int nt)
{
  const double a = patch->a, b = patch->b, Fb = patch->F_bound, mu = p->mu;
  double chk = ((dc_nf(a) + dc_nf(b)) + (dc_nf(Fb) + dc_nf(patch->formed))) +
               ((dc_nf(patch->axis[0]) + dc_nf(patch->axis[1])) + (dc_nf(patch->axis[2]) + dc_nf(mu))) +
               ((dc_nf(n[0]) + dc_nf(n[1])) + (dc_nf(n[2]) + dc_nf(du[0]))) + ((dc_nf(du[1]) + dc_nf(du[2])) + (dc_nf(m->s0) + dc_nf(m->s1))) +
               ((dc_nf(h->a_prev) + dc_nf(h->nseg)) + dc_nf(h->n_prev[0])) + (dc_nf(h->n_prev[1]) + dc_nf(h->n_prev[2]));
  if (p->twisting) chk += dc_nf(dphi) + dc_nf(h->nseg_t);
  if (p->dissipation) chk += dc_nf(dt) + dc_nf(p->t_visc);
  if (chk != 0.0) return DC_EDOM;   /* NaN: an input is not finite */
  if (!(mu >= 0.0 && p->t_visc >= 0.0 && (p->dissipation == 0 || p->dissipation == 1) &&
        (p->twisting == 0 || p->twisting == 1) && pair_ok(m) && Fb >= 0.0 && b >= 0.0 && a >= b &&
        (a == 0.0 || b >= 1e-150 * a) && (!p->dissipation || dt > 0.0)))
    return DC_EDOM;
  if (!(fabs(dc_dot3(n, n) - 1.0) <= 1e-6) || !(h->a_prev >= 0.0)) return DC_EDOM;
  /* the stored pieces: their values in independent sums; the
     breakpoints finite and increasing to 1 in one comparison chain (a NaN
     fails every comparison) */
  int order = 1;   /* breakpoints increase from 0 to 1 */
  {
    double c0 = 0.0, c1 = 0.0, c2 = 0.0, xp = 0.0;
    for (int j = 0; j < ns; j++) {
      const dc_cmd_piece *q = &h->seg[j];
      c0 += dc_nf(q->u0[0]) + dc_nf(q->u1[0]);
      c1 += dc_nf(q->u0[1]) + dc_nf(q->u1[1]);
      c2 += dc_nf(q->u0[2]) + dc_nf(q->u1[2]);
      order &= q->xi > xp;
      xp = q->xi;
    }
    order &= ns == 0 || xp <= 1.0;   /* increasing, so all <= 1 (and finite) */
    chk += (c0 + c1) + c2;
  }
  if (p->twisting)
    for (int j = 0; j < nt; j++) {
      chk += dc_nf(h->seg_t[j].xi) + (dc_nf(h->seg_t[j].t0) + dc_nf(h->seg_t[j].t1));
      order &= h->seg_t[j].xi > (j ? h->seg_t[j - 1].xi : 0.0) && h->seg_t[j].xi <= 1.0;
    }
  if (chk != 0.0 || !order) return DC_EDOM;
  return DC_OK;
}

/* The contact's frame: unit normal, Mindlin's no-slip stiffness along the
   major axis (Eqs. 56-58 per unit s0, dc/mindlin.h), and the increment of
   the stuck springs d = M du_t, M = diag(1, k_minor/k_major) in the axes. */
typedef struct {
  double nh[3];     /* unit normal */
  double tnu;       /* s1/s0 of the pair */
  double cm, rho;   /* major-axis compliance per unit s0; k_minor/k_major */
  double ax[3];     /* unit major axis in the contact plane (ellipse) */
  int ell;          /* an ellipse with its axis (el and ax set) */
  dc_ellint el;     /* its elliptic integrals */
  double k_major;   /* [N/m] */
  double dut[3];    /* du less its normal part */
  double d[3];      /* M dut */
} cmd_frame;

DC_INLINE int cmd_frame_of(const dc_mindlin_pair *m, const dc_patch *patch, const double n[3], const double du[3],
                           double axl, cmd_frame *f)
{
  const double a = patch->a, b = patch->b;
  const double nn = dc_dot3(n, n), in = 1.0 / sqrt(nn);
  DC_UNROLL3 for (int k = 0; k < 3; k++) f->nh[k] = n[k] * in;
  const double *nh = f->nh;
  f->tnu = m->s1 / m->s0;
  f->cm = (2.0 - f->tnu) * (M_PI / 4.0);
  f->rho = 1.0;
  f->ax[0] = f->ax[1] = f->ax[2] = 0.0;
  f->ell = a > b && axl > 0.0;
  if (f->ell) {
    const double g = b / a;
    if (dc_ellint_m1(g * g, &f->el) != DC_OK) return DC_EDOM;
    double cn;
    axis_compliances(f->tnu, &f->el, &f->cm, &cn);
    f->rho = f->cm / cn;   /* k_minor / k_major */
    const double an = dc_dot3(patch->axis, nh);
    DC_UNROLL3 for (int k = 0; k < 3; k++) f->ax[k] = patch->axis[k] - an * nh[k];
    const double al = norm_dir(3, f->ax, f->ax);
    if (!(al > 0.0)) return DC_EDOM;   /* axis along n */
  }
  f->k_major = pq(2.0 * M_PI, a, 1.0, 1.0, m->s0, f->cm);
  const double dn = dc_dot3(du, nh);
  DC_UNROLL3 for (int k = 0; k < 3; k++) f->dut[k] = du[k] - dn * nh[k];
  if (f->ell) {
    const double da = (1.0 - f->rho) * dc_dot3(f->ax, f->dut);
    DC_UNROLL3 for (int k = 0; k < 3; k++) f->d[k] = f->rho * f->dut[k] + da * f->ax[k];
  } else {
    DC_UNROLL3 for (int k = 0; k < 3; k++) f->d[k] = f->dut[k];
  }
  return DC_OK;
}

/* How the stored force profile turns with the contact plane: NULL where
   the normal has not moved, else tr filled. */
DC_INLINE const cmd_turn *cmd_turn_of(const dc_cmd_state *h, const double *nh, int nsu, cmd_turn *tr)
{
  const double *a = h->n_prev, *b = nh;
  if (nsu == 0 || (a[0] == b[0] && a[1] == b[1] && a[2] == b[2])) return NULL;
  const double c = dc_dot3(a, b);
  tr->nh = nh;
  tr->keep = !(c > -0.999);
  if (!tr->keep) {
    const double a0 = a[0], a1 = a[1], a2 = a[2], b0 = b[0], b1 = b[1], b2 = b[2];
    const double w0 = a1 * b2 - a2 * b1, w1 = a2 * b0 - a0 * b2, w2 = a0 * b1 - a1 * b0;
    const double ic = 1.0 / (1.0 + c);
    /* c I + ic w w^T - b a^T, then + [w]x */
    tr->M[0][0] = c + ic * w0 * w0 - b0 * a0;
    tr->M[0][1] = (0.0 + ic * w0 * w1 - b0 * a1) - w2;
    tr->M[0][2] = (0.0 + ic * w0 * w2 - b0 * a2) + w1;
    tr->M[1][0] = (0.0 + ic * w1 * w0 - b1 * a0) + w2;
    tr->M[1][1] = c + ic * w1 * w1 - b1 * a1;
    tr->M[1][2] = (0.0 + ic * w1 * w2 - b1 * a2) - w0;
    tr->M[2][0] = (0.0 + ic * w2 * w0 - b2 * a0) - w1;
    tr->M[2][1] = (0.0 + ic * w2 * w1 - b2 * a1) + w0;
    tr->M[2][2] = c + ic * w2 * w2 - b2 * a2;
  }
  return tr;
}

/* The force (Eqs. 59-71: the springs' profile stepped, F = k_major int u
   dxi in the plane), its tangent stiffness along du (Eqs. 68, 70: theta k;
   on an ellipse it depends on the direction), the dissipative force
   (Eq. 85) and the clip onto mu F_bound. Returns the profile's piece
   count (pieces in pf); *I_nf: 0 if its integral is finite, else NaN. */
DC_INLINE int cmd_force(const dc_cmd_params *p, const dc_mindlin_pair *m, const dc_patch *patch, const cmd_frame *f,
                        const dc_cmd_piece *seg, const cmd_turn *tr, int nsu, double r, double dt, piece *pf,
                        double *F, double *kt_out, double *stick_out, double *I_nf)
{
  const double mu = p->mu, Fb = patch->F_bound;
  const double *nh = f->nh;
  /* Coulomb limits L0 (1 - xi^2) integrate to mu F_bound: L0 = 3 mu F_b / (2 k_major) */
  const double L0 = pq(0.75 / M_PI * f->cm, mu, Fb, m->s0, patch->a, 1.0);
  double stick, I[3];
  const int nfp = profile_step3(nsu, seg, tr, r, f->d, L0, pf, &stick, I);
  *I_nf = (dc_nf(I[0]) + dc_nf(I[1])) + dc_nf(I[2]);
  DC_UNROLL3 for (int k = 0; k < 3; k++) F[k] = f->k_major * I[k];
  {
    const double fn = dc_dot3(F, nh);
    DC_UNROLL3 for (int k = 0; k < 3; k++) F[k] -= fn * nh[k];
  }
  double kt = stick * f->k_major;
  if (f->ell) {
    double dir[3];
    double l = norm_dir(3, f->dut, dir);
    if (!(l > 0.0)) l = norm_dir(3, F, dir);
    const double ea = dc_dot3(dir, f->ax);
    kt *= l > 0.0 ? f->rho + (1.0 - f->rho) * ea * ea : 0.5 * (1.0 + f->rho);
  }
  const double lim = mu * Fb;
  if (p->dissipation && stick > 0.0 && p->t_visc > 0.0) {
    /* Eq. 85: A_t (theta K0) d(delta)/dt */
    const double fd = p->t_visc / dt * stick * f->k_major;
    double G[3];
    DC_UNROLL3 for (int k = 0; k < 3; k++) G[k] = F[k] + fd * f->d[k];
    if (isfinite(G[0]) && isfinite(G[1]) && isfinite(G[2])) {
      DC_UNROLL3 for (int k = 0; k < 3; k++) F[k] = G[k];
    } else if (norm_dir(3, f->d, G) > 0.0) {   /* the viscous part dominates: at the limit along d */
      DC_UNROLL3 for (int k = 0; k < 3; k++) F[k] = lim * G[k];
    }
  }
  {
    double e[3];
    const double fn = dc_dot3(F, nh);   /* the viscous part may leave the plane by rounding */
    DC_UNROLL3 for (int k = 0; k < 3; k++) F[k] -= fn * nh[k];
    /* clipped onto the limit (rounding, dissipation); the squares decide
       only where they are normal doubles clearly inside it */
    const double f2 = dc_dot3(F, F), l2 = lim * lim;
    if (!(f2 >= DBL_MIN && l2 <= DBL_MAX && f2 < (1.0 - 1e-14) * l2) && norm_dir(3, F, e) > lim)
      DC_UNROLL3 for (int k = 0; k < 3; k++) F[k] = lim * e[k];
  }
  *kt_out = kt;
  *stick_out = stick;
  return nfp;
}

/* Twisting (Eq. 77, generalised to two bodies; full slip 3/8 mu F a E):
   the twist profile stepped by dphi; returns its piece count (pt), the
   moment and its tangent stiffness; adds dc_nf of its integral to *I_nf. */
DC_INLINE int cmd_twist(const dc_cmd_params *p, const dc_mindlin_pair *m, const dc_patch *patch, const cmd_frame *f,
                        const dc_cmd_state *h, int ntu, double r, double dphi, piece *pt, double *Mt_out, double *kr_out,
                        double *I_nf)
{
  const double a = patch->a, b = patch->b, mu = p->mu, Fb = patch->F_bound;
  double tf = 8.0 / M_PI, E = M_PI / 2.0;   /* circle */
  if (f->ell) {
    tf = twist_factor(f->tnu, b / a, &f->el);
    E = f->el.E;
  }
  const double ktw = pq(2.0 * M_PI / 3.0 * tf, a, a, a, m->s0, 1.0);
  const double Ms = pq(0.375 * E, mu, Fb, a, 1.0, 1.0);
  const double Lt = pq(0.5625 * E * 3.0 / (2.0 * M_PI * tf), mu, Fb, m->s0, a, a);   /* 3 Ms / (2 ktw) */
  double st, It;
  const int ntw = profile_step1(ntu, h->seg_t, r, &dphi, Lt, pt, &st, &It);
  *I_nf += dc_nf(It);
  double Mt = ktw * It;
  if (fabs(Mt) > Ms) Mt = copysign(Ms, Mt);
  *Mt_out = Mt;
  *kr_out = ktw * st;
  return ntw;
}

/* Whether every result is finite (the values to be stored among them).
   The stored values are when the profiles' integrals are (I_nf == 0):
   each value enters its integral as h ((1 - w) v0 + w v1), h >= 0,
   w in [1/3, 1/2], so a non-finite one makes its term and the sum
   non-finite; the breakpoints lie in [0, 1]. Only an integral that
   overflowed needs the values checked one by one. */
DC_INLINE int cmd_results_finite(const double *F, double kt, double stick, double Mt, double kr, double I_nf,
                                 const piece *pf, int nfp, const piece *pt, int ntw)
{
  double fin = ((dc_nf(F[0]) + dc_nf(F[1])) + (dc_nf(F[2]) + dc_nf(kt))) + ((dc_nf(stick) + dc_nf(Mt)) + dc_nf(kr));
  if (fin != 0.0) return 0;
  if (I_nf == 0.0) return 1;
  for (int j = 0; j < nfp; j++)
    fin += (dc_nf(pf[j].v0[0]) + dc_nf(pf[j].v0[1])) + (dc_nf(pf[j].v0[2]) + dc_nf(pf[j].v1[0])) +
           (dc_nf(pf[j].v1[1]) + dc_nf(pf[j].v1[2]));
  for (int j = 0; j < ntw; j++) fin += dc_nf(pt[j].v0[0]) + dc_nf(pt[j].v1[0]);
  return fin == 0.0;
}

/* The new history: normal, patch size, the profiles; pieces no longer
   used are 0 (one history per state). */
DC_INLINE void cmd_commit(const dc_cmd_params *p, const double *nh, double a, const piece *pf, int nfp, int ns,
                          const piece *pt, int ntw, int nt, dc_cmd_state *h)
{
  DC_UNROLL3 for (int k = 0; k < 3; k++) h->n_prev[k] = nh[k];
  h->a_prev = a;
  h->nseg = nfp;
  for (int j = 0; j < nfp; j++) memcpy(&h->seg[j], (const char *)&pf[j] + offsetof(piece, x1), sizeof(dc_cmd_piece));
  if (nfp < ns) memset(&h->seg[nfp], 0, sizeof(dc_cmd_piece) * (ns - nfp));
  if (p->twisting) {
    h->nseg_t = ntw;
    for (int j = 0; j < ntw; j++) {
      h->seg_t[j].xi = pt[j].x1;
      h->seg_t[j].t0 = pt[j].v0[0];
      h->seg_t[j].t1 = pt[j].v1[0];
    }
    if (ntw < nt) memset(&h->seg_t[ntw], 0, sizeof(dc_cmd_twist_piece) * (nt - ntw));
  }
}

/* dc_cmd_step with (checked) or without the check of the inputs' domain. */
DC_INLINE int cmd_step(int checked, const dc_cmd_params *p, const dc_mindlin_pair *m, const dc_patch *patch,
                       const double n[3], const double du[3], double dphi, double dt, dc_cmd_state *h, dc_cmd_out *out)
{
  int ns, nt;
  if (cmd_counts(p, h, &ns, &nt) != DC_OK) return DC_EDOM;
  if (checked && cmd_check(p, m, patch, n, du, dphi, dt, h, ns, nt) != DC_OK) return DC_EDOM;
  const double a = patch->a, b = patch->b;
  const double axl = dc_dot3(patch->axis, patch->axis);
  if (a > b && !(axl > 0.0) && b < (1.0 - 1e-6) * a) return DC_EDOM;   /* an ellipse needs its axis */

  /* not formed, or no area: the history starts afresh */
  if (patch->formed == 0.0 || a == 0.0) {
    memset(h, 0, p->twisting ? sizeof *h : DC_CMD_FORCE_NFIELDS * sizeof(double));
    memset(out, 0, sizeof *out);
    return DC_OK;
  }

  cmd_frame f;
  if (cmd_frame_of(m, patch, n, du, axl, &f) != DC_OK) return DC_EDOM;
  const int fresh = !(h->a_prev > 0.0);
  const double r = fresh ? 1.0 : h->a_prev / a;   /* the pieces' radii scale by a_prev / a */
  const int nsu = fresh ? 0 : ns;
  cmd_turn turn_buf;
  const cmd_turn *tr = cmd_turn_of(h, f.nh, nsu, &turn_buf);

  piece pf[MAXP], pt[MAXP];
  double F[3], kt, stick, Mt = 0.0, kr = 0.0, I_nf;
  const int nfp = cmd_force(p, m, patch, &f, h->seg, tr, nsu, r, dt, pf, F, &kt, &stick, &I_nf);
  const int ntw = p->twisting ? cmd_twist(p, m, patch, &f, h, fresh ? 0 : nt, r, dphi, pt, &Mt, &kr, &I_nf) : 0;
  if (!cmd_results_finite(F, kt, stick, Mt, kr, I_nf, pf, nfp, pt, ntw)) return DC_ERANGE;

  DC_UNROLL3 for (int k = 0; k < 3; k++) out->Ft[k] = F[k];
  out->kt = kt;
  out->stick = stick;
  out->Mt = Mt;
  out->kr = kr;
  cmd_commit(p, f.nh, a, pf, nfp, ns, pt, ntw, nt, h);
  return DC_OK;
}

int dc_cmd_step(const dc_cmd_params *p, const dc_mindlin_pair *m, const dc_patch *patch,
                const double n[3], const double du[3], double dphi, double dt,
                dc_cmd_state *h, dc_cmd_out *out)
{
  return cmd_step(1, p, m, patch, n, du, dphi, dt, h, out);
}

int dc_cmd_step_trusted(const dc_cmd_params *p, const dc_mindlin_pair *m, const dc_patch *patch,
                        const double n[3], const double du[3], double dphi, double dt,
                        dc_cmd_state *h, dc_cmd_out *out)
{
  return cmd_step(0, p, m, patch, n, du, dphi, dt, h, out);
}
