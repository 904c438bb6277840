/* Johnson-Greenwood approximate JKR for elliptical contacts (review Eqs.
   19-28; derivation, conventions and the seed corrections are in
   dc/jkr_elliptic.h): the state as a function of the eccentricity, and the
   geometry of a contact (Hertz shape, separation and pull-off points by
   the extremum searches). The solve for a given overlap, dc_jkr_contact, is
   in jkr_elliptic_solve.c; classical JKR for spheres in jkr_sphere.c. */
#include "dc/jkr_elliptic.h"
#include "dc/elliptic_integrals.h"
#include "dc/hertz_elliptic.h"
#include "dc/root_find.h"
#include "dc/status.h"
#include "dc/contract.h"
#include "jkr_cbrt.h"
#include "jkr_extrema_guess.h"
#include "jkr_private.h"
#include <float.h>
#include <math.h>
#include <string.h>

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
   relative precision of b/a when it is small (jg_eval in jkr_private.h).
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

/* The v-derivative of dbar (which = 0) or Pbar (which = 1) at v; the
   point is kept in *p. */
static double deriv_of(const dc_jkr_geom *G, double v, int which, jg_point *p)
{
  jg_eval(G, v, p);
  return which ? p->dPbar : p->ddbar;
}

/* The extremum searches: dc_root_brent_ends on that derivative, the
   points kept in the finder's three slots (so the root's point needs no
   evaluation of its own). */
typedef struct {
  const dc_jkr_geom *G;
  int which;
  jg_point pt[3];
} ext_search;

static double ext_deriv(double v, void *ctx, int slot)
{
  ext_search *e = ctx;
  return deriv_of(e->G, v, e->which, &e->pt[slot]);
}

/* The zero of the derivative over [a, b] with fa < 0 < fb (a minimum; the
   points at a and b in slots 0 and 1), to 1e-12 relative in v: the
   extremal values (delta_break, F_pull) are then exact to rounding (second
   order), e2_break and e2_pull to ~1e-12. Its point in *p. Any failure,
   the lack of a sign change included, is DC_ENOCONV (the search failed). */
static int ext_root(ext_search *e, double a, double b, double fa, double fb, double *root, jg_point *p)
{
  if (!(fa < 0.0 && fb > 0.0)) return DC_ENOCONV;
  dc_root_result r;
  if (dc_root_brent_ends(ext_deriv, e, a, b, fa, fb, 1e-12, 1e-300, 200, &r) != DC_OK) return DC_ENOCONV;
  *root = r.x;
  *p = e->pt[r.slot];
  return DC_OK;
}

/* Bracket [lo, hi] around the guess of extremum `which` (0: separation,
   1: pull-off), half-width `hw` (relative), clipped to [vmin, vmax]. The
   guess: ln(v/v_H) from jkr_extrema_guess.h (the library's own searches at
   16 ratios per decade) by 4-point Lagrange interpolation in log10 of the
   ratio, within 4e-7 of the extremum; it only places the bracket, the
   search finds the extremum to rounding. */
static void ext_bracket(const dc_jkr_geom *G, int which, double hw, double vmin, double vmax,
                        double *lo, double *hi)
{
  double u = -DC_JKR_GUESS_PER_DECADE * log10(G->lam2);
  if (!(u > 0.0)) u = 0.0;
  if (u > DC_JKR_GUESS_ROWS - 1) u = DC_JKR_GUESS_ROWS - 1;
  int i = (int)u - 1;
  if (i < 0) i = 0;
  if (i > DC_JKR_GUESS_ROWS - 4) i = DC_JKR_GUESS_ROWS - 4;
  const double f = u - i;   /* position in the stencil rows i .. i+3, in [0, 3] */
  const int col = (G->use_m1 ? 2 : 0) + which;
  const double y0 = dc_jkr_extrema_guess[i][col], y1 = dc_jkr_extrema_guess[i + 1][col];
  const double y2 = dc_jkr_extrema_guess[i + 2][col], y3 = dc_jkr_extrema_guess[i + 3][col];
  const double lg = -(f - 1) * (f - 2) * (f - 3) / 6 * y0 + f * (f - 2) * (f - 3) / 2 * y1 -
                    f * (f - 1) * (f - 3) / 2 * y2 + f * (f - 1) * (f - 2) / 6 * y3;
  const double g = G->v_hertz * exp(lg);
  *lo = fmax(vmin, g * (1.0 - hw));
  *hi = fmin(vmax, g * (1.0 + hw));
}

