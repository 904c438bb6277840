/* Plumbing shared by the project's LAMMPS GRANULAR sub-models (the
   gran_sub_mod_dc_*.h files beside it): the normal sub-model base that
   hands the contact patch (dc/contract.h) to the other sub-models of the
   same contact, coefficient range checks reported as LAMMPS errors, and the
   history swap factors from a law's history table. No physics here: the
   laws are c_core's (c_core/include/dc/). */
#ifndef LMP_DC_SUB_MOD_H
#define LMP_DC_SUB_MOD_H

#include <cmath>
#include <cstring>
#include <initializer_list>
#include <string>
#include <utility>

#include "dc/contract.h"
#include "dc/hertz_elliptic.h"
#include "dc/mindlin.h"
#include "dc/status.h"
#include "error.h"
#include "gran_sub_mod_normal.h"
#include "gran_sub_mod_rolling.h"
#include "granular_model.h"

namespace LAMMPS_NS {
namespace Granular_NS {

/* Base of the project's normal sub-models. Each law fills F_, S_ and,
   when a sub-model asked for it (want_patch), patch_ in evaluate(), which
   runs once per contact and step from calculate_contact_radius (LAMMPS
   calls it before every other sub-model; contact_radius_flag is always
   set). LAMMPS' own tangential, rolling and twisting models see the
   contact radius (a b)^1/2, the radius of the circle of the patch's area,
   and Fncrit: |F_n + F_damp| for non-adhesive laws (as LAMMPS' hertz), the
   patch's friction load F_bound for adhesive ones (as LAMMPS' jkr). */
class GranSubModDcNormal : public GranSubModNormal {
 public:
  GranSubModDcNormal(class GranularModel *gm, class LAMMPS *lmp) : GranSubModNormal(gm, lmp)
  {
    material_properties = 1;
    contact_radius_flag = 1;
  }

  double calculate_contact_radius() override
  {
    evaluate();
    return radius_;
  }
  double calculate_forces() override { return F_; }
  void set_fncrit() override { Fncrit = cohesive_flag ? patch_.F_bound : std::fabs(gm->Fntot); }

  /* Called by a reader's init(): from then on the patch is filled. */
  void want_patch() { patch_wanted_ = true; }
  const dc_patch &patch() const { return patch_; }
  /* Tangent stiffness dF/d delta [N/m] of this step (damping acts on it). */
  double stiffness() const { return S_; }
  /* E* [Pa] and G* [Pa] of the contact (pair or wall). */
  double estar() const { return Estar_; }
  double gstar() const { return Gstar_; }
  /* The compliance sums of the two bodies' materials (dc/mindlin.h). */
  const dc_mindlin_pair &mindlin_pair() const { return pair_; }

 protected:
  virtual void evaluate() = 0;

  /* E* and G* from coeffs E, nu (pair: both bodies of that material; wall:
     a rigid-free wall of the same material, as LAMMPS' hertz/material). */
  void material_from(double E, double nu)
  {
    Emod = E;
    poiss = nu;
    if (mixed_) return;
    dc_mindlin_pair_init(E, nu, E, nu, &pair_);
    if (gm->contact_type == PAIR) {
      Estar_ = mix_stiffnessE(E, E, nu, nu);
      Gstar_ = mix_stiffnessG(E, E, nu, nu);
    } else {
      Estar_ = mix_stiffnessE_wall(E, nu);
      Gstar_ = mix_stiffnessG_wall(E, nu);
    }
  }
  /* For mix_coeffs of a pair of types: E* and G* of two materials. */
  void mix_material(double E1, double nu1, double E2, double nu2)
  {
    Estar_ = mix_stiffnessE(E1, E2, nu1, nu2);
    Gstar_ = mix_stiffnessG(E1, E2, nu1, nu2);
    dc_mindlin_pair_init(E1, nu1, E2, nu2, &pair_);
    mixed_ = true;
  }

  /* dc_check_coeff with this sub-model's name. */
  void check_coeff(const char *coeff, double value, double lo, int lo_open, double hi, int hi_open,
                   const char *range);
  /* The first three coefficients of every project normal sub-model,
     E [Pa] > 0, damp >= 0, nu in (-1, 0.5]: checked, damp and the material
     set. */
  void material_coeffs();
  /* Hertz on a sphere contact of effective radius R at overlap delta > 0:
     F_, S_, radius_ and (if wanted) the patch; the arithmetic of the
     LIGGGHTS models' sphere path. */
  void hertz_circle(double R, double delta);

