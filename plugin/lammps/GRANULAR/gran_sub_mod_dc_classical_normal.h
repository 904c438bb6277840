/* LAMMPS normal sub-model dc/classical: the classical normal laws (linear
   spring-dashpot, Hertz, Walton-Braun hysteretic linear spring) from
   c_core (dc/classical_normal.h, Lopez Rangel 2021 Sec. 3), the project's
   LIGGGHTS model classical with its settings as numeric coefficients.

   pair_coeff ... dc/classical E damp nu law dlaw stiffness kn vchar S limit
     E [Pa] > 0, nu in (-1, 0.5]: E* (matched stiffness, hertz) and G*;
     damp: the law's damping coefficient: the coefficient of restitution
       e in (0, 1] for law 0 and 2 and for law 1 with dlaw 0 or 3;
       viscoelasticTime [s] >= 0 for law 1 with dlaw 1;
       kuwabaraKonoDamping [N s m^-3/2] >= 0 for law 1 with dlaw 2;
       unused (>= 0) otherwise;
     law (LIGGGHTS classicalNormal): 0 lsd, 1 hertz, 2 hlsConstant,
       3 hlsVariable;
     dlaw (LIGGGHTS damping, law 1 only, else 0): 0 restitution,
       1 viscoelastic, 2 kuwabaraKono, 3 tsuji, 4 none;
     stiffness (LIGGGHTS classicalStiffness, laws 0, 2, 3): 0 given (kn),
       1 duration, 2 overlap, 3 energy (matched to the elastic Hertz
       collision at vchar);
     kn [N/m] > 0 with stiffness 0 (else unused, >= 0);
     vchar [m/s] > 0 with a matched stiffness (else unused, >= 0);
     S [1/m] >= 0: unloading stiffness slope (law 3);
     limit: 0 or 1 (LIGGGHTS limitForce: the total force clipped at 0).
   The dashpot is the law's own (c_core gives the total force): the
   damping sub-model must be dc/classical, which adds nothing and hands the
   law's damping coefficient to the tangential sub-model (damp_prefactor,
   as LIGGGHTS' tangential_damping). History: the largest overlap (hls;
   1 value, 0 for the other laws), reset when the surfaces part. */
#ifdef GRAN_SUB_MOD_CLASS
// clang-format off
GranSubModStyle(dc/classical,GranSubModNormalDcClassical,NORMAL);
GranSubModStyle(dc/classical,GranSubModDampingDcClassical,DAMPING);
// clang-format on
#else
#ifndef GRAN_SUB_MOD_DC_CLASSICAL_NORMAL_H
#define GRAN_SUB_MOD_DC_CLASSICAL_NORMAL_H

#include "dc_sub_mod.h"
#include "gran_sub_mod_damping.h"
#include "dc/classical_normal.h"

namespace LAMMPS_NS {
namespace Granular_NS {

class GranSubModNormalDcClassical : public GranSubModDcNormal {
 public:
  GranSubModNormalDcClassical(class GranularModel *, class LAMMPS *);
  void coeffs_to_local() override;
  void mix_coeffs(double *, double *) override;
  void init() override;
  /* The law's damping coefficient [N s/m] of this step. */
  double gamma() const { return gamma_; }

 protected:
  void evaluate() override;

 private:
  dc_classical_normal m_ = {};
  double gamma_ = 0.0;
};

/* The damping of dc/classical: the force is in the normal model's. */
class GranSubModDampingDcClassical : public GranSubModDamping {
 public:
  GranSubModDampingDcClassical(class GranularModel *, class LAMMPS *);
  void init() override;
  double calculate_forces() override;

 private:
  GranSubModNormalDcClassical *normal = nullptr;
};

}    // namespace Granular_NS
}    // namespace LAMMPS_NS

#endif
#endif