/* Brent on the derivative `which` from a bracket around the tabulated
   guess, widened (x8) until the derivative changes sign, else over the
   full range [vmin, vmax]. */
static int find_extremum(const dc_jkr_geom *G, int which, double vmin, double vmax, double *root,
                         jg_point *p)
{
  ext_search e;
  e.G = G;
  e.which = which;
  for (double hw = 4e-6; hw < 1.0; hw *= 8.0) {
    double lo, hi;
    ext_bracket(G, which, hw, vmin, vmax, &lo, &hi);
    if (!(lo < hi)) continue;
    const double flo = deriv_of(G, lo, which, &e.pt[0]);
    if (!(flo < 0.0)) continue;
    const double fhi = deriv_of(G, hi, which, &e.pt[1]);
    if (fhi > 0.0) return ext_root(&e, lo, hi, flo, fhi, root, p);
  }
  const double flo = deriv_of(G, vmin, which, &e.pt[0]);
  const double fhi = deriv_of(G, vmax, which, &e.pt[1]);
  return ext_root(&e, vmin, vmax, flo, fhi, root, p);
}

/* The geometry is built in a local copy and handed out only when every
   double of it is finite: on any error *out is untouched. */
static int geometry_done(const dc_jkr_geom *G, dc_jkr_geom *out)
{
  const dc_hertz_geom *h = &G->hertz;
  const double v[] = {G->R_major, G->R_minor, G->Rhat, G->lambda, G->lam2, G->l2c, G->Estar, G->w,
                      h->R_major, h->R_minor, h->Rc, h->e2, h->m1, h->K, h->E, h->D, h->gamma, h->beta,
                      h->R_force, h->R_area, G->e2_hertz, G->a_scale, G->delta_scale, G->F_scale,
                      G->e2_break, G->delta_break, G->F_break, G->dbar_break, G->e2_pull, G->delta_pull,
                      G->F_pull, G->guess_c1, G->guess_c2, G->pert_X0, G->pert_X1, G->pert_g0, G->pert_g1,
                      G->pert_P0, G->pert_P1, G->pert_rho0, G->dbar_switch, G->v_hertz, G->v_break};
  for (size_t i = 0; i < sizeof v / sizeof v[0]; i++)
    if (!isfinite(v[i])) return DC_ERANGE;
  *out = *G;
  return DC_OK;
}

