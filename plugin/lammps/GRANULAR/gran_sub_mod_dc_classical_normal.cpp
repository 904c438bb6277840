/* dc/classical (gran_sub_mod_dc_classical_normal.h). */
#include "gran_sub_mod_dc_classical_normal.h"

#include <cstring>

using namespace LAMMPS_NS;
using namespace Granular_NS;

GranSubModNormalDcClassical::GranSubModNormalDcClassical(GranularModel *gm, LAMMPS *lmp) :
    GranSubModDcNormal(gm, lmp)
{
  num_coeffs = 10;
  dc_history_transfer(this, dc_classical_normal_history, DC_CLASSICAL_NORMAL_NFIELDS);
}

void GranSubModNormalDcClassical::coeffs_to_local()
{
  material_coeffs();
  const int law = dc_check_choice(error, name, "law", coeffs[3], 4, "{0 lsd, 1 hertz, 2 hlsConstant, 3 hlsVariable}");
  dc_check_choice(error, name, "dlaw", coeffs[4], law == DC_CLASSICAL_HERTZ ? 5 : 1,
                  "{0 restitution, 1 viscoelastic, 2 kuwabaraKono, 3 tsuji, 4 none} (law 1; 0 for the other laws)");
  dc_check_choice(error, name, "stiffness", coeffs[5], 4, "{0 given, 1 duration, 2 overlap, 3 energy}");
  dc_check_choice(error, name, "limit", coeffs[9], 2, "{0, 1}");
  dc_classical_normal_params p;
  std::memset(&p, 0, sizeof p);
  p.law = static_cast<int>(coeffs[3]);
  p.damping = p.law == DC_CLASSICAL_HERTZ ? static_cast<int>(coeffs[4]) : DC_DAMPING_NONE;
  p.stiffness = static_cast<int>(coeffs[5]);
  p.limit = static_cast<int>(coeffs[9]);
  p.Estar = Estar_;
  p.kn = coeffs[6];
  p.v_char = coeffs[7];
  p.S = coeffs[8];
  const bool uses_e = p.law == DC_CLASSICAL_LSD || p.law == DC_CLASSICAL_HLS_CONSTANT ||
      (p.law == DC_CLASSICAL_HERTZ && (p.damping == DC_DAMPING_RESTITUTION || p.damping == DC_DAMPING_TSUJI));
  p.e = uses_e ? damp : 1.0;
  p.A = p.eta_kk = damp;
  dc_param_error err;
  if (dc_classical_normal_init(&p, &m_, &err) != DC_OK) {
    static const char *const coeff_of[][2] = {{"youngsModulus", "E"},
                                              {"coefficientRestitution", "damp"},
                                              {"viscoelasticTime", "damp"},
                                              {"kuwabaraKonoDamping", "damp"},
                                              {"kn", "kn"},
                                              {"characteristicVelocity", "vchar"},
                                              {"unloadingStiffnessSlope", "S"},
                                              {"classicalStiffness", "stiffness"},
                                              {"classicalNormal", "law"},
                                              {"damping", "dlaw"},
                                              {"limitForce", "limit"}};
    const char *c = err.name;
    for (auto &n : coeff_of)
      if (!std::strcmp(err.name, n[0])) c = n[1];
    error->all(FLERR, "{} coefficient {} = {} is outside {}", name, c, err.value, err.range);
  }
}

void GranSubModNormalDcClassical::mix_coeffs(double *icoeffs, double *jcoeffs)
{
  for (int k = 3; k < 6; k++)
    if (icoeffs[k] != jcoeffs[k]) error->all(FLERR, "{}: types with different law, dlaw or stiffness cannot be mixed", name);
  mix_material(icoeffs[0], icoeffs[2], jcoeffs[0], jcoeffs[2]);
  coeffs[0] = icoeffs[0] == jcoeffs[0] ? icoeffs[0] : mix_geom(icoeffs[0], jcoeffs[0]);
  for (int k = 1; k < 10; k++) coeffs[k] = (k >= 3 && k <= 5) || k == 9 ? icoeffs[k] : mix_geom(icoeffs[k], jcoeffs[k]);
  coeffs_to_local();
}

void GranSubModNormalDcClassical::init()
{
  GranSubModDcNormal::init();
  if (!dynamic_cast<GranSubModDampingDcClassical *>(gm->damping_model))
    error->all(FLERR, "{} carries the law's own dashpot: use damping dc/classical, not {}", name,
               gm->damping_model->name);
}

GranSubModDampingDcClassical::GranSubModDampingDcClassical(GranularModel *gm, LAMMPS *lmp) :
    GranSubModDamping(gm, lmp)
{
}

void GranSubModDampingDcClassical::init()
{
  GranSubModDamping::init();
  normal = dynamic_cast<GranSubModNormalDcClassical *>(gm->normal_model);
  if (!normal) error->all(FLERR, "Damping {} is the dashpot of normal dc/classical, not of {}", name, gm->normal_model->name);
}

/* Nothing: dc/classical's force holds the dashpot. */
double GranSubModDampingDcClassical::calculate_forces()
{
  damp_prefactor = normal->gamma();
  return 0.0;
}

/* The LIGGGHTS model's surfacesIntersect: the total force (elastic and
   the law's dashpot) from dc_classical_normal_step; history written only
   when gm->history_update. */
void GranSubModNormalDcClassical::evaluate()
{
  dc_classical_normal_state h = {gm->history[history_index]};
  dc_classical_normal_out out;
  const int st = dc_classical_normal_step(&m_, gm->Reff, gm->meff, gm->delta, -gm->vnnr, &h, &out);
  if (st != DC_OK)
    error->one(FLERR, "{}: contact of radius {}, mass {}, overlap {}, normal velocity {}: {}", name, gm->Reff,
               gm->meff, gm->delta, gm->vnnr, dc_status_str(st));
  if (gm->history_update) gm->history[history_index] = h.delta_max;
  F_ = out.F;
  S_ = out.c.kn;
  gamma_ = out.gamma;
  radius_ = out.c.a;
  if (patch_wanted_) dc_patch_from_contact(&out.c, nullptr, &patch_);
}
