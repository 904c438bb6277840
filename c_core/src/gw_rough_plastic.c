/* GW rough contact with elastic, elastic-plastic and fully plastic summits
   (Jeng & Wang 2003; review Eqs. 47-53, corrected): see
   dc/gw_rough_plastic.h for the law, its limits and the seed errors. */
#include "dc/gw_rough_plastic.h"
#include "dc/gw_integrals.h"
#include "dc/status.h"
#include "scaled_product.h"
#include <float.h>
#include <math.h>

#define INV_SQRT_2PI 0.39894228040143267794

/* 10-point Gauss-Legendre on [-1, 1]: nodes +-X10[k], weights W10[k]. */
static const double X10[5] = {
  0.14887433898163121088, 0.43339539412924719080, 0.67940956829902440623,
  0.86506336668898451073, 0.97390652851717172008};
static const double W10[5] = {
  0.29552422471475287017, 0.26926671930999635509, 0.21908636251598204400,
  0.14945134915058059315, 0.066671344308688137594};

/* Gaussian window of a regime: phi below e^-45 of its largest value on
   the regime; regimes below e^-60 of phi's largest value are skipped. */
#define WINDOW_T2 90.0
#define SKIP_T2 120.0

/* phi(s) = exp(-s^2/2)/sqrt(2 pi), s^2 split exactly (fma) so its rounding
   does not cost digits at large |s|. */
static double phi(double s)
{
  if (fabs(s) > 40.0) return 0.0;
  const double ss = s * s, err = fma(s, s, -ss);
  return INV_SQRT_2PI * exp(-0.5 * ss) * (1.0 - 0.5 * err);
}

/* phi(h + u) for the exact sum: its rounding d (TwoSum) corrected to first
   order, phi(x + d) = phi(x)(1 - x d), so that large |h + u| (phi's
   relative sensitivity is |x| per unit) costs no digits. */
static inline double phi_sum(double h, double u)
{
  const double x = h + u, hh = x - u;
  const double d = (h - hh) + (u - (x - hh));
  return phi(x) * (1.0 - x * d);
}

/* Width of the panel that starts at s0 (moving to larger s) for a
   10-point rule on a Gaussian whose largest value on the range is at
   s_pk: w |s|max <= 4 (relative error ~1e-16 per panel, measured),
   relaxed to 4 + T/2 where the panel's weight exp(-T) relative to that
   largest value is small; at most 2. */
static double panel_width(double s0, double s_pk)
{
  double w;
  if (s0 >= s_pk) {   /* moving away from the peak */
    double T = 0.5 * (s0 - s_pk) * (s0 + s_pk);
    if (T < 0.0) T = 0.0;
    const double c = 4.0 + 0.5 * T, as = fabs(s0);
    w = 2.0 * c / (as + sqrt(as * as + 4.0 * c));   /* w (|s0| + w) = c */
  } else {            /* moving towards it (s0 < s_pk <= 0): the near end is >= |s0| - 2 */
    const double as = -s0, d = as > 2.0 ? as - 2.0 : 0.0;
    double T = 0.5 * (d * d - s_pk * s_pk);
    if (T < 0.0) T = 0.0;
    w = (4.0 + 0.5 * T) / as;
  }
  return w < 2.0 ? w : 2.0;
}

/* The largest phi(h + u) for u in [u0, u1]: at s = h + u nearest 0. */
static double peak_of(double h, double u0, double u1)
{
  const double s0 = h + u0, s1 = h + u1;
  return s0 > 0.0 ? s0 : (s1 < 0.0 ? s1 : 0.0);
}

/* Summands of the integrals (dc_gw_plastic_sums without n_panels). */
typedef struct {
  double Je, Je12, Jp, Jdp, JA;
} sums;

/* Per-shape constants of the elastic-plastic range. */
typedef struct {
  double a, lm1, c_h, dP, inv_lr, inv_rm1, inv_a, inv_ba;
  int small_lr;   /* ln(b/a) < 1/16 */
} ep_consts;

