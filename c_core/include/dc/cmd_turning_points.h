/* Mindlin-Deresiewicz tangential force with bounded memory: the force and
   a few remembered turning points carry the state (cmd_tangential's
   setting cmdMemory turningPoints; the exact spring profile is
   dc/cmd_tangential.h).

   Model, one direction at constant friction load S = mu F_bound (review
   Eqs. 59, 66-68; Mindlin & Deresiewicz 1953): each branch of the
   load path starts at an anchor A (0 for the virgin branch, else the
   turning point where it began) and follows
     F = A + sigma m S (1 - theta^3),  theta^2 = 1 - c2,
     c2 grows by 2 k s / (3 m S) with the displacement s along the branch,
   m = 1 on the virgin branch, 2 on later ones (Masing's rule); theta is
   the stuck fraction of the contact radius, k Mindlin's no-slip stiffness
   k_major (dc/mindlin.h). c2 is linear in s, so a step has no step-size
   error. A reversal pushes the force as a turning point and starts a
   branch with m = 2; a branch that reaches the previous turning point
   continues on the branch before it (the memory rule: Madelung's rule,
   the return to the virgin curve at minus the first turning point); full
   slip (|F| = S) clears the memory. At constant S this equals the exact
   spring profile to rounding for every path with at most
   DC_CMDTP_MAX_TURNS turning points remembered at once. A reversal with
   the memory full forgets the two newest turning points (the innermost
   loop): the branches that would have returned to them return to the
   older one.

   Varying friction load (Eqs. 70-71), between the steps' displacements:
   a smaller S clips the slipping annulus: the force falls by
   (S_prev - S)(1 - theta) along its branch, and turning points outside
   the new limit are drawn onto it; a larger S leaves the force (the
   annulus sticks). Either way theta is then taken from the force (a
   cube root: Newton steps from the previous step's theta^2). This is where the law is approximate (the exact profile
   keeps the annulus' shape; here the branch is a Mindlin-Deresiewicz
   branch again at once); the measured differences are in
   doc/cmd_tangential.md.

   Three dimensions: the force and the turning points turn with the
   contact plane as the exact law's profile does (the rotation taking the
   previous normal to the new one). The displacement of the stuck springs
   d = M du (M = diag(1, k_minor/k_major) in the ellipse axes, as the
   exact law) splits into its part along the branch's excess X = F - A,
   which drives the branch (a negative part is a reversal), and the rest,
   which turns X with the stiffness of the stuck core, k theta. |F| <= S.
   A subnormal force or displacement has too few bits for a direction: the
   first starts a fresh branch, the second counts as none.

   Twisting (flag): the same law for the moment about n, with Mindlin's
   torsional stiffness and the full-slip moment of dc/cmd_tangential.h.
   Dissipation (flag, Eq. 85): A_t theta k d/dt added to the output force
   (not stored), |F| <= S kept. Signs and units as dc/cmd_tangential.h. */
#ifndef DC_CMD_TURNING_POINTS_H
#define DC_CMD_TURNING_POINTS_H

#include "dc/cmd_tangential.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Turning points remembered at once (force and twist each). */
#define DC_CMDTP_MAX_TURNS 4

/* Per-contact history: plain doubles, all zero at the start. */
typedef struct {
  double n_prev[3];                    /* normal of the previous step (flips); 0: fresh */
  double F[3];                         /* the spring force [N] (flips) */
  double c2;                           /* 1 - theta^2 of the current branch, in [0, 1] */
  double S_prev;                       /* friction limit mu F_bound of the previous step [N] */
  double nturn;                        /* turning points remembered, 0 .. DC_CMDTP_MAX_TURNS */
  double T[DC_CMDTP_MAX_TURNS][3];     /* their forces, oldest first [N] (flips) */
  double M;                            /* the twisting spring moment [N m] */
  double c2_t, S_prev_t, nturn_t;      /* as c2, S_prev (full-slip moment), nturn */
  double Tt[DC_CMDTP_MAX_TURNS];       /* twist turning points [N m] */
} dc_cmdtp_state;

enum { DC_CMDTP_HISTORY_NFIELDS = (int)(sizeof(dc_cmdtp_state) / sizeof(double)) };
/* Without twisting only the first DC_CMDTP_FORCE_NFIELDS fields (up to M)
   are read or written: a wrapper may store just those. */
enum { DC_CMDTP_FORCE_NFIELDS = (int)(offsetof(dc_cmdtp_state, M) / sizeof(double)) };
extern const dc_history_field dc_cmdtp_history[DC_CMDTP_HISTORY_NFIELDS];

/* One step of one contact: inputs, outputs and errors as dc_cmd_step,
   with h this law's history: nturn (and nturn_t with twisting) a whole
   number in [0, DC_CMDTP_MAX_TURNS], c2 (c2_t) in [0, 1], S_prev
   (S_prev_t) >= 0, all finite. On an error h and out are
   untouched. No allocation; the circle skips the elliptic integrals. */
int dc_cmdtp_step(const dc_cmd_params *p, const dc_mindlin_pair *m, const dc_patch *patch,
                  const double n[3], const double du[3], double dphi, double dt,
                  dc_cmdtp_state *h, dc_cmd_out *out);

/* The same for inputs in the domain by construction (a wrapper: the
   normal model's patch, a history this law wrote): only the counts and
   the results are checked; the same bits as dc_cmdtp_step wherever that
   returns DC_OK. */
int dc_cmdtp_step_trusted(const dc_cmd_params *p, const dc_mindlin_pair *m, const dc_patch *patch,
                          const double n[3], const double du[3], double dphi, double dt,
                          dc_cmdtp_state *h, dc_cmd_out *out);

#ifdef __cplusplus
}
#endif
#endif
