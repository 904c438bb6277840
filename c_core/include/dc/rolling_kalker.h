/* Rolling contact of elliptic patches: Kalker's linear creep theory and
   the Vermeulen-Johnson saturation (review Sec. 4, Eqs. 86-93; Kalker,
   Three-dimensional elastic bodies in rolling contact, 1990; Johnson,
   Contact Mechanics, Sec. 8.4).

   Domain. Steady rolling with small creepage: the contact point moves over
   both bodies at the rolling speed V (much faster than the slip), the
   patch and the creepages change little while a material point crosses the
   contact (time 2a/V), the bodies are quasi-identical (Kalker's combined
   G and nu; a pair that is not quasi-identical gets the same combination,
   its normal-tangential coupling is ignored). Kalker's linear theory is
   exact for infinitesimal creepage (no slip anywhere); Vermeulen-Johnson
   saturates the force at mu F_bound for large creepage.

   Zero rolling speed (the rule). Creepage is slip / V. When V <= v_min
   (rollingVelocityMin) the law does not act: dc_rolling_force returns
   DC_OK with zero force and moment and out->rolling = 0, and the
   tangential law of the contact (history based, e.g. cmd_tangential) is
   the one that acts; with rolling = 1 a wrapper applies the creep force
   in its place. No division by V happens below v_min, so V -> 0 gives no
   overflow.

   Kinematics (review Eqs. 89-91, derived; dc_rolling_kinematics). n is
   the unit normal from j to i; dv = w_i - w_j the difference of the
   material velocities of the two bodies at the contact point
   (w = v + omega x (c - x_centre)), s its tangential part (the rigid
   slip); dw = omega_i - omega_j. With K_i, K_j the curvature tensors of
   the two surfaces at the contact (convex positive, in the tangent
   plane), the contact point moves over body i at u_i and over body j at
   u_j = u_i + s, where the normal's rate on both bodies agrees:
       K_i u_i + K_j u_j = dw x n,
   so the rolling velocity (mean of the two) is
       Vbar = (K_i + K_j)^-1 [dw x n + (K_i - K_j) s / 2],
   V = |Vbar|, x = Vbar / V (rolling direction), y = n x x, and
       xi_x = s.x / V,  xi_y = s.y / V,  phi = dw.n / V.
   Checks: sphere rolling on a plane without slip: Vbar = omega R; a
   stationary sphere on a belt moving at U: V = U/2, xi = 2 (the full
   slip of Kalker's definition); i and j swapped: same Vbar.
   Seed errors (OCR text), checked with spheres (body i above j, n = z,
   w_i = v_i + Omega_i x (-R_i z), w_j = v_j + Omega_j x (R_j z)):
   - Eq. 89 is the longitudinal rigid slip over Vbar, right for spheres;
     for other shapes the lever arm is c - x_centre, not a radius of
     curvature (the wrapper puts it into dv).
   - Eq. 90 is labelled xi_x (it is xi_y) and reads
     [v_iy - v_jy - (Omega_ix/Omega_iy - Omega_jx/Omega_jy) Vbar] / Vbar.
     The lateral rigid slip is v_iy - v_jy + R_i Omega_ix + R_j Omega_jx;
     the printed ratios equal R Omega_x / Vbar only in pure rolling
     (R_i Omega_iy = Vbar), there with the opposite sign, and they divide
     by Omega_y (zero for a body that does not turn).
   - Eq. 91 is right; Vbar is not defined in the seed: the formula above
     is the rolling velocity of two convex bodies.

   Forces (Eqs. 86-88, dc_rolling_force). With c = (a b)^1/2 and G, nu
   combined (G = 2/s0, nu = s1/s0 from dc_mindlin_pair), on body i:
       F_x = -G c^2 c11 xi_x
       F_y = -G c^2 c22 xi_y - G c^3 c23 phi
       M_z =  G c^3 c23 xi_y - G c^4 c33 phi      (about n)
   Seed error: Eqs. 86-88 print (a_c b_c)^2, (a_c b_c)^3, (a_c b_c)^4;
   the powers belong to c = (a_c b_c)^1/2 (Kalker's c^2, c^3, c^4): the
   printed forms are not forces (m^4 G), and Eqs. 92-93 of the same review
   use a_c b_c = c^2. The signs hold for x along the rolling velocity, y =
   n x x, creepages of i against j (tests/reference/gen_kalker.py: the
   lateral force from positive spin is negative, the moment from positive
   lateral creepage positive, both with the same c23).
   The force lies in the plane: F = F_x x + F_y y; on j: -F, -M_z n.

   Creep coefficients c11, c22, c23, c33 of the axis ratio g = a_x/b_y
   (a_x the semi-axis along the rolling direction) and nu in [0, 0.5]:
   computed by tests/reference/gen_kalker.py (Galin polynomial traction
   expansion on the ellipse, least leading-edge traction, extrapolated in
   the degree; see there) on 17 Chebyshev-Lobatto points of ln g in
   [ln 0.1, ln 10] and 9 Chebyshev points of nu; the law evaluates the
   Chebyshev series of ln c_ij, in nu and then on 129 uniform points of
   ln g once per material pair; per call a 4-point Lagrange interpolation
   in ln g (within 2e-6 of the series: the long fuzz, 1e6 calls, found
   1.24e-6 at nu = 0.5 next to g = 0.1, the grid's end). Kalker's published values (1990,
   Table E.3: c11, c22, c23 to 3 digits for g = 0.1..10, nu = 0, 0.25,
   0.5) lie within 1.2 % of these, within 0.8 % for g in [0.2, 5], and
   below them in 111 of 171 entries (his expansion was of lower degree).
   Outside [0.1, 10]: Kalker's asymptotes (1990, as for the
   published table), scaled to meet the table at its edge: for g < 0.1 the
   scale tends to 1 as g (c11, c22, c33) and g^1/2 (c23), for g > 10 as
   Lambda^-2, Lambda = ln(16 g^2) (the order of the asymptotes' remainder).
   c33 for g > 10 has no published asymptote: c33(10) (Lambda/Lambda(10))^p
   with p from the slope of ln c33 at the edge. Errors: see
   dc_kalker_coefficients.

   Rolling not along an axis of the patch (Kalker's theory assumes it is),
   at the angle alpha to the major axis: the coefficients of the effective
   axis ratio g = h(alpha)/h(alpha + 90 deg), h the patch's half-width along
   a direction (h^2 = a^2 cos^2 + b^2 sin^2), with c33 times the ratio of
   the lateral second moments of the patch and of that aligned ellipse,
   h(alpha) h(alpha + 90 deg) / (a b); the cross terms of oblique rolling
   (F_x from eta and phi, M_z from xi) are left out. Exact on the axes and
   for circles. Against gen_kalker.py --oblique-table (the same expansion
   for a turned ellipse, kalker_oblique.csv; test_rolling_kalker.c prints
   the figures): a/b = 2 at 20 and 45 deg, nu = 0..0.5: c11, c22, c23
   within 4.6 %, c33 10-21 % low, cross terms up to 11 % of c11; a/b = 5
   at 20, 45, 70 deg: c11 within 5 %, c22 11 %, c23 15 %, c33 6-66 % low,
   cross terms up to 12 %. (The mean of the two aligned sets,
   cos^2 c(a/b) + sin^2 c(b/a), is 7-154 % off at 45 deg.) Oblique
   rolling of elongated patches is therefore approximate, above all the
   spin moment.

   Vermeulen-Johnson (Eqs. 92-93, setting rollingCreepModel = 1). With F_L
   the linear force (above, spin included in F_y as Shen, Hedrick & Elkins
   1983 do) and beta = |F_L| / (mu F_bound):
       F = F_L [1 - (1 - beta/3)^3] / beta   (beta < 3),  F = mu F_bound F_L/|F_L|  (beta >= 3),
   which is Eqs. 92-93 solved for F (for each component,
   xi_i = -3 mu F_n/(c^2 G c_ii) (F_i/F_t)[1 - (1 - F_t/(mu F_n))^1/3]),
   equal to Kalker's F to first order in creepage and |F| = mu F_bound at
   beta >= 3. M_z: the linear moment times the same factor (Shen, Hedrick &
   Elkins), then bounded by the full-slip spin moment of the Hertz
   pressure, M_s = 3/8 mu F_bound a E(e^2). Linear Kalker (setting 0) is
   bounded the same way: |F| <= mu F_bound (scaled back onto the disc),
   |M_z| <= M_s; inside its domain neither bound acts. */
