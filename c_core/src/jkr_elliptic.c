/* Johnson-Greenwood approximate JKR for elliptical contacts (review Eqs.
   19-28; derivation, conventions and the seed corrections are in
   dc/jkr_elliptic.h): the state as a function of the eccentricity, and the
   geometry of a contact (Hertz shape, separation and pull-off points,
   tabulated in the radius ratio). The solve for a given overlap,
   dc_jkr_contact, is in jkr_elliptic_solve.c; classical JKR for spheres in
   jkr_sphere.c. */
#include "dc/jkr_elliptic.h"
#include "dc/elliptic_integrals.h"
#include "dc/hertz_elliptic.h"
#include "dc/status.h"
#include "dc/contract.h"
#include "dc/poly14.h"
#include "jkr_cbrt.h"
#include "jkr_elliptic_private.h"
#include <float.h>
#include <math.h>
#include <string.h>

#include "jkr_geometry_poly.h"

#if DC_JG_NLANES != 18
#error "jkr_geometry_poly.h: lane count differs from dc_jkr_geometry"
#endif

/* dC/dm = (D - (4 - 3m) C)/(2 m (1-m)) (from dK/dm = B/(2 m1), dD/dm =
   (D - C)/(2 m1), dB/dm = C/2). The numerator cancels to O(m) as m -> 0
   (relative error ~6e-16/m), so below m = 0.05 the Taylor series of dC/dm
   is used instead: coefficients (n+1) c_(n+1) of C = sum c_n m^n, from the
   series of K and E (c_0 = pi/16, c_1 = 3 pi/64, ...); 13 terms leave
   < 1e-17 relative at m = 0.05. Both branches: <= 1.2e-14 relative. */
static double dc_C_dm_(double m, double m1, double D, double C)
{
  if (m < 0.05) {
    static const double c[13] = {
      0.14726215563702156, 0.23009711818284618, 0.28186896977398658, 0.3171025909957349,
      0.34258404920074931, 0.36185440196829146, 0.37693166871697027, 0.3890473294971586,
      0.39899456235362004, 0.40730694906932046, 0.41435649241859716, 0.42041040221042731,
      0.42566553223805765};
    double s = c[12];
    for (int n = 11; n >= 0; n--) s = s * m + c[n];
    return s;
  }
  return (D - (4.0 - 3.0 * m) * C) / (2.0 * m * m1);
}

/* Qn = lambda Delta Q = (1 - lambda^2) B - m (D - C) = m1 D - lambda^2 B
   (the two are equal since B - m (D - C) = m1 D), and its derivative
   dQn/dm = -((1 + lambda^2) C + D)/2 = -lambda Delta Pi2 / 2. Qn vanishes at
   the Hertz shape (lambda^2 = m1 D/B, the Hertz relation), so the form is
   chosen whose terms are smallest there: for m < 1/2 both terms of the
   first are O(m); for slender ellipses both terms of the second are
   O(m1 K), whereas those of the first are O(1) and would leave an absolute
   error of ~eps in Q against Y = O(m1 Pi2) (a 4e-10 relative error of F at
   R_minor/R_major = 1e-5). */
static void dc_jkr_Qn_(const dc_jkr_geom *G, double m, double m1, const dc_ellint *el,
                       double *Qn, double *dQn)
{
  *Qn = m < 0.5 ? G->l2c * el->B - m * (el->D - el->C) : m1 * el->D - G->lam2 * el->B;
  *dQn = -0.5 * ((1.0 + G->lam2) * el->C + el->D);
}

/* Review Eqs. 19-23 in the cancellation-free Q/u form (header comment),
   with their derivatives in the solver variable v: v = m = e^2, or, for
   slender contacts (e2_hertz > 1/2), v = m1 = 1 - e^2, which keeps full
   relative precision of b/a when it is small (jg_eval in jkr_elliptic_private.h).
   sv = dm/dv: the derivatives are returned in the solver variable v. */
