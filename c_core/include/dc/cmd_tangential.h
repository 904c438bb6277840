/* Cattaneo-Mindlin-Deresiewicz tangential force of elliptic and circular
   contacts with full load history, and Mindlin twisting (review Sec. 3.1,
   Eqs. 56-77 and 85; Mindlin 1949; Mindlin & Deresiewicz 1953; Johnson,
   Contact Mechanics, ch. 7).

   Model. The contact is a bed of independent annular "springs" at the
   normalised elliptic radius xi in [0, 1] (xi = r / semi-axis; homothetic
   ellipses), the one-dimensional picture of the method of dimensionality
   reduction (Popov & Hess), in which Cattaneo-Mindlin is exact:
   - every spring sticks and moves by the same displacement increment, or
     slips on its Coulomb limit |u(xi)| <= L0 (1 - xi^2),
     L0 = 3 mu F_bound / (2 k_major); the limits integrate to mu F_bound;
   - the force is F = k_major int_0^1 u(xi) dxi (k_major, k_minor: Mindlin's
     no-slip stiffnesses along the ellipse axes, dc/mindlin.h);
   - on an ellipse the stuck springs move by M du, M = diag(1, k_minor/k_major)
     in the axes (the no-slip compliance of review Eqs. 56-58, with the
     force not parallel to du);
   - as the patch grows the new rim enters unloaded; as it shrinks the rim
     leaves and takes its load along; a smaller friction load clips the
     springs (slip under decreasing normal force).
   With a fixed direction this is exactly Mindlin-Deresiewicz: virgin
   loading F = mu F_b [1 - (1 - 2 w / (3 mu F_b))^3/2], w = |K0 du| (Eq. 59,
   any theta; Eqs. 60-61 on the axes, Phi of Eq. 61 generalised to
   Phi(theta) = 4 / (pi (2 - nu) chi(theta))), unloading and reloading from
   turning points (Eqs. 66-68, Masing's factor 2), the closed loop and its
   energy (Eq. 69), the memory rule (a branch that reaches an earlier
   turning point continues on the earlier curve), gross sliding at
   mu F_bound, and the increments under varying normal force
   dF = theta k du +- mu dN (1 - theta) (Eqs. 70-71; theta = stick
   fraction), all without step-size error for a step in which du and the
   patch change linearly. The profile u(xi) is kept piecewise linear in
   xi^2 (each piece: end radius, end values): at constant normal force the
   pieces are the turning points.

   Seed errors (review, OCR text), checked with
   tests/reference/gen_cmd_tangential.py (an independent spring-bed
   simulation and quadrature):
   - Eqs. 56, 59, 66, 67 and 69 hold for one elastic body on a rigid one
     (circle: k = 8 G a / (2 - nu)), Eqs. 68 and 70-74 for two identical
     bodies (compliance (2-nu)/(4 G a)): Eq. 68 is not the derivative of
     Eq. 67 (that is (2-nu) Phi / (8 G a) (...)^-1/3). Implemented in the
     pair form: compliance sums of dc_mindlin_pair.
   - Eq. 71 (decreasing tangential, increasing normal force): the signs of
     mu dN/dF_t are reversed, and F* is the turning point shifted by the
     normal force since: with m = mu dN/dF_t,
       S = C0 [-m + (1 + m) (1 - (F* + mu (N - N*) - F)/(2 mu N))^-1/3],
     continuous with the no-slip branch S = C0 at m = -1 (the printed form
     gives C0 (2 (...)^-1/3 - 1) there); Eq. 73 (first line) is this form.
     Checked by a brute-force spring bed to 2e-7 (generator) and by the law.
   - Eq. 73, second line: [1 + 1/(1 + Theta Lambda)] is [1 + Lambda/(1 +
     Theta Lambda)] (the virgin curve in reverse after the memory point;
     the printed one misses the brute-force bed by 40 %).
   - Eqs. 72-74 and 75 hold with C0 at the current contact radius (Eq. 75
     is the exact area of the stabilised loop to 25 digits); Eq. 76 is its
     small-amplitude limit (without the stray eta) in the one-body form.
   - Eq. 85: F_dis = eta/(2G) d(delta)/dt dF/d(delta) is right; its second
     form drops the factor G^/G (dF/d delta = 8 G^ a / Phi (...)^1/2).
   - Eq. 77 (twisting) is right for two identical bodies with "mu" the shear
     modulus and R_i the semi-major axis a; for a pair of different bodies
     the 2x2 Cerruti system of dc_cmd_twist_stiffness replaces it.

   Three-dimensional rule. The history vectors (the spring profile, in
   global coordinates) turn with the contact plane: each step they are
   rotated by the rotation that takes the previous normal to the new one
   (magnitudes and angles kept), and what is left along n is projected off.
   A spring whose trial displacement leaves its Coulomb disc slips radially
   back onto it; each contiguous slipping zone takes one direction, that of
   its integrated trial displacement. In a fixed direction this is exact
   (above); a change of direction loads the stuck core elastically and the
   rim slips along the new resultant (the vector form of Thornton & Yin
   1991 / Vu-Quoc & Zhang 1999 with no special cases: |F| <= mu F_bound
   always, since every spring is on or inside its limit). Between the axes
   of an ellipse the force keeps Mindlin's no-slip direction while the
   exact one turns toward the displacement as slip spreads: against a
   boundary-element solution (tests/reference/gen_cmd_bem.py) the force
   magnitude is within 0.06 % of mu F in every direction, the direction
   within 0.6 degrees in partial slip and 2.8 degrees in sliding (b/a =
   0.3, theta = 45 degrees, nu = 0.3).

   Twisting (flag): Mindlin's no-slip torsional stiffness of the ellipse
   (dc_cmd_twist_stiffness, checked against Eq. 77 and a Cerruti
   quadrature; circle 16 a^3 / (3 s0), i.e. 16 G a^3 / 3 for one body on a
   rigid one), the full-slip moment M_s = 3/8 mu F_b a E(e^2) (circle
   3 pi mu F_b a / 16), and between them the same spring bed and memory as
   the force, with the Cattaneo-shaped limits: M = M_s [1 - (1 -
   2 k phi / (3 M_s))^3/2] on first loading. This is not Lubkin's exact
   partial-slip curve (which reaches M_s only asymptotically); its ends are
   exact, in between it lies up to 0.20 M_s above Lubkin's curve (circle;
   0.215 M_s for b/a = 0.5 against a boundary-element solution:
   tests/reference/cmd_bem_comparison.md).

   Dissipation (flag, review Eq. 85): F_dis = A_t dF/d(delta) d(delta)/dt,
   A_t = eta/(2G) [s] (property tangentialViscoelasticTime), with the
   tangent stiffness of the stuck core; |F_t| stays <= mu F_bound (the sum
   is scaled back onto it).

   Signs: du is the displacement of body i relative to body j at the
   contact point in this step; Ft is the spring force along the
   accumulated displacement (for a stuck contact Ft = K0 du): the force on
   i is -Ft and on j +Ft (LIGGGHTS' shear history convention). dphi is the
   relative rotation (omega_i - omega_j) . n dt; the moment on i is
   -Mt n. */