/* Elastic summit at compression u, with quadrature weight wq (phi and the
   Jacobian included) and su = sqrt(u). */
static inline void add_elastic(sums *S, double u, double su, double wq)
{
  S->Je += wq * u * su;
  S->Je12 += wq * su;
  S->JA += wq * u;
}

/* Elastic-plastic summit at u = a + off (off >= 0 given exactly, so that
   x keeps its precision when b - a is tiny). */
static inline void add_ep(sums *S, const ep_consts *k, double u, double off, double wq)
{
  const double x = off * k->inv_ba;
  const double c = x * x * (3.0 - 2.0 * x);
  const double A = 1.0 + k->lm1 * c;
  const double ra = 1.0 + off * k->inv_a;   /* u/a */
  /* ln(u/a): log1p keeps it exact to rounding where ln(b/a) is small */
  const double lr_u = k->small_lr ? log1p(off * k->inv_a) : log(ra);
  const double P = k->c_h - k->dP * (1.0 - lr_u * k->inv_lr);
  const double dA = k->lm1 * 6.0 * x * (1.0 - x) * ra * k->inv_rm1;   /* u dA/du */
  S->JA += wq * u * A;
  S->Jp += wq * u * A * P;
  S->Jdp += wq * (A * P + dA * P + A * k->dP * k->inv_lr);
}

/* The 10 Gauss-Legendre offsets t[k] = r (1 -+ X) of a panel of
   half-width r from its start, and the weights W r. */
static void panel_offsets(double r, double *t, double *w)
{
  for (int k = 0; k < 5; k++) {
    t[2 * k] = r * (1.0 - X10[k]);
    t[2 * k + 1] = r * (1.0 + X10[k]);
    w[2 * k] = w[2 * k + 1] = W10[k] * r;
  }
}

/* Adds the summits of one regime, u in [u0, u1] (elastic if kc is NULL,
   else elastic-plastic with u0 >= a), by 10-point panels; returns their
   number. Panel ends from panel_width, each panel at most twice as long as
   its start u (u^1/2 and ln u are singular at u = 0: relative error
   < 1e-15 for ratio 2, measured), snapped to u1 when close.
   h > -16: panels laid in u (u stays exact near 0; phi_sum keeps phi's
   precision at any h; u < 40 on every window here). h <= -16: panels laid
   in s = h + u (|s| < 11 on the window), so that u = s - h keeps its
   relative precision and panels of width ~1 stay resolved for any h; the
   offset u - a of an elastic-plastic node is taken from s_a = h + a and
   its rounding (TwoSum), so x keeps its precision when b - a is tiny. */
