/* Classical normal laws of the lecture notes (dc/classical_normal.h). */
#include "dc/classical_normal.h"
#include "dc/hertz_elliptic.h"
#include "dc/status.h"
#include <float.h>
#include <math.h>

const dc_history_field dc_classical_normal_history[DC_CLASSICAL_NORMAL_NFIELDS] = {
  {"classical_delta_max", 0},
};

/* An integer setting in [0, hi]. */
static int setting_check(const char *name, int v, int hi, const char *range, dc_param_error *err)
{
  if (v >= 0 && v <= hi) return DC_OK;
  err->name = name;
  err->value = (double)v;
  err->range = range;
  return DC_EDOM;
}

static int uses_e(const dc_classical_normal_params *p)
{
  switch (p->law) {
  case DC_CLASSICAL_LSD: case DC_CLASSICAL_HLS_CONSTANT: return 1;
  case DC_CLASSICAL_HERTZ: return p->damping == DC_DAMPING_RESTITUTION || p->damping == DC_DAMPING_TSUJI;
  default: return 0;
  }
}

int dc_classical_normal_check(const dc_classical_normal_params *p, dc_param_error *err)
{
  int st = setting_check("classicalNormal", p->law, 3, "{0 lsd, 1 hertz, 2 hls_constant, 3 hls_variable}", err);
  if (st) return st;
  if ((st = setting_check("limitForce", p->limit, 1, "{0, 1}", err))) return st;
  const int hertz = p->law == DC_CLASSICAL_HERTZ;
  if (!hertz) {
    if ((st = setting_check("classicalStiffness", p->stiffness, 3,
                            "{0 given, 1 duration, 2 overlap, 3 energy}", err)))
      return st;
    if (p->law == DC_CLASSICAL_HLS_VARIABLE && p->stiffness == DC_CLASSICAL_K_DURATION)
      return setting_check("classicalStiffness", p->stiffness, -1,
                           "{0 given, 2 overlap, 3 energy} with hls_variable", err);
    if (p->stiffness == DC_CLASSICAL_K_GIVEN) {
      if ((st = dc_param_check("kn", p->kn, 0.0, 1, DBL_MAX, 0, "(0, inf)", err))) return st;
    } else {
      if ((st = dc_param_check("youngsModulus", p->Estar, 0.0, 1, DBL_MAX, 0, "E* in (0, inf)", err)))
        return st;
      if ((st = dc_param_check("characteristicVelocity", p->v_char, 0.0, 1, DBL_MAX, 0, "(0, inf)", err)))
        return st;
    }
  } else {
    if ((st = setting_check("damping", p->damping, 4,
                            "{0 restitution, 1 viscoelastic, 2 kuwabara_kono, 3 tsuji, 4 none}", err)))
      return st;
    if ((st = dc_param_check("youngsModulus", p->Estar, 0.0, 1, DBL_MAX, 0, "E* in (0, inf)", err))) return st;
    if (p->damping == DC_DAMPING_VISCOELASTIC &&
        (st = dc_param_check("viscoelasticTime", p->A, 0.0, 0, DBL_MAX, 0, "[0, inf)", err)))
      return st;
    if (p->damping == DC_DAMPING_KUWABARA_KONO &&
        (st = dc_param_check("kuwabaraKonoDamping", p->eta_kk, 0.0, 0, DBL_MAX, 0, "[0, inf)", err)))
      return st;
  }
  if (uses_e(p) && (st = dc_param_check("coefficientRestitution", p->e, 0.0, 1, 1.0, 0, "(0, 1]", err)))
    return st;
  if (p->law == DC_CLASSICAL_HLS_VARIABLE &&
      (st = dc_param_check("unloadingStiffnessSlope", p->S, 0.0, 0, DBL_MAX, 0, "[0, inf)", err)))
    return st;
  return DC_OK;
}

/* x = -ln e / pi >= 0 (1/|beta| of the notes). */
static double log_ratio(double e) { return -log(e) / M_PI; }