int dc_jkr_geometry(double R1, double R2, double Estar, double w, dc_jkr_geom *out)
{
  if (!(R1 > 0.0 && R2 > 0.0 && isfinite(R1) && isfinite(R2) && Estar > 0.0 && isfinite(Estar) &&
        w >= 0.0 && isfinite(w)))
    return DC_EDOM;
  const double Rmaj = fmax(R1, R2), Rmin = fmin(R1, R2);
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
  /* The w = 0 contact is dc_hertz_contact with this geometry. For w > 0 it
     only gives the starting value of the Hertz shape, which near the circle
     (1 - ratio < 1e-3) is not needed: a failure there is not passed on. */
  int st = dc_hertz_geometry(Rmaj, Rmin, &G->hertz);
  const int hertz_ok = st == DC_OK;
  if (!hertz_ok) memset(&G->hertz, 0, sizeof G->hertz);
  G->e2_hertz = G->hertz.e2;
  G->circular = G->l2c < DC_JKR_CIRCULAR_TOL;
  G->a_scale = dc_jkr_length_scale_(w, Estar, G->Rhat);
  G->delta_scale = dc_jkr_delta_scale_(G->a_scale, G->Rhat);
  G->F_scale = 8.0 * w * G->Rhat;
  if (!(G->delta_scale > 0.0)) {  /* w = 0 (or so small that the overlap scale underflows) */
    if (!hertz_ok) return st;
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
  /* Solver variable v (e^2, or 1 - e^2 for slender contacts), and the
     Hertz state as the zero of Qn (dc_jkr_Qn_) by Newton's method. Start:
     dc_hertz_geometry's e^2, except near the circle, where that comes from
     the ratio R_minor/R_major and so carries an absolute error ~eps (all
     of e^2 ~ 4/3 (1 - ratio) at 1 - ratio = 1e-9 and below); there Qn =
     l2c pi/4 - 3 pi m/16 + O(m^2, l2c m) gives e^2 = 4/3 l2c. */
  if (!hertz_ok && !(G->l2c < 1e-3)) return st;
  G->use_m1 = G->e2_hertz > 0.5;
  double vH = G->use_m1 ? G->hertz.m1 : G->hertz.e2;
  if (G->l2c < 1e-3) vH = 4.0 / 3.0 * G->l2c;
  for (int i = 0;; i++) {
    const double m = G->use_m1 ? 1.0 - vH : vH, m1 = G->use_m1 ? vH : 1.0 - vH;
    dc_ellint el;
    if (m <= 0.5) dc_ellint_m(m, &el); else dc_ellint_m1(m1, &el);
    double Qn, dQn;
    dc_jkr_Qn_(G, m, m1, &el, &Qn, &dQn);
    const double step = (G->use_m1 ? -1.0 : 1.0) * Qn / dQn;
    double vn = vH - step;
    if (!(vn > 0.0 && vn < 1.0)) vn = vn <= 0.0 ? 0.5 * vH : 0.5 * (1.0 + vH);
    if (i == 40 || !isfinite(vn)) return DC_ENOCONV;
    /* Newton is quadratic: once the step is at the rounding level of Qn
       (which can leave it a few eps above 4 eps vH for ever, seen at
       R_minor/R_major = 0.0772), applying it is exact to rounding */
    const int done = fabs(step) <= 64.0 * DBL_EPSILON * vH;
    vH = vn;
    if (done) break;
  }
  G->v_hertz = vH;
  G->e2_hertz = G->use_m1 ? 1.0 - vH : vH;
  /* Extrema of dbar and Pbar on the family: dbar -> 0- and Pbar -> 0-
     for a vanishing contact (e^2 -> 0), both -> +oo at the Hertz end. In v
     the derivative is < 0 towards the vanishing contact when v = e^2 and
     > 0 when v = 1 - e^2. */
  const double v0 = G->use_m1 ? 1.0 - 1e-6 * G->e2_hertz : 1e-6 * vH;  /* near e^2 = 0 */
  const double v1 = G->use_m1 ? vH * (1.0 + 1e-6) : vH * (1.0 - 1e-6);  /* near Hertz   */
  double vb, vp;
  jg_point p, pp;
  st = find_extremum(G, 0, fmin(v0, v1), fmax(v0, v1), &vb, &p);
  if (st != DC_OK) return st;
  st = find_extremum(G, 1, fmin(vb, v1), fmax(vb, v1), &vp, &pp);
  if (st != DC_OK) return st;
  G->v_break = vb;
  G->e2_break = p.m;
  G->dbar_break = p.dbar;
  G->delta_break = G->delta_scale * p.dbar;
  G->F_break = G->F_scale * p.Pbar;
  const double dbar_b = p.dbar;
  p = pp;
  G->e2_pull = p.m;
  G->delta_pull = G->delta_scale * p.dbar;
  G->F_pull = G->F_scale * p.Pbar;
  /* Hertz end: first-order coefficients and the switch to them */
  jg_eval(G, vH, &p);
  G->pert_X0 = p.X;
  G->pert_g0 = p.g;
  G->pert_rho0 = sqrt(p.g) * sqrt(p.X) * sqrt(sqrt(p.X));   /* g0^1/2 X0^3/4 */
  G->pert_X1 = p.dX / p.drho;
  G->pert_g1 = p.dg / p.drho;
  G->pert_P0 = p.Y / (p.X * sqrt(p.X));
  G->pert_P1 = (p.dY * p.X - 1.5 * p.Y * p.dX) / (p.X * p.X * sqrt(p.X)) / p.drho;
  const double rho_sw = 1e-8 * vH * fabs(p.drho);
  const double g23X = dc_jkr_cbrt_(p.g * p.g) * p.X, crs = dc_jkr_cbrt_(rho_sw);
  G->dbar_switch = g23X / (crs * crs * crs * crs);   /* g^2/3 X rho_sw^-4/3 */
  /* Starting values: |v_H - v| = |v_H - v_b|/(1 + c1 d^1/2 + c2 d^3/4),
     d = dbar - dbar_b; c2 from the Hertz asymptote (rho = |drho/dv|
     |v_H - v|, dbar = g^2/3 X rho^-4/3), c1 through the pull-off point. */
  const double span = fabs(vH - vb);
  G->guess_c2 = span * fabs(p.drho) / (sqrt(g23X) * sqrt(sqrt(g23X)));   /* (g^2/3 X)^-3/4 */
  const double dp = G->delta_pull / G->delta_scale - dbar_b;
  const double need = span / fabs(vH - vp) - 1.0 - G->guess_c2 * sqrt(dp) * sqrt(sqrt(dp));
  G->guess_c1 = need > 0.0 ? need / sqrt(dp) : 0.0;
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
