/* Classical normal contact laws of the lecture notes (Lopez Rangel 2021,
   "DEM contact force models", Sec. 3; "notes"): one model, a law setting.

   - LSD: linear spring-dashpot (notes Sec. 3.3, LSDn),
       F = K delta + eta d(delta)/dt,  eta = -2 ln e (m K)^1/2 / (ln^2 e + pi^2)^1/2,
     K given (property kn) or matched to the elastic Hertz collision at the
     characteristic impact velocity v (below).
   - HERTZ: F = K_HZ delta^3/2 + gamma d(delta)/dt, K_HZ = 4/3 E* R^1/2
     (Sec. 3.4, NSDn), gamma from the damping setting of dc/damping.h:
     BSHP (viscoelastic), Kuwabara-Kono, Tsuji with the notes' coefficient,
     LIGGGHTS' restitution damping, or none.
   - HLS_CONSTANT, HLS_VARIABLE: hysteretic linear spring (Sec. 3.5, Walton
     & Braun 1986): loading F = K_L delta; unloading and reloading on the
     line F = K_U (delta - delta_res) through (delta_max, K_L delta_max),
     delta_res = delta_max (1 - K_L/K_U), F >= 0; K_U = K_L / e^2
     (constant) or K_U = K_L + S F_max = K_L (1 + S delta_max) (variable).
     The notes switch branches on the sign of d(delta)/dt, which puts a
     force jump on reloading; here reloading follows the unloading line up
     to delta_max (Walton & Braun), so the force is a function of delta and
     the history delta_max only. A single collision is the same either way.

   Sign conventions: delta > 0 is overlap, ddelta = d(delta)/dt > 0 while
   approaching (LIGGGHTS: ddelta = -vn); forces > 0 repel.

   Closed forms of one collision from impact velocity v (m the effective
   mass), derived and checked by tests/reference/gen_classical.py against
   a 30-digit integration of m delta'' = -F:
     LSD:   Tc = pi / W, W = (K/m - eta^2/(4 m^2))^1/2,
            delta_max = v (m/K)^1/2 exp(-atan(b)/b), b = pi / |ln e|,
            rebound v e; with limitForce the force ends at F = 0 at
            W t = atan2(eta W, -(K - eta^2/(2m))), rebound larger than v e.
     HERTZ (elastic): delta_max = (15/16 m v^2 / (R^1/2 E*))^2/5,
            Tc = c_T (m^2 / (v R E*^2))^1/5,
            c_T = 2 (15/16)^2/5 pi^1/2 Gamma(7/5)/Gamma(9/10) = 2.868266.
     HLS:   delta_max = v (m/K_L)^1/2, F_max = v (m K_L)^1/2,
            Tc = pi/2 (m/K_L)^1/2 (1 + e), delta_res = delta_max (1 - e^2),
            e = (K_L/K_U)^1/2 (variable: e = (1 + S delta_max)^-1/2).
   Matched stiffness, K = c (v R E*^2 m^1/2)^2/5:
     DURATION (equal Tc):  LSD c = pi^2/c_T^2 (1 + ln^2 e/pi^2) = 1.199668 (...),
                           HLS c = pi^2/(4 c_T^2) (1 + e)^2 = 0.299917 (1 + e)^2;
     OVERLAP (equal delta_max): c = (16/15)^4/5 exp(-2 atan(b)/b) = 1.052987 exp(...)
                           for LSD, (16/15)^4/5 for HLS;
     ENERGY (equal strain energy 1/2 K delta_max^2 = 2/5 K_HZ delta_max^5/2):
                           c = (16/15)^4/5 = 1.052987 (LIGGGHTS' hooke kn).
   Seed errors (notes, OCR text):
   - LSD collision duration "pi (m/K)^1/2 (1 + 1/beta^2)": the square root
     covers (1 + 1/beta^2) too, Tc = pi (m/K (1 + 1/beta^2))^1/2 (from
     Tc = pi/W with the notes' eta; the notes' next slide has it right);
   - Hertz c_T is 2.8683, printed as 2.870 and 2.86; the matching constants
     1.198 and 0.2996 follow from 2.870, exact 1.19967 and 0.29992;
   - maximum-overlap matching of a damped LSD needs the factor
     exp(-2 atan(beta)/beta) (the notes give 1.053, its elastic value,
     which is the energy matching).
   All checked in tests/reference/gen_classical.py. */
#ifndef DC_CLASSICAL_NORMAL_H
#define DC_CLASSICAL_NORMAL_H

#include "dc/contract.h"
#include "dc/damping.h"

