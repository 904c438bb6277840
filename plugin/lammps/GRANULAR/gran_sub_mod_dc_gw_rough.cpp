/* dc/gw_rough (gran_sub_mod_dc_gw_rough.h). */
#include "gran_sub_mod_dc_gw_rough.h"

#include "dc/feng_rough.h"
#include "dc/gw_rough_table.h"
#include "dc/hertz_elliptic.h"

#include <cstring>

using namespace LAMMPS_NS;
using namespace Granular_NS;

GranSubModNormalDcGwRough::GranSubModNormalDcGwRough(GranularModel *gm, LAMMPS *lmp) :
    GranSubModDcNormal(gm, lmp)
{
  num_coeffs = 14;
  beyond_contact = 1;
}

void GranSubModNormalDcGwRough::coeffs_to_local()
{
  material_coeffs();
  check_coeff("sigma", coeffs[3], 0.0, 0, HUGE_VAL, 1, "[0, inf)");
  form_ = dc_check_choice(error, name, "form", coeffs[4], 3, "{0 table, 1 feng, 2 GW closed form}");
  if (form_ != FORM_ELLIPTIC)
    check_coeff("mu", coeffs[5], DC_FENG_MU_MIN, 0, DC_FENG_MU_MAX, 0, "[1, 50]");
  else
    check_coeff("n_asp", coeffs[6], 0.0, 1, HUGE_VAL, 1, "(0, inf)");
  dc_check_choice(error, name, "fitted", coeffs[7], 2, "{0, 1}");
  plastic_ = dc_check_choice(error, name, "plastic", coeffs[8], form_ == FORM_ELLIPTIC ? 2 : 1,
                             "{0, 1} (1 with form 2 only)") == 1;
  if (!mixed_sigma_) sigma_ = dc_gw_roughness_combine(coeffs[3], coeffs[3]);
  n_asp_ = coeffs[6];
  dc_param_error err;
  if (plastic_) {
    pp_ = dc_gw_plastic_default_params(coeffs[9], coeffs[2]);
    if (coeffs[10] != 0.0) pp_.K_v = coeffs[10];
    pp_.c_h = coeffs[11];
    pp_.c_A = coeffs[12];
    check_coeff("Kv", coeffs[10], 0.0, 0, HUGE_VAL, 1, "(0, inf), or 0 for the default");
    if (dc_gw_plastic_check(&pp_, &err) != DC_OK) dc_plasticity_fail(error, name, err);
  }
  check_coeff("w", coeffs[13], 0.0, 0, HUGE_VAL, 1, "[0, inf)");
  if (coeffs[13] != 0.0 && form_ != FORM_ELLIPTIC)
    error->all(FLERR, "{} coefficient w = {} needs form 2 (the GW closed form; 0 for forms 0 and 1)", name, coeffs[13]);
  adhesive_ = coeffs[13] != 0.0 && sigma_ != 0.0;
  if (adhesive_) {
    if (dc_gwa_table_check(Estar_, coeffs[13], sigma_, n_asp_, &err) != DC_OK ||
        dc_gwa_table_pair_init(Estar_, coeffs[13], sigma_, n_asp_, &pa_) != DC_OK)
      error->all(FLERR, "{}: {} = {} is outside {} (the adhesive summits of w, sigma, n_asp)", name, err.name,
                 err.value, err.range);
    // history: the summits' branch (gwa_touched, gwa_delta_max), then what the contact's radius fixes
    dc_history_field table[DC_GWA_TABLE_HISTORY_NFIELDS + DC_GWA_TABLE_CONTACT_NFIELDS];
    std::memcpy(table, dc_gwa_table_history, sizeof dc_gwa_table_history);
    std::memcpy(table + DC_GWA_TABLE_HISTORY_NFIELDS, dc_gwa_table_contact_history,
                sizeof dc_gwa_table_contact_history);
    dc_history_transfer(this, table, DC_GWA_TABLE_HISTORY_NFIELDS + DC_GWA_TABLE_CONTACT_NFIELDS);
  } else {
    dc_history_transfer(this, nullptr, 0);
  }
  reach_R_ = 0.0;
  bound_ = dc_gw_bound();
  geom_ = dc_hertz_geom();
  if (sigma_ == 0.0) return;
  if (form_ == FORM_ELLIPTIC) {
    if (!plastic_ && dc_gw_bound_material(Estar_, n_asp_, sigma_, &bound_) != DC_OK)
      bound_.sigma = 0.0;    // 1/sigma or n_asp E* leaves the normal doubles: the checked form
  } else if (dc_gw_sphere_pair_init(form_ == FORM_FENG ? DC_GW_SPHERE_FENG : DC_GW_SPHERE_TABULATED,
                                    coeffs[7] == 1.0 ? DC_FENG_FITTED : DC_FENG_TABLE, coeffs[5], Estar_, sigma_,
                                    &law_)) {
    error->all(FLERR, "{} coefficient sigma = {} with E* = {} is out of the range of doubles", name, coeffs[3], Estar_);
  }
}

