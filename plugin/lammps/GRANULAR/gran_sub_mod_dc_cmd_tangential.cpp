/* dc/cmd_tangential and dc/cmd_twisting (gran_sub_mod_dc_cmd_tangential.h). */
#include "gran_sub_mod_dc_cmd_tangential.h"

#include <cstring>

#include "atom.h"
#include "dc/cmd_turning_points.h"
#include "dc/status.h"
#include "dc_sub_mod.h"
#include "error.h"
#include "granular_model.h"

using namespace LAMMPS_NS;
using namespace Granular_NS;

namespace {
/* The law's history: the force's fields, then the twist's. */
const int CMD_TWIST = DC_CMD_HISTORY_NFIELDS - DC_CMD_FORCE_NFIELDS;
const int CMDTP_TWIST = DC_CMDTP_HISTORY_NFIELDS - DC_CMDTP_FORCE_NFIELDS;
int force_fields(int memory) { return memory ? (int) DC_CMDTP_FORCE_NFIELDS : (int) DC_CMD_FORCE_NFIELDS; }
int twist_fields(int memory) { return memory ? CMDTP_TWIST : CMD_TWIST; }
const dc_history_field *table(int memory) { return memory ? dc_cmdtp_history : dc_cmd_history; }
/* dc/cmd_twisting keeps room for either law's twist */
const int TWIST_SLOTS = CMD_TWIST > CMDTP_TWIST ? CMD_TWIST : CMDTP_TWIST;
static_assert((int) DC_CMD_HISTORY_NFIELDS >= (int) DC_CMDTP_HISTORY_NFIELDS, "a scratch state holds either history");
}    // namespace

GranSubModTangentialDcCmd::GranSubModTangentialDcCmd(GranularModel *gm, LAMMPS *lmp) : GranSubModTangential(gm, lmp)
{
  num_coeffs = 4;
  allow_cohesion = 1;   /* the project's adhesive normal models; LAMMPS' cohesive ones refused in init() */
  k = damp = mu = 0.0;
}

void GranSubModTangentialDcCmd::coeffs_to_local()
{
  dc_check_coeff(error, name, "mu", coeffs[0], 0.0, 0, HUGE_VAL, 1, "[0, inf)");
  memory_ = dc_check_choice(error, name, "memory", coeffs[1], 2, "{0 (profile), 1 (turningPoints)}");
  dc_check_coeff(error, name, "t_visc", coeffs[2], 0.0, 0, HUGE_VAL, 1, "[0, inf) s");
  dc_check_choice(error, name, "rough", coeffs[3], 2, "{0 (off), 1 (on)}");
  mu = coeffs[0];
  params_.mu = coeffs[0];
  params_.t_visc = coeffs[2];
  params_.dissipation = coeffs[2] > 0.0;
  params_.twisting = 0;
  dc_param_error err;
  if (dc_cmd_check(&params_, &err) != DC_OK)
    error->all(FLERR, "{}: {} = {} is outside {}", name, err.name, err.value, err.range);
  dc_history_transfer(this, table(memory_), force_fields(memory_));
}

/* mu and t_visc: geometric means (LAMMPS' mixing); the flags must agree. */
void GranSubModTangentialDcCmd::mix_coeffs(double *icoeffs, double *jcoeffs)
{
  if (icoeffs[1] != jcoeffs[1] || icoeffs[3] != jcoeffs[3])
    error->all(FLERR, "{}: types with different memory or rough coefficients do not mix; give their pair_coeff",
               name);
  coeffs[0] = mix_geom(icoeffs[0], jcoeffs[0]);
  coeffs[1] = icoeffs[1];
  coeffs[2] = mix_geom(icoeffs[2], jcoeffs[2]);
  coeffs[3] = icoeffs[3];
  coeffs_to_local();
}

void GranSubModTangentialDcCmd::init()
{
  if (coeffs[3] != 0.0)
    error->all(FLERR, "{} coefficient rough = 1 (tangentialRoughness) needs a normal sub-model that publishes the "
               "summits' patch; none is available in LAMMPS", name);
  contact_.init(this, gm, error, false);
  pair_ = contact_.pair;
  handover_ = dc_handover(gm);
  if (gm->twisting_model->name == "marshall")
    error->all(FLERR, "{} with twisting marshall: marshall reads a linear tangential stiffness, which this law has "
               "not; use twisting dc/cmd_twisting", name);
  twist_ = dynamic_cast<GranSubModTwistingDcCmd *>(gm->twisting_model);
  params_.twisting = twist_ ? 1 : 0;
}