#ifndef DC_CMD_TANGENTIAL_H
#define DC_CMD_TANGENTIAL_H

#include <stddef.h>
#include "dc/contract.h"
#include "dc/mindlin.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Pieces of the spring profile (force and twist each). At constant normal
   force a profile holds 2 + (number of remembered turning points) pieces,
   and every state that fits is exact. Beyond the cap, pairs of neighbouring
   pieces are replaced by one (linear in xi^2, keeping their force and their
   outer value exactly), least mean-square change first, down to one piece
   below the cap: a remembered turning point is lost, and the branches that
   would have returned to it are approximate (test: 12 nested turning
   points, at most 1.4e-4 mu F_n beyond the cap). Loading past the largest
   turning point still returns to the virgin curve. */
#define DC_CMD_MAX_SEG 8
#define DC_CMD_MAX_TURNS (DC_CMD_MAX_SEG - 2)

/* Per type pair. */
typedef struct {
  double mu;        /* coefficientFriction, >= 0 */
  double t_visc;    /* tangentialViscoelasticTime A_t = eta/(2G) [s], >= 0 (used with dissipation) */
  int dissipation;  /* setting cmdDissipation: 1 adds Eq. 85 */
  int twisting;     /* setting cmdTwisting: 1 computes the twisting moment */
} dc_cmd_params;

/* Parameter check (dc/contract.h): mu >= 0, t_visc >= 0, both finite;
   flags 0 or 1. DC_OK, or DC_EDOM with err naming the property or setting. */
int dc_cmd_check(const dc_cmd_params *p, dc_param_error *err);

/* One piece of a profile, in the per-contact history: its outer radius
   xi (/ a_prev) and its values at the inner and outer end. */
typedef struct {
  double xi;
  double u0[3];   /* [m] (flips) */
  double u1[3];
} dc_cmd_piece;
typedef struct {
  double xi;
  double t0, t1;  /* [rad] (no flip: (w_i - w_j).n is symmetric) */
} dc_cmd_twist_piece;

/* Per-contact history: plain doubles, all zero at the start; piece by
   piece, so that a profile of few pieces reads and writes few cache lines. */
typedef struct {
  double n_prev[3];                   /* normal of the previous step (flips) */
  double a_prev;                      /* semi-major axis of the previous step [m]; 0: fresh */
  double nseg;                        /* pieces of the force profile */
  dc_cmd_piece seg[DC_CMD_MAX_SEG];   /* the force profile, from the centre out */
  double nseg_t;                      /* pieces of the twist profile */
  dc_cmd_twist_piece seg_t[DC_CMD_MAX_SEG];
} dc_cmd_state;

/* Its field table (dc/contract.h), in struct order: a wrapper registers
   DC_CMD_HISTORY_NFIELDS doubles and views them as a dc_cmd_state. */
enum { DC_CMD_HISTORY_NFIELDS = (int)(sizeof(dc_cmd_state) / sizeof(double)) };
/* Without twisting only the first DC_CMD_FORCE_NFIELDS fields (up to
   nseg_t) are read or written: a wrapper may store just those. */