static int regime_panels(sums *S, const ep_consts *kc, double h, double s_pk, double u0, double u1)
{
  int n = 0;
  double t[10], w[10];
  if (h > -16.0) {
    double p = u0;
    if (!kc && u0 < panel_width(h + u0, s_pk)) {
      /* elastic: first panel from u = 0 in u = p1 tau^2 (u^3/2, u^1/2
         polynomial in tau; the mass below u0 is correct mass); width 0.4,
         1/|h| beyond |h| = 2.5: the Gaussian exp(-(h + p1 tau^2)^2/2) in
         tau then keeps the relative error near 1e-16 (measured) */
      double p1 = fabs(h) > 2.5 ? 1.0 / fabs(h) : 0.4;
      if (p1 > u1) p1 = u1;
      const double sp = sqrt(p1);
      for (int k = 0; k < 5; k++)
        for (int sg = -1; sg <= 1; sg += 2) {
          const double tau = 0.5 * (1.0 + sg * X10[k]);
          const double u = p1 * tau * tau;
          /* du = 2 p1 tau dtau, dtau = W/2 */
          add_elastic(S, u, sp * tau, W10[k] * p1 * tau * phi_sum(h, u));
        }
      n++;
      p = p1;
    }
    while (p < u1) {
      const double wd = panel_width(h + p, s_pk);
      double q = p + (wd < p ? wd : p);
      if (q > u1 || u1 - q < 1e-3 * (q - p)) q = u1;
      if (!(q > p)) break;   /* not reached: p > 0 and below 40 */
      panel_offsets(0.5 * (q - p), t, w);
      if (kc) {
        const double pa = p - kc->a;   /* exact: p is a or a panel end beyond it */
        for (int k = 0; k < 10; k++) {
          const double u = p + t[k];
          add_ep(S, kc, u, pa + t[k], w[k] * phi_sum(h, u));
        }
      } else {
        for (int k = 0; k < 10; k++) {
          const double u = p + t[k];
          add_elastic(S, u, sqrt(u), w[k] * phi_sum(h, u));
        }
      }
      n++;
      p = q;
    }
  } else {
    double s_a = 0.0, e_a = 0.0;   /* s_a + e_a = h + a exactly */
    if (kc) {
      s_a = h + kc->a;
      const double hh = s_a - kc->a;
      e_a = (h - hh) + (kc->a - (s_a - hh));
    }
    double p = h + u0;
    const double s1 = h + u1;
    while (p < s1) {
      const double wd = panel_width(p, s_pk);   /* <= 2 < u here */
      double q = p + wd;
      if (q > s1 || s1 - q < 1e-3 * wd) q = s1;
      if (!(q > p)) break;   /* not reached: |p| < 15 */
      panel_offsets(0.5 * (q - p), t, w);
      for (int k = 0; k < 10; k++) {
        const double s = p + t[k], u = s - h;
        if (kc) {
          double off = (s - s_a) - e_a;
          if (off < 0.0) off = 0.0;
          add_ep(S, kc, u, off, w[k] * phi(s));
        } else {
          add_elastic(S, u, sqrt(u), w[k] * phi(s));
        }
      }
      n++;
      p = q;
    }
  }
  return n;
}

/* The window of u in [u0, u1] (one regime): where phi(h + u) is above
   e^-45 of its largest value on the regime, s_p (returned). */
static double regime_window(double h, double u0, double u1, double *w0, double *w1)
{
  const double s_p = peak_of(h, u0, u1), L = sqrt(s_p * s_p + WINDOW_T2);
  *w0 = -L - h > u0 ? -L - h : u0;
  *w1 = L - h < u1 ? L - h : u1;
  return s_p;
}

/* The integrals for a shape with a >= 0 (0: no elastic summits), b =
   ratio a (may be +inf when a is), any h >= DC_GW_H_MIN. Each regime is
   integrated over its own Gaussian window (phi above e^-45 of its largest
   value on the regime), so each integral keeps its relative precision;
   the elastic-plastic and plastic regimes are skipped (returned as 0)
   where their largest phi is below e^-60 of phi's largest value over all
   u >= 0: they then add < 1e-21 of the force (their integrands exceed the
   elastic one by at most lambda c_h/Km (a h)^3/2 <~ 1e5 there). */
