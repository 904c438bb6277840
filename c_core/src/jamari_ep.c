/* Jamari-Schipper elastic-plastic elliptic contact with elastic unloading
   (review Eqs. 41-46; the unloading branch and the seed corrections are
   described in dc/jamari_ep.h). */
#include "dc/jamari_ep.h"
#include "dc/status.h"
#include "scaled_product.h"
#include <float.h>
#include <math.h>

const dc_history_field dc_jamari_history[DC_JAMARI_HISTORY_NFIELDS] = {
  {"jamari_delta_max", 0}, {"jamari_delta_res", 0}, {"jamari_F_max", 0}, {"jamari_area_max", 0},
};

int dc_jamari_check(const dc_jamari_params *p, dc_param_error *err)
{
  int st = dc_param_check("hardness", p->H, 0.0, 1, INFINITY, 1, "(0, inf)", err);
  if (st == DC_OK) st = dc_param_check("plasticityKv", p->K_v, 0.0, 1, INFINITY, 1, "(0, inf)", err);
  if (st == DC_OK)
    st = dc_param_check("plasticityCh", p->c_h, 2.0 / 3.0 * p->K_v, 0, INFINITY, 1, "[2/3 plasticityKv, inf)", err);
  if (st == DC_OK) st = dc_param_check("plasticityCa", p->c_A, 2.0, 0, INFINITY, 1, "[2, inf)", err);
  /* the yield pressures K_v H and c_h H must be doubles */
  if (st == DC_OK)
    st = dc_param_check("hardness", p->H, 0.0, 1, DBL_MAX / (p->c_h > p->K_v ? p->c_h : p->K_v), 0,
                        "(0, DBL_MAX / max(plasticityKv, plasticityCh)]", err);
  return st;
}

static int params_ok(const dc_jamari_params *p)
{
  return p->H > 0.0 && p->H <= DBL_MAX && p->K_v > 0.0 && p->K_v <= DBL_MAX &&
         p->c_h >= 2.0 / 3.0 * p->K_v && p->c_h <= DBL_MAX && p->c_A >= 2.0 && p->c_A <= DBL_MAX;
}

/* What the loading curve needs beyond the Hertz geometry. */
typedef struct {
  double d1, d2;    /* delta_n1 (Eq. 41), delta_n2 (Eq. 44, >= d1) */
  double q;         /* c_A rho = delta_n2/delta_n1 before the raise to d1 */
  double ce;        /* pi R_area: Hertz area per overlap (Eq. 2) */
  double ap;        /* 1/rho = truncation area / Hertz area (Eq. 42 / Eq. 2) */
  double p1, dp;    /* 2/3 K_v H and (c_h - 2/3 K_v) H */
} onsets;

/* Eq. 41 into o->d1 (all the elastic regime needs). DC_ERANGE where K_v H
   or c_h H overflows. */
static int get_d1(const dc_hertz_geom *g, double Estar, const dc_jamari_params *p, onsets *o)
{
  const double KH = p->K_v * p->H, cH = p->c_h * p->H;
  if (!(KH <= DBL_MAX && cH <= DBL_MAX)) return DC_ERANGE;
  /* second printed form: 2 Rc E K (K_v H/E*)^2 */
  const double HE = p->H / Estar, h = p->K_v * HE;
  o->d1 = 2.0 * g->Rc * g->E * g->K * (h * h);
  if (!(HE >= DBL_MIN && h >= DBL_MIN && h <= DBL_MAX && o->d1 >= DBL_MIN && o->d1 <= DBL_MAX)) {
    /* an intermediate or the result left the range: mantissas multiplied,
       exponents summed, one scaling at the end (inf: no yield within the
       doubles; below DBL_MIN: DC_ERANGE beyond it) */
    const double num[8] = {2.0, g->Rc, g->E, g->K, p->K_v, p->K_v, p->H, p->H};
    double m = 1.0;
    int e = 0, k;
    for (int i = 0; i < 8; i++) {
      m *= frexp(num[i], &k);
      e += k;
      m = frexp(m, &k);
      e += k;
    }
    for (int i = 0; i < 2; i++) {
      m /= frexp(Estar, &k);
      e -= k;
      m = frexp(m, &k);
      e += k;
    }
    o->d1 = ldexp(m, e);
  }
  return DC_OK;
}

