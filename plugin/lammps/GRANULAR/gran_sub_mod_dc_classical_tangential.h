/* LAMMPS tangential sub-model dc/classical: the classical tangential laws
   of the lecture notes as one sub-model with a law coefficient (c_core:
   dc/classical_tangential.h, classical_tangential_step.h), the project's
   LIGGGHTS model `tangential classical` (tangential_model_classical.h).

   pair_coeff ... tangential dc/classical law kt_mode damp_mode mu kt gammat e_t eta_l t_visc
     law       (LIGGGHTS classicalTangential) 0 coulomb, 1 viscous,
               2 viscousSliding, 3 springSliding, 4 springDashpotSliding,
               5 diRenzo, 6 langston, 7 zheng, 8 tsuji, 9 incremental
     kt_mode   (classicalTangentialStiffness; laws 3, 4, 9) 0 given (kt),
               1 ratio (4 G* / E* K_n, K_n the normal force over delta),
               2 mindlin (8 G* a)
     damp_mode (classicalTangentialDamping; laws 4, 5) 0 none, 1 given
               (gammat), 2 restitution (e_t), 3 normal (the damping
               sub-model's coefficient)
     mu        coefficient of friction [-] >= 0 (all laws but viscous)
     kt        [N/m] > 0 where kt_mode 0 is used (else any value)
     gammat    [N s/m] >= 0 (laws 1, 2; damp_mode 1)
     e_t       tangential restitution [-] in [0, 1] (damp_mode 2)
     eta_l     langstonDamping [-] >= 0 (law 6)
     t_visc    tangentialViscoelasticTime [s] >= 0 (law 7)
   The coefficients a law does not read are not checked (as the LIGGGHTS
   model, which does not ask for their properties); the ranges are those of
   dc_classical_tangential_check.
   G*, E* and the contact patch (semi-axis a, friction load F_bound) come
   from the normal sub-model (DcContactReader: under a LAMMPS normal model
   the circle (R delta)^1/2, as the LIGGGHTS model under a stock one);
   meff, the normal damping coefficient (the damping sub-model's) and K_n
   as LIGGGHTS' sidata.meff, gamman, kn. The velocity
   at the contact point is dc_contact_point_velocity's (lever arms
   radius - delta/2). LAMMPS applies this force's torque with the lever
   arms radius - delta/2 on a pair, radius on a wall.
   With a rolling sub-model that takes the tangential force over
   (dc/kalker; dc_handover), it applies nothing while the contact rolls
   and its history starts afresh, as the LIGGGHTS model.
   History: the spring (3 values), incremental also the force at the last
   reversal (3 more); they flip when i and j swap. */
#ifdef GRAN_SUB_MOD_CLASS
// clang-format off
GranSubModStyle(dc/classical,GranSubModTangentialDcClassical,TANGENTIAL);
// clang-format on
#else
#ifndef GRAN_SUB_MOD_DC_CLASSICAL_TANGENTIAL_H
#define GRAN_SUB_MOD_DC_CLASSICAL_TANGENTIAL_H

#include "dc/classical_tangential.h"
#include "dc_sub_mod.h"
#include "gran_sub_mod_tangential.h"

namespace LAMMPS_NS {
namespace Granular_NS {

class GranSubModTangentialDcClassical : public GranSubModTangential {
 public:
  GranSubModTangentialDcClassical(class GranularModel *, class LAMMPS *);
  void coeffs_to_local() override;
  void init() override;
  void calculate_forces() override;

 protected:
  int law_ = 0, nfields_ = 0;
  dc_classical_tangential model_ = {};
  DcContactReader contact_;
  GranSubModDcHandover *handover_ = nullptr;    // found once at init
};

}    // namespace Granular_NS
}    // namespace LAMMPS_NS

#endif
#endif