  double F_ = 0.0, S_ = 0.0, radius_ = 0.0;
  double Estar_ = 0.0, Gstar_ = 0.0;
  dc_mindlin_pair pair_ = {};
  dc_patch patch_ = {};
  bool patch_wanted_ = false, mixed_ = false;
};

/* The project's normal sub-model of this contact, or nullptr (a LAMMPS
   normal model). */
inline GranSubModDcNormal *dc_normal(GranularModel *gm)
{
  return dynamic_cast<GranSubModDcNormal *>(gm->normal_model);
}

/* What the project's tangential and rolling sub-models read from the
   normal model of their contact (LIGGGHTS: contact_patch.h's reader): the
   contact patch, E*, G* and the compliance sums of the two materials. From
   the project's normal sub-model; under a LAMMPS normal model with E and
   nu (hertz/material, ...) the circle a = (R delta)^1/2 with friction load
   its elastic force, as the LIGGGHTS models read a stock normal model, and
   both bodies of its material (a mixed type pair: its mixed E and nu, as
   LAMMPS' mindlin). */
class DcContactReader {
 public:
  /* From the reader's init(); with need_project_normal a LAMMPS normal
     model is refused (a law that needs more than the circle). */
  void init(GranSubMod *reader, GranularModel *gm, Error *error, bool need_project_normal)
  {
    normal_ = dc_normal(gm);
    GranSubModNormal *nm = gm->normal_model;
    if (normal_) {
      normal_->want_patch();
      estar = normal_->estar();
      gstar = normal_->gstar();
      pair = normal_->mindlin_pair();
      return;
    }
    if (need_project_normal)
      error->all(FLERR, "{} needs one of the project's normal sub-models (dc/hertz_elliptic, ...) for the contact "
                 "patch, not {}", reader->name, nm->name);
    if (nm->get_cohesive_flag())
      error->all(FLERR, "{} under the cohesive LAMMPS normal model {}: the circular patch is Hertz's; use a project "
                 "normal sub-model (dc/)", reader->name, nm->name);
    const double E = nm->get_emod(), nu = nm->get_poiss();
    if (!nm->get_material_properties() || dc_mindlin_pair_init(E, nu, E, nu, &pair) != DC_OK)
      error->all(FLERR, "{} needs a normal model with E > 0 and nu in (-1, 0.5] (e.g. dc/hertz_elliptic, "
                 "hertz/material), not {}", reader->name, nm->name);
    gstar = dc_mindlin_pair_gstar(&pair);
    estar = dc_mindlin_pair_estar(&pair);
  }

  /* This step's patch. */
  const dc_patch &patch(const GranularModel *gm)
  {
    if (normal_) return normal_->patch();
    dc_patch_circular(gm->Reff, gm->delta, gm->Fnormal, &stock_);
    return stock_;
  }

  GranSubModDcNormal *normal() const { return normal_; }

  double estar = 0.0, gstar = 0.0;
  dc_mindlin_pair pair = {};