/* The rest: Eq. 44, the area factors, the yield pressures. */
static void get_rest(const dc_hertz_geom *g, const dc_jamari_params *p, onsets *o)
{
  /* rho = Rc beta / (2 (R_major R_minor)^1/2) = R_area / (2 (R_major R_minor)^1/2) */
  const double prod = g->R_major * g->R_minor;
  const double gm = g->R_major == g->R_minor ? g->R_major
                    : prod >= DBL_MIN && prod <= DBL_MAX ? sqrt(prod) : sqrt(g->R_major) * sqrt(g->R_minor);
  const double rho = g->R_area / (2.0 * gm);
  o->q = p->c_A * rho;                                          /* Eq. 44 */
  o->d2 = o->q > 1.0 ? o->q * o->d1 : o->d1;
  o->ce = M_PI * g->R_area;
  o->ap = 1.0 / rho;
  o->p1 = 2.0 / 3.0 * (p->K_v * p->H);
  o->dp = fmax(0.0, p->c_h * p->H - o->p1);
}

/* By-products of the plastic branches for the residual overlap. */
typedef struct {
  double ex;   /* A / A_Hertz - 1 at delta */
  double A1;   /* F / (2/3 K_v H A_Hertz) - 1 = (1 + ex) pm/p1 - 1 */
  double l;    /* ln(delta/delta_n1); -1: not formed (fully plastic) */
} plastic_aux;

/* Eqs. 45-46 (d1 < delta < d2) and 42-43 (delta >= d2): force, slope, area,
   semi-axes; delta > d1 >= DBL_MIN. DC_ERANGE if a result overflows. */
static int plastic_contact(const dc_hertz_geom *g, const dc_jamari_params *p, const onsets *o, double delta,
                           dc_contact *c, plastic_aux *aux)
{
  double pm, kn, ratio, ex, pi1;   /* mean pressure, dF/d delta, A/A_Hertz, ratio - 1, pm/p1 - 1 */
  double l = -1.0;   /* ln(delta/d1), formed where needed (-1: not yet) */
  if (delta >= o->d2) {
    /* Eqs. 42-43: A = 2 pi (R_i R_j)^1/2 delta = ap ce delta, F = c_h H A */
    ratio = o->ap;
    ex = o->ap - 1.0;
    pm = p->c_h * p->H;
    pi1 = o->dp / o->p1;
    kn = o->ce * o->ap * pm;
  } else {
    /* Eqs. 45-46 with t = (delta - d1)/(d2 - d1), ln(delta/d1)/ln(d2/d1),
       formed as at delta = d2 (t = 1 and the ratio of logs = 1 there) */
    const double span = o->d2 - o->d1;
    const double t = fmin(1.0, (delta - o->d1) / span);
    const double w = t * t * (3.0 - 2.0 * t), dw = 6.0 * t * (1.0 - t);
    const double L = log1p(span / o->d1);
    const double k = o->ap - 1.0;
    l = log1p((delta - o->d1) / o->d1);   /* from the exact difference: full precision near d1 */
    const double s = fmin(1.0, l / L);
    pm = o->p1 + o->dp * s;                                      /* Eq. 45 bracket */
    pi1 = o->dp / o->p1 * s;
    ex = k * w;
    ratio = 1.0 + ex;                                            /* Eq. 46 / (pi Rc beta delta) */
    /* dF/d delta = ce [(1 + k (w + delta w'/(d2 - d1))) pm + ratio dp/L] */
    kn = o->ce * ((1.0 + k * (w + delta / span * dw)) * pm + ratio * (o->dp / L));
  }
  double area = o->ce * delta * ratio;
  double F = area * pm;
  double a = sqrt(2.0 * g->R_major * delta * g->D / g->K * ratio);
  /* where an intermediate product left the range: the same without that */
  if (!(isfinite(area) && area >= DBL_MIN)) area = dc_scaled_product(3, (const double[]){o->ce, delta, ratio});
  if (!(isfinite(F) && F >= DBL_MIN)) F = dc_scaled_product(4, (const double[]){o->ce, delta, ratio, pm});
  if (!isfinite(a))
    a = dc_scaled_product(3, (const double[]){sqrt(2.0 * g->D / g->K * ratio), sqrt(g->R_major), sqrt(delta)});
  if (!(isfinite(F) && isfinite(kn) && isfinite(area) && isfinite(a))) return DC_ERANGE;
  c->F = c->F_bound = F;
  c->kn = kn;
  c->area = area;
  c->a = a;
  c->b = a * sqrt(g->m1);
  c->formed = 1;
  aux->ex = ex;
  aux->A1 = ex + ratio * pi1;
  aux->l = l;
  return DC_OK;
}

