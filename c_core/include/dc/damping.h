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

/* The lecture notes' Hertz damping laws (Lopez Rangel 2021, "DEM contact
   force models", Sec. 3.4; "notes"), F_dis = gamma d(delta)/dt on
   F_el = K_HZ delta^3/2 with K_HZ = 4/3 E* R^1/2 (for an ellipse R is the
   force-equivalent radius Rc gamma^2 of dc/hertz_elliptic.h), written with
   the tangent stiffness S = dF_el/d delta = 3/2 K_HZ delta^1/2 where they
   can be, so that every Hertz-type normal model takes them as one setting:
   - BSHP (Brilliantov et al. 1996): the notes' F_dis = K_HZ A' delta^1/2
     d(delta)/dt is dc_damping_viscoelastic with A = 2/3 A' (review
     Eq. 37 puts the tangent stiffness where the notes put K_HZ delta^1/2);
   - Kuwabara-Kono: gamma = eta delta^1/2 (dc_damping_kuwabara_kono);
   - Tsuji et al. 1992: gamma = eta delta^1/4 with the notes' coefficient
     (Norouzi et al. 2016) eta = alpha (m K_HZ)^1/2 (dc_damping_tsuji).
   Restitution: constant for Tsuji's form gamma ~ delta^1/4 (the
   restitution damping above is that form with alpha = 2 (5/4)^1/2 (-beta),
   and its restitution is e, to 1e-25 in a 30-digit integration; the
   notes' alpha misses e by -1.7 % at e = 0.1, -0.26 % at 0.3, under 0.06 %
   from 0.5 up), a function of the impact velocity for BSHP and
   Kuwabara-Kono (tests/reference/gen_classical.py, 30-digit integration;
   tests/unit/test_classical_normal.c). */

/* The damping setting of a normal model; the meaning of its coefficient
   (dc_damping_gamma's coef) in brackets. */
typedef enum {
  DC_DAMPING_RESTITUTION = 0,   /* dc_damping_restitution [beta of coefficientRestitution] */
  DC_DAMPING_VISCOELASTIC = 1,  /* dc_damping_viscoelastic, BSHP [viscoelasticTime A, s] */
  DC_DAMPING_KUWABARA_KONO = 2, /* dc_damping_kuwabara_kono [kuwabaraKonoDamping eta, N s m^-3/2] */
  DC_DAMPING_TSUJI = 3,         /* dc_damping_tsuji [alpha of coefficientRestitution, dc_damping_tsuji_alpha] */
  DC_DAMPING_NONE = 4           /* gamma = 0 */
} dc_damping_law;

/* Kuwabara & Kono 1987 (notes, KKn): gamma = eta delta^1/2. Domain:
   eta >= 0, delta >= 0. */
static inline double dc_damping_kuwabara_kono(double eta, double delta) { return eta * sqrt(delta); }

/* Tsuji et al. 1992 (notes, TTIn): gamma = eta delta^1/4 with
   eta = alpha (m K_HZ)^1/2, i.e. gamma = alpha (m 2/3 S)^1/2 since
   K_HZ delta^1/2 = 2/3 S. Domain: alpha >= 0, S >= 0, m > 0. */
static inline double dc_damping_tsuji(double alpha, double S, double meff)
{
  return alpha * sqrt(2.0 / 3.0 * S * meff);
}

/* The notes' coefficient of Tsuji damping (Norouzi et al. 2016, a fit to
   the restitution of the damped Hertz collision):
   alpha = -2.2664 ln e / (ln^2 e + 10.1354)^1/2, for e in (0, 1]; DC_EDOM
   outside. Its restitution is constant in the impact velocity, 1.7 % below
   e at e = 0.1 (above). */
int dc_damping_tsuji_alpha(double e, double *alpha);

/* gamma [N s/m] of a damping law (dc_damping_law) with its coefficient
   coef, on a Hertz-type contact of tangent stiffness S, overlap delta and
   effective mass m. Inline, unchecked: the domains above; an unknown law
   gives 0. */
static inline double dc_damping_gamma(int law, double coef, double S, double delta, double meff)
{
  switch (law) {
  case DC_DAMPING_RESTITUTION: return dc_damping_restitution(coef, S, meff);
  case DC_DAMPING_VISCOELASTIC: return dc_damping_viscoelastic(coef, S);
  case DC_DAMPING_KUWABARA_KONO: return dc_damping_kuwabara_kono(coef, delta);
  case DC_DAMPING_TSUJI: return dc_damping_tsuji(coef, S, meff);
  default: return 0.0;
  }
}

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
