/* LAMMPS normal sub-model dc/jkr_elliptic: adhesive elastic contact of
   spheres from c_core (dc/jkr_sphere.h: classical JKR; dc/maugis_dugdale.h:
   DMT, Maugis-Dugdale and the Tabor parameter's choice), the project's
   LIGGGHTS model jkr_elliptic on spheres with its settings as coefficients.

   pair_coeff ... dc/jkr_elliptic E damp nu w law z0
     E [Pa] > 0, damp (the damping sub-model's coefficient, >= 0),
     nu in (-1, 0.5]: as dc/hertz_elliptic;
     w [J/m^2] >= 0: work of adhesion (LIGGGHTS workOfAdhesion);
     law: the adhesion law (LIGGGHTS adhesionLaw), 0 jkr, 1 dmt, 2 maugis
       (Maugis-Dugdale), 3 tabor (per contact: JKR above Tabor parameter 5,
       DMT below 0.1, Maugis-Dugdale between);
     z0 [m]: equilibrium separation (LIGGGHTS equilibriumSeparation),
       > 0 for laws 2 and 3, >= 0 (unused) for 0 and 1.
   Adhesive (cohesive_flag, beyond_contact): a JKR neck formed at touch
   holds in tension until the law lets it go (delta_break), the
   Maugis-Dugdale zone acts before touch; the formed flag and the
   Maugis-Dugdale state are per-contact history. The damping sub-models
   (dc/restitution, ...) act on the flat-punch stiffness 2 E* a (0 while
   no contact circle exists), as the LIGGGHTS model; Fncrit is the
   friction load F + 2 |F_pulloff|. w = 0 is dc/hertz_elliptic. */
#ifdef GRAN_SUB_MOD_CLASS
// clang-format off
GranSubModStyle(dc/jkr_elliptic,GranSubModNormalDcJkrElliptic,NORMAL);
// clang-format on
#else
#ifndef GRAN_SUB_MOD_DC_JKR_ELLIPTIC_H
#define GRAN_SUB_MOD_DC_JKR_ELLIPTIC_H

#include "dc_sub_mod.h"
#include "dc/maugis_dugdale.h"

namespace LAMMPS_NS {
namespace Granular_NS {

class GranSubModNormalDcJkrElliptic : public GranSubModDcNormal {
 public:
  GranSubModNormalDcJkrElliptic(class GranularModel *, class LAMMPS *);
  void coeffs_to_local() override;
  void mix_coeffs(double *, double *) override;
  bool touch() override;
  double pulloff_distance(double, double) override;

 protected:
  void evaluate() override;

 private:
  enum { LAW_JKR = 0, LAW_DMT = 1, LAW_MD = 2, LAW_TABOR = 3 };
  int law_of(double R) const;
  double reach(double R) const;
  void none();
  double w_ = 0.0, z0_ = 0.0;
  int law_ = LAW_JKR;
  dc_md_sphere_pair md_ = {};
};

}    // namespace Granular_NS
}    // namespace LAMMPS_NS

#endif
#endif