void dc_jkr_eval_m_(const dc_jkr_geom *G, double m, double m1, double sv, jg_point *p)
{
  /* The values (Pi2, Q, rho, abar, dbar, Pbar) are formed with true
     divisions; the derivatives, which only steer Newton's method and give
     kn, use reciprocals computed once (one rounding more, and fewer
     dependent divisions on the path). */
  dc_ellint el;
  if (m <= 0.5) dc_ellint_m(m, &el); else dc_ellint_m1(m1, &el);
  const double K = el.K, D = el.D, B = el.B, C = el.C;
  const double lam = G->lambda, lam2 = G->lam2;
  const double im1 = 1.0 / m1;
  const double dK = 0.5 * B * im1, dD = 0.5 * (D - C) * im1, dB = 0.5 * C;
  const double dC = dc_C_dm_(m, m1, D, C);

  const double Del = D * B + m1 * C * D + B * C;
  const double dDel = dD * B + D * dB - C * D + m1 * (dC * D + C * dD) + dB * C + B * dC;
  const double lD = lam * Del;
  const double ilD = 1.0 / lD, dlnDel = dDel / Del;
  const double Pi2 = ((1.0 + lam2) * C + D) / lD;
  const double dPi2 = ((1.0 + lam2) * dC + dD) * ilD - Pi2 * dlnDel;
  double Qn, dQn;
  dc_jkr_Qn_(G, m, m1, &el, &Qn, &dQn);
  const double Q = Qn / lD;
  const double dQ = dQn * ilD - Q * dlnDel;
  const double g = sqrt(m1);
  const double q4 = sqrt(g);                        /* g^1/2 */
  const double ig = 1.0 / g, dg = -0.5 * ig;
  /* u = 1 - g^1/2 = (1 - g^2)/((1 + g^1/2)(1 + g)): no cancellation */
  const double uden = (1.0 + q4) * (1.0 + g);
  const double u = m / uden, iu = uden / m;
  p->m1 = m1;
  const double du = 0.25 * ig / q4;
  const double rho = Q / u;
  const double drho = (dQ - rho * du) * iu;
  const double irho = 1.0 / rho;

  const double X = m1 * Pi2 * K + Q * B - 2.0 * K * rho;
  const double dX = -Pi2 * K + m1 * (dPi2 * K + Pi2 * dK) + dQ * B + Q * dB - 2.0 * (dK * rho + K * drho);
  const double Y = m1 * Pi2 / 3.0 + Q / 3.0 - rho;
  const double dY = (-Pi2 + m1 * dPi2 + dQ) / 3.0 - drho;

  /* abar^3 = g / rho^2, dbar = abar^2 X, Pbar = g Y / rho^2 */
  const double grr = g / (rho * rho);
  const double abar = dc_jkr_cbrt_(grr);
  const double dln = dg * ig - 2.0 * drho * irho;          /* d ln(g/rho^2)/dm */
  const double lna = dln * (1.0 / 3.0);                     /* d ln abar/dm */
  p->m = m; p->g = g; p->rho = rho; p->X = X; p->Y = Y;
  p->abar = abar;
  p->dbar = abar * abar * X;
  p->Pbar = grr * Y;
  p->dg = sv * dg; p->drho = sv * drho; p->dX = sv * dX; p->dY = sv * dY;
  p->dabar = sv * abar * lna;
  p->ddbar = sv * abar * abar * (2.0 * lna * X + dX);
  p->dPbar = sv * grr * (Y * dln + dY);
}

/* The geometry is built in a local copy and handed out only when every
   double of it is finite: on any error *out is untouched. The radii, E*,
   w, Rhat, lambda, lam2 and l2c are finite by the domain check, the
   Hertz part by dc_hertz_geometry's status; the rest is checked. */
static int geometry_done(const dc_jkr_geom *G, dc_jkr_geom *out)
{
  const double v[] = {G->e2_hertz, G->a_scale, G->delta_scale, G->F_scale, G->e2_break, G->delta_break,
                      G->F_break, G->dbar_break, G->e2_pull, G->delta_pull, G->F_pull, G->guess_c1, G->guess_c2,
                      G->pert_X0, G->pert_X1, G->pert_g0, G->pert_g1, G->pert_P0, G->pert_P1, G->pert_rho0,
                      G->dbar_switch, G->v_hertz, G->v_break};
  double nan_if_any = 0.0;   /* x - x is 0 for a finite x, NaN for inf or NaN */
  for (size_t i = 0; i < sizeof v / sizeof v[0]; i++) nan_if_any += v[i] - v[i];
  if (nan_if_any != 0.0) return DC_ERANGE;
  *out = *G;
  return DC_OK;
}