static void integrals(const dc_gw_plastic_shape *sh, double ratio, double h, dc_gw_plastic_sums *J)
{
  sums S = {0.0, 0.0, 0.0, 0.0, 0.0};
  int n = 0;
  J->n_panels = 0;
  if (h > 40.0) {   /* phi(h) below the subnormals: nothing touches */
    J->Je = J->Je12 = J->Jp = J->Jdp = J->JA = 0.0;
    return;
  }
  const double a = sh->a, b = sh->b;
  const double s_pk = h > 0.0 ? h : 0.0;
  const double skip2 = s_pk * s_pk + SKIP_T2;   /* a regime's peak s^2 beyond this: skipped */
  /* elastic-plastic regime, u in [a, b] */
  double p0 = 0.0, p1 = 0.0;
  const double s_ep = regime_window(h, a, b, &p0, &p1);
  /* narrower than the doubles resolve (1/a or 1/(b - a) overflows: b - a
     below 1e-302) it adds nothing: skipped */
  const int ep_fits = 1.0 / a <= DBL_MAX && 1.0 / (a * (ratio - 1.0)) <= DBL_MAX;
  const int ep_on = ep_fits && s_ep * s_ep <= skip2 && p0 < p1;
  /* fully plastic regime, u > b */
  const double s_pl = h + b > 0.0 ? h + b : 0.0;
  const int pl_on = b < HUGE_VAL && (ep_on || s_pl * s_pl <= skip2);
  /* elastic regime, u in [0, a] */
  double e0 = 0.0, e1 = 0.0;
  const double s_el = regime_window(h, 0.0, a, &e0, &e1);
  if (!ep_on && !pl_on && e1 < a) {
    /* all weight on elastic summits: gw_rough's closed form */
    double F[4];
    dc_gw_F_all(h, F);
    S.Je = F[DC_GW_F32];
    S.Je12 = F[DC_GW_F12];
    S.JA = F[DC_GW_F1];
  } else if (e0 < e1) {
    n += regime_panels(&S, NULL, h, s_el, e0, e1);
  }
  if (ep_on) {
    const double lr = log(ratio);
    const ep_consts kc = {a, sh->lambda - 1.0, sh->c_h, sh->c_h - sh->Km, 1.0 / lr,
                          1.0 / (ratio - 1.0), 1.0 / a, 1.0 / (a * (ratio - 1.0)), lr < 0.0625};
    n += regime_panels(&S, &kc, h, s_ep, p0, p1);
  }
  if (pl_on) {
    /* in closed form at x = h + b with its rounding d corrected to first
       order (F_0' = -phi, F_1' = -F_0): F_n is as sensitive as phi to its
       argument */
    double F[4];
    const double x = h + b, hh = x - b, d = (h - hh) + (b - (x - hh));
    dc_gw_F_all(x, F);
    const double F0 = F[DC_GW_F0] - phi(x) * d, F1 = F[DC_GW_F1] - F[DC_GW_F0] * d;
    const double tail_u = F1 + b * F0;
    S.Jp += sh->lambda * sh->c_h * tail_u;
    S.Jdp += sh->lambda * sh->c_h * F0;
    S.JA += sh->lambda * tail_u;
  }
  if (ratio == 1.0 && pl_on)
    /* no elastic-plastic range: f jumps at u = a from K_m a (elastic, in
       P_H units) to lambda c_h a, a point mass in f' */
    S.Jdp += (sh->lambda * sh->c_h - sh->Km) * a * phi_sum(h, a);
  J->Je = S.Je;
  J->Je12 = S.Je12;
  J->Jp = S.Jp;
  J->Jdp = S.Jdp;
  J->JA = S.JA;
  J->n_panels = n;
}

dc_gw_plastic_params dc_gw_plastic_default_params(double hardness, double nu)
{
  dc_gw_plastic_params p;
  p.hardness = hardness;
  p.K_v = 0.454 + 0.41 * nu;
  p.c_h = 1.0;
  p.c_A = 108.0;
  p.plastic_area = DC_GW_PLASTIC_AREA_JW;
  return p;
}

int dc_gw_plastic_check(const dc_gw_plastic_params *p, dc_param_error *err)
{
  int st;
  if ((st = dc_param_check("hardness", p->hardness, 0.0, 1, HUGE_VAL, 1, "(0, inf)", err))) return st;
  if ((st = dc_param_check("plasticityKv", p->K_v, 0.0, 1, HUGE_VAL, 1, "(0, inf)", err))) return st;
  if ((st = dc_param_check("plasticityCh", p->c_h, 2.0 / 3.0 * p->K_v, 0, HUGE_VAL, 1,
                           "[2/3 plasticityKv, inf)", err)))
    return st;
  if ((st = dc_param_check("plasticityCa", p->c_A, 2.0, 0, HUGE_VAL, 1, "[2, inf)", err))) return st;
  if (p->plastic_area != DC_GW_PLASTIC_AREA_JW && p->plastic_area != DC_GW_PLASTIC_AREA_TRUNCATED) {
    err->name = "plasticArea";
    err->value = p->plastic_area;
    err->range = "{0 (Jeng-Wang), 1 (truncation)}";
    return DC_EDOM;
  }
  return DC_OK;
}

