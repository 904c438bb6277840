/* dc/classical (gran_sub_mod_dc_classical_tangential.h). */
#include "gran_sub_mod_dc_classical_tangential.h"

#include "atom.h"
#include "dc/classical_tangential_step.h"
#include "dc/status.h"
#include "error.h"
#include "gran_sub_mod_damping.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace Granular_NS;

GranSubModTangentialDcClassical::GranSubModTangentialDcClassical(GranularModel *gm, LAMMPS *lmp) :
    GranSubModTangential(gm, lmp)
{
  num_coeffs = 9;
}

/* The three settings (integers in their ranges); the history they need. */
void GranSubModTangentialDcClassical::coeffs_to_local()
{
  law_ = dc_check_choice(error, name, "law", coeffs[0], 10, "{0, 1, ..., 9}");
  dc_check_choice(error, name, "kt_mode", coeffs[1], 3, "{0, 1, 2}");
  dc_check_choice(error, name, "damp_mode", coeffs[2], 4, "{0, 1, 2, 3}");
  mu = coeffs[3];
  nfields_ = law_ == DC_CT_INCREMENTAL ? DC_CT_HISTORY_NFIELDS : DC_CT_SPRING_NFIELDS;
  dc_history_transfer(this, dc_classical_tangential_history, nfields_);
}

/* The law's parameters with G*, E* of the normal sub-model (checked by
   dc_classical_tangential_init). */
void GranSubModTangentialDcClassical::init()
{
  contact_.init(this, gm, error, false);
  handover_ = dc_handover(gm);
  dc_classical_tangential_params p;
  std::memset(&p, 0, sizeof p);
  p.law = law_;
  p.stiffness = (int) coeffs[1];
  p.damping = (int) coeffs[2];
  p.mu = coeffs[3];
  p.kt = coeffs[4];
  p.gammat = coeffs[5];
  p.e_t = coeffs[6];
  p.eta_l = coeffs[7];
  p.t_visc = coeffs[8];
  p.Gstar = contact_.gstar;
  p.Estar = contact_.estar;
  /* the coefficients the law does not read (the LIGGGHTS model's defaults) */
  const bool springy = law_ == DC_CT_SPRING_SLIDING || law_ == DC_CT_SPRING_DASHPOT_SLIDING ||
      law_ == DC_CT_INCREMENTAL;
  const bool dashpot = law_ == DC_CT_SPRING_DASHPOT_SLIDING || law_ == DC_CT_DI_RENZO;
  if (law_ == DC_CT_VISCOUS) p.mu = 0.0;
  if (!(p.stiffness == DC_CT_KT_GIVEN && springy)) p.kt = 1.0;
  if (!(law_ == DC_CT_VISCOUS || law_ == DC_CT_VISCOUS_SLIDING || (p.damping == DC_CT_DAMP_GIVEN && dashpot)))
    p.gammat = 0.0;
  if (!(p.damping == DC_CT_DAMP_RESTITUTION && dashpot)) p.e_t = 0.0;
  if (law_ != DC_CT_LANGSTON) p.eta_l = 0.0;
  if (law_ != DC_CT_ZHENG) p.t_visc = 0.0;
  dc_param_error err;
  if (dc_classical_tangential_init(&p, &model_, &err) != DC_OK)
    dc_param_fail(error, name, err,
                  {{"coefficientFriction", "mu"}, {"kt", "kt"}, {"gammat", "gammat"},
                   {"coefficientRestitutionTangential", "e_t"}, {"langstonDamping", "eta_l"},
                   {"tangentialViscoelasticTime", "t_visc"}},
                  "of the normal sub-model (E, nu)");
}

void GranSubModTangentialDcClassical::calculate_forces()
{
  double *hist = &gm->history[history_index];
  if (handover_ && handover_->rolls()) {    // the rolling sub-model owns the tangential force
    if (gm->history_update) std::memset(hist, 0, nfields_ * sizeof(double));
    gm->fs[0] = gm->fs[1] = gm->fs[2] = 0.0;
    return;
  }
  double vt[3];
  dc_contact_point_velocity(gm, vt);
  const dc_patch &p = contact_.patch(gm);
  /* LIGGGHTS' kn: the secant normal stiffness; gamman: the damping's */
  const dc_classical_tangential_contact c = {gm->meff, gm->delta > 0.0 ? gm->Fnormal / gm->delta : 0.0,
                                             gm->damping_model->get_damp_prefactor()};
  dc_classical_tangential_state scratch, *h = reinterpret_cast<dc_classical_tangential_state *>(hist);
  if (nfields_ < DC_CT_HISTORY_NFIELDS || !gm->history_update) {
    std::memset(&scratch, 0, sizeof scratch);
    std::memcpy(&scratch, hist, nfields_ * sizeof(double));
    h = &scratch;
  }
  dc_classical_tangential_out out;
  if (dc_classical_tangential_step_law(law_, 0, &model_, &p, &c, gm->nx, nullptr, vt, gm->dt, h, &out) != DC_OK) {
    const int st = dc_classical_tangential_step(&model_, &p, &c, gm->nx, nullptr, vt, gm->dt, h, &out);
    error->one(FLERR, "{}: contact patch a = {}, friction load {}, velocity {} {} {}: {}", name, p.a, p.F_bound,
               vt[0], vt[1], vt[2], dc_status_str(st));
  }
  if (h == &scratch && gm->history_update) std::memcpy(hist, &scratch, nfields_ * sizeof(double));
  /* out.Ft acts on j: LAMMPS' fs is the force on i */
  for (int k = 0; k < 3; k++) gm->fs[k] = -out.Ft[k];
}