#ifdef __cplusplus
extern "C" {
#endif

/* c_T of the elastic Hertz collision duration, and the matching constants. */
#define DC_CLASSICAL_HERTZ_TC 2.8682656991953313822
#define DC_CLASSICAL_MATCH_DURATION 1.1996677571941672796   /* pi^2 / c_T^2 */
#define DC_CLASSICAL_MATCH_OVERLAP 1.0529869257785705828    /* (16/15)^4/5 */

/* Setting classicalNormal. */
typedef enum {
  DC_CLASSICAL_LSD = 0,
  DC_CLASSICAL_HERTZ = 1,
  DC_CLASSICAL_HLS_CONSTANT = 2,
  DC_CLASSICAL_HLS_VARIABLE = 3
} dc_classical_normal_law;

/* Setting classicalStiffness: how K (LSD) or K_L (HLS) is set. */
typedef enum {
  DC_CLASSICAL_K_GIVEN = 0,     /* property kn */
  DC_CLASSICAL_K_DURATION = 1,  /* equal collision duration (not with HLS_VARIABLE) */
  DC_CLASSICAL_K_OVERLAP = 2,   /* equal maximum overlap */
  DC_CLASSICAL_K_ENERGY = 3     /* equal maximum strain energy */
} dc_classical_stiffness;

/* Per type pair; the deck names in brackets. Unused fields are not read. */
typedef struct {
  int law;        /* [classicalNormal] dc_classical_normal_law */
  int stiffness;  /* [classicalStiffness] dc_classical_stiffness (LSD, HLS) */
  int damping;    /* [damping] dc_damping_law (HERTZ) */
  int limit;      /* [limitForce] 1: total force clipped at 0 */
  double Estar;   /* E* [Pa] from youngsModulus, poissonsRatio (HERTZ; matched K) */
  double kn;      /* [kn] K or K_L [N/m] (stiffness GIVEN) */
  double v_char;  /* [characteristicVelocity] [m/s] (matched K) */
  double e;       /* [coefficientRestitution] in (0, 1] (LSD, HLS_CONSTANT,
                     HLS with DURATION, HERTZ with RESTITUTION or TSUJI damping) */
  double A;       /* [viscoelasticTime] [s] >= 0 (HERTZ, VISCOELASTIC) */
  double eta_kk;  /* [kuwabaraKonoDamping] [N s m^-3/2] >= 0 (HERTZ, KUWABARA_KONO) */
  double S;       /* [unloadingStiffnessSlope] [1/m] >= 0 (HLS_VARIABLE) */
} dc_classical_normal_params;

/* Parameter check (dc/contract.h): DC_OK, or DC_EDOM with err naming the
   property or setting of the first bad field (for E* "youngsModulus"). */
int dc_classical_normal_check(const dc_classical_normal_params *p, dc_param_error *err);

/* A checked type pair with its derived constants (made once at set-up). */
typedef struct {
  dc_classical_normal_params p;
  double kc;        /* matched: K = kc (R^2 m)^1/5; given: K = kc */
  int matched;      /* 1: K depends on R and m */
  double zeta;      /* LSD: eta = zeta (m K)^1/2 */
  double dcoef;     /* HERTZ: the damping coefficient of dc_damping_gamma */
  double ku_ratio;  /* HLS_CONSTANT: K_U / K_L = 1/e^2 */
} dc_classical_normal;

/* Check and derive: DC_OK, or DC_EDOM with err (m untouched); DC_ERANGE
   (err names the property that overflows) when a constant overflows. */
int dc_classical_normal_init(const dc_classical_normal_params *p, dc_classical_normal *m,
                             dc_param_error *err);

/* Per-contact history: delta_max (HLS; the others leave it 0). Start 0. */
typedef struct {
  double delta_max;  /* largest overlap of this contact [m] */
} dc_classical_normal_state;

enum { DC_CLASSICAL_NORMAL_NFIELDS = 1 };
extern const dc_history_field dc_classical_normal_history[DC_CLASSICAL_NORMAL_NFIELDS];

/* Output of one step. */
typedef struct {
  dc_contact c;   /* elastic force, tangent stiffness dF_el/d delta, the
                     circle a = b = (R delta)^1/2, F_bound = elastic force */
  double gamma;   /* damping coefficient [N s/m]: F_dis = gamma ddelta */
  double F;       /* total normal force F_el + gamma ddelta (>= 0 with limitForce) */
  double K;       /* stiffness in use: K (LSD), K_L (HLS), K_HZ (HERTZ) [N/m, N/m^3/2] */
} dc_classical_normal_out;

/* One step of one contact: effective radius R > 0 and mass meff > 0,
   overlap delta, its rate ddelta (finite), history h (delta_max >= 0
   finite). delta <= 0: formed = 0, zero force, h reset. Updates h; DC_EDOM
   for inputs outside the domain, DC_ERANGE when a result overflows or the
   matched stiffness underflows to 0; on an error h and out are untouched.
   No allocation. */
int dc_classical_normal_step(const dc_classical_normal *m, double R, double meff, double delta,
                             double ddelta, dc_classical_normal_state *h, dc_classical_normal_out *out);

/* K (LSD) or K_L (HLS) of a contact; K_HZ for HERTZ. Same domain. */
int dc_classical_normal_stiffness(const dc_classical_normal *m, double R, double meff, double *K);

/* Figures of one collision at impact velocity v0 (closed forms above). */
typedef struct {
  double Tc;    /* collision duration [s] (LSD with limit: until F = 0) */
  double dmax;  /* maximum overlap [m] */
  double e;     /* restitution */
  double Fmax;  /* maximum elastic force [N] (HLS, HERTZ) */
  double dres;  /* residual overlap [m] (HLS) */
} dc_classical_collision;

/* LSD with stiffness K, damping eta < 2 (m K)^1/2 (underdamped), limit 0/1. */
int dc_classical_lsd_collision(double K, double eta, double meff, double v0, int limit,
                               dc_classical_collision *c);
/* Elastic Hertz, F = K_HZ delta^3/2. */
int dc_classical_hertz_collision(double Khz, double meff, double v0, dc_classical_collision *c);
/* HLS: law HLS_CONSTANT with x = e, or HLS_VARIABLE with x = S [1/m]. */
int dc_classical_hls_collision(int law, double KL, double x, double meff, double v0,
                               dc_classical_collision *c);

#ifdef __cplusplus
}
#endif
#endif
