/* Viscoelastic dissipation in adhesive contacts: corrected review Eqs.
   39-40 (derivation and the seed errors in dc/dissipation_adhesive.h). */
#include "dc/dissipation_adhesive.h"
#include "dc/damping.h"
#include "dc/status.h"
#include <float.h>
#include <math.h>

/* Corrected Eqs. 39-40: F_dis = A ddelta k_punch, k_punch = pi E* a/K(e^2). */
int dc_dissip_adhesive_ab(double A, double Estar, double a, double b, double ddelta, double *F_dis)
{
  if (!(A >= 0.0 && isfinite(A) && Estar > 0.0 && isfinite(Estar) && a > 0.0 && isfinite(a) && b > 0.0 &&
        b <= a && isfinite(ddelta)))
    return DC_EDOM;
  double k;
  const int st = dc_punch_stiffness(Estar, a, b, &k);
  if (st != DC_OK) return st;
  const double F = A * ddelta * k;
  if (!isfinite(F)) return DC_ERANGE;
  *F_dis = F;
  return DC_OK;
}

/* Corrected Eqs. 39-40 evaluated on a JKR state. */
int dc_dissip_adhesive_state(double A, double Estar, const dc_jkr_state *s, double ddelta, double *F_dis)
{
  if (!(A >= 0.0 && isfinite(A) && Estar > 0.0 && isfinite(Estar) && isfinite(ddelta))) return DC_EDOM;
  if (!s->contact) { *F_dis = 0.0; return DC_OK; }
  if (!(isfinite(s->a) && isfinite(s->b))) return DC_EDOM;
  if (!(s->a > 0.0)) { *F_dis = 0.0; return DC_OK; }   /* touching: a = 0, k_punch = 0 */
  return dc_dissip_adhesive_ab(A, Estar, s->a, s->b > 0.0 ? s->b : s->a, ddelta, F_dis);
}

/* Contact-radius form (Brilliantov et al. 2007) of corrected Eqs. 39-40:
   d/da [F_H - F_B/3] = 4 E* a^2/R - (2 pi w E* a)^1/2. */
int dc_dissip_adhesive_radius_rate(double A, double R, double Estar, double w, double a, double da_dt,
                                   double *F_dis)
{
  if (!(A >= 0.0 && isfinite(A) && R > 0.0 && isfinite(R) && Estar > 0.0 && isfinite(Estar) && w >= 0.0 &&
        isfinite(w) && a > 0.0 && isfinite(a) && isfinite(da_dt)))
    return DC_EDOM;
  const double F = A * da_dt * (4.0 * Estar * a * a / R - sqrt(2.0 * M_PI * w * Estar * a));
  if (!isfinite(F)) return DC_ERANGE;
  *F_dis = F;
  return DC_OK;
}

/* Corrected Eq. 40 for spheres: JKR force plus the dissipative force. */
int dc_jkr_sphere_viscoelastic(double R, double Estar, double w, double A, double delta, double ddelta,
                               dc_jkr_state *s, double *F_total)
{
  /* A and ddelta first: a non-finite one is DC_EDOM whatever the state */
  if (!(A >= 0.0 && isfinite(A) && isfinite(ddelta))) return DC_EDOM;
  /* into a local state: an error leaves *s and *F_total untouched */
  dc_jkr_state t;
  int st = dc_jkr_sphere(R, Estar, w, delta, &t);
  if (st != DC_OK) return st;
  double Fd;
  st = dc_dissip_adhesive_state(A, Estar, &t, ddelta, &Fd);
  if (st != DC_OK) return st;
  const double F = t.F + Fd;
  if (!isfinite(F)) return DC_ERANGE;
  *s = t;
  *F_total = F;
  return DC_OK;
}
