/* LAMMPS normal sub-model dc/jamari_ep: Jamari-Schipper elastic /
   elastic-plastic / fully plastic contact of spheres with elastic unloading
   and reloading from the largest overlap, from c_core (dc/jamari_ep.h,
   review Eqs. 41-46), the project's LIGGGHTS model jamari_ep on spheres.

   pair_coeff ... dc/jamari_ep E damp nu H Kv Ch Ca
     E [Pa] > 0, damp (the damping sub-model's coefficient, >= 0),
     nu in (-1, 0.5]: as dc/hertz_elliptic;
     H [Pa] > 0: hardness of the softer body (LIGGGHTS hardness);
     Kv > 0: maximum Hertz pressure at first yield over H, or 0 for the
       default 0.454 + 0.41 nu (LIGGGHTS plasticityKv);
     Ch >= 2/3 Kv: mean pressure at full plasticity over H (plasticityCh,
       LIGGGHTS' default 1);
     Ca >= 2: area at full plasticity over the Hertz area at first yield
       (plasticityCa, LIGGGHTS' default 108).
   Mixed types take the softer type's H, nu (for Kv 0), Kv, Ch and Ca, as
   the LIGGGHTS model. History: the largest overlap beyond first yield and
   its unloading branch (4 values), kept while the surfaces overlap. The
   plastic dissipation is the law's own; a damping sub-model (dc/restitution
   with damp 1: none) acts on top of it on the tangent stiffness. Below
   first yield the force is dc/hertz_elliptic's. */
#ifdef GRAN_SUB_MOD_CLASS
// clang-format off
GranSubModStyle(dc/jamari_ep,GranSubModNormalDcJamariEp,NORMAL);
// clang-format on
#else
#ifndef GRAN_SUB_MOD_DC_JAMARI_EP_H
#define GRAN_SUB_MOD_DC_JAMARI_EP_H

#include "dc_sub_mod.h"
#include "dc/jamari_ep.h"

namespace LAMMPS_NS {
namespace Granular_NS {

class GranSubModNormalDcJamariEp : public GranSubModDcNormal {
 public:
  GranSubModNormalDcJamariEp(class GranularModel *, class LAMMPS *);
  void coeffs_to_local() override;
  void mix_coeffs(double *, double *) override;

 protected:
  void evaluate() override;

 private:
  dc_jamari_params p_ = {};
  double yield_ratio_ = 0.0;    // delta_n1 / R of sphere contacts
};

}    // namespace Granular_NS
}    // namespace LAMMPS_NS

#endif
#endif