 private:
  GranSubModDcNormal *normal_ = nullptr;
  dc_patch stock_ = {};
};

/* The relative tangential velocity of the surfaces at the contact point,
   with the lever arms to the contact point, radius - delta/2 (a wall: the
   sphere's), as LIGGGHTS' and the project's LIGGGHTS models take it and as
   LAMMPS applies the torque of a pair; LAMMPS' own sub-models take the
   radii (gm->vtr). */
inline void dc_contact_point_velocity(const GranularModel *gm, double vtr[3])
{
  const double *n = gm->nx, h = 0.5 * gm->delta;
  double w[3];
  if (gm->contact_type == PAIR)
    for (int k = 0; k < 3; k++) w[k] = (gm->radi - h) * gm->omegai[k] + (gm->radj - h) * gm->omegaj[k];
  else
    for (int k = 0; k < 3; k++) w[k] = (gm->radi - h) * gm->omegai[k];
  vtr[0] = gm->vt[0] - (w[1] * n[2] - w[2] * n[1]);
  vtr[1] = gm->vt[1] - (w[2] * n[0] - w[0] * n[2]);
  vtr[2] = gm->vt[2] - (w[0] * n[1] - w[1] * n[0]);
}

/* A rolling sub-model that owns the tangential force while the contact
   rolls (dc/kalker; LIGGGHTS: rolling_contact.h): the project's tangential
   sub-models ask it every step, before it runs, and while rolls() is true
   apply nothing and start their history afresh. */
class GranSubModDcHandover {
 public:
  virtual ~GranSubModDcHandover() noexcept(false) = default;    // as LAMMPS' Pointers
  /* Whether this contact rolls at this step (it then applies the force). */
  virtual bool rolls() = 0;
};

inline GranSubModDcHandover *dc_handover(GranularModel *gm)
{
  return dynamic_cast<GranSubModDcHandover *>(gm->rolling_model);
}

/* A sub-model's history swap factors from a law's table (dc/contract.h):
   -1 where the value changes sign when i and j swap, +1 elsewhere. */
inline void dc_history_transfer(GranSubMod *m, const dc_history_field *table, int n)
{
  m->size_history = n;
  m->nondefault_history_transfer = 1;
  delete[] m->transfer_history_factor;
  m->transfer_history_factor = new double[n];
  for (int k = 0; k < n; k++) m->transfer_history_factor[k] = table[k].flips ? -1.0 : 1.0;
}

/* An integer setting: value one of 0, 1, ..., n - 1, else a LAMMPS error
   naming the sub-model, the coefficient, its value and the choices
   (text, e.g. "{0 lsd, 1 hertz}"). Returns the value. */
inline int dc_check_choice(Error *error, const std::string &model, const char *coeff, double value, int n,
                           const char *choices)
{
  if (!(value >= 0.0 && value <= n - 1 && value == std::floor(value)))
    error->all(FLERR, "{} coefficient {} = {} is outside {}", model, coeff, value, choices);
  return static_cast<int>(value);
}

/* A c_core parameter error (dc_<law>_check) as a LAMMPS error: the
   coefficient's name from map (pairs of c_core's name, the LIGGGHTS
   property's, and the coefficient's; a name not in map: other, or
   c_core's), with c_core's beside it. */
inline void dc_param_fail(Error *error, const std::string &model, const dc_param_error &err,
                          std::initializer_list<std::pair<const char *, const char *>> map,
                          const char *other = nullptr)
{
  const char *coeff = other ? other : err.name;
  for (const auto &m : map)
    if (std::strcmp(err.name, m.first) == 0) coeff = m.second;
  error->all(FLERR, "{} coefficient {} ({}) = {} is outside {}", model, coeff, err.name, err.value, err.range);
}

/* The plastic laws' parameters (dc/jamari_ep.h, dc/gw_rough_plastic.h),
   the coefficients H, Kv, Ch, Ca. */
inline void dc_plasticity_fail(Error *error, const std::string &model, const dc_param_error &err)
{
  dc_param_fail(error, model, err,
                {{"hardness", "H"}, {"plasticityKv", "Kv"}, {"plasticityCh", "Ch"}, {"plasticityCa", "Ca"}});
}

/* lo <= value <= hi (open ends as flagged) or a LAMMPS error naming the
   sub-model, the coefficient, its value and its range. */
inline void dc_check_coeff(Error *error, const std::string &model, const char *coeff, double value, double lo,
                           int lo_open, double hi, int hi_open, const char *range)
{
  dc_param_error err;
  if (dc_param_check(coeff, value, lo, lo_open, hi, hi_open, range, &err) != DC_OK)
    error->all(FLERR, "{} coefficient {} = {} is outside {}", model, coeff, value, range);
}

inline void GranSubModDcNormal::check_coeff(const char *coeff, double value, double lo, int lo_open, double hi,
                                             int hi_open, const char *range)
{
  dc_check_coeff(error, name, coeff, value, lo, lo_open, hi, hi_open, range);
}

inline void GranSubModDcNormal::material_coeffs()
{
  check_coeff("E", coeffs[0], 0.0, 1, HUGE_VAL, 1, "(0, inf)");
  check_coeff("damp", coeffs[1], 0.0, 0, HUGE_VAL, 1, "[0, inf)");
  check_coeff("nu", coeffs[2], -1.0, 1, 0.5, 0, "(-1, 0.5]");
  damp = coeffs[1];
  material_from(coeffs[0], coeffs[2]);
}

inline void GranSubModDcNormal::hertz_circle(double R, double delta)
{
  double kn;
  radius_ = dc_hertz_stiffness(Estar_, R, delta, &kn, &S_);
  F_ = kn * delta;
  if (patch_wanted_ && !dc_hertz_patch_circle(R, delta, F_, &patch_)) {
    dc_hertz_geom g;
    dc_contact c;
    dc_hertz_geometry_circle(R, &g);
    dc_hertz_normal(&g, Estar_, delta, &c);
    dc_patch_from_contact(&c, nullptr, &patch_);
  }
}

}    // namespace Granular_NS
}    // namespace LAMMPS_NS

#endif
