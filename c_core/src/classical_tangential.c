/* Classical tangential laws of the lecture notes (dc/classical_tangential.h). */
#include "dc/classical_tangential.h"
#include "dc/classical_tangential_step.h"
#include "dc/status.h"
#include <float.h>
#include <math.h>
#include <stddef.h>
#include <string.h>

const dc_history_field dc_classical_tangential_history[DC_CT_HISTORY_NFIELDS] = {
  {"ct_spring_x", 1}, {"ct_spring_y", 1}, {"ct_spring_z", 1},
  {"ct_reversal_x", 1}, {"ct_reversal_y", 1}, {"ct_reversal_z", 1},
};

static int setting_check(const char *name, int v, int hi, const char *range, dc_param_error *err)
{
  if (v >= 0 && v <= hi) return DC_OK;
  err->name = name;
  err->value = (double)v;
  err->range = range;
  return DC_EDOM;
}

static int uses_stiffness_setting(int law)
{
  return law == DC_CT_SPRING_SLIDING || law == DC_CT_SPRING_DASHPOT_SLIDING || law == DC_CT_INCREMENTAL;
}

static int uses_damping_setting(int law) { return law == DC_CT_SPRING_DASHPOT_SLIDING || law == DC_CT_DI_RENZO; }

static int uses_gstar(const dc_classical_tangential_params *p)
{
  if (uses_stiffness_setting(p->law)) return p->stiffness != DC_CT_KT_GIVEN;
  return p->law == DC_CT_DI_RENZO || p->law == DC_CT_LANGSTON || p->law == DC_CT_ZHENG || p->law == DC_CT_TSUJI;
}

int dc_classical_tangential_check(const dc_classical_tangential_params *p, dc_param_error *err)
{
  int st = setting_check("classicalTangential", p->law, 9,
                         "{0 coulomb, 1 viscous, 2 viscous_sliding, 3 spring_sliding, 4 spring_dashpot_sliding, "
                         "5 di_renzo, 6 langston, 7 zheng, 8 tsuji, 9 incremental}",
                         err);
  if (st) return st;
  if (p->law != DC_CT_VISCOUS &&
      (st = dc_param_check("coefficientFriction", p->mu, 0.0, 0, DBL_MAX, 0, "[0, inf)", err)))
    return st;
  if (uses_stiffness_setting(p->law)) {
    if ((st = setting_check("classicalTangentialStiffness", p->stiffness, 2, "{0 given, 1 ratio, 2 mindlin}", err)))
      return st;
    if (p->stiffness == DC_CT_KT_GIVEN && (st = dc_param_check("kt", p->kt, 0.0, 1, DBL_MAX, 0, "(0, inf)", err)))
      return st;
  }
  if (uses_gstar(p) && (st = dc_param_check("youngsModulus", p->Gstar, 0.0, 1, DBL_MAX, 0,
                                            "G* (from youngsModulus, poissonsRatio) in (0, inf)", err)))
    return st;
  if (uses_stiffness_setting(p->law) && p->stiffness == DC_CT_KT_RATIO &&
      (st = dc_param_check("youngsModulus", p->Estar, 0.0, 1, DBL_MAX, 0, "E* in (0, inf)", err)))
    return st;
  int damping = DC_CT_DAMP_NONE;
  if (uses_damping_setting(p->law)) {
    if ((st = setting_check("classicalTangentialDamping", p->damping, 3,
                            "{0 none, 1 given, 2 restitution, 3 normal}", err)))
      return st;
    damping = p->damping;
  }
  if ((p->law == DC_CT_VISCOUS || p->law == DC_CT_VISCOUS_SLIDING || damping == DC_CT_DAMP_GIVEN) &&
      (st = dc_param_check("gammat", p->gammat, 0.0, 0, DBL_MAX, 0, "[0, inf)", err)))
    return st;
  if (damping == DC_CT_DAMP_RESTITUTION &&
      (st = dc_param_check("coefficientRestitutionTangential", p->e_t, 0.0, 0, 1.0, 0, "[0, 1]", err)))
    return st;
  if (p->law == DC_CT_LANGSTON &&
      (st = dc_param_check("langstonDamping", p->eta_l, 0.0, 0, DBL_MAX, 0, "[0, inf)", err)))
    return st;
  if (p->law == DC_CT_ZHENG &&
      (st = dc_param_check("tangentialViscoelasticTime", p->t_visc, 0.0, 0, DBL_MAX, 0, "[0, inf)", err)))
    return st;
  return DC_OK;
}

int dc_classical_tangential_init(const dc_classical_tangential_params *p, dc_classical_tangential *m,
                                 dc_param_error *err)
{
  int st = dc_classical_tangential_check(p, err);
  if (st) return st;
  dc_classical_tangential r;
  r.p = *p;
  r.zeta_t = 0.0;
  r.ratio = 0.0;
  if (uses_damping_setting(p->law) && p->damping == DC_CT_DAMP_RESTITUTION) {
    /* Deen et al.: eta_t = -2 ln e_t (2/7 m K_t)^1/2 / (ln^2 e_t + pi^2)^1/2 */
    if (p->e_t == 0.0) r.zeta_t = 2.0;
    else {
      const double l = log(p->e_t);
      r.zeta_t = -2.0 * l / sqrt(l * l + M_PI * M_PI);
    }
  }
  if (uses_stiffness_setting(p->law) && p->stiffness == DC_CT_KT_RATIO) {
    r.ratio = 4.0 * (p->Gstar / p->Estar);
    if (!(r.ratio > 0.0 && r.ratio <= DBL_MAX)) {
      err->name = "youngsModulus";
      err->value = p->Estar;
      err->range = "4 G* / E* representable";
      return DC_ERANGE;
    }
  }
  *m = r;
  return DC_OK;
}

int dc_classical_tangential_step(const dc_classical_tangential *m, const dc_patch *patch,
                                 const dc_classical_tangential_contact *c, const double n[3],
                                 const double du[3], const double vt[3], double dt,
                                 dc_classical_tangential_state *h, dc_classical_tangential_out *out)
{
  return dc_classical_tangential_step_law(m->p.law, 1, m, patch, c, n, du, vt, dt, h, out);
}
