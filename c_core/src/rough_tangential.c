/* Rough no-slip tangential stiffness (Hisakado-Tsukizoe, review Eqs. 78-84);
   formulas and seed corrections in dc/rough_tangential.h. */
#include "dc/rough_tangential.h"
#include "dc/gw_integrals.h"
#include "dc/status.h"
#include <math.h>

int dc_rough_tangential_stiffness(double G, double chi, double n_asp, double R_asp,
                                  double sigma, double delta, double *kt)
{
  if (!(G > 0.0 && isfinite(G) && chi > 0.0 && isfinite(chi) && n_asp > 0.0 &&
        isfinite(n_asp) && R_asp > 0.0 && isfinite(R_asp) && sigma >= 0.0 &&
        isfinite(sigma) && isfinite(delta)))
    return DC_EDOM;
  const double pre = 2.0 * M_PI * n_asp * G * chi;
  if (sigma == 0.0 || sigma <= 1e-80 * fabs(delta)) {
    *kt = delta > 0.0 ? pre * sqrt(R_asp * delta) : 0.0;
    return DC_OK;
  }
  double F12;
  dc_gw_F(DC_GW_F12, -delta / sigma, &F12);
  *kt = pre * sqrt(R_asp * sigma) * F12;   /* Eq. 83 with chi* = chi F_1/2 */
  return DC_OK;
}