#ifndef DC_ROLLING_KALKER_H
#define DC_ROLLING_KALKER_H

#include <float.h>
#include <math.h>
#include "dc/contract.h"
#include "dc/mindlin.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Setting rollingCreepModel. */
enum { DC_ROLLING_KALKER = 0, DC_ROLLING_VJ = 1 };

/* Chebyshev-Lobatto nodes of ln(a_x/b_y) in [-ln 10, ln 10]. */
#define DC_KALKER_NODES 17
/* Uniform points of ln(a_x/b_y) in [-ln 10, ln 10] of a material's table. */
#define DC_KALKER_FINE 129

/* Per type pair. */
typedef struct {
  double mu;     /* coefficientFriction, >= 0 */
  double v_min;  /* rollingVelocityMin [m/s], > 0: at V <= v_min the law does not act */
  int model;     /* setting rollingCreepModel: DC_ROLLING_KALKER or DC_ROLLING_VJ */
  double roll_min;  /* rollingDistanceMin [-], >= 0: the net distance a contact must have
                       rolled, over its patch's semi-axis a, before the law acts
                       (dc_rolling_acts_rolled); 0: at once */
} dc_rolling_params;

/* Parameter check (dc/contract.h): mu >= 0 finite, v_min > 0 finite,
   model 0 or 1, roll_min >= 0 finite. DC_OK, or DC_EDOM with err naming the property. */