int dc_jkr_geometry(double R1, double R2, double Estar, double w, dc_jkr_geom *out)
{
  if (!(R1 > 0.0 && R2 > 0.0 && isfinite(R1) && isfinite(R2) && Estar > 0.0 && isfinite(Estar) &&
        w >= 0.0 && isfinite(w)))
    return DC_EDOM;
  const double Rmaj = R1 > R2 ? R1 : R2, Rmin = R1 > R2 ? R2 : R1;
  if (Rmin / Rmaj < DC_JKR_RATIO_MIN) return DC_EDOM;
  dc_jkr_geom geom;
  dc_jkr_geom *const G = &geom;
  memset(G, 0, sizeof *G);
  G->R_major = Rmaj;
  G->R_minor = Rmin;
  G->Rhat = sqrt(Rmaj) * sqrt(Rmin);
  G->lambda = sqrt(Rmin / Rmaj);
  G->lam2 = Rmin / Rmaj;
  G->l2c = (Rmaj - Rmin) / Rmaj;
  G->Estar = Estar;
  G->w = w;
  /* the w = 0 contact is dc_hertz_contact with this geometry */
  const int st = dc_hertz_geometry(Rmaj, Rmin, &G->hertz);
  if (st != DC_OK) return st;
  G->e2_hertz = G->hertz.e2;
  G->circular = G->l2c < DC_JKR_CIRCULAR_TOL;
  G->a_scale = dc_jkr_length_scale_(w, Estar, G->Rhat);
  G->delta_scale = dc_jkr_delta_scale_(G->a_scale, G->Rhat);
  G->F_scale = 8.0 * w * G->Rhat;
  if (!(G->delta_scale > 0.0)) {  /* w = 0 (or so small that the overlap scale underflows) */
    G->w = 0.0;
    G->a_scale = G->delta_scale = G->F_scale = 0.0;
    G->e2_break = G->e2_pull = G->e2_hertz;
    return geometry_done(G, out);
  }
  if (G->circular) {
    const double R = G->Rhat;
    G->delta_break = dc_jkr_sphere_delta_break(R, Estar, w);
    G->F_break = -5.0 / 6.0 * M_PI * w * R;
    G->F_pull = -dc_jkr_sphere_pulloff(R, w);
    /* pull-off at a^3 = 9 pi w R^2/(8 E*): delta = a^2/R - (2 pi w a/E*)^1/2 */
    const double ap = cbrt(9.0 * M_PI * w * R * R / (8.0 * Estar));
    G->delta_pull = ap * ap / R - sqrt(2.0 * M_PI * w * ap / Estar);
    return geometry_done(G, out);
  }
  /* The reduced geometry depends on R_minor/R_major alone: the Hertz shape
     (Qn = 0), the separation point (min dbar), the pull-off point (min
     Pbar), the first-order expansion at the Hertz end (X = X0 + X1 rho, g =
     g0 + g1 rho, F/(F_scale dbar^3/2) = P0 + P1 rho, rho = rho0 dbar^-3/4;
     P1 is zero), the switch to it (where the distance to the Hertz state is
     1e-8 of v_H) and the starting-value model of the solve (|v_H - v| =
     |v_H - v_b|/(1 + c1 d^1/2 + c2 d^3/4), d = dbar - dbar_b, c2 from the
     Hertz asymptote, c1 through the pull-off point, clipped at 0), from
     the tables of jkr_geometry_poly.h (tests/reference/gen_jkr_geometry_poly.py,
     mpmath, within ~1 ulp). t = ln(R_minor/R_major) from whichever of
     lam2 and l2c = 1 - lam2 is below 1/2 (each rounded once from the
     radii: the other can lose relative precision); the solver variable v
     is e^2, or 1 - e^2 for slender contacts (e2_H > 1/2). */
  const double t = G->lam2 < 0.5 ? log(G->lam2) : log1p(-G->l2c);
  const int pc = -t < DC_JG_PIECES - 1 ? (int)(-t) : DC_JG_PIECES - 1;
  double y[DC_JG_NLANES], rest[DC_JG_NLANES];
  dc_poly14(&dc_jg_poly[pc][0][0], DC_JG_NLANES, DC_JG_NLANES, t - dc_jg_centre[pc], y, rest);
  const double eH = G->l2c * y[0], m1H = G->lam2 * y[1];
  G->use_m1 = eH > 0.5;
  const double vH = G->use_m1 ? m1H : eH, vb = G->use_m1 ? y[3] : eH * y[2], vp = G->use_m1 ? m1H * y[5] : eH * y[4];
  G->v_hertz = vH;
  G->e2_hertz = G->use_m1 ? 1.0 - vH : vH;
  G->v_break = vb;
  G->e2_break = G->use_m1 ? 1.0 - vb : vb;
  G->dbar_break = y[6];
  G->delta_break = G->delta_scale * y[6];
  G->F_break = G->F_scale * y[7];
  G->e2_pull = G->use_m1 ? 1.0 - vp : vp;
  G->delta_pull = G->delta_scale * y[8];
  G->F_pull = G->F_scale * y[9];
  G->pert_X0 = y[10];
  G->pert_X1 = y[11];
  G->pert_g0 = sqrt(m1H);
  G->pert_g1 = G->l2c * y[12];
  G->pert_P0 = y[13];
  G->pert_P1 = 0.0;
  G->pert_rho0 = y[17];
  /* the switch, tabulated with the distance measured in e^2: in 1 - e^2
     it is (e2_H/m1_H)^4/3 times that */
  const double q = eH / m1H;
  G->dbar_switch = G->use_m1 ? y[14] * q * dc_jkr_cbrt_(q) : y[14];
  G->guess_c1 = y[15] > 0.0 ? y[15] : 0.0;
  G->guess_c2 = y[16];
  return geometry_done(G, out);
}