static int params_ok(const dc_gw_plastic_params *p)
{
  dc_param_error e;
  return dc_gw_plastic_check(p, &e) == DC_OK;
}

int dc_gw_plastic_summit_init(const dc_hertz_geom *g, double Estar, const dc_gw_plastic_params *p,
                              dc_gw_plastic_summit *s)
{
  if (!(Estar > 0.0 && isfinite(Estar) && params_ok(p))) return DC_EDOM;
  dc_gw_plastic_summit t;
  /* lambda: JW 4 eps/beta = K/(K - D) (Eqs. 49, 12); truncation Eq. 42 */
  if (g->e2 == 0.0) {
    t.lambda = 2.0;   /* circle: both rules, exactly */
  } else if (p->plastic_area == DC_GW_PLASTIC_AREA_JW) {
    t.lambda = g->K / (g->K - g->D);
  } else {
    const double RR = g->R_major * g->R_minor;
    t.lambda = 2.0 * ((RR >= DBL_MIN && RR <= DBL_MAX ? sqrt(RR) : sqrt(g->R_major) * sqrt(g->R_minor)) / g->R_area);
  }
  if (!(t.lambda >= 1.0)) t.lambda = 1.0;   /* not reached (tested down to R_minor/R_major = 1e-12) */
  /* Eq. 41 for a summit: w1 = (pi K_v H/(2 E*))^2 R_area^2/R_force */
  double t1 = M_PI / 2.0 * p->K_v * (p->hardness / Estar) * (g->R_area / sqrt(g->R_force));
  if (isnan(t1)) t1 = M_PI / 2.0 * (p->K_v * (p->hardness / Estar)) * (g->R_area / sqrt(g->R_force));   /* inf x 0 */
  if (isnan(t1)) return DC_ERANGE;
  t.w1 = t1 * t1;
  /* w2 = (c_A/lambda) w1 (the plastic area at w2 is c_A times the Hertz
     area at w1); no elastic-plastic range where c_A <= lambda */
  t.ratio = p->c_A / t.lambda > 1.0 ? p->c_A / t.lambda : 1.0;
  t.w2 = t.w1 * t.ratio;
  t.Km = 2.0 / 3.0 * p->K_v;
  t.c_h = p->c_h;
  t.inv_log_ratio = t.ratio > 1.0 ? 1.0 / log(t.ratio) : 0.0;
  t.H = p->hardness;
  t.Estar = Estar;
  t.R_force = g->R_force;
  t.R_area = g->R_area;
  *s = t;
  return DC_OK;
}

/* The summit law at omega >= w1: A = pi R_area omega af, f = A H pf,
   df = pi R_area H dfac. */
static void plastic_factors(const dc_gw_plastic_summit *s, double omega, double *af, double *pf, double *dfac)
{
  const double rho = s->ratio;   /* w2/w1 */
  const double r = s->w1 > 0.0 ? omega / s->w1 : HUGE_VAL;
  if (r <= rho && rho > 1.0) {   /* elastic-plastic (ZMC form, see the header) */
    const double rm1 = rho - 1.0;
    const double x = (r - 1.0) / rm1;
    const double c = x * x * (3.0 - 2.0 * x);
    const double dP = s->c_h - s->Km;
    *af = 1.0 + (s->lambda - 1.0) * c;
    *pf = s->c_h - dP * (1.0 - log(r) * s->inv_log_ratio);
    *dfac = *af * *pf + (s->lambda - 1.0) * 6.0 * x * (1.0 - x) * r / rm1 * *pf + *af * dP * s->inv_log_ratio;
  } else {               /* fully plastic */
    *af = s->lambda;
    *pf = s->c_h;
    *dfac = s->c_h * s->lambda;
  }
}