int dc_rolling_check(const dc_rolling_params *p, dc_param_error *err);

/* The material pair as the law needs it: Kalker's G and nu and the
   coefficient series at this nu. Plain data, filled once per type pair. */
typedef struct {
  double G;                         /* 2 / s0 [Pa] */
  double nu;                        /* s1 / s0, in [0, 0.5] */
  double fine[DC_KALKER_FINE][4];   /* c11, c22, c23, c33 at ln g = ln 10 (k/64 - 1), from the series */
  double circle[4];                 /* c11, c22, c23, c33 at g = 1 */
  double edge_lo[4], edge_hi[5];    /* table / asymptote at g = 0.1 and g = 10 (c33: value, power) */
} dc_rolling_material;

/* From the compliance sums of dc_mindlin_pair_init (s0 > 0). DC_EDOM with
   err naming "poissonsRatio" when nu = s1/s0 is outside [0, 0.5] (Kalker's
   coefficients are tabulated there), or "youngsModulus" when s0 is not
   positive and finite or is below 2/DBL_MAX (G = 2/s0 overflows); rm
   untouched then. */
int dc_rolling_material_init(const dc_mindlin_pair *m, dc_rolling_material *rm, dc_param_error *err);

/* Kalker's creep coefficients. */
typedef struct {
  double c11, c22, c23, c33;
} dc_kalker_coef;

/* c_ij for the axis ratio g = a_x / b_y (semi-axis along the rolling
   direction over the one across it), g in [1e-150, 1e150] (else DC_EDOM).
   Accuracy (tests/unit/test_rolling_kalker.c prints it): for g in
   [0.1, 10] the series differ from gen_kalker.py at points not used by
   them by at most 1.4e-6 (c11), 3.0e-6 (c22), 2.6e-5 (c23), 9.1e-5 (c33)
   relative, within the generator's own error estimate (<= 4e-4). Beyond,
   against the generator: g = 0.01, 0.03: c11, c22, c33 within 0.7 %, c23
   within 2.9 %; g = 30: c11, c22, c23 within 0.3 %, c33 2.6 %; g = 100:
   c11 within 1 %, c22 and c23 within 4.6 %, c33 within 4 % for nu <= 0.25
   and +51 % at nu = 0.5 (where the generator is itself uncertain by 2-20 %). */
int dc_kalker_coefficients(const dc_rolling_material *rm, double g, dc_kalker_coef *c);

/* The same for any nu in [0, 0.5] without a material (slow: sums the nu
   series at every node; for tests and tools). */
int dc_kalker_coefficients_nu(double g, double nu, dc_kalker_coef *c);

/* Principal curvatures of one body's surface at the contact point. */
typedef struct {
  double k1, k2;   /* [1/m], >= 0 for convex surfaces, 0 for a flat one */
  double d1[3];    /* unit direction of k1 in the tangent plane; ignored when k1 == k2 */
} dc_rolling_curvature;

/* What the kinematics give the force law. */
typedef struct {
  double V;          /* rolling speed |Vbar| [m/s] */
  double ex[3];      /* rolling direction Vbar / V (zero when V == 0) */
  double slip[3];    /* rigid slip s (tangential part of dv) [m/s] */
  double spin;       /* dw . n [rad/s] */
} dc_rolling_kin;