enum { DC_CMD_FORCE_NFIELDS = (int)(offsetof(dc_cmd_state, nseg_t) / sizeof(double)) };
extern const dc_history_field dc_cmd_history[DC_CMD_HISTORY_NFIELDS];

/* Output of one step. */
typedef struct {
  double Ft[3];   /* tangential force [N], normal to n, |Ft| <= mu F_bound */
  double kt;      /* tangent stiffness along du (along Ft if du = 0) [N/m] */
  double stick;   /* stuck fraction of the contact radius, 0 (sliding) .. 1 */
  double Mt;      /* twisting moment about n [N m] (0 without twisting) */
  double kr;      /* torsional tangent stiffness [N m/rad] (0 without twisting) */
} dc_cmd_out;

/* One step of one contact (the hot path). Inputs:
   patch: this step's contact patch (dc/contract.h): a >= b >= 0 with
     b >= 1e-150 a (or a = b = 0), the unit major axis in the plane for
     a > b (zero allowed only for a circle), F_bound >= 0; formed = 0 resets
     the history and gives zeros;
   m: the material pair (dc_mindlin_pair_init), s0 > 0;
   n: the unit contact normal of this step (|n|^2 within 1e-6 of 1);
   du: displacement increment of this step (its normal part is removed);
   dphi: twist increment about n [rad] (read with twisting);
   dt: time step [s] > 0 (read with dissipation);
   h: all zero, or left by earlier calls (its breakpoints increase to 1,
   pieces past nseg are 0).
   Updates h (pieces it no longer uses become 0, so that one state has one
   history; the twist fields are not touched without twisting) and fills
   out. DC_EDOM for
   a non-finite or out-of-domain input (a history whose piece count nseg,
   or nseg_t with twisting, is not a whole number in [0, DC_CMD_MAX_SEG]
   included); DC_ERANGE when a result, a stored
   value or a limit (3 mu F_b / (2 k), the stiffnesses) overflows. On an
   error h and out are untouched. A friction load so small that the force
   is subnormal gives a force whose direction has few significant bits. No
   allocation; the circle (a == b) skips the elliptic integrals. */
int dc_cmd_step(const dc_cmd_params *p, const dc_mindlin_pair *m, const dc_patch *patch,
                const double n[3], const double du[3], double dphi, double dt,
                dc_cmd_state *h, dc_cmd_out *out);

/* dc_cmd_step for a caller whose inputs lie in the domain above by
   construction (a LIGGGHTS wrapper: LIGGGHTS' unit normal, the normal
   model's patch, a history this law wrote): their finiteness, ranges and
   the stored breakpoints' order are not checked (about a tenth of the
   step), the piece counts and the results are (DC_EDOM, DC_ERANGE, h and
   out untouched); the same bits as dc_cmd_step wherever that returns
   DC_OK. On an error, dc_cmd_step says which input is out of its domain. */
int dc_cmd_step_trusted(const dc_cmd_params *p, const dc_mindlin_pair *m, const dc_patch *patch,
                        const double n[3], const double du[3], double dphi, double dt,
                        dc_cmd_state *h, dc_cmd_out *out);

/* Mindlin's no-slip stiffnesses (dc_mindlin_stiffness) in one call from
   the semi-axes: k_major, k_minor [N/m] for a >= b > 0 (b >= 1e-150 a);
   both 8 a / (2 s0 - s1) for a == b. DC_EDOM outside; DC_ERANGE when one
   overflows (outputs untouched). */
int dc_cmd_stiffness(const dc_mindlin_pair *m, double a, double b, double *k_major, double *k_minor);

/* Mindlin's no-slip torsional stiffness dM/dphi of an elliptic contact,
   semi-axes a >= b > 0 (b >= 1e-150 a) [N m/rad]: the traction
   (-P y, Q x) (1 - x^2/a^2 - y^2/b^2)^-1/2 that turns the contact rigidly
   (Cerruti's kernel, compliance sums s0, s1) gives
     k = 2 pi/3 a [a^2 (s0 B - 2 s1 (B - D + C)) + b^2 (s0 D - 2 s1 C)] / det,
     det = a11 a22 - s1^2 C (B - D + C),
     a11 = (s0 - s1) B + s1 (D - C),  a22 = (s0 - s1) D + s1 (D - C),
   with B, C, D of e^2 = 1 - b^2/a^2 (dc/elliptic_integrals.h). Circle:
   16 a^3 / (3 s0). Review Eq. 77 is the same for two identical bodies.
   DC_EDOM outside; DC_ERANGE on overflow (k untouched). */
int dc_cmd_twist_stiffness(const dc_mindlin_pair *m, double a, double b, double *k);

/* Full-slip twisting moment of a Hertz pressure on the ellipse:
   M_s = 3/8 mu F a E(e^2) (circle 3 pi mu F a / 16). Same domain as
   dc_cmd_twist_stiffness, mu >= 0, F >= 0. */
int dc_cmd_twist_slip_moment(double mu, double F, double a, double b, double *M);

#ifdef __cplusplus
}
#endif
#endif
