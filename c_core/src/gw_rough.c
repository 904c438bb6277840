/* GW rough contact of non-spherical bodies (review Eqs. 29-36); see
   dc/gw_rough.h for the law, its limits and the seed corrections. */
#include "dc/gw_rough.h"
#include "dc/gw_integrals.h"
#include "dc/status.h"
#include "scaled_product.h"
#include <math.h>
#include <string.h>


static int state_finite(const dc_gw_rough_state *s)
{
  return isfinite(s->F) && isfinite(s->kn) && isfinite(s->area);
}

int dc_gw_rough_elliptic(const dc_hertz_geom *g, double Estar, double n_asp,
                         double sigma, double delta, dc_gw_rough_state *out)
{
  if (!(Estar > 0.0 && isfinite(Estar) && n_asp > 0.0 && isfinite(n_asp) &&
        sigma >= 0.0 && isfinite(sigma) && isfinite(delta)))
    return DC_EDOM;
  dc_gw_rough_state s;
  if (sigma <= 1e-80 * fabs(delta) || sigma == 0.0) {
    /* smooth limit: elliptic Hertz (review Eqs. 1-2) times n_asp */
    if (delta <= 0.0) {
      s.F = s.area = s.kn = 0.0;
      s.h = 1e300;
    } else {
      dc_hertz_state hs;
      const int st = dc_hertz_contact(g, Estar, delta, &hs);
      s.F = n_asp * hs.F;
      s.kn = n_asp * hs.kn;
      s.area = n_asp * hs.area;
      s.h = -1e300;
      if (st != DC_OK || !state_finite(&s)) {   /* a product overflowed */
        const double sR = sqrt(g->R_force), sd = sqrt(delta);
        s.F = dc_scaled_product(6, (const double[]){n_asp, 4.0 / 3.0, Estar, sR, sd, delta});
        s.kn = dc_scaled_product(5, (const double[]){n_asp, 2.0, Estar, sR, sd});
        s.area = dc_scaled_product(4, (const double[]){n_asp, M_PI, g->R_area, delta});
      }
    }
  } else {
    const double h = -delta / sigma;
    if (h < DC_GW_H_MIN) return DC_ERANGE;  /* unreachable: sigma > 1e-80 |delta| */
    double Fn[4];
    dc_gw_F_all(h, Fn);
    const double sRc = sqrt(g->Rc), ss = sqrt(sigma);
    s.F = n_asp * 4.0 / 3.0 * Estar * sRc * sigma * ss * g->gamma * Fn[DC_GW_F32];
    s.kn = n_asp * 2.0 * Estar * sRc * ss * g->gamma * Fn[DC_GW_F12];
    s.area = n_asp * M_PI * g->Rc * sigma * g->beta * Fn[DC_GW_F1];
    s.h = h;
    if (!state_finite(&s)) {   /* a product overflowed */
      s.F = dc_scaled_product(8, (const double[]){n_asp, 4.0 / 3.0, Estar, sRc, sigma, ss, g->gamma, Fn[DC_GW_F32]});
      s.kn = dc_scaled_product(7, (const double[]){n_asp, 2.0, Estar, sRc, ss, g->gamma, Fn[DC_GW_F12]});
      s.area = dc_scaled_product(6, (const double[]){n_asp, M_PI, g->Rc, sigma, g->beta, Fn[DC_GW_F1]});
    }
  }
  if (!state_finite(&s)) return DC_ERANGE;
  *out = s;
  return DC_OK;
}

int dc_gw_bound_material(double Estar, double n_asp, double sigma, dc_gw_bound *b)
{
  if (!(Estar > 0.0 && isfinite(Estar) && n_asp > 0.0 && isfinite(n_asp) && sigma > 0.0 && isfinite(sigma)))
    return DC_EDOM;
  dc_gw_bound q;
  memset(&q, 0, sizeof q);
  q.Estar = Estar;
  q.n_asp = n_asp;
  q.sigma = sigma;
  q.inv_sigma = 1.0 / sigma;
  q.ss = sqrt(sigma);
  q.kF = n_asp * 4.0 / 3.0 * Estar;   /* the leading products of dc_gw_rough_elliptic */
  q.kk = n_asp * 2.0 * Estar;
  if (!isnormal(q.inv_sigma)) return DC_ERANGE;
  *b = q;
  return DC_OK;
}

int dc_gw_bound_init(const dc_hertz_geom *g, double Estar, double n_asp, double sigma, dc_gw_bound *b)
{
  dc_gw_bound q;
  int st = dc_gw_bound_material(Estar, n_asp, sigma, &q);
  if (st == DC_OK) st = dc_gw_bound_bind(&q, g);
  if (st == DC_OK) *b = q;
  return st;
}

int dc_gw_rough_normal(const dc_hertz_geom *g, double Estar, double delta, double F, double kn, dc_contact *c)
{
  if (!(isfinite(F) && isfinite(kn))) return DC_EDOM;
  dc_contact smooth;
  const int st = dc_hertz_normal(g, Estar, delta, &smooth);
  if (st != DC_OK) return st;
  *c = smooth;
  c->F = F;
  c->kn = kn;
  c->F_bound = F > 0.0 ? F : 0.0;
  c->formed = F > 0.0;
  return DC_OK;
}

int dc_gw_rough_check(double n_asp, dc_param_error *err)
{
  return dc_param_check("asperityCount", n_asp, 0.0, 1, HUGE_VAL, 1, "(0, inf)", err);
}

int dc_gw_sphere_pair_init(int law, int feng_variant, double mu, double Estar, double sigma,
                           dc_gw_sphere_pair *out)
{
  int st;
  if (law == DC_GW_SPHERE_FENG) {
    dc_feng_law L;
    dc_feng_pair f;
    if ((st = dc_feng_init(mu, feng_variant, &L)) != DC_OK || (st = dc_feng_pair_init(&L, Estar, sigma, &f)) != DC_OK)
      return st;
    memset(out, 0, sizeof *out);
    out->law = law;
    out->feng = f;
    return DC_OK;
  }
  if (law == DC_GW_SPHERE_TABULATED) {
    dc_gw_table_law L;
    if ((st = dc_gw_table_init(mu, &L)) != DC_OK) return st;
    /* writes out->table only on success */
    if ((st = dc_gw_table_pair_init(&L, Estar, sigma, &out->table)) != DC_OK) return st;
    memset(&out->feng, 0, sizeof out->feng);
    out->law = law;
    return DC_OK;
  }
  return DC_EDOM;
}