void GranSubModTangentialDcCmd::calculate_forces()
{
  const int nf = force_fields(memory_), nt = twist_ ? twist_fields(memory_) : 0;
  double *hf = &gm->history[history_index];
  double *ht = twist_ ? &gm->history[twist_->history_index] : nullptr;
  Mt_ = 0.0;
  if (handover_ && handover_->rolls()) {   /* the rolling sub-model owns the tangential force */
    if (gm->history_update) {
      memset(hf, 0, nf * sizeof(double));
      if (nt) memset(ht, 0, nt * sizeof(double));
    }
    gm->fs[0] = gm->fs[1] = gm->fs[2] = 0.0;
    return;
  }

  const dc_patch &p = contact_.patch(gm);

  const double dt = gm->dt, *n = gm->nx;
  double vtr[3];
  dc_contact_point_velocity(gm, vtr);
  const double du[3] = {vtr[0] * dt, vtr[1] * dt, vtr[2] * dt};
  double dphi = 0.0;
  if (twist_) {
    const double *wi = gm->omegai, *wj = gm->omegaj;
    const double w[3] = {wi[0] - wj[0], wi[1] - wj[1], wi[2] - wj[2]};
    dphi = (w[0] * n[0] + w[1] * n[1] + w[2] * n[2]) * dt;
  }

  /* the law's state in place where the force's and the twist's fields are
     adjacent and the history may change; else in a scratch copy */
  double scratch[DC_CMD_HISTORY_NFIELDS];
  const bool in_place = gm->history_update && (!nt || ht == hf + nf);
  double *h = hf;
  if (!in_place) {
    memcpy(scratch, hf, nf * sizeof(double));
    if (nt) memcpy(scratch + nf, ht, nt * sizeof(double));
    h = scratch;
  }
  dc_cmd_out out;
  dc_cmdtp_state *htp = reinterpret_cast<dc_cmdtp_state *>(h);
  dc_cmd_state *hx = reinterpret_cast<dc_cmd_state *>(h);
  const int trusted = memory_ ? dc_cmdtp_step_trusted(&params_, &pair_, &p, n, du, dphi, dt, htp, &out)
                              : dc_cmd_step_trusted(&params_, &pair_, &p, n, du, dphi, dt, hx, &out);
  if (trusted != DC_OK) {
    const int st = memory_ ? dc_cmdtp_step(&params_, &pair_, &p, n, du, dphi, dt, htp, &out)
                           : dc_cmd_step(&params_, &pair_, &p, n, du, dphi, dt, hx, &out);
    error->one(FLERR, "{}: contact of atom {}: patch a = {}, b = {}, friction load {}, displacement {} {} {}: {}", name,
               atom->tag[gm->i], p.a, p.b, p.F_bound, du[0], du[1], du[2], dc_status_str(st));
  }
  if (!in_place && gm->history_update) {
    memcpy(hf, scratch, nf * sizeof(double));
    if (nt) memcpy(ht, scratch + nf, nt * sizeof(double));
  }
  /* the law's Ft acts on j; LAMMPS' fs on i */
  gm->fs[0] = -out.Ft[0];
  gm->fs[1] = -out.Ft[1];
  gm->fs[2] = -out.Ft[2];
  Mt_ = out.Mt;
}

GranSubModTwistingDcCmd::GranSubModTwistingDcCmd(GranularModel *gm, LAMMPS *lmp) : GranSubModTwisting(gm, lmp)
{
  num_coeffs = 0;
  allow_cohesion = 1;
  /* the twist's fields never flip (dphi = (w_i - w_j).n is symmetric) */
  dc_history_transfer(this, dc_cmd_history + DC_CMD_FORCE_NFIELDS, TWIST_SLOTS);
}

void GranSubModTwistingDcCmd::init()
{
  tangential_ = dynamic_cast<GranSubModTangentialDcCmd *>(gm->tangential_model);
  if (!tangential_) error->all(FLERR, "{} needs tangential dc/cmd_tangential, not {}", name, gm->tangential_model->name);
  const int m = tangential_->memory();
  nfields_ = twist_fields(m);
  for (int k = 0; k < nfields_; k++)
    if (table(m)[force_fields(m) + k].flips != (transfer_history_factor[k] < 0.0))
      error->all(FLERR, "{}: history field {} flips unlike its slot", name, table(m)[force_fields(m) + k].name);
}

/* LAMMPS adds magtortwist n to the torque on i; the law's moment on i is -Mt n. */
void GranSubModTwistingDcCmd::calculate_forces()
{
  gm->magtortwist = -tangential_->moment();
}
