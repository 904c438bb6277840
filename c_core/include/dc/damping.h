/* Normal and tangential damping laws: the dissipative force coefficient
   (F_dis = -gamma v_n, v_n the normal approach velocity sign convention of
   the caller) from a contact stiffness. The lecture-note damping laws
   (Lopez Rangel 2021) join here as settings of the normal models.
   Hot-path functions are inline and unchecked; their domain is stated. */
#ifndef DC_DAMPING_H
#define DC_DAMPING_H

#include <math.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Restitution-based damping (as LIGGGHTS' hertz: Tsuji-type with the
   tangent stiffness S): gamma = -2 sqrt(5/6) beta (S m)^1/2, with
   beta = ln e / (ln^2 e + pi^2)^1/2 <= 0 (dc_damping_beta) and m the
   effective mass. Domain: S >= 0, m > 0. */
static inline double dc_damping_restitution(double beta, double S, double meff)
{
  const double sqrtFiveOverSix = 0.91287092917527685576161630466800355658790782499663875;
  return -2. * sqrtFiveOverSix * beta * sqrt(S * meff);
}

/* beta = ln e / (ln^2 e + pi^2)^1/2 of a coefficient of restitution e in
   (0, 1]; DC_EDOM outside. */
int dc_damping_beta(double e, double *beta);

/* Viscoelastic damping (Brilliantov et al.; review Eq. 37):
   F_dis = A (d delta/dt) S, i.e. gamma = A S, with A [s] the dissipative
   time and S the tangent (or, for adhesive contacts, flat-punch) stiffness. */
static inline double dc_damping_viscoelastic(double A, double S) { return A * S; }

/* Flat-punch stiffness of a contact ellipse of semi-axes a >= b > 0:
   k = pi E* a / K(e^2), e^2 = 1 - b^2/a^2 (2 E* a for a circle); the
   stiffness an adhesive (JKR) contact's damping acts on
   (dc/dissipation_adhesive.h). DC_EDOM unless E* > 0, a >= b > 0 finite;
   DC_ERANGE (k untouched) when k overflows. */
int dc_punch_stiffness(double Estar, double a, double b, double *k);

/* The same for a circle of radius a: 2 E* a. */
static inline double dc_punch_stiffness_circle(double Estar, double a) { return 2.0 * Estar * a; }

#ifdef __cplusplus
}
#endif
#endif