int dc_classical_normal_init(const dc_classical_normal_params *p, dc_classical_normal *m,
                             dc_param_error *err)
{
  int st = dc_classical_normal_check(p, err);
  if (st) return st;
  dc_classical_normal r;
  r.p = *p;
  r.kc = 0.0;
  r.matched = 0;
  r.zeta = 0.0;
  r.dcoef = 0.0;
  r.ku_ratio = 1.0;
  if (p->law == DC_CLASSICAL_HERTZ) {
    if (p->damping == DC_DAMPING_RESTITUTION) dc_damping_beta(p->e, &r.dcoef);
    else if (p->damping == DC_DAMPING_TSUJI) dc_damping_tsuji_alpha(p->e, &r.dcoef);
    else if (p->damping == DC_DAMPING_VISCOELASTIC) r.dcoef = p->A;
    else if (p->damping == DC_DAMPING_KUWABARA_KONO) r.dcoef = p->eta_kk;
  } else {
    const int lsd = p->law == DC_CLASSICAL_LSD;
    if (p->stiffness == DC_CLASSICAL_K_GIVEN) {
      r.kc = p->kn;
    } else {
      const double x = lsd ? log_ratio(p->e) : 0.0;
      double c = DC_CLASSICAL_MATCH_OVERLAP;
      if (p->stiffness == DC_CLASSICAL_K_DURATION)
        c = lsd ? DC_CLASSICAL_MATCH_DURATION * (1.0 + x * x)
                : 0.25 * DC_CLASSICAL_MATCH_DURATION * (1.0 + p->e) * (1.0 + p->e);
      else if (p->stiffness == DC_CLASSICAL_K_OVERLAP && lsd && x > 0.0)
        c *= exp(-2.0 * x * atan(1.0 / x));   /* exp(-2 atan(b)/b), b = 1/x */
      /* c (v E*^2)^2/5; from logarithms where v E*^2 is out of range */
      const double q = p->v_char * p->Estar * p->Estar;
      if (q >= DBL_MIN && q <= DBL_MAX) r.kc = c * pow(q, 0.4);
      else r.kc = exp(log(c) + 0.4 * log(p->v_char) + 0.8 * log(p->Estar));
      if (!(r.kc > 0.0 && r.kc <= DBL_MAX)) {
        err->name = "youngsModulus";
        err->value = p->Estar;
        err->range = "c (characteristicVelocity E*^2)^2/5 representable";
        return DC_ERANGE;
      }
      r.matched = 1;
    }
    if (lsd) {
      double beta;
      dc_damping_beta(p->e, &beta);
      r.zeta = -2.0 * beta;   /* eta = -2 ln e (m K)^1/2 / (ln^2 e + pi^2)^1/2 */
    } else if (p->law == DC_CLASSICAL_HLS_CONSTANT) {
      r.ku_ratio = 1.0 / (p->e * p->e);
      if (!(r.ku_ratio <= DBL_MAX)) {
        err->name = "coefficientRestitution";
        err->value = p->e;
        err->range = "1/e^2 representable";
        return DC_ERANGE;
      }
    }
  }
  *m = r;
  return DC_OK;
}

static int finite_pos(double x) { return x > 0.0 && x <= DBL_MAX; }

/* K = kc (R^2 m)^1/5 for a matched stiffness, else kc (LSD, HLS). */
static int linear_stiffness(const dc_classical_normal *m, double R, double meff, double *K)
{
  if (!m->matched) { *K = m->kc; return DC_OK; }
  const double q = R * R * meff;
  double k;
  if (q >= DBL_MIN && q <= DBL_MAX) k = m->kc * pow(q, 0.2);
  else k = exp(log(m->kc) + 0.2 * (2.0 * log(R) + log(meff)));
  if (!finite_pos(k)) return DC_ERANGE;
  *K = k;
  return DC_OK;
}

int dc_classical_normal_stiffness(const dc_classical_normal *m, double R, double meff, double *K)
{
  if (!finite_pos(R) || !finite_pos(meff)) return DC_EDOM;
  if (m->p.law == DC_CLASSICAL_HERTZ) {
    /* K_HZ = 4/3 E* R^1/2 */
    const double k = 4.0 / 3.0 * m->p.Estar * sqrt(R);
    if (!finite_pos(k)) return DC_ERANGE;
    *K = k;
    return DC_OK;
  }
  return linear_stiffness(m, R, meff, K);
}

