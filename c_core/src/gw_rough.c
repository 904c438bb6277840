/* GW rough contact of non-spherical bodies (review Eqs. 29-36); see
   dc/gw_rough.h for the law, its limits and the seed corrections. */
#include "dc/gw_rough.h"
#include "dc/gw_integrals.h"
#include "dc/status.h"
#include <math.h>

int dc_gw_rough_elliptic(const dc_hertz_geom *g, double Estar, double n_asp,
                         double sigma, double delta, dc_gw_rough_state *s)
{
  if (!(Estar > 0.0 && isfinite(Estar) && n_asp > 0.0 && isfinite(n_asp) &&
        sigma >= 0.0 && isfinite(sigma) && isfinite(delta)))
    return DC_EDOM;
  const double sRc = sqrt(g->Rc);
  if (sigma <= 1e-80 * fabs(delta) || sigma == 0.0) {
    /* smooth limit: elliptic Hertz (review Eqs. 1-2) times n_asp */
    if (delta <= 0.0) { s->F = s->area = s->kn = 0.0; s->h = 1e300; return DC_OK; }
    dc_hertz_state hs;
    dc_hertz_contact(g, Estar, delta, &hs);
    s->F = n_asp * hs.F;
    s->kn = n_asp * hs.kn;
    s->area = n_asp * hs.area;
    s->h = -1e300;
    return DC_OK;
  }
  const double h = -delta / sigma;
  if (h < DC_GW_H_MIN) return DC_ERANGE;  /* unreachable: sigma > 1e-80 |delta| */
  double Fn[4];
  dc_gw_F_all(h, Fn);
  const double ss = sqrt(sigma);
  s->F = n_asp * 4.0 / 3.0 * Estar * sRc * sigma * ss * g->gamma * Fn[DC_GW_F32];
  s->kn = n_asp * 2.0 * Estar * sRc * ss * g->gamma * Fn[DC_GW_F12];
  s->area = n_asp * M_PI * g->Rc * sigma * g->beta * Fn[DC_GW_F1];
  s->h = h;
  return DC_OK;
}
