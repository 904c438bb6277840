/* dc/kalker (gran_sub_mod_dc_kalker.h). */
#include "gran_sub_mod_dc_kalker.h"

#include "atom.h"
#include "dc/mindlin.h"
#include "dc/status.h"
#include "gran_sub_mod_tangential.h"
#include "error.h"
#include "update.h"

#include <cstring>
#include <string>

using namespace LAMMPS_NS;
using namespace Granular_NS;

namespace {
/* The net rolled distance (rolling_contact.h: dc_rolled_x/y/z): the rolling
   velocity does not change sign when i and j swap. */
const dc_history_field rolled_history[3] = {{"dc_rolled_x", 0}, {"dc_rolled_y", 0}, {"dc_rolled_z", 0}};
}    // namespace

GranSubModRollingDcKalker::GranSubModRollingDcKalker(GranularModel *gm, LAMMPS *lmp) :
    GranSubModRolling(gm, lmp)
{
  num_coeffs = 4;
}

void GranSubModRollingDcKalker::coeffs_to_local()
{
  params_.mu = coeffs[0];
  params_.model = (int) coeffs[1];
  params_.v_min = coeffs[2];
  params_.roll_min = coeffs[3];
  dc_check_choice(error, name, "creep", coeffs[1], 2, "{0 kalker, 1 vermeulenJohnson}");
  dc_param_error err;
  if (dc_rolling_check(&params_, &err) != DC_OK)
    dc_param_fail(error, name, err,
                  {{"coefficientFriction", "mu"}, {"rollingVelocityMin", "vmin"}, {"rollingDistanceMin", "dmin"}});
  if (params_.roll_min > 0.0)
    dc_history_transfer(this, rolled_history, 3);
  else
    size_history = 0;
}

void GranSubModRollingDcKalker::init()
{
  contact_.init(this, gm, error, true);
  if (gm->tangential_model->name.rfind("dc/", 0) != 0)
    error->all(FLERR, "{} needs a tangential sub-model that hands the tangential force over while the contact "
               "rolls (dc/classical, ...), not {}", name, gm->tangential_model->name);
  dc_param_error err;
  if (dc_rolling_material_init(&contact_.pair, &material_, &err) != DC_OK)
    error->all(FLERR, "{}: the normal sub-model's E = {} and nu = {}: need E > 0 and nu in [0, 0.5]", name,
               contact_.normal()->get_emod(), contact_.normal()->get_poiss());
}

/* rolling_contact.h, RollingHandover::rolls on spheres: the speed bound of
   isotropic bodies first, then the kinematics and dc_rolling_acts_rolled. */