int dc_gw_plastic_summit_law(const dc_gw_plastic_summit *s, double omega, double *f, double *area,
                             double *df)
{
  if (!isfinite(omega)) return DC_EDOM;
  double F, A, D;
  if (omega <= 0.0) {
    F = A = D = 0.0;
  } else if (omega < s->w1) {   /* elastic (Eqs. 1-2), as dc_hertz_contact */
    const double root = sqrt(s->R_force * omega);
    F = 4.0 / 3.0 * s->Estar * root * omega;
    D = 2.0 * s->Estar * root;
    A = M_PI * s->R_area * omega;
    const double sR = sqrt(s->R_force), so = sqrt(omega);
    if (!isfinite(F)) F = dc_scaled_product(5, (const double[]){4.0 / 3.0, s->Estar, sR, so, omega});
    if (!isfinite(D)) D = dc_scaled_product(4, (const double[]){2.0, s->Estar, sR, so});
    if (!isfinite(A)) A = dc_scaled_product(3, (const double[]){M_PI, s->R_area, omega});
  } else {
    double af, pf, dfac;
    plastic_factors(s, omega, &af, &pf, &dfac);
    A = M_PI * s->R_area * omega * af;
    F = A * s->H * pf;
    D = M_PI * s->R_area * s->H * dfac;
    if (!isfinite(A)) A = dc_scaled_product(4, (const double[]){M_PI, s->R_area, omega, af});
    if (!isfinite(F)) F = dc_scaled_product(6, (const double[]){M_PI, s->R_area, omega, af, s->H, pf});
    if (!isfinite(D)) D = dc_scaled_product(4, (const double[]){M_PI, s->R_area, s->H, dfac});
  }
  if (!(isfinite(F) && isfinite(A) && isfinite(D))) return DC_ERANGE;
  *f = F;
  *area = A;
  *df = D;
  return DC_OK;
}

int dc_gw_plastic_integrals(const dc_gw_plastic_shape *sh, double h, dc_gw_plastic_sums *J)
{
  if (!(sh->a > 0.0 && isfinite(sh->a) && sh->b >= sh->a && isfinite(sh->b) &&
        sh->lambda >= 1.0 && isfinite(sh->lambda) && sh->Km > 0.0 && sh->c_h >= sh->Km &&
        isfinite(sh->c_h) && isfinite(h) && h >= DC_GW_H_MIN))
    return DC_EDOM;
  dc_gw_plastic_sums t;
  integrals(sh, sh->b / sh->a, h, &t);
  if (!(isfinite(t.Je) && isfinite(t.Je12) && isfinite(t.Jp) && isfinite(t.Jdp) && isfinite(t.JA))) return DC_ERANGE;
  *J = t;
  return DC_OK;
}

/* The rough sum for a summit law s, roughness sigma > 0 and h = -delta/sigma:
   J with the prefactors left to the caller. Jp and Jdp are linear in
   (Km, c_h): where they overflow (c_h near the largest doubles) they are
   taken with both scaled down; returns the factor Jp, Jdp need (1 or 2^600). */
static double rough_sums(const dc_gw_plastic_summit *s, double sigma, double h, dc_gw_plastic_sums *J)
{
  dc_gw_plastic_shape sh;
  sh.a = s->w1 / sigma;
  sh.b = sh.a * s->ratio;
  if (!(sh.b < HUGE_VAL)) sh.b = HUGE_VAL;
  sh.lambda = s->lambda;
  sh.Km = s->Km;
  sh.c_h = s->c_h;
  integrals(&sh, s->ratio, h, J);
  if (isfinite(J->Jp) && isfinite(J->Jdp)) return 1.0;
  sh.Km = ldexp(s->Km, -600);
  sh.c_h = ldexp(s->c_h, -600);
  integrals(&sh, s->ratio, h, J);
  return 0x1p600;
}