int dc_classical_normal_step(const dc_classical_normal *m, double R, double meff, double delta,
                             double ddelta, dc_classical_normal_state *h, dc_classical_normal_out *out)
{
  if (!finite_pos(R) || !finite_pos(meff) || !isfinite(delta) || !isfinite(ddelta)) return DC_EDOM;
  const double dmax0 = h->delta_max;
  if (!(dmax0 >= 0.0 && dmax0 <= DBL_MAX)) return DC_EDOM;
  dc_classical_normal_out o;
  if (delta <= 0.0) {
    o.c.F = o.c.kn = o.c.area = o.c.a = o.c.b = o.c.F_bound = 0.0;
    o.c.formed = 0;
    o.gamma = o.F = 0.0;
    o.K = 0.0;
    h->delta_max = 0.0;
    *out = o;
    return DC_OK;
  }
  double F, kn, gamma = 0.0, K, dmax = dmax0;
  switch (m->p.law) {
  case DC_CLASSICAL_LSD: {
    /* notes LSDn: F = K delta + eta ddelta, eta = zeta (m K)^1/2 */
    int st = linear_stiffness(m, R, meff, &K);
    if (st) return st;
    F = K * delta;
    kn = K;
    gamma = m->zeta * sqrt(meff * K);
    if (!isfinite(gamma)) gamma = m->zeta * (sqrt(meff) * sqrt(K));
    break;
  }
  case DC_CLASSICAL_HERTZ: {
    /* notes NSDn: F = K_HZ delta^3/2 + gamma ddelta (dc/damping.h) */
    double kn_sec, S;
    dc_hertz_stiffness(m->p.Estar, R, delta, &kn_sec, &S);
    if (!isfinite(S)) {   /* R delta out of range: the root as a product */
      const double root = sqrt(R) * sqrt(delta);
      S = 2.0 * m->p.Estar * root;
      kn_sec = 4.0 / 3.0 * m->p.Estar * root;
    }
    F = kn_sec * delta;
    kn = S;
    K = 4.0 / 3.0 * m->p.Estar * sqrt(R);
    gamma = dc_damping_gamma(m->p.damping, m->dcoef, S, delta, meff);
    if (!isfinite(gamma) && m->p.damping == DC_DAMPING_RESTITUTION)
      gamma = -2.0 * 0.91287092917527685576 * m->dcoef * (sqrt(S) * sqrt(meff));
    else if (!isfinite(gamma) && m->p.damping == DC_DAMPING_TSUJI)
      gamma = m->dcoef * (sqrt(2.0 / 3.0 * S) * sqrt(meff));
    break;
  }
  default: {
    /* Walton-Braun: F = max(0, K_L delta_max + K_U (delta - delta_max)),
       the unloading line through (delta_max, K_L delta_max) */
    int st = linear_stiffness(m, R, meff, &K);
    if (st) return st;
    if (delta > dmax) dmax = delta;
    double KU = K * m->ku_ratio;
    if (m->p.law == DC_CLASSICAL_HLS_VARIABLE) {
      const double Sd = m->p.S * dmax;   /* may overflow where K_L S delta_max does not */
      KU = isfinite(Sd) ? K * (1.0 + Sd) : K * m->p.S * dmax;
    }
    if (!(KU <= DBL_MAX)) return DC_ERANGE;
    F = K * dmax + KU * (delta - dmax);
    if (delta == dmax) { F = K * delta; kn = K; }
    else if (F > 0.0) kn = KU;
    else { F = 0.0; kn = 0.0; }
    break;
  }
  }
  const double Rd = R * delta;
  double a = (Rd >= DBL_MIN && Rd <= DBL_MAX) ? sqrt(Rd) : sqrt(R) * sqrt(delta);
  double area = M_PI * a * a;
  double Ftot = F + gamma * ddelta;
  if (m->p.limit && Ftot < 0.0) Ftot = 0.0;
  if (!isfinite(F) || !isfinite(kn) || !isfinite(gamma) || !isfinite(Ftot) || !isfinite(area) || !isfinite(K))
    return DC_ERANGE;
  o.c.F = F;
  o.c.kn = kn;
  o.c.area = area;
  o.c.a = o.c.b = a;
  o.c.F_bound = F > 0.0 ? F : 0.0;
  o.c.formed = 1;
  o.gamma = gamma;
  o.F = Ftot;
  o.K = K;
  h->delta_max = m->p.law >= DC_CLASSICAL_HLS_CONSTANT ? dmax : 0.0;
  *out = o;
  return DC_OK;
}

