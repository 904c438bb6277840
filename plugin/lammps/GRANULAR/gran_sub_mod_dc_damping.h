/* LAMMPS damping sub-models of the project's damping laws (c_core:
   dc/damping.h), on the tangent stiffness S = dF/d delta of a dc/ normal
   sub-model; the coefficient is the normal sub-model's `damp`:
     damping dc/restitution     damp = coefficient of restitution e in (0, 1]:
                                gamma = -2 (5/6)^1/2 beta (S m*)^1/2
     damping dc/viscoelastic    damp = dissipative time A [s] >= 0: gamma = A S
     damping dc/kuwabara_kono   damp = eta [N s m^-3/2] >= 0: gamma = eta delta^1/2
     damping dc/tsuji           damp = e in (0, 1] (the notes' alpha(e)):
                                gamma = alpha (2/3 S m*)^1/2
   F_damp = -gamma v_n, as the LIGGGHTS models' `damping` setting. The
   project's tangential sub-models damp with the same law on their tangential
   stiffness (gamma_of); LAMMPS' own tangential models see gamma as the
   damping prefactor. */
#ifdef GRAN_SUB_MOD_CLASS
// clang-format off
GranSubModStyle(dc/restitution,GranSubModDampingDcRestitution,DAMPING);
GranSubModStyle(dc/viscoelastic,GranSubModDampingDcViscoelastic,DAMPING);
GranSubModStyle(dc/kuwabara_kono,GranSubModDampingDcKuwabaraKono,DAMPING);
GranSubModStyle(dc/tsuji,GranSubModDampingDcTsuji,DAMPING);
// clang-format on
#else
#ifndef GRAN_SUB_MOD_DC_DAMPING_H
#define GRAN_SUB_MOD_DC_DAMPING_H

#include "gran_sub_mod_damping.h"

namespace LAMMPS_NS {
namespace Granular_NS {

class GranSubModDcNormal;

class GranSubModDampingDc : public GranSubModDamping {
 public:
  GranSubModDampingDc(class GranularModel *, class LAMMPS *, int law);
  void init() override;
  double calculate_forces() override;
  /* gamma [N s/m] of this law on a stiffness S [N/m] (the tangential one) */
  double gamma_of(double S) const;

 protected:
  int law;
  double coef;    // the law's coefficient (beta, A, eta or alpha)
  GranSubModDcNormal *normal;
};

class GranSubModDampingDcRestitution : public GranSubModDampingDc {
 public:
  GranSubModDampingDcRestitution(class GranularModel *gm, class LAMMPS *lmp);
};
class GranSubModDampingDcViscoelastic : public GranSubModDampingDc {
 public:
  GranSubModDampingDcViscoelastic(class GranularModel *gm, class LAMMPS *lmp);
};
class GranSubModDampingDcKuwabaraKono : public GranSubModDampingDc {
 public:
  GranSubModDampingDcKuwabaraKono(class GranularModel *gm, class LAMMPS *lmp);
};
class GranSubModDampingDcTsuji : public GranSubModDampingDc {
 public:
  GranSubModDampingDcTsuji(class GranularModel *gm, class LAMMPS *lmp);
};

}    // namespace Granular_NS
}    // namespace LAMMPS_NS

#endif
#endif