static int state_finite(const dc_gw_rough_state *s)
{
  return isfinite(s->F) && isfinite(s->kn) && isfinite(s->area);
}

int dc_gw_rough_plastic(const dc_hertz_geom *g, double Estar, const dc_gw_plastic_params *p,
                        double n_asp, double sigma, double delta, dc_gw_rough_state *out)
{
  if (!(Estar > 0.0 && isfinite(Estar) && n_asp > 0.0 && isfinite(n_asp) && sigma >= 0.0 &&
        isfinite(sigma) && isfinite(delta) && params_ok(p)))
    return DC_EDOM;
  dc_gw_plastic_summit sm;
  int st = dc_gw_plastic_summit_init(g, Estar, p, &sm);
  if (st != DC_OK) return st;
  dc_gw_rough_state s;
  if (sigma <= 1e-80 * fabs(delta) || sigma == 0.0) {
    /* smooth limit: n_asp summits at delta */
    if (delta <= 0.0) {
      s.F = s.area = s.kn = 0.0;
      s.h = 1e300;
    } else {
      s.h = -1e300;
      if (delta < sm.w1) {   /* exactly gw_rough's smooth path */
        dc_hertz_state hs;
        st = dc_hertz_contact(g, Estar, delta, &hs);
        s.F = n_asp * hs.F;
        s.kn = n_asp * hs.kn;
        s.area = n_asp * hs.area;
        if (st != DC_OK || !state_finite(&s)) {
          const double sR = sqrt(g->R_force), sd = sqrt(delta);
          s.F = dc_scaled_product(6, (const double[]){n_asp, 4.0 / 3.0, Estar, sR, sd, delta});
          s.kn = dc_scaled_product(5, (const double[]){n_asp, 2.0, Estar, sR, sd});
          s.area = dc_scaled_product(4, (const double[]){n_asp, M_PI, g->R_area, delta});
        }
      } else {
        double f, A, D;
        st = dc_gw_plastic_summit_law(&sm, delta, &f, &A, &D);
        if (st == DC_OK) {
          s.F = n_asp * f;
          s.kn = n_asp * D;
          s.area = n_asp * A;
        }
        if (st != DC_OK || !state_finite(&s)) {
          /* one summit's results, or n_asp times them, out of the doubles:
             n_asp inside the scaled products */
          double af, pf, dfac;
          plastic_factors(&sm, delta, &af, &pf, &dfac);
          s.F = dc_scaled_product(7, (const double[]){n_asp, M_PI, sm.R_area, delta, af, sm.H, pf});
          s.kn = dc_scaled_product(5, (const double[]){n_asp, M_PI, sm.R_area, sm.H, dfac});
          s.area = dc_scaled_product(5, (const double[]){n_asp, M_PI, sm.R_area, delta, af});
        }
      }
    }
  } else {
    const double h = -delta / sigma;
    if (h < DC_GW_H_MIN) return DC_ERANGE;  /* unreachable: sigma > 1e-80 |delta| */
    dc_gw_plastic_sums J;
    const double cs = rough_sums(&sm, sigma, h, &J);
    const double sRc = sqrt(g->Rc), ss = sqrt(sigma), H = p->hardness;
    /* elastic summits as dc_gw_rough_elliptic, plastic ones with P_H */
    const double Fe = n_asp * 4.0 / 3.0 * Estar * sRc * sigma * ss * g->gamma * J.Je;
    const double ke = n_asp * 2.0 * Estar * sRc * ss * g->gamma * J.Je12;
    const double Fp = n_asp * M_PI * g->Rc * sigma * g->beta * H * J.Jp * cs;
    const double kp = n_asp * M_PI * g->Rc * g->beta * H * J.Jdp * cs;
    s.F = Fe + Fp;
    s.kn = ke + kp;
    s.area = n_asp * M_PI * g->Rc * sigma * g->beta * J.JA;
    s.h = h;
    if (!state_finite(&s) || (s.F == 0.0 && (J.Je > 0.0 || J.Jp > 0.0))) {
      /* a product left the range of doubles: scaled products, summed in
         the larger term's scale */
      const double fe = dc_scaled_product(8, (const double[]){n_asp, 4.0 / 3.0, Estar, sRc, sigma, ss, g->gamma, J.Je});
      const double fp = dc_scaled_product(8, (const double[]){n_asp, M_PI, g->Rc, sigma, g->beta, H, J.Jp, cs});
      const double ge = dc_scaled_product(7, (const double[]){n_asp, 2.0, Estar, sRc, ss, g->gamma, J.Je12});
      const double gp = dc_scaled_product(7, (const double[]){n_asp, M_PI, g->Rc, g->beta, H, J.Jdp, cs});
      s.F = fe + fp;
      s.kn = ge + gp;
      s.area = dc_scaled_product(6, (const double[]){n_asp, M_PI, g->Rc, sigma, g->beta, J.JA});
    }
  }
  if (!state_finite(&s)) return DC_ERANGE;
  *out = s;
  return DC_OK;
}