/* Rolling velocity, direction and slip (review Eqs. 89-91, derived above)
   from the unit normal n (from j to i, |n|^2 within 1e-6 of 1), the
   curvatures of i and j, dv = w_i - w_j at the contact point and
   dw = omega_i - omega_j. K_i + K_j must be positive definite (the
   relative curvature of a contact; its smaller eigenvalue > 1e-12 of the
   larger), every input finite, d1 unit and in the plane (within 1e-6)
   where k1 != k2; else DC_EDOM (a subnormal relative curvature, a radius
   beyond 1e308 m, may be taken as flat). DC_ERANGE when V or the sum of
   the curvatures overflows. Where the normal part of dv exceeds its
   tangential part by 1e12 and more, the rounding of the normal part rules
   the slip and the direction (only finite outputs are promised then).
   Outputs untouched on error. */
int dc_rolling_kinematics(const double n[3], const dc_rolling_curvature *ci,
                          const dc_rolling_curvature *cj, const double dv[3],
                          const double dw[3], dc_rolling_kin *k);

/* As dc_rolling_kinematics, with each relative principal radius capped at
   R_max [m] (R_max in (0, inf], inf: no cap), as the normal models cap
   them (maxRadiusFactor times the effective radius): where K_i + K_j is
   below 1/R_max along a principal direction it is raised to 1/R_max there,
   half of the raise added to each body, so that K_i - K_j (the slip term)
   is kept. A relative curvature that is still not positive definite (flat
   on flat with R_max = inf, a line contact, concave input; the test of
   dc_rolling_kinematics) has no rolling velocity: V = 0, ex = 0, slip and
   spin as defined, DC_OK, so that the contact is not rolling (the
   tangential law acts). The other domain errors as dc_rolling_kinematics;
   DC_EDOM for R_max <= 0 or NaN. For the LIGGGHTS wrappers, whose
   superquadric faces may be flat. */
int dc_rolling_kinematics_capped(const double n[3], const dc_rolling_curvature *ci,
                                 const dc_rolling_curvature *cj, const double dv[3],
                                 const double dw[3], double R_max, dc_rolling_kin *k);

/* Output of the force law. */
typedef struct {
  double F[3];                  /* creep force on body i [N] (on j: -F) */
  double Mz;                    /* spin moment on body i about n [N m] (on j: -Mz) */
  double Fx, Fy;                /* F along ex and along n x ex */
  double xi_x, xi_y, phi;       /* creepages [-], [-], spin creepage [1/m] */
  dc_kalker_coef c;             /* coefficients used */
  double saturation;            /* |F| / (mu F_bound), 0..1 (0 when mu F_bound = 0) */
  double step_factor;           /* dc_rolling_force_step's factor on the linear law (1: dc_rolling_force) */
  int rolling;                  /* 1: the creep force acts; 0: V <= v_min or no contact (zeros) */
} dc_rolling_out;

/* Creep force and spin moment of one contact (Eqs. 86-88, 92-93): p
   checked, rm from dc_rolling_material_init, patch of this step (a >= b,
   b > 0 and b >= 1e-150 a when formed: the axis ratios of
   dc_kalker_coefficients; F_bound >= 0, unit axis in the plane for a > b), n
   the unit normal (as for the kinematics), k from dc_rolling_kinematics.
   Not formed, a == 0 or V <= v_min: zeros, rolling = 0, DC_OK. DC_EDOM for
   an input out of its domain or non-finite; DC_ERANGE when a result
   overflows, or a slip component beyond DBL_MAX/4 overflows its dot
   product with the rolling direction. out untouched on error. No
   allocation; a circular patch skips the coefficient series. */
int dc_rolling_force(const dc_rolling_params *p, const dc_rolling_material *rm,
                     const dc_patch *patch, const double n[3], const dc_rolling_kin *k,
                     dc_rolling_out *out);

/* What the explicit time step of a DEM code needs to know of the two
   bodies: the step dt [s], the slip's inverse effective mass
   inv_m = sum over the bodies of 1/m + r^2/I [1/kg] (r the lever arm to
   the contact point, I the moment of inertia about an axis in the contact
   plane; a sphere on a plane: 7/(2m)) and the spin's inverse inertia
   inv_I = sum of 1/I about the normal [1/(kg m^2)]; a wall adds nothing. */
typedef struct {
  double dt, inv_m, inv_I;
} dc_rolling_step;

