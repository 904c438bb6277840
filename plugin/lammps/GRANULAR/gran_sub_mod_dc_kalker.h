/* LAMMPS rolling sub-model dc/kalker: rolling contact of spheres by
   Kalker's linear creep theory with the Vermeulen-Johnson saturation as a
   setting (c_core: dc/rolling_kalker.h), the project's LIGGGHTS model
   `rolling_friction kalker` (rolling_model_kalker.h, rolling_contact.h).
   Creep forces and the spin moment while the contact rolls; not a
   rolling-resistance torque.

   pair_coeff ... rolling dc/kalker mu creep vmin dmin
     mu    coefficient of friction [-] >= 0 (saturation at mu F_bound;
           LIGGGHTS: coefficientFriction)
     creep 0: Kalker's linear law bounded by mu F_bound, 1: Vermeulen-Johnson
           (LIGGGHTS: rollingCreepModel kalker | vermeulenJohnson, default 1)
     vmin  rolling speed [m/s] in (0, inf) at or below which the contact does
           not roll (LIGGGHTS: rollingVelocityMin, default 1e-3)
     dmin  net rolled distance [-] >= 0, over the patch's semi-axis a, before
           the law acts (LIGGGHTS: rollingDistanceMin, default 2; 0: at once)
   Kalker's material: the two bodies' materials as the normal sub-model has
   them (DcContactReader: both of its E and nu, or of a mixed type pair's
   two), nu in [0, 0.5]. maxRadiusFactor of the
   LIGGGHTS model concerns superquadrics only.

   Who owns the tangential force (GranSubModDcHandover, dc_sub_mod.h):
   rolls() decides per contact and step from the kinematics of this step,
   as rolling_contact.h does, when the project's tangential sub-model asks
   (it runs first); while the contact rolls the tangential sub-model
   applies nothing and starts its history afresh, and this sub-model
   applies the creep force and the spin moment. The normal sub-model must
   be one of the project's (the contact patch) and the tangential one a
   dc/ one that hands over: else an error at init, as LIGGGHTS stops at
   set-up.

   How the force is applied. LAMMPS applies a rolling sub-model's gm->fr as
   a torque Reff (n x fr) only, a rolling resistance. A creep force is a
   tangential force at the contact point: calculate_forces adds it to
   gm->forces and its moment to gm->torquesi/torquesj with the lever arms
   of LAMMPS' pair, radius - delta/2 (a wall as well, as LIGGGHTS), adds
   the spin moment about n, and sets gm->fr to zero.

   History: the net rolled distance (3 values, not flipped when i and j
   swap) when dmin > 0. */
#ifdef GRAN_SUB_MOD_CLASS
// clang-format off
GranSubModStyle(dc/kalker,GranSubModRollingDcKalker,ROLLING);
// clang-format on
#else
#ifndef GRAN_SUB_MOD_DC_KALKER_H
#define GRAN_SUB_MOD_DC_KALKER_H

#include "dc/rolling_kalker.h"
#include "dc_sub_mod.h"
#include "gran_sub_mod_rolling.h"

namespace LAMMPS_NS {
namespace Granular_NS {

class GranSubModRollingDcKalker : public GranSubModRolling, public GranSubModDcHandover {
 public:
  GranSubModRollingDcKalker(class GranularModel *, class LAMMPS *);
  void coeffs_to_local() override;
  void init() override;
  void calculate_forces() override;
  bool rolls() override;

 protected:
  dc_rolling_params params_ = {};
  dc_rolling_material material_ = {};
  dc_rolling_kin kin_ = {};
  DcContactReader contact_;
  bool decided_ = false, acts_ = false;
};

}    // namespace Granular_NS
}    // namespace LAMMPS_NS

#endif
#endif
