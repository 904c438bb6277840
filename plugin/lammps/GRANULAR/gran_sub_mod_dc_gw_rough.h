/* LAMMPS normal sub-model dc/gw_rough: Greenwood-Williamson rough contact
   of spheres from c_core (dc/gw_rough_table.h, dc/feng_rough.h: the
   rough-sphere laws; dc/gw_rough.h, dc/gw_rough_plastic.h: the GW closed
   form with elastic or elastic-plastic summits; review Eqs. 29-36), the
   project's LIGGGHTS model gw_rough on spheres with its settings as
   coefficients.

   pair_coeff ... dc/gw_rough E damp nu sigma form mu n_asp fitted plastic H Kv Ch Ca w
     E [Pa] > 0, damp (the damping sub-model's coefficient, >= 0),
     nu in (-1, 0.5]: as dc/hertz_elliptic;
     sigma [m] >= 0: rms summit height of each surface (LIGGGHTS
       surfaceRoughness); a contact has (sigma_i^2 + sigma_j^2)^1/2 (a wall:
       of the same roughness as the sphere); 0 is dc/hertz_elliptic;
     form: 0 the tabulated rough-sphere law (LIGGGHTS roughSphereLaw table,
       the default), 1 Feng's law (roughSphereLaw feng), 2 the GW closed
       form (gwElliptic on);
     mu in [1, 50]: Feng's mu (roughnessMu; forms 0 and 1, else unused);
     n_asp > 0: asperity count (asperityCount; form 2, else unused);
     fitted: 0 or 1 (fengFitted: Feng's fitted formulas, form 1);
     plastic: 0 or 1 (gwPlastic, form 2: elastic-plastic summits);
     H [Pa] > 0, Kv (0: the default 0.454 + 0.41 nu), Ch, Ca: the summits'
       plasticity (hardness, plasticityKv, plasticityCh, plasticityCa of
       jamari_ep; plastic 1, else unused);
     w [J/m^2] >= 0: work of adhesion of JKR summits (form 2; LIGGGHTS
       cohesion gw_adhesion with workOfAdhesion, dc/gw_rough_adhesive_table.h),
       0 none: the adhesive part of the force, with its loading and
       unloading branches in the contact history, acting from 8 sigma apart
       and, once the summits touched, until the lowest attached one lets go.
   The rough force acts before the surfaces touch (beyond_contact), from
   delta = -6 sigma (form 0) or -3 sigma (forms 1, 2); history only with
   w > 0 (10 values). The
   damping sub-models act on the rough part's dF/d delta (none where it is
   negative), the tangential ones see the radius (R delta)^1/2 once
   delta > 0 and Fncrit = |F_n + F_damp| without the adhesive part (as
   LIGGGHTS' normal force). */
#ifdef GRAN_SUB_MOD_CLASS
// clang-format off
GranSubModStyle(dc/gw_rough,GranSubModNormalDcGwRough,NORMAL);
// clang-format on
#else
#ifndef GRAN_SUB_MOD_DC_GW_ROUGH_H
#define GRAN_SUB_MOD_DC_GW_ROUGH_H

#include "dc_sub_mod.h"
#include "dc/gw_rough.h"
#include "dc/gw_rough_adhesive_table.h"
#include "dc/gw_rough_plastic.h"

namespace LAMMPS_NS {
namespace Granular_NS {

class GranSubModNormalDcGwRough : public GranSubModDcNormal {
 public:
  GranSubModNormalDcGwRough(class GranularModel *, class LAMMPS *);
  void coeffs_to_local() override;
  void mix_coeffs(double *, double *) override;
  bool touch() override;
  double pulloff_distance(double, double) override;
  void set_fncrit() override { Fncrit = std::fabs(gm->Fntot - Fa_); }

 protected:
  void evaluate() override;

 private:
  enum { FORM_TABLE = 0, FORM_FENG = 1, FORM_ELLIPTIC = 2 };
  double reach() const;
  double reach_adhesive(double R);
  void adhesion();
  int form_ = FORM_TABLE;
  bool plastic_ = false, mixed_sigma_ = false;
  double sigma_ = 0.0, n_asp_ = 0.0;
  dc_gw_sphere_pair law_ = {};
  dc_gw_plastic_params pp_ = {};
  dc_gw_bound bound_ = {};    // the closed form bound to geom_ (sigma 0: not bound)
  dc_hertz_geom geom_ = {};   // the circle of the last effective radius (form 2)
  bool adhesive_ = false;
  dc_gwa_table_pair pa_ = {};
  double reach_R_ = 0.0, reach_adh_ = 0.0;    // the adhesive reach of the last radius
  double Fa_ = 0.0;                            // the adhesive part of F_ [N]
};

}    // namespace Granular_NS
}    // namespace LAMMPS_NS

#endif
#endif