/* The loading curve beyond d1 (Eqs. 45-46, 42-43); o complete. */
static int loading_plastic(const dc_hertz_geom *g, const dc_jamari_params *p, const onsets *o, double delta,
                           dc_contact *c, plastic_aux *aux)
{
  if (!(o->d1 >= DBL_MIN)) return DC_ERANGE;
  return plastic_contact(g, p, o, delta, c, aux);
}

static int inputs_ok(double Estar, const dc_jamari_params *p, double delta)
{
  return Estar > 0.0 && Estar <= DBL_MAX && isfinite(delta) && params_ok(p);
}

int dc_jamari_onsets(const dc_hertz_geom *g, double Estar, const dc_jamari_params *p, double *delta_n1,
                     double *delta_n2)
{
  if (!inputs_ok(Estar, p, 0.0)) return DC_EDOM;
  onsets o;
  const int st = get_d1(g, Estar, p, &o);
  if (st != DC_OK) return st;
  get_rest(g, p, &o);
  if (!(o.d1 >= DBL_MIN && o.d2 <= DBL_MAX)) return DC_ERANGE;
  *delta_n1 = o.d1;
  *delta_n2 = o.d2;
  return DC_OK;
}

int dc_jamari_loading(const dc_hertz_geom *g, double Estar, const dc_jamari_params *p, double delta, dc_contact *c)
{
  if (!inputs_ok(Estar, p, delta)) return DC_EDOM;
  onsets o;
  const int st = get_d1(g, Estar, p, &o);
  if (st != DC_OK) return st;
  if (delta <= o.d1) return dc_hertz_normal(g, Estar, delta, c);
  get_rest(g, p, &o);
  plastic_aux aux;
  return loading_plastic(g, p, &o, delta, c, &aux);
}

/* The residual overlap of the unloading branch from the loading state at
   delta > d1 (header): delta (1 - min(phi, 1)/alpha^1/2), alpha = 1 + ex,
   phi = F/F_Hertz = (1 + A1)/(delta/d1)^1/2 (F_Hertz(delta) = 2/3 K_v H
   A_Hertz (delta/d1)^1/2 by Eq. 41), with 1 - phi = (expm1(l/2) - A1)/exp(l/2)
   and alpha^1/2 - 1 = ex/(alpha^1/2 + 1): no cancellation but between
   terms of the size of l. */
static double residual(double delta, double d1, const plastic_aux *x)
{
  const double sa = sqrt(1.0 + x->ex);
  const double sa1 = x->ex / (sa + 1.0);                      /* alpha^1/2 - 1 */
  const double l = x->l >= 0.0 ? x->l : log1p((delta - d1) / d1);
  const double h = expm1(0.5 * l);                            /* (delta/d1)^1/2 - 1 */
  if (!(x->A1 < h)) return delta * (sa1 / sa);                /* phi >= 1 */
  const double om = h <= DBL_MAX ? (h - x->A1) / (1.0 + h) : 1.0;   /* 1 - phi */
  return delta * ((sa1 + om) / sa);
}