bool GranSubModRollingDcKalker::rolls()
{
  if (decided_) return acts_;
  decided_ = true;
  const bool wall = gm->contact_type != PAIR;
  const double *n = gm->nx, h = 0.5 * gm->delta;
  const double cri = gm->radi - h, crj = wall ? 0.0 : gm->radj - h;
  const double *oi = gm->omegai, *oj = gm->omegaj;
  double ri[3], rj[3], wi[3], wj[3], dv[3], dw[3];
  for (int c = 0; c < 3; c++) {
    ri[c] = -cri * n[c];
    rj[c] = wall ? 0.0 : crj * n[c];
  }
  wi[0] = gm->vi[0] + oi[1] * ri[2] - oi[2] * ri[1];
  wi[1] = gm->vi[1] + oi[2] * ri[0] - oi[0] * ri[2];
  wi[2] = gm->vi[2] + oi[0] * ri[1] - oi[1] * ri[0];
  if (wall) {
    for (int c = 0; c < 3; c++) {
      wj[c] = gm->vj[c];
      dw[c] = oi[c];
    }
  } else {
    wj[0] = gm->vj[0] + oj[1] * rj[2] - oj[2] * rj[1];
    wj[1] = gm->vj[1] + oj[2] * rj[0] - oj[0] * rj[2];
    wj[2] = gm->vj[2] + oj[0] * rj[1] - oj[1] * rj[0];
    for (int c = 0; c < 3; c++) dw[c] = oi[c] - oj[c];
  }
  for (int c = 0; c < 3; c++) dv[c] = wi[c] - wj[c];

  /* the net rolled distance, or (set-up: history unchanged) a copy */
  double scratch[3] = {0.0, 0.0, 0.0}, *rolled = scratch;
  if (size_history > 0) {
    rolled = &gm->history[history_index];
    if (!gm->history_update) {
      std::memcpy(scratch, rolled, sizeof scratch);
      rolled = scratch;
    }
  }
  const double ki = 1.0 / gm->radi, kj = wall ? 0.0 : 1.0 / gm->radj;
  if (dc_rolling_speed_bound_isotropic(ki, kj, dv, dw) <= params_.v_min) {
    rolled[0] = rolled[1] = rolled[2] = 0.0;
    return acts_ = false;
  }
  dc_rolling_curvature ci = {}, cj = {};
  ci.k1 = ci.k2 = ki;
  cj.k1 = cj.k2 = kj;
  const int st = dc_rolling_kinematics_capped(n, &ci, &cj, dv, dw, INFINITY, &kin_);
  if (st != DC_OK)
    error->one(FLERR, "{}: {} contact: rolling kinematics: {} (relative velocity {} {} {} m/s, relative spin {} {} "
               "{} 1/s)", name, wall ? "wall" : "pair", dc_status_str(st), dv[0], dv[1], dv[2], dw[0], dw[1], dw[2]);
  dc_rolling_params prm = params_;
  prm.mu = 0.0;
  acts_ = dc_rolling_acts_rolled(&prm, &contact_.patch(gm), &kin_, update->dt, rolled) != 0;
  return acts_;
}

void GranSubModRollingDcKalker::calculate_forces()
{
  gm->fr[0] = gm->fr[1] = gm->fr[2] = 0.0;
  const bool acts = rolls();
  decided_ = false;    // the next contact decides afresh
  if (!acts) return;

  const bool wall = gm->contact_type != PAIR;
  const double h = 0.5 * gm->delta, cri = gm->radi - h, crj = wall ? 0.0 : gm->radj - h;
  /* the bodies for the stable step (rolling_model_kalker.h: stepOf) */
  dc_rolling_step step;
  step.dt = update->dt;
  step.inv_m = step.inv_I = 0.0;
  const double mi = wall ? gm->meff : atom->rmass[gm->i];
  const double Ii = 0.4 * mi * gm->radi * gm->radi;
  step.inv_m += 1.0 / mi + cri * cri / Ii;
  step.inv_I += 1.0 / Ii;
  if (!wall) {
    const double mj = atom->rmass[gm->j];
    const double Ij = 0.4 * mj * gm->radj * gm->radj;
    step.inv_m += 1.0 / mj + crj * crj / Ij;
    step.inv_I += 1.0 / Ij;
  }
  const dc_patch &p = contact_.patch(gm);
  const double *n = gm->nx;
  dc_rolling_out out;
  const int st = dc_rolling_force_step(&params_, &material_, &p, n, &kin_, &step, &out);
  if (st != DC_OK)
    error->one(FLERR, "{}: patch a = {}, b = {}, friction load {}, rolling speed {} m/s, slip {} {} {} m/s, spin "
               "{} 1/s: {}", name, p.a, p.b, p.F_bound, kin_.V, kin_.slip[0], kin_.slip[1], kin_.slip[2], kin_.spin,
               dc_status_str(st));

  /* out.F on i at the contact point, out.Mz on i about n; -F, -Mz on j */
  const double *F = out.F;
  const double t0 = n[1] * F[2] - n[2] * F[1], t1 = n[2] * F[0] - n[0] * F[2], t2 = n[0] * F[1] - n[1] * F[0];
  const double t[3] = {t0, t1, t2};
  for (int c = 0; c < 3; c++) {
    gm->forces[c] += F[c];
    gm->torquesi[c] += -cri * t[c] + out.Mz * n[c];
    if (!wall) gm->torquesj[c] += -crj * t[c] - out.Mz * n[c];
  }
}
