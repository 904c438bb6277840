/* How smooth the elliptic summits' correction to the circular table is, for
   sizing a superquadric table of dc/gw_rough_adhesive_table.h (not a test;
   a measurement). With the circle's scales matched to the elliptic JKR
   summit's separation point (delta_c = delta_break / (-3/8 pi^4/3), F_s =
   F_break / (-5 pi/48), tests/reference/gwa_elliptic_factor.c), the exact
   adhesive part (dc_gw_rough_adhesive - dc_gw_rough_elliptic, summits
   dc_jkr_geometry(R_major, rho R_major)) is F_s G_b(x, eta) (1 + C) with G_b
   the circular table at eta = ln(sigma/delta_c); this prints, per branch,
   max |C| and the error of 4-point cubic (Catmull-Rom) interpolation of C at
   midpoints for node spacings in ln rho (rho 1 to 0.01), in x and in eta.
   Measured (30 November 2026): |C| up to 0.21; in ln rho spacing 0.38 (13
   nodes) within 1.8e-5; in x spacing 0.5 within 3.4e-5 (4.4e-4 at 1);
   in eta spacing 0.5 within 1.1e-5 on loading, but on unloading 2.4e-5 at
   rho 0.7, 9.6e-4 at 0.1, 2.1e-3 at 0.03 (spacing 0.25: 1e-4 at 0.1,
   2.3e-4 at 0.03): unloading wants rows about 1/8 apart in eta, or a coordinate that
   follows its separation line. Runs in a few seconds.
   Build and run (from the repository root, library built in B):
     cc -O2 -std=gnu11 -Wall -Wextra -Ic_core/include tests/reference/gwa_elliptic_correction.c \
        B/c_core/libdemcontact.a -lgsl -lgslcblas -lm -o /tmp/gwa_ec && /tmp/gwa_ec */
#include "dc/gw_rough.h"
#include "dc/gw_rough_adhesive.h"
#include "dc/gw_rough_adhesive_table.h"
#include "dc/jkr_elliptic.h"
#include <math.h>
#include <stdio.h>

static const double E = 2.7e6, Rmaj = 7.5e-4, w = 0.05;

/* C at ratio rho, branch b, reduced x (h, or h - D unloading), eta */
static double corr(double rho, int b, double x, double eta)
{
  const double ub = -3.0 / 8.0 * pow(M_PI, 4.0 / 3.0);
  dc_jkr_geom g;
  if (dc_jkr_geometry(Rmaj, Rmaj * rho, E, w, &g) != DC_OK) return NAN;
  const double dcm = g.delta_break / ub, Fsm = g.F_break / (-5.0 * M_PI / 48.0);
  const double sigma = exp(eta) * dcm, D = -g.delta_break / sigma, h = b ? x + D : x;
  dc_gw_adhesive_state s;
  dc_gw_rough_state e;
  double G, Gx;
  if (dc_gw_rough_adhesive(&g, 1.0, sigma, -h * sigma, b, &s) != DC_OK ||
      dc_gw_rough_elliptic(&g.hertz, E, 1.0, sigma, -h * sigma, &e) != DC_OK ||
      dc_gwa_table_reduced(b, x, eta, &G, &Gx) != DC_OK)
    return NAN;
  return (s.F - e.F) / (Fsm * G) - 1.0;
}

/* Catmull-Rom at the midpoint of y1, y2 */
static double mid(double y0, double y1, double y2, double y3)
{
  return (9.0 * (y1 + y2) - (y0 + y3)) / 16.0;
}

int main(void)
{
  const double s0 = log(0.01);
  const int N = 24;   /* fine steps in ln rho: 2N */
  printf("ln rho (13, 7, 4 nodes over rho 1..0.01): max |C|, midpoint error of cubic interpolation\n");
  for (double eta = -2.0; eta <= 4.0; eta += 2.0)
    for (int b = 0; b < 2; b++) {
      double maxC = 0.0, err[3] = {0, 0, 0};
      for (double x = -5.0; x <= 3.0; x += 2.0) {
        double c[2 * N + 1];
        for (int k = 0; k <= 2 * N; k++) {
          c[k] = corr(exp(s0 * (1.0 - (double)k / (2 * N))), b, x, eta);
          maxC = fmax(maxC, fabs(c[k]));
        }
        const int st[3] = {2, 4, 8};
        for (int q = 0; q < 3; q++)
          for (int k = st[q]; k + 2 * st[q] <= 2 * N; k += st[q])
            err[q] = fmax(err[q], fabs(mid(c[k - st[q]], c[k], c[k + st[q]], c[k + 2 * st[q]]) - c[k + st[q] / 2]));
      }
      printf("  eta %5.2f %s: max|C| %.3g; spacing %.2f: %.1e, %.2f: %.1e, %.2f: %.1e\n", eta,
             b ? "unloading" : "loading  ", maxC, -s0 / N, err[0], -2 * s0 / N, err[1], -4 * s0 / N, err[2]);
    }
  printf("x and eta at fixed rho: midpoint error of cubic interpolation, spacings 0.25, 0.5, 1\n");
  const double rhos[] = {0.7, 0.3, 0.1, 0.03}, d[3] = {0.25, 0.5, 1.0};
  for (int ir = 0; ir < 4; ir++)
    for (int b = 0; b < 2; b++) {
      double ex[3] = {0, 0, 0}, ee[3] = {0, 0, 0};
      for (int q = 0; q < 3; q++) {
        for (double eta = -4.0; eta <= 7.5; eta += 1.1)
          for (double x = -6.0; x <= 7.0 - 3 * d[q]; x += 0.37)
            ex[q] = fmax(ex[q], fabs(mid(corr(rhos[ir], b, x, eta), corr(rhos[ir], b, x + d[q], eta),
                                         corr(rhos[ir], b, x + 2 * d[q], eta), corr(rhos[ir], b, x + 3 * d[q], eta)) -
                                     corr(rhos[ir], b, x + 1.5 * d[q], eta)));
        for (double x = -6.0; x <= 7.0; x += 0.9)
          for (double eta = -4.5; eta <= 8.0 - 3 * d[q]; eta += 0.41)
            ee[q] = fmax(ee[q], fabs(mid(corr(rhos[ir], b, x, eta), corr(rhos[ir], b, x, eta + d[q]),
                                         corr(rhos[ir], b, x, eta + 2 * d[q]), corr(rhos[ir], b, x, eta + 3 * d[q])) -
                                     corr(rhos[ir], b, x, eta + 1.5 * d[q])));
      }
      printf("  rho %.2f %s: in x %.1e %.1e %.1e; in eta %.1e %.1e %.1e\n", rhos[ir], b ? "unloading" : "loading  ",
             ex[0], ex[1], ex[2], ee[0], ee[1], ee[2]);
    }
  return 0;
}
