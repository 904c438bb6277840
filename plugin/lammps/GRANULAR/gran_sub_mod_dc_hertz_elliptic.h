/* LAMMPS normal sub-model dc/hertz_elliptic: Hertz contact from c_core
   (dc/hertz_elliptic.h, review Eq. 1), the project's LIGGGHTS model
   hertz_elliptic on spheres (a circle: R = the effective radius).

   pair_coeff ... dc/hertz_elliptic E damp nu
     E [Pa] > 0, damp (the damping sub-model's coefficient, >= 0),
     nu in (-1, 0.5]; the coefficients of LAMMPS' hertz/material, whose
     force it equals to rounding. */
#ifdef GRAN_SUB_MOD_CLASS
// clang-format off
GranSubModStyle(dc/hertz_elliptic,GranSubModNormalDcHertzElliptic,NORMAL);
// clang-format on
#else
#ifndef GRAN_SUB_MOD_DC_HERTZ_ELLIPTIC_H
#define GRAN_SUB_MOD_DC_HERTZ_ELLIPTIC_H

#include "dc_sub_mod.h"

namespace LAMMPS_NS {
namespace Granular_NS {

class GranSubModNormalDcHertzElliptic : public GranSubModDcNormal {
 public:
  GranSubModNormalDcHertzElliptic(class GranularModel *, class LAMMPS *);
  void coeffs_to_local() override;
  void mix_coeffs(double *, double *) override;

 protected:
  void evaluate() override;
};

}    // namespace Granular_NS
}    // namespace LAMMPS_NS

#endif
#endif
