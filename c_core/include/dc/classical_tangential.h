/* Classical tangential contact laws of the lecture notes (Lopez Rangel
   2021, "DEM contact force models", Sec. 4; "notes"): one model, a law
   setting; the cheap alternatives to cmd_tangential.

   Laws (F the force along the relative tangential motion, mu F_n the
   friction limit with F_n = the patch's F_bound):
   - COULOMB (4.2):  F = mu F_n v_t/|v_t|;
   - VISCOUS (4.3):  F = eta_t v_t;
   - VISCOUS_SLIDING (4.4): F = eta_t v_t, |F| <= mu F_n;
   - SPRING_SLIDING (4.5): F = K_t delta_t, |F| <= mu F_n, the spring
     shortened to mu F_n / K_t when it slides;
   - SPRING_DASHPOT_SLIDING (4.6, LSDt): F = K_t delta_t + eta_t v_t,
     |F| <= mu F_n; when it slides the spring is set so that
     K_t delta_t + eta_t v_t is the limited force (the notes'
     delta_t = sign(delta_t) (mu F_n - eta_t v_t)/K_t, Maw et al.);
   - DI_RENZO (4.7, DDt): SPRING_DASHPOT_SLIDING with K_t = 16/3 G* a
     (2/3 of Mindlin's 8 G* a, a = (R delta_n)^1/2);
   - LANGSTON (4.7, LTH): F = mu F_n (1 - (1 - min(|delta_t|, d)/d)^3/2)
     + eta (4 m k)^1/2 v_t, k = dF/d delta_t = 8 G* a (1 - x)^1/2,
     d = 3 mu F_n / (16 G* a), x = min(|delta_t|, d)/d;
   - ZHENG (4.7, ZZYt): LANGSTON's elastic force plus
     A_t (1 - 0.4 A_t |v_t| / d) k v_t (the factor kept >= 0);
   - TSUJI (4.7, TTIt): SPRING_DASHPOT_SLIDING with K_t = 8 G* a and
     eta_t = the normal damping coefficient;
   - INCREMENTAL (4.8, Walton & Braun 1986): dF = K_t d(delta_t),
     K_t = K0 (1 - (T - T*)/(mu F_n - T*))^1/3 in the frame of the motion
     (T, T*: force and force at the last reversal along the motion),
     integrated exactly along each step, so that at constant normal force
     a collinear path has no step-size error:
       first loading  T = mu F_n (1 - (1 - 2 K0 x / (3 mu F_n))^3/2),
       after a reversal at T*: T* - T = (mu F_n + T*) (1 - (1 - 2 K0 x /
       (3 (mu F_n + T*)))^3/2) (the Cattaneo-Mindlin shape without
       Masing's factor 2).
   Stiffness setting (SPRING_SLIDING, SPRING_DASHPOT_SLIDING; K0 of
   INCREMENTAL): GIVEN (property kt), RATIO K_t = 4 G* / E* K_n, which is the
   notes' (1 - nu)/(1 - nu/2) K_n for equal materials (Mindlin's stiffness
   over Hertz's, 8 G* a / (2 E* a)), MINDLIN K_t = 8 G* a.
   Damping setting (SPRING_DASHPOT_SLIDING, DI_RENZO): NONE, GIVEN
   (property gammat), RESTITUTION (Deen et al. 2007, from the tangential
   restitution e_t: eta_t = -2 ln e_t (2/7 m K_t)^1/2 / (ln^2 e_t +
   pi^2)^1/2, 2 (2/7 m K_t)^1/2 for e_t = 0), NORMAL (eta_t = eta_n).

   Seed errors (notes, OCR text), checked in
   tests/unit/test_classical_tangential.c:
   - Deen's eta_t: the square root covers 2/7 m K_t (the printed
     sqrt(2/7) m K_t is not a damping coefficient in kg/s); 2/7 m is the
     tangential mass of a solid sphere at its contact point, and with it a
     stuck contact rebounds tangentially with e_t (test);
   - LTH viscous force: eta_t (...)^1/2 multiplies the velocity, not
     delta_t (the printed product is not a force);
   - incrementally slipping friction: the sign s belongs in the numerator,
     K_t = K0 (1 - s (F - F*) / (mu F_n - s F*))^1/3; with s in front of K0
     a reversal from the limit (s = -1, F = F* = mu F_n) gives K_t = -K0
     and the force grows past mu F_n;
   - G of the effective parameters is (sum (2 - nu_i)/G_i)^-1, the 2 - nu_i^2
     of the OCR text gives neither Mindlin's 8 G a nor the stiffness ratio;
   - TTIt's K_t = (2R)^1/2 E / ((2 - nu)(1 + nu)) delta_n^1/2 is Mindlin's
     8 G* a for two equal spheres of radius R (the particle radius, not
     the effective one); LTH's d = mu (2 - nu)/(2 (1 - nu)) delta_n is
     3 mu F_n/(16 G* a) for Hertz between equal materials (tests).

   Three dimensions: the history vectors turn with the contact plane (the
   part along n is projected off and the length kept, as LIGGGHTS' stock
   history does). The force is limited along its own direction. A reversal
   of INCREMENTAL is a step whose displacement has a negative component
   along F - F*; that step's T, T* are the components along it (the notes
   leave 3D open).

   Signs (as dc/cmd_tangential.h): du and v_t are the displacement and
   velocity of body i relative to body j at the contact point; Ft acts on j,
   -Ft on i (for a stuck spring Ft = K_t delta_t). */
#ifndef DC_CLASSICAL_TANGENTIAL_H
#define DC_CLASSICAL_TANGENTIAL_H