int dc_gw_plastic_flat(const dc_gw_plastic_params *p, double Estar, double R_s, double eta,
                       double sigma, double delta, dc_gw_plastic_flat_state *st)
{
  if (!(Estar > 0.0 && isfinite(Estar) && R_s > 0.0 && isfinite(R_s) && eta > 0.0 && isfinite(eta) &&
        sigma > 0.0 && isfinite(sigma) && isfinite(delta) && params_ok(p)))
    return DC_EDOM;
  const double h = -delta / sigma;
  if (!(h >= DC_GW_H_MIN)) return DC_EDOM;
  if (!isfinite(h)) return DC_ERANGE;   /* d/sigma itself overflows */
  dc_hertz_geom g;
  int rc = dc_hertz_geometry(R_s, R_s, &g);
  if (rc != DC_OK) return rc;
  dc_gw_plastic_summit sm;
  if ((rc = dc_gw_plastic_summit_init(&g, Estar, p, &sm)) != DC_OK) return rc;
  dc_gw_plastic_sums J;
  const double cs = rough_sums(&sm, sigma, h, &J);
  const double sR = sqrt(R_s), ss = sqrt(sigma), H = p->hardness;
  dc_gw_plastic_flat_state t;
  t.p = eta * (4.0 / 3.0 * Estar * sR * sigma * ss * J.Je + M_PI * R_s * sigma * H * J.Jp * cs);
  t.dp = eta * (2.0 * Estar * sR * ss * J.Je12 + M_PI * R_s * H * J.Jdp * cs);
  t.area_ratio = eta * M_PI * R_s * sigma * J.JA;
  t.h = h;
  if (!(isfinite(t.p) && isfinite(t.dp) && isfinite(t.area_ratio)) || (t.p == 0.0 && (J.Je > 0.0 || J.Jp > 0.0))) {
    /* a product left the range of doubles: scaled products (as dc_gw_rough_plastic) */
    t.p = dc_scaled_product(7, (const double[]){eta, 4.0 / 3.0, Estar, sR, sigma, ss, J.Je}) +
          dc_scaled_product(7, (const double[]){eta, M_PI, R_s, sigma, H, J.Jp, cs});
    t.dp = dc_scaled_product(6, (const double[]){eta, 2.0, Estar, sR, ss, J.Je12}) +
           dc_scaled_product(6, (const double[]){eta, M_PI, R_s, H, J.Jdp, cs});
    t.area_ratio = dc_scaled_product(5, (const double[]){eta, M_PI, R_s, sigma, J.JA});
  }
  if (!(isfinite(t.p) && isfinite(t.dp) && isfinite(t.area_ratio))) return DC_ERANGE;
  *st = t;
  return DC_OK;
}
