/* dc/jamari_ep (gran_sub_mod_dc_jamari_ep.h). */
#include "gran_sub_mod_dc_jamari_ep.h"

#include "dc/hertz_elliptic.h"

#include <cstring>

using namespace LAMMPS_NS;
using namespace Granular_NS;

GranSubModNormalDcJamariEp::GranSubModNormalDcJamariEp(GranularModel *gm, LAMMPS *lmp) :
    GranSubModDcNormal(gm, lmp)
{
  num_coeffs = 7;
  dc_history_transfer(this, dc_jamari_history, DC_JAMARI_HISTORY_NFIELDS);
}

void GranSubModNormalDcJamariEp::coeffs_to_local()
{
  material_coeffs();
  check_coeff("Kv", coeffs[4], 0.0, 0, HUGE_VAL, 1, "(0, inf), or 0 for the default");
  p_ = dc_jamari_defaults(coeffs[3], coeffs[2]);
  if (coeffs[4] != 0.0) p_.K_v = coeffs[4];
  p_.c_h = coeffs[5];
  p_.c_A = coeffs[6];
  dc_param_error err;
  if (dc_jamari_check(&p_, &err) != DC_OK) dc_plasticity_fail(error, name, err);
  yield_ratio_ = dc_jamari_circle_yield_ratio(Estar_, &p_);
}

/* The softer type's H, nu, Kv, Ch, Ca (the LIGGGHTS model's choice). */
void GranSubModNormalDcJamariEp::mix_coeffs(double *icoeffs, double *jcoeffs)
{
  mix_material(icoeffs[0], icoeffs[2], jcoeffs[0], jcoeffs[2]);
  const double *soft = jcoeffs[3] < icoeffs[3] ? jcoeffs : icoeffs;
  coeffs[0] = icoeffs[0] == jcoeffs[0] ? icoeffs[0] : mix_geom(icoeffs[0], jcoeffs[0]);
  coeffs[1] = mix_geom(icoeffs[1], jcoeffs[1]);
  coeffs[2] = soft[2];
  for (int k = 3; k < 7; k++) coeffs[k] = soft[k];
  coeffs_to_local();
}

/* The LIGGGHTS model's sphere path: hertz_elliptic's arithmetic below
   first yield without plastic memory, else dc_jamari_step; history
   written only when gm->history_update. */
void GranSubModNormalDcJamariEp::evaluate()
{
  const double R = gm->Reff, delta = gm->delta;
  dc_jamari_state h;
  std::memcpy(&h, &gm->history[history_index], sizeof h);
  if (h.delta_max == 0.0 && delta <= yield_ratio_ * R) {
    hertz_circle(R, delta);
    return;
  }
  dc_hertz_geom g;
  dc_hertz_geometry_circle(R, &g);
  dc_contact c;
  const int st = dc_jamari_step(&g, Estar_, &p_, delta, &h, &c);
  if (st != DC_OK)
    error->one(FLERR, "{}: overlap {}, radius {}, E* {}: {}", name, delta, R, Estar_, dc_status_str(st));
  if (gm->history_update) std::memcpy(&gm->history[history_index], &h, sizeof h);
  F_ = c.F;
  S_ = c.kn;
  radius_ = std::sqrt(c.a * c.b);
  if (patch_wanted_) dc_patch_from_contact(&c, nullptr, &patch_);
}