/* sigma (sigma_i^2 + sigma_j^2)^1/2; the softer type's plasticity, as the
   LIGGGHTS model. */
void GranSubModNormalDcGwRough::mix_coeffs(double *icoeffs, double *jcoeffs)
{
  if (icoeffs[4] != jcoeffs[4] || icoeffs[7] != jcoeffs[7] || icoeffs[8] != jcoeffs[8])
    error->all(FLERR, "{}: types with different form, fitted or plastic cannot be mixed", name);
  mix_material(icoeffs[0], icoeffs[2], jcoeffs[0], jcoeffs[2]);
  const double *soft = jcoeffs[9] < icoeffs[9] ? jcoeffs : icoeffs;
  coeffs[0] = icoeffs[0] == jcoeffs[0] ? icoeffs[0] : mix_geom(icoeffs[0], jcoeffs[0]);
  coeffs[1] = mix_geom(icoeffs[1], jcoeffs[1]);
  coeffs[2] = soft[2];
  coeffs[3] = dc_gw_roughness_combine(icoeffs[3], jcoeffs[3]);
  for (int k = 4; k < 14; k++)
    coeffs[k] = k == 5 || k == 6 || k == 13 ? mix_geom(icoeffs[k], jcoeffs[k]) : soft[k];
  sigma_ = coeffs[3];
  mixed_sigma_ = true;
  coeffs_to_local();
}

/* The force's reach before touch [m]: 6 sigma (table), 3 sigma (Feng, the
   closed form). */
double GranSubModNormalDcGwRough::reach() const
{
  return (form_ == FORM_ELLIPTIC ? 3.0 : -dc_gw_sphere_reach(form_ == FORM_FENG ? DC_GW_SPHERE_FENG
                                                                                 : DC_GW_SPHERE_TABULATED)) *
      sigma_;
}

/* The adhesive summits' reach for radius R [m]: (D + 8) sigma once
   touched (dc_gwa_table_reach). */
double GranSubModNormalDcGwRough::reach_adhesive(double R)
{
  if (R != reach_R_) {
    reach_adh_ = dc_gwa_table_reach(&pa_, R) * (1.0 + 1e-9);
    reach_R_ = R;
  }
  return reach_adh_;
}

/* Within the rough force's reach; adhesive: within 8 sigma (untouched) or,
   touching at the last step (gm->touch), within the summits' reach. */
bool GranSubModNormalDcGwRough::touch()
{
  double h = reach();
  if (adhesive_) {
    const double a = gm->touch ? reach_adhesive(gm->Reff) : DC_GWA_TABLE_X_CUT * sigma_ * (1.0 + 1e-9);
    if (a > h) h = a;
  }
  const double d = gm->radsum + h;
  return gm->rsq < d * d;
}

double GranSubModNormalDcGwRough::pulloff_distance(double radi, double radj)
{
  const double h = reach(), R = radi * radj / (radi + radj);
  if (!adhesive_ || !(R > 0.0)) return h;
  const double a = reach_adhesive(R);
  return a > h ? a : h;
}