#include "dc/contract.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Setting classicalTangential. */
typedef enum {
  DC_CT_COULOMB = 0,
  DC_CT_VISCOUS = 1,
  DC_CT_VISCOUS_SLIDING = 2,
  DC_CT_SPRING_SLIDING = 3,
  DC_CT_SPRING_DASHPOT_SLIDING = 4,
  DC_CT_DI_RENZO = 5,
  DC_CT_LANGSTON = 6,
  DC_CT_ZHENG = 7,
  DC_CT_TSUJI = 8,
  DC_CT_INCREMENTAL = 9
} dc_ct_law;

/* Setting classicalTangentialStiffness. */
typedef enum { DC_CT_KT_GIVEN = 0, DC_CT_KT_RATIO = 1, DC_CT_KT_MINDLIN = 2 } dc_ct_stiffness;

/* Setting classicalTangentialDamping. */
typedef enum {
  DC_CT_DAMP_NONE = 0,
  DC_CT_DAMP_GIVEN = 1,
  DC_CT_DAMP_RESTITUTION = 2,
  DC_CT_DAMP_NORMAL = 3
} dc_ct_damping;

/* Per type pair; deck names in brackets; unused fields are not read. */
typedef struct {
  int law;        /* [classicalTangential] dc_ct_law */
  int stiffness;  /* [classicalTangentialStiffness] (SPRING_SLIDING, SPRING_DASHPOT_SLIDING, INCREMENTAL) */
  int damping;    /* [classicalTangentialDamping] (SPRING_DASHPOT_SLIDING, DI_RENZO) */
  double mu;      /* [coefficientFriction] >= 0 (all but VISCOUS) */
  double kt;      /* [kt] [N/m] > 0 (stiffness GIVEN) */
  double gammat;  /* [gammat] [N s/m] >= 0 (VISCOUS, VISCOUS_SLIDING, damping GIVEN) */
  double e_t;     /* [coefficientRestitutionTangential] in [0, 1] (damping RESTITUTION) */
  double Gstar;   /* G* = 1/sum (2 - nu_i)/G_i [Pa] > 0 (RATIO, MINDLIN, DI_RENZO, LANGSTON, ZHENG, TSUJI) */
  double Estar;   /* E* [Pa] > 0 (RATIO) */
  double eta_l;   /* [langstonDamping] [-] >= 0 (LANGSTON) */
  double t_visc;  /* [tangentialViscoelasticTime] A_t = eta/(2G) [s] >= 0 (ZHENG) */
} dc_classical_tangential_params;

/* Parameter check (dc/contract.h): DC_OK, or DC_EDOM with err naming the
   property or setting (G*, E*: "youngsModulus", the range saying which). */
int dc_classical_tangential_check(const dc_classical_tangential_params *p, dc_param_error *err);

/* A checked type pair with its derived constants. */
typedef struct {
  dc_classical_tangential_params p;
  double zeta_t;  /* damping RESTITUTION: eta_t = zeta_t (2/7 m K_t)^1/2 */
  double ratio;   /* stiffness RATIO: 4 G* / E* */
} dc_classical_tangential;

int dc_classical_tangential_init(const dc_classical_tangential_params *p, dc_classical_tangential *m,
                                 dc_param_error *err);

/* What a step needs from the normal model and the pair; every field must
   lie in its domain (DC_EDOM otherwise), each is used by the laws named. */
typedef struct {
  double meff;    /* effective mass [kg] > 0 (damping RESTITUTION, LANGSTON) */
  double kn;      /* normal stiffness [N/m] >= 0 (stiffness RATIO) */
  double gamman;  /* normal damping coefficient [N s/m] >= 0 (damping NORMAL, TSUJI) */
} dc_classical_tangential_contact;

/* Per-contact history, all zero at the start. */
typedef struct {
  double spring[3];  /* tangential spring [m]; INCREMENTAL: the force [N] (flips) */
  double rev[3];     /* INCREMENTAL: force at the last reversal [N] (flips); others 0 */
} dc_classical_tangential_state;

/* Field table; laws other than INCREMENTAL read and write only the first
   DC_CT_SPRING_NFIELDS fields (a wrapper may store just those). */
enum { DC_CT_HISTORY_NFIELDS = 6, DC_CT_SPRING_NFIELDS = 3 };
extern const dc_history_field dc_classical_tangential_history[DC_CT_HISTORY_NFIELDS];

typedef struct {
  double Ft[3];   /* force [N] (on j; -Ft on i), in the contact plane */
  double kt;      /* tangent stiffness of the spring along the motion [N/m]; 0 sliding or springless */
  double gammat;  /* damping coefficient used [N s/m] */
  int sliding;    /* 1: limited at mu F_bound */
} dc_classical_tangential_out;

/* One step of one contact. patch: this step's contact patch (a >= 0,
   F_bound >= 0, formed = 0 resets h and gives zeros); c: see above; n: the
   unit normal (|n|^2 within 1e-6 of 1); du: the displacement increment,
   or NULL for vt dt (dt > 0 is read only then); vt: the relative
   tangential velocity (parts along n are removed from du and vt). Updates
   h. DC_EDOM for a non-finite or out-of-domain input, DC_ERANGE when a
   result overflows (or the results come within a factor 11 of DBL_MAX);
   on an error h and out are untouched. No allocation. */
int dc_classical_tangential_step(const dc_classical_tangential *m, const dc_patch *patch,
                                 const dc_classical_tangential_contact *c, const double n[3],
                                 const double du[3], const double vt[3], double dt,
                                 dc_classical_tangential_state *h, dc_classical_tangential_out *out);

#ifdef __cplusplus
}
#endif
#endif