/* Stable at any time step. Near zero creepage the law is a viscous force
   on the slip, F = -(G c^2 c11 / V) s (and the like for the lateral slip
   and the spin), so a DEM code's explicit step, which applies this step's
   F over the next, multiplies the slip by 1 - x per step, x = dt G c^2
   c11 / (V m_eff): it flips the force's sign every step beyond x = 1
   (chatter) and grows beyond x = 2. The force of this function is the
   linear law times dc_rolling_step_factor(x) = (1 + x^4)^-1/4, before
   saturation, with x the largest step ratio of the coupled law: dt G c^2
   / V times the spectral radius of M^-1 A on (s_x; s_y, c omega_n), i.e.
   the larger of c11 inv_m and that of the block [[c22 inv_m, c23 inv_m],
   [-c23 c^2 inv_I, c33 c^2 inv_I]] (lateral slip and spin, coupled by
   c23). Then x (1 + x^4)^-1/4 < 1 at every x: a real mode shrinks each
   step without changing sign, at large x towards the force that stops it
   in one step, m_eff |s| / dt; a complex pair (c23^2 c^2 inv_I large
   against ((c22 inv_m - c33 c^2 inv_I)/2)^2 / inv_m) still shrinks, its
   real part being at least sqrt(c22 c33 / (c22 c33 + c23^2)) of its
   modulus. At x <= 0.2 (dt below a tenth of the explicit limit) the force
   is the linear law within x^4 / 4 <= 4e-4. A steady rolling contact
   (x small) gets Kalker's law.
   step: dt >= 0, inv_m >= 0, inv_I >= 0, finite (else DC_EDOM); otherwise
   as dc_rolling_force; out->step_factor holds the factor. */
int dc_rolling_force_step(const dc_rolling_params *p, const dc_rolling_material *rm, const dc_patch *patch,
                          const double n[3], const dc_rolling_kin *k, const dc_rolling_step *step,
                          dc_rolling_out *out);

/* (1 + x^4)^-1/4 for x > 0, 1 for x <= 0 or NaN; 1/x where x^4 overflows
   (0 at x = +inf: a step ratio that overflows, inputs at the edge of the
   doubles, gives no linear force). */
double dc_rolling_step_factor(double x);

/* The hand-over rule (zero rolling speed, above): 1 when dc_rolling_force
   acts on this contact (rolling = 1: patch formed, a > 0, V > v_min), 0
   when the contact's tangential law acts instead. For a wrapper whose
   tangential law runs before the rolling law and must know which of the
   two acts. Reads p->v_min, patch->formed, patch->a and k->V only; no
   domain check (dc_rolling_force makes them). */
int dc_rolling_acts(const dc_rolling_params *p, const dc_patch *patch, const dc_rolling_kin *k);

/* The hand-over rule with Kalker's steady state: the creep law is the
   steady-state law of a contact that rolls, whose traction pattern is set
   up as material crosses the patch (Kalker's transient rolling: the creep
   force builds over a rolled distance of the order of the patch, and a
   contact that rocks back and forth never reaches it). So the law acts
   once the contact has rolled a net distance of roll_min a since it last
   stopped: rolled[3] (the contact's history, zero for a new contact)
   accumulates Vbar dt = V ex dt while the patch is formed and V > v_min,
   and is cleared otherwise; returns 1 when |rolled| >= roll_min a (a the
   patch's semi-axis; roll_min = 0: dc_rolling_acts). dt >= 0. A rocking
   contact's rolled distance returns towards zero; steady rolling grows it
   by V dt per step. No domain check (dc_rolling_force makes them). */
int dc_rolling_acts_rolled(const dc_rolling_params *p, const dc_patch *patch, const dc_rolling_kin *k, double dt,
                           double rolled[3]);

/* An upper bound of the rolling speed V of two isotropic bodies (spheres,
   a sphere on a plane: curvatures ki, kj >= 0 with ki + kj > 0) from the
   relative velocity dv at the contact point and the relative spin dw,
   without the kinematics: V = |P (dw x n / (ki + kj) + h s)| with
   |h| <= 1/2 and |s| <= |dv| (the isotropic case of Eqs. 89-91 above), so
   V <= |dw| / (ki + kj) + |dv| / 2 <= the same with 1-norms, returned with
   a margin of 1e-9 for rounding (+inf where that is not finite). A
   bound <= v_min tells a wrapper that dc_rolling_acts is 0 without the
   kinematics (a settled or sliding contact that does not roll). Inline,
   unchecked. */
static inline double dc_rolling_speed_bound_isotropic(double ki, double kj, const double dv[3], const double dw[3])
{
  const double w = fabs(dw[0]) + fabs(dw[1]) + fabs(dw[2]), v = fabs(dv[0]) + fabs(dv[1]) + fabs(dv[2]);
  const double b = (w / (ki + kj) + 0.5 * v) * (1.0 + 1e-9);
  return b <= DBL_MAX ? b : HUGE_VAL;
}

#ifdef __cplusplus
}
#endif
#endif
