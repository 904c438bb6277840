/* LAMMPS tangential sub-model dc/cmd_tangential and twisting sub-model
   dc/cmd_twisting: the Cattaneo-Mindlin-Deresiewicz tangential force of
   elliptic and circular contacts with full load history (c_core:
   dc/cmd_tangential.h, the exact spring profile) or with up to 4
   remembered turning points (dc/cmd_turning_points.h), and Mindlin's
   twisting moment about the normal by the same law; the project's
   LIGGGHTS model cmd_tangential (settings as numeric coefficients).

   tangential dc/cmd_tangential mu memory t_visc rough
     mu      coefficientFriction, >= 0
     memory  cmdMemory: 0 the exact profile, 1 turningPoints
     t_visc  tangentialViscoelasticTime [s] >= 0; 0: cmdDissipation off,
             > 0: cmdDissipation on (review Eq. 85)
     rough   tangentialRoughness: 0 (1 needs a rough normal sub-model
             publishing the summits' patch; none is in LAMMPS yet: refused)
   twisting dc/cmd_twisting    (no coefficients; cmdTwisting on)
     only with tangential dc/cmd_tangential: the law gives the force and
     the moment from one state in one call, so the tangential sub-model
     evaluates both and dc/cmd_twisting hands the moment to LAMMPS
     (magtortwist) and keeps the twist's part of the law's history.

   The contact patch (semi-axes, major axis, friction load, formed) is the
   project's normal sub-model's (DcContactReader); under a LAMMPS
   normal model the circle a = (R delta)^1/2, R the effective radius, with
   friction load its elastic force (not with a cohesive LAMMPS normal
   model). Mindlin's stiffness from the two bodies' materials as the
   normal model has them (DcContactReader; under a LAMMPS normal model
   its E and nu, mixed for a mixed type pair as LAMMPS' mindlin). The damping sub-model does not act on the tangential
   force: the law's dissipation is its own (slip, t_visc). With a rolling
   sub-model that takes the tangential force over (dc_handover) nothing
   is applied while the contact rolls and the history starts afresh. At a
   run's set-up (history_update 0) the law steps on a copy of the history,
   as the LIGGGHTS wrapper does: the set-up force holds one more step's
   increment, so two runs differ slightly from one (a restart does not). */
#ifdef GRAN_SUB_MOD_CLASS
// clang-format off
GranSubModStyle(dc/cmd_tangential,GranSubModTangentialDcCmd,TANGENTIAL);
GranSubModStyle(dc/cmd_twisting,GranSubModTwistingDcCmd,TWISTING);
// clang-format on
#else
#ifndef GRAN_SUB_MOD_DC_CMD_TANGENTIAL_H
#define GRAN_SUB_MOD_DC_CMD_TANGENTIAL_H

#include "dc/cmd_tangential.h"
#include "dc/mindlin.h"
#include "dc_sub_mod.h"
#include "gran_sub_mod_tangential.h"
#include "gran_sub_mod_twisting.h"

namespace LAMMPS_NS {
namespace Granular_NS {

class GranSubModTwistingDcCmd;

class GranSubModTangentialDcCmd : public GranSubModTangential {
 public:
  GranSubModTangentialDcCmd(class GranularModel *, class LAMMPS *);
  void coeffs_to_local() override;
  void mix_coeffs(double *, double *) override;
  void init() override;
  void calculate_forces() override;
  /* The twisting moment about n of this step [N m] (on i: -Mt n). */
  double moment() const { return Mt_; }
  int memory() const { return memory_; }

 private:
  dc_cmd_params params_ = {};
  DcContactReader contact_;
  GranSubModDcHandover *handover_ = nullptr;    // found once (a cast per call costs more than the law's plumbing)
  dc_mindlin_pair pair_ = {};
  int memory_ = 0;
  double Mt_ = 0.0;
  GranSubModTwistingDcCmd *twist_ = nullptr;
};

class GranSubModTwistingDcCmd : public GranSubModTwisting {
 public:
  GranSubModTwistingDcCmd(class GranularModel *, class LAMMPS *);
  void init() override;
  void calculate_forces() override;
  /* The twist's history fields in use (cmdMemory of the tangential). */
  int nfields() const { return nfields_; }

 private:
  GranSubModTangentialDcCmd *tangential_ = nullptr;
  int nfields_ = 0;
};

}    // namespace Granular_NS
}    // namespace LAMMPS_NS

#endif
#endif