/* The LIGGGHTS model's roughForce on spheres. */
void GranSubModNormalDcGwRough::evaluate()
{
  const double reff = gm->Reff, delta = gm->delta, h = reach(), d = gm->radsum + h;
  Fa_ = 0.0;
  if (sigma_ != 0.0 && (delta <= -h || (gm->contact_type == PAIR && gm->rsq >= d * d))) {
    F_ = S_ = radius_ = 0.0;
    patch_ = dc_patch();
    adhesion();
    return;
  }
  dc_hertz_geom g;
  const dc_hertz_geom *gp = &g;
  g.R_force = g.R_area = reff;
  if (form_ == FORM_ELLIPTIC && sigma_ != 0.0) {
    if (geom_.R_major != reff) {
      dc_hertz_geometry_circle(reff, &geom_);
      if (bound_.sigma != 0.0) dc_gw_bound_bind(&bound_, &geom_);
    }
    gp = &geom_;
  }
  double P, Sn, kn;
  if (sigma_ == 0.0) {
    radius_ = dc_hertz_stiffness(Estar_, gp->R_force, delta, &kn, &Sn);
    P = kn * delta;
  } else {
    if (form_ == FORM_ELLIPTIC) {
      int st;
      if (!plastic_ && bound_.sigma != 0.0) {
        st = dc_gw_bound_force(&bound_, delta, &P, &Sn);
      } else {
        dc_gw_rough_state s;
        st = plastic_ ? dc_gw_rough_plastic(gp, Estar_, &pp_, n_asp_, sigma_, delta, &s)
                      : dc_gw_rough_elliptic(gp, Estar_, n_asp_, sigma_, delta, &s);
        if (st == DC_OK) {
          P = s.F;
          Sn = s.kn;
        }
      }
      if (st != DC_OK)
        error->one(FLERR, "{}: overlap {}, roughness {}, radius {}: {}", name, delta, sigma_, reff, dc_status_str(st));
    } else {
      dc_gw_sphere_pair_force(&law_, std::sqrt(reff), delta, &P, &Sn);
    }
    radius_ = delta > 0.0 ? std::sqrt(gp->R_area * delta) : 0.0;
  }
  F_ = P;
  S_ = Sn;
  adhesion();
  if (patch_wanted_) {
    if (!(form_ == FORM_ELLIPTIC && sigma_ != 0.0)) dc_hertz_geometry(reff, reff, &g);
    dc_contact c;
    dc_gw_rough_normal(gp, Estar_, delta, P, Sn, &c);
    dc_patch_from_contact(&c, nullptr, &patch_);
  }
}

/* The adhesive summits (LIGGGHTS cohesion gw_adhesion on spheres): their
   force Fa_ added to F_; history written only when gm->history_update. */
void GranSubModNormalDcGwRough::adhesion()
{
  if (!adhesive_) return;
  const double R = gm->Reff, delta = gm->delta;
  double *stored = &gm->history[history_index];
  double hist[DC_GWA_TABLE_HISTORY_NFIELDS];
  dc_gwa_table_contact con;
  std::memcpy(hist, stored, sizeof hist);
  if (dc_gwa_table_apart(&pa_, delta, hist)) return;
  std::memcpy(&con, stored + DC_GWA_TABLE_HISTORY_NFIELDS, sizeof con);
  if (con.R != R) {
    const int st = dc_gwa_table_contact_init(&pa_, R, &con);
    if (st != DC_OK) error->one(FLERR, "{}: adhesive summits of radius {}: {}", name, R, dc_status_str(st));
  }
  dc_gwa_table_out o;
  int st = DC_OK;
  if (!dc_gwa_table_step_settled(&pa_, &con, delta, hist, &o)) st = dc_gwa_table_step_contact_any(&pa_, &con, delta, hist, &o);
  if (st != DC_OK)
    error->one(FLERR, "{}: adhesive summits at overlap {}, radius {}: {}", name, delta, R, dc_status_str(st));
  if (gm->history_update) {
    std::memcpy(stored, hist, sizeof hist);
    std::memcpy(stored + DC_GWA_TABLE_HISTORY_NFIELDS, &con, sizeof con);
  }
  Fa_ = o.F;
  F_ += o.F;
}
