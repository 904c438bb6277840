/* How far the circular table of dc/gw_rough_adhesive_table.h is from the
   adhesive part of rough contact with elliptic JKR summits (the elliptic
   factor, for superquadrics): for R_minor/R_major from 1 to 0.01 it prints
   the worst relative difference, over h = -delta/sigma in [-3, 3] on both
   branches and two works of adhesion (tau ~ 36 and ~ 8), between
     the exact adhesive part  dc_gw_rough_adhesive - dc_gw_rough_elliptic
       (elliptic summits, dc_jkr_geometry(R_major, R_minor))
   and the circular table at two equivalent radii: Rhat = (R_major
   R_minor)^1/2 (the JKR scales of dc_jkr_geom) and R_force (the Hertz
   force's). Measured (2026-11-29), with Rhat: 5.0e-5 at ratio 0.97,
   6.0e-4 at 0.9, 6.9e-3 at 0.7, 2.6e-2 at 0.5, 0.27 at 0.1, 1.0 at 0.01
   (R_force: about twice that). A third column matches the circle's
   scales to the elliptic summit's instead of a radius: delta_c from its
   separation overlap (delta_break / delta_c = -3/8 pi^4/3 for a circle),
   F_s from its force there (F_break / F_s = -5 pi/48), the table read at
   tau = sigma/delta_c (dc_gwa_table_reduced): 1.7e-5 at 0.97, 2.0e-4 at
   0.9, 2.3e-3 at 0.7, 8.2e-3 at 0.5, 2.3e-2 at 0.3, 5.5e-2 at 0.1, 0.10 at
   0.01 (30 November).
   No equivalent circle meets 1e-4 below a ratio of ~0.97, so a table for
   elliptic summits needs R_minor/R_major as a coordinate of its own (the
   matched-scale circle leaves a correction of up to 10 % to tabulate).
   Runs in under a second.
   Build and run (from the repository root, library built in B):
     cc -O2 -std=gnu11 -Wall -Wextra -Ic_core/include tests/reference/gwa_elliptic_factor.c \
        B/c_core/libdemcontact.a -lgsl -lgslcblas -lm -o /tmp/gwa_ef && /tmp/gwa_ef */
#include "dc/gw_rough.h"
#include "dc/gw_rough_adhesive.h"
#include "dc/gw_rough_adhesive_table.h"
#include "dc/jkr_elliptic.h"
#include <math.h>
#include <stdio.h>

int main(void)
{
  const double E = 2.7e6, sigma = 2.1e-5, Rmaj = 7.5e-4;
  const double ws[] = {0.05, 0.5};
  const double ratios[] = {1.0, 0.97, 0.9, 0.7, 0.5, 0.3, 0.1, 0.03, 0.01};
  const double ub = -3.0 / 8.0 * pow(M_PI, 4.0 / 3.0);   /* delta_break / delta_c of a circle */
  printf("R_minor/R_major  worst rel. difference: circle at Rhat   at R_force   matched scales   (tau at Rhat: %s)\n",
         "w = 0.05, 0.5");
  for (int ir = 0; ir < 9; ir++) {
    double worst[3] = {0, 0, 0}, tau[2] = {0, 0};
    for (int iw = 0; iw < 2; iw++) {
      dc_jkr_geom g;
      dc_gwa_table_pair p;
      if (dc_jkr_geometry(Rmaj, Rmaj * ratios[ir], E, ws[iw], &g) != DC_OK ||
          dc_gwa_table_pair_init(E, ws[iw], sigma, 1.0, &p) != DC_OK) return 1;
      tau[iw] = sigma / (p.dc_coef * cbrt(g.Rhat));
      const double dcm = g.delta_break / ub, Fsm = g.F_break / (-5.0 * M_PI / 48.0), D = -g.delta_break / sigma;
      for (int b = 0; b < 2; b++)
        for (double h = 3.0; h >= -3.0; h -= 0.5) {
          const double delta = -h * sigma;
          dc_gw_adhesive_state s;
          dc_gw_rough_state e;
          if (dc_gw_rough_adhesive(&g, 1.0, sigma, delta, b, &s) != DC_OK ||
              dc_gw_rough_elliptic(&g.hertz, E, 1.0, sigma, delta, &e) != DC_OK) return 1;
          const double exact = s.F - e.F;
          const double R[2] = {g.Rhat, g.hertz.R_force};
          for (int k = 0; k < 2; k++) {
            double F, kn;
            if (dc_gwa_table_force(&p, R[k], b, delta, &F, &kn) != DC_OK) return 1;
            worst[k] = fmax(worst[k], fabs(F / exact - 1));
          }
          double G, Gx;
          if (dc_gwa_table_reduced(b, b ? h - D : h, log(sigma / dcm), &G, &Gx) != DC_OK) return 1;
          worst[2] = fmax(worst[2], fabs(Fsm * G / exact - 1));
        }
    }
    printf("%-16g %29.2e %12.2e %16.2e   %.3g, %.3g\n", ratios[ir], worst[0], worst[1], worst[2], tau[0], tau[1]);
  }
  return 0;
}