int dc_classical_lsd_collision(double K, double eta, double meff, double v0, int limit,
                               dc_classical_collision *c)
{
  if (!finite_pos(K) || !finite_pos(meff) || !finite_pos(v0) || !(eta >= 0.0) || !isfinite(eta) ||
      (limit != 0 && limit != 1))
    return DC_EDOM;
  /* with psi = eta/(2m) and W = (K/m - psi^2)^1/2 in units free of the
     scales (no intermediate leaves the doubles where the figures do not):
     z = psi (m/K)^1/2 = eta / (2 (m K)^1/2), t0 = (m/K)^1/2, W t0 = s */
  const double z = fabs(eta) / (2.0 * (sqrt(meff) * sqrt(K)));   /* eta = -0 as 0 (atan2 below) */
  if (!(z < 1.0)) return DC_EDOM;   /* not underdamped */
  const double q = meff / K, t0 = q >= DBL_MIN && q <= DBL_MAX ? sqrt(q) : sqrt(meff) / sqrt(K);
  const double s = sqrt((1.0 - z) * (1.0 + z));
  const double r = z / s;   /* psi/W = 1/|beta| */
  dc_classical_collision o;
  /* delta = v0/W exp(-psi t) sin(W t): maximum at W t = atan(W/psi),
     where sin(W t) = s */
  const double wm = atan2(s, z);
  o.dmax = v0 * t0 * exp(-r * wm);
  o.Fmax = 0.0;
  o.dres = 0.0;
  if (!limit) {
    /* delta = 0 at W Tc = pi; rebound v0 exp(-psi pi/W) */
    o.Tc = M_PI * t0 / s;
    o.e = exp(-M_PI * r);
  } else {
    /* F = K delta + eta ddelta = 0: tan(W t) = -eta W / (K - eta psi) = -2 z s / (1 - 2 z^2) */
    const double th = atan2(2.0 * z * s, -(1.0 - 2.0 * z * z));
    o.Tc = th * t0 / s;
    o.e = fabs(exp(-r * th) * (cos(th) - r * sin(th)));
  }
  if (!isfinite(o.Tc) || !isfinite(o.dmax) || !isfinite(o.e)) return DC_ERANGE;
  *c = o;
  return DC_OK;
}

int dc_classical_hertz_collision(double Khz, double meff, double v0, dc_classical_collision *c)
{
  if (!finite_pos(Khz) || !finite_pos(meff) || !finite_pos(v0)) return DC_EDOM;
  /* 1/2 m v0^2 = 2/5 K_HZ delta_max^5/2; Tc = 2 delta_max/v0 int_0^1 (1 - x^5/2)^-1/2 dx */
  const double I = 1.4716375921623523287;   /* pi^1/2 Gamma(7/5) / Gamma(9/10) */
  dc_classical_collision o;
  o.dmax = exp(0.4 * (log(1.25) + log(meff) + 2.0 * log(v0) - log(Khz)));
  o.Tc = 2.0 * I * o.dmax / v0;
  if (!isfinite(o.Tc)) o.Tc = 2.0 * I * (o.dmax / v0);   /* 2 I delta_max overflowed */
  o.e = 1.0;
  o.Fmax = Khz * o.dmax * sqrt(o.dmax);
  o.dres = 0.0;
  if (!isfinite(o.Tc) || !isfinite(o.Fmax) || !(o.dmax > 0.0)) return DC_ERANGE;
  *c = o;
  return DC_OK;
}

int dc_classical_hls_collision(int law, double KL, double x, double meff, double v0,
                               dc_classical_collision *c)
{
  if (!finite_pos(KL) || !finite_pos(meff) || !finite_pos(v0) || !isfinite(x)) return DC_EDOM;
  dc_classical_collision o;
  /* (m/K_L)^1/2 and (m K_L)^1/2, from the roots where the quotient or product leaves the doubles */
  const double q = meff / KL, mk = meff * KL;
  const double w = q >= DBL_MIN && q <= DBL_MAX ? sqrt(q) : sqrt(meff) / sqrt(KL);
  o.dmax = v0 * w;
  o.Fmax = v0 * (mk >= DBL_MIN && mk <= DBL_MAX ? sqrt(mk) : sqrt(meff) * sqrt(KL));
  if (law == DC_CLASSICAL_HLS_CONSTANT) {
    if (!(x > 0.0 && x <= 1.0)) return DC_EDOM;
    o.e = x;
  } else if (law == DC_CLASSICAL_HLS_VARIABLE) {
    if (!(x >= 0.0)) return DC_EDOM;
    /* (K_L / (K_L + S F_max))^1/2; S delta_max alone may overflow */
    const double Sd = x * o.dmax;
    o.e = isfinite(Sd) ? 1.0 / sqrt(1.0 + Sd) : 1.0 / (sqrt(x) * sqrt(o.dmax));
  } else {
    return DC_EDOM;
  }
  o.Tc = 0.5 * M_PI * w * (1.0 + o.e);
  o.dres = o.dmax * (1.0 - o.e * o.e);
  if (!isfinite(o.Tc) || !isfinite(o.dmax) || !isfinite(o.Fmax) || !isfinite(o.e)) return DC_ERANGE;
  *c = o;
  return DC_OK;
}