void dc_jkr_elliptic_fill_(const dc_jkr_geom *G, const jg_point *p, double s_m, dc_jkr_state *s)
{
  /* s_m: remaining Newton correction in the solver variable, applied to
     first order */
  const double sg = G->use_m1 ? -1.0 : 1.0;   /* dm/dv */
  const double g = p->g + p->dg * s_m;
  const double abar = p->abar + p->dabar * s_m;
  s->contact = 1;
  s->a = G->a_scale * abar;
  s->b = g * s->a;
  s->area = M_PI * s->a * s->b;
  s->e2 = p->m + sg * s_m;
  s->F = G->F_scale * (p->Pbar + p->dPbar * s_m);
  s->delta = G->delta_scale * (p->dbar + p->ddbar * s_m);
  s->kn = dc_jkr_finite_kn_(sg * G->F_scale * p->dPbar, sg * G->delta_scale * p->ddbar);
}

/* Below e^2 = E2_SMALL (1 - lambda^2) the forward map is taken in its
   leading order in e^2: the relative corrections are O(e^2) and O(e^2/(1 -
   lambda^2)) (the m (D - C) term of Qn against l2c B), both below 1e-20;
   it keeps rho ~ 1/e^2 and its square out of overflow. */
#define E2_SMALL 1e-20

int dc_jkr_at_eccentricity(const dc_jkr_geom *G, double e2, dc_jkr_state *s)
{
  if (G->circular || G->w == 0.0 || !(e2 > 0.0 && e2 < G->e2_hertz)) return DC_EDOM;
  dc_jkr_state t;
  if (e2 < E2_SMALL * G->l2c) {
    /* m -> 0: K, D, B, C -> pi/2, pi/4, pi/4, pi/16, Delta -> 3 pi^2/32,
       Q -> l2c pi/(4 lambda Delta), u -> m/4, so rho = r1/m with r1 =
       32 l2c/(3 pi lambda); X = -pi r1/m, Y = -r1/m, and abar = (m/r1)^2/3,
       dbar = -pi (m/r1)^1/3, Pbar = -m/r1, each to a relative O(m). With
       c = (m/r1)^1/3 (no power of m that could underflow):
       kn = F_scale Pbar'/(delta_scale dbar') = 3 F_scale c^2/(pi delta_scale). */
    const double r1 = 32.0 / (3.0 * M_PI) * G->l2c / G->lambda;
    const double c = cbrt(e2) / cbrt(r1), abar = c * c;
    t.contact = 1;
    t.a = t.b = G->a_scale * abar;
    t.area = M_PI * t.a * t.b;
    t.e2 = e2;
    t.F = -G->F_scale * (e2 / r1);
    t.delta = -M_PI * G->delta_scale * c;
    t.kn = 3.0 * G->F_scale * abar / (M_PI * G->delta_scale);
  } else {
    /* at m = e2 itself (for slender contacts, v = 1 - e2 would round e2
       below 1/2 to the spacing of the doubles near 1) */
    jg_point p;
    const double sg = G->use_m1 ? -1.0 : 1.0;
    dc_jkr_eval_m_(G, e2, 1.0 - e2, sg, &p);
    if (!(p.rho > 0.0)) return DC_ERANGE;   /* e2 within rounding of e2_hertz: a -> oo */
    dc_jkr_elliptic_fill_(G, &p, 0.0, &t);
    if (sg * p.ddbar <= 0.0) t.kn = dc_jkr_finite_kn_(-sg * G->F_scale * p.dPbar, -sg * G->delta_scale * p.ddbar);
  }
  if (!dc_jkr_state_finite_(&t)) return DC_ERANGE;
  *s = t;
  return DC_OK;
}

const dc_history_field dc_jkr_history[DC_JKR_HISTORY_NFIELDS] = {
  {"jkr_contact", 0}, {"jkr_hint_v", 0}, {"jkr_hint_L", 0}, {"jkr_hint_s", 0},
};

int dc_jkr_check(double w, dc_param_error *err)
{
  return dc_param_check("workOfAdhesion", w, 0.0, 0, HUGE_VAL, 1, "[0, inf) J/m^2", err);
}

void dc_jkr_normal(const dc_jkr_state *s, double F_pulloff, dc_contact *c)
{
  c->F = s->F;
  c->kn = s->kn;
  c->area = s->area;
  c->a = s->a;
  c->b = s->b;
  c->F_bound = s->contact ? dc_jkr_friction_load(s->F, F_pulloff) : 0.0;
  c->formed = s->contact;
}