int dc_jamari_step(const dc_hertz_geom *g, double Estar, const dc_jamari_params *p, double delta,
                   dc_jamari_state *h, dc_contact *c)
{
  if (!inputs_ok(Estar, p, delta)) return DC_EDOM;
  const double dmax = h->delta_max, dres = h->delta_res, Fmax = h->F_max, Amax = h->area_max;
  const int fresh = dmax == 0.0 && dres == 0.0 && Fmax == 0.0 && Amax == 0.0;
  if (!fresh && !(isfinite(dmax) && isfinite(dres) && isfinite(Fmax) && isfinite(Amax))) return DC_EDOM;
  onsets o;
  int st = get_d1(g, Estar, p, &o);
  if (st != DC_OK) return st;
  const int memory = dres >= 0.0 && dres < dmax && Fmax > 0.0 && Amax > 0.0;

  if (!memory || delta >= dmax) {
    /* the loading curve */
    if (delta <= o.d1) {
      /* elastic: no memory (cleared if the geometry moved delta_n1 past it) */
      st = dc_hertz_normal(g, Estar, delta, c);
      if (st == DC_OK && !fresh) *h = (dc_jamari_state){0.0, 0.0, 0.0, 0.0};
      return st;
    }
    get_rest(g, p, &o);
    dc_contact cl;
    plastic_aux aux;
    st = loading_plastic(g, p, &o, delta, &cl, &aux);
    if (st != DC_OK) return st;
    const double dr = residual(delta, o.d1, &aux);
    h->delta_max = delta;
    /* delta_res < delta_max: phi below rounding (delta_max beyond ~1e30
       delta_n1) leaves the branch one ulp wide */
    h->delta_res = dr < delta ? (dr >= 0.0 ? dr : 0.0) : nextafter(delta, 0.0);
    h->F_max = cl.F;
    h->area_max = cl.area;
    *c = cl;
    return DC_OK;
  }

  /* the unloading branch, capped by the loading curve */
  const double x = delta - dres;
  if (x <= 0.0) {
    c->F = c->F_bound = c->kn = c->area = c->a = c->b = 0.0;
    c->formed = 0;
    return DC_OK;
  }
  const double u = dmax - dres;
  const double r = fmin(1.0, x / u), sr = sqrt(r);
  double F = Fmax * r * sr;                                     /* F_max (x/u)^3/2 */
  double kn = 1.5 * Fmax * sr / u;
  const double area = Amax * r;
  dc_contact cl;
  if (delta <= o.d1) {
    st = dc_hertz_normal(g, Estar, delta, &cl);
    if (st != DC_OK) return st;
    if (cl.F < F) {
      F = cl.F;
      kn = cl.kn;
    }
  } else {
    get_rest(g, p, &o);
    /* the loading force is >= 2/3 K_v H A_Hertz = F(d1) delta/d1 beyond d1:
       the curve itself only where the branch is above that */
    if (!(F <= o.p1 * o.ce * delta)) {
      plastic_aux aux;
      st = loading_plastic(g, p, &o, delta, &cl, &aux);
      if (st != DC_OK) return st;
      if (cl.F < F) {
        F = cl.F;
        kn = cl.kn;
      }
    }
  }
  const double sm1 = sqrt(g->m1);
  const double a = sqrt(area / (M_PI * sm1));
  if (!(isfinite(kn) && isfinite(a))) return DC_ERANGE;
  c->F = c->F_bound = F;
  c->kn = kn;
  c->area = area;
  c->a = a;
  c->b = a * sm1;
  c->formed = 1;
  return DC_OK;
}
