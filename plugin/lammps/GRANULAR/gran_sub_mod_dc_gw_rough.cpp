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
  num_coeffs = 13;
  beyond_contact = 1;
}

static bool is_int(double x, double lo, double hi)
{
  return x >= lo && x <= hi && x == std::floor(x);
}

void GranSubModNormalDcGwRough::coeffs_to_local()
{
  check_coeff("E", coeffs[0], 0.0, 1, HUGE_VAL, 1, "(0, inf)");
  check_coeff("damp", coeffs[1], 0.0, 0, HUGE_VAL, 1, "[0, inf)");
  check_coeff("nu", coeffs[2], -1.0, 1, 0.5, 0, "(-1, 0.5]");
  check_coeff("sigma", coeffs[3], 0.0, 0, HUGE_VAL, 1, "[0, inf)");
  if (!is_int(coeffs[4], 0, 2))
    error->all(FLERR, "{} coefficient form = {} is outside {{0 table, 1 feng, 2 GW closed form}}", name, coeffs[4]);
  form_ = static_cast<int>(coeffs[4]);
  if (form_ != FORM_ELLIPTIC)
    check_coeff("mu", coeffs[5], DC_FENG_MU_MIN, 0, DC_FENG_MU_MAX, 0, "[1, 50]");
  else
    check_coeff("n_asp", coeffs[6], 0.0, 1, HUGE_VAL, 1, "(0, inf)");
  if (!is_int(coeffs[7], 0, 1)) error->all(FLERR, "{} coefficient fitted = {} is outside {{0, 1}}", name, coeffs[7]);
  if (!is_int(coeffs[8], 0, 1) || (coeffs[8] == 1.0 && form_ != FORM_ELLIPTIC))
    error->all(FLERR, "{} coefficient plastic = {} is outside {{0, 1}} (1 with form 2 only)", name, coeffs[8]);
  plastic_ = coeffs[8] == 1.0;
  damp = coeffs[1];
  material_from(coeffs[0], coeffs[2]);
  if (!mixed_sigma_) sigma_ = dc_gw_roughness_combine(coeffs[3], coeffs[3]);
  n_asp_ = coeffs[6];
  dc_param_error err;
  if (plastic_) {
    pp_ = dc_gw_plastic_default_params(coeffs[9], coeffs[2]);
    if (coeffs[10] != 0.0) pp_.K_v = coeffs[10];
    pp_.c_h = coeffs[11];
    pp_.c_A = coeffs[12];
    check_coeff("Kv", coeffs[10], 0.0, 0, HUGE_VAL, 1, "(0, inf), or 0 for the default");
    if (dc_gw_plastic_check(&pp_, &err) != DC_OK) {
      static const char *const coeff_of[][2] = {
          {"hardness", "H"}, {"plasticityKv", "Kv"}, {"plasticityCh", "Ch"}, {"plasticityCa", "Ca"}};
      const char *c = err.name;
      for (auto &n : coeff_of)
        if (!std::strcmp(err.name, n[0])) c = n[1];
      error->all(FLERR, "{} coefficient {} = {} is outside {}", name, c, err.value, err.range);
    }
  }
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
  for (int k = 4; k < 13; k++) coeffs[k] = k == 5 || k == 6 ? mix_geom(icoeffs[k], jcoeffs[k]) : soft[k];
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

bool GranSubModNormalDcGwRough::touch()
{
  const double d = gm->radsum + reach();
  return gm->rsq < d * d;
}

double GranSubModNormalDcGwRough::pulloff_distance(double, double)
{
  return reach();
}

/* The LIGGGHTS model's roughForce on spheres. */
void GranSubModNormalDcGwRough::evaluate()
{
  const double reff = gm->Reff, delta = gm->delta, h = reach(), d = gm->radsum + h;
  if (sigma_ != 0.0 && (delta <= -h || (gm->contact_type == PAIR && gm->rsq >= d * d))) {
    F_ = S_ = radius_ = 0.0;
    patch_ = dc_patch();
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
  if (patch_wanted_) {
    if (!(form_ == FORM_ELLIPTIC && sigma_ != 0.0)) dc_hertz_geometry(reff, reff, &g);
    dc_contact c;
    dc_gw_rough_normal(gp, Estar_, delta, P, Sn, &c);
    dc_patch_from_contact(&c, nullptr, &patch_);
  }
}
