/* LIGGGHTS tangential model `classical`: the classical tangential laws of the
   lecture notes as one model with a law setting (c_core:
   dc/classical_tangential.h, Lopez Rangel 2021 Sec. 4): the cheap
   alternatives to cmd_tangential.

   Deck: pair_style gran model <normal> tangential classical classicalTangential LAW [settings]
   Settings:
     classicalTangential LAW   coulomb | viscous | viscousSliding | springSliding (default)
                               | springDashpotSliding | diRenzo | langston | zheng | tsuji
                               | incremental
     classicalTangentialStiffness given | ratio | mindlin (default mindlin): K_t of
                               springSliding, springDashpotSliding, incremental:
                               property kt [N/m], 4 G* / E* K_n, or 8 G* a
     classicalTangentialDamping none | given | restitution | normal (default none):
                               springDashpotSliding, diRenzo: property gammat
                               [N s/m], coefficientRestitutionTangential (Deen),
                               or the normal damping coefficient
   Properties: coefficientFriction (peratomtypepair, all laws but viscous),
     youngsModulus and poissonsRatio (G*, E*), and as the law needs: kt,
     gammat (peratomtypepair; viscous, viscousSliding, damping given),
     coefficientRestitutionTangential, langstonDamping [-],
     tangentialViscoelasticTime [s] (zheng).
   The contact patch (semi-axes, friction load) comes from the normal model
   (contact_patch.h). The normal model's tangential_damping does not apply:
   damping is the law's own. With `rolling_friction kalker` it hands the
   tangential force over while the contact rolls (rolling_contact.h): it
   applies nothing then and its spring starts afresh when the contact
   stops rolling. */
#ifdef TANGENTIAL_MODEL
TANGENTIAL_MODEL(TANGENTIAL_CLASSICAL,classical,@DC_MODEL_ID@)
#else
#ifndef TANGENTIAL_MODEL_CLASSICAL_H_
#define TANGENTIAL_MODEL_CLASSICAL_H_

#include <cstdio>
#include <cstring>
#include <vector>
#include "atom.h"
#include "contact_frame.h"
#include "contact_models.h"
#include "contact_patch.h"
#include "error.h"
#include "global_properties.h"
#include "rolling_contact.h"
#include "tangential_model_base.h"
#include "update.h"
#include "dc/classical_tangential.h"
#include "dc/classical_tangential_step.h"
#include "dc/contract.h"
#include "dc/status.h"

namespace LIGGGHTS {
namespace ContactModels {

template<>
class TangentialModel<TANGENTIAL_CLASSICAL> : public TangentialModelBase
{
  typedef void (*IntersectFn)(TangentialModel *, const SurfacesIntersectData &, ForceData &, ForceData &);

public:
  TangentialModel(LAMMPS *lmp, IContactHistorySetup *hsetup, class ContactModelBase *c) :
    TangentialModelBase(lmp, hsetup, c), law(DC_CT_SPRING_SLIDING), stiffness(DC_CT_KT_MINDLIN),
    damping(DC_CT_DAMP_NONE), history_offset(-1), stride(1), intersect_(&intersect<DC_CT_SPRING_SLIDING, false>)
  {
    patch.request(c);
    handover.attach(c);
  }

  void registerSettings(Settings &settings)
  {
    static const char *const laws[] = {"coulomb", "viscous", "viscousSliding", "springSliding",
                                       "springDashpotSliding", "diRenzo", "langston", "zheng", "tsuji",
                                       "incremental"};
    static const int law_ids[] = {DC_CT_COULOMB, DC_CT_VISCOUS, DC_CT_VISCOUS_SLIDING, DC_CT_SPRING_SLIDING,
                                  DC_CT_SPRING_DASHPOT_SLIDING, DC_CT_DI_RENZO, DC_CT_LANGSTON, DC_CT_ZHENG,
                                  DC_CT_TSUJI, DC_CT_INCREMENTAL};
    settings.registerChoice("classicalTangential", law, laws, law_ids, 10, "springSliding");
    static const char *const kts[] = {"given", "ratio", "mindlin"};
    static const int kt_ids[] = {DC_CT_KT_GIVEN, DC_CT_KT_RATIO, DC_CT_KT_MINDLIN};
    settings.registerChoice("classicalTangentialStiffness", stiffness, kts, kt_ids, 3, "mindlin");
    static const char *const damps[] = {"none", "given", "restitution", "normal"};
    static const int damp_ids[] = {DC_CT_DAMP_NONE, DC_CT_DAMP_GIVEN, DC_CT_DAMP_RESTITUTION, DC_CT_DAMP_NORMAL};
    settings.registerChoice("classicalTangentialDamping", damping, damps, damp_ids, 4, "none");
    handover.registerSettings(settings);
  }

  /* The spring (3 values), and the reversal force of incremental (3 more). */
  void postSettings(IContactHistorySetup *hsetup, ContactModelBase *c)
  {
    patch.setup(lmp, c);
    handover.setup(lmp, hsetup);
    intersect_ = patch.published() && !handover.active() ? pick<true>(law) : pick<false>(law);
    for (int k = 0; k < nfields(); k++) {
      const int off = hsetup->add_history_value(dc_classical_tangential_history[k].name,
                                                dc_classical_tangential_history[k].flips ? "1" : "0");
      if (k == 0) history_offset = off;
    }
  }

  void connectToProperties(PropertyRegistry &registry)
  {
    const char *caller = "tangential_model classical";
    const int n = registry.max_type();
    stride = n + 1;
    double **mu = matrix(registry, "coeffFrict", &MODEL_PARAMS::createCoeffFrict, law != DC_CT_VISCOUS);
    double **kt = matrix(registry, "kt", &createKt, stiffness == DC_CT_KT_GIVEN && springy());
    const bool given = law == DC_CT_VISCOUS || law == DC_CT_VISCOUS_SLIDING ||
                       (damping == DC_CT_DAMP_GIVEN && dashpot());
    double **gt = matrix(registry, "gammat", &createGammat, given);
    double **et = matrix(registry, "coefficientRestitutionTangential", &createEt,
                         damping == DC_CT_DAMP_RESTITUTION && dashpot());
    double **eta = matrix(registry, "langstonDamping", &createLangston, law == DC_CT_LANGSTON);
    double **tv = matrix(registry, "tangentialViscoelasticTime", &createTvisc, law == DC_CT_ZHENG);
    registry.registerProperty("Yeff", &MODEL_PARAMS::createYeff, caller);
    registry.registerProperty("Geff", &MODEL_PARAMS::createGeff, caller);
    double **Y = registry.getMatrixProperty("Yeff", caller)->data;
    double **G = registry.getMatrixProperty("Geff", caller)->data;
    models.assign((n + 1) * (n + 1), dc_classical_tangential());
    for (int i = 1; i <= n; i++)
      for (int j = 1; j <= n; j++) {
        dc_classical_tangential_params p;
        memset(&p, 0, sizeof p);
        p.law = law;
        p.stiffness = stiffness;
        p.damping = damping;
        p.mu = mu ? mu[i][j] : 0.0;
        p.kt = kt ? kt[i][j] : 1.0;
        p.gammat = gt ? gt[i][j] : 0.0;
        p.e_t = et ? et[i][j] : 0.0;
        p.Gstar = G[i][j];
        p.Estar = Y[i][j];
        p.eta_l = eta ? eta[i][j] : 0.0;
        p.t_visc = tv ? tv[i][j] : 0.0;
        dc_param_error err;
        if (dc_classical_tangential_init(&p, &models[i * (n + 1) + j], &err) != DC_OK) {
          char msg[256], what[200];
          dc_param_error_format(&err, i, j, what, sizeof what);
          snprintf(msg, sizeof msg, "Tangential model classical: %s", what);
          error->all(FLERR, msg);
        }
      }
  }

  /* The law's own evaluation, chosen once from the setting: one indirect
     call per contact. */
  __attribute__((always_inline)) inline void surfacesIntersect(const SurfacesIntersectData &sidata,
                                                               ForceData &i_forces, ForceData &j_forces)
  {
    intersect_(this, sidata, i_forces, j_forces);
  }

  /* One law's evaluation, its law a constant in the step (compiled as
     scalar code: GCC's basic-block vectorizer adds shuffles here); PLAIN:
     the normal model publishes the patch and no rolling model shares the
     contact (both known at set-up). */
  template<int LAW, bool PLAIN>
  __attribute__((optimize("no-tree-slp-vectorize"))) static void intersect(TangentialModel *self,
                                                                           const SurfacesIntersectData &sidata,
                                                                           ForceData &i_forces, ForceData &j_forces)
  {
    self->intersectLaw<LAW, PLAIN>(sidata, i_forces, j_forces);
  }
  template<bool PLAIN>
  static IntersectFn pick(int law)
  {
    switch (law) {
    case DC_CT_COULOMB: return &intersect<DC_CT_COULOMB, PLAIN>;
    case DC_CT_VISCOUS: return &intersect<DC_CT_VISCOUS, PLAIN>;
    case DC_CT_VISCOUS_SLIDING: return &intersect<DC_CT_VISCOUS_SLIDING, PLAIN>;
    case DC_CT_SPRING_SLIDING: return &intersect<DC_CT_SPRING_SLIDING, PLAIN>;
    case DC_CT_SPRING_DASHPOT_SLIDING: return &intersect<DC_CT_SPRING_DASHPOT_SLIDING, PLAIN>;
    case DC_CT_DI_RENZO: return &intersect<DC_CT_DI_RENZO, PLAIN>;
    case DC_CT_LANGSTON: return &intersect<DC_CT_LANGSTON, PLAIN>;
    case DC_CT_ZHENG: return &intersect<DC_CT_ZHENG, PLAIN>;
    case DC_CT_TSUJI: return &intersect<DC_CT_TSUJI, PLAIN>;
    default: return &intersect<DC_CT_INCREMENTAL, PLAIN>;
    }
  }
  template<int LAW, bool PLAIN>
  __attribute__((always_inline)) inline void intersectLaw(const SurfacesIntersectData &sidata, ForceData &i_forces,
                                                          ForceData &j_forces)
  {
    if (sidata.contact_flags) *sidata.contact_flags |= CONTACT_TANGENTIAL_MODEL;
    dc_patch stock;
    const dc_patch &p = PLAIN ? patch.publishedPatch() : patch.read(sidata, stock);
    if (!PLAIN && handover.active() && handover.rolls(lmp, sidata, p)) {   /* the rolling model owns the tangential force */
      if (sidata.computeflag && sidata.shearupdate)
        memset(&sidata.contact_history[history_offset], 0, nfields() * sizeof(double));
      return;
    }
    const double vt[3] = {sidata.vtr1, sidata.vtr2, sidata.vtr3};
    const dc_classical_tangential_contact c = {sidata.meff, sidata.kn, sidata.gamman};
    dc_classical_tangential_state *h =
        reinterpret_cast<dc_classical_tangential_state *>(&sidata.contact_history[history_offset]);
    dc_classical_tangential_state scratch;
    if (!(sidata.computeflag && sidata.shearupdate)) {   /* a pass that must not change the history */
      memset(&scratch, 0, sizeof scratch);
      memcpy(&scratch, h, nfields() * sizeof(double));
      h = &scratch;
    }
    /* the inputs lie in the law's domain by construction (LIGGGHTS' unit
       normal and velocities, the normal model's patch): the step unchecked,
       its results checked; on an error the checked step names the cause */
    dc_classical_tangential_out out;
    const dc_classical_tangential *m = &models[sidata.itype * stride + sidata.jtype];
    if (dc_classical_tangential_step_law(LAW, 0, m, &p, &c, sidata.en, NULL, vt, update->dt, h, &out) != DC_OK)
      fail(sidata, *m, p, *h);
    applyTangentialForceAs<true>(sidata, out.Ft, sidata.cri, sidata.crj, atom->x, i_forces, j_forces);   /* Ft on j */
  }

  /* Apart: the spring is released (as stock tangential history). */
  void surfacesClose(SurfacesCloseData &scdata, ForceData &, ForceData &)
  {
    if (scdata.contact_history)
      memset(&scdata.contact_history[history_offset], 0, nfields() * sizeof(double));
  }

  void beginPass(SurfacesIntersectData &, ForceData &, ForceData &) {}
  void endPass(SurfacesIntersectData &, ForceData &, ForceData &) {}

private:
  /* A c_core error: the checked step names the cause and the run stops
     (its own copies of the step's data, so that the hot path's stay in
     registers). */
  __attribute__((noinline)) void fail(const SurfacesIntersectData &sidata, const dc_classical_tangential &m,
                                      const dc_patch &p, dc_classical_tangential_state h)
  {
    const double vt[3] = {sidata.vtr1, sidata.vtr2, sidata.vtr3};
    const dc_classical_tangential_contact c = {sidata.meff, sidata.kn, sidata.gamman};
    dc_classical_tangential_out out;
    const int st = dc_classical_tangential_step(&m, &p, &c, sidata.en, NULL, vt, update->dt, &h, &out);
    char msg[320];
    snprintf(msg, sizeof msg, "Tangential model classical: contact of atom %d: patch a = %g, friction load %g, "
             "velocity %g %g %g: %s", (int)atom->tag[sidata.i], p.a, p.F_bound, vt[0], vt[1], vt[2], dc_status_str(st));
    error->one(FLERR, msg);
  }

  /* history values stored: the laws other than incremental read only the spring */
  int nfields() const { return law == DC_CT_INCREMENTAL ? DC_CT_HISTORY_NFIELDS : DC_CT_SPRING_NFIELDS; }
  bool springy() const
  {
    return law == DC_CT_SPRING_SLIDING || law == DC_CT_SPRING_DASHPOT_SLIDING || law == DC_CT_INCREMENTAL;
  }
  bool dashpot() const { return law == DC_CT_SPRING_DASHPOT_SLIDING || law == DC_CT_DI_RENZO; }

  /* A per-type-pair property the law needs (NULL when it does not). */
  double **matrix(PropertyRegistry &registry, const char *name, MatrixProperty *(*create)(PropertyRegistry &, const char *, bool),
                  bool needed)
  {
    if (!needed) return NULL;
    const char *caller = "tangential_model classical";
    registry.registerProperty(name, create, caller);
    return registry.getMatrixProperty(name, caller)->data;
  }
  static MatrixProperty *createKt(PropertyRegistry &r, const char *c, bool s)
  { return MODEL_PARAMS::createPerTypePairProperty(r, "kt", c, s, 0.0); }
  static MatrixProperty *createGammat(PropertyRegistry &r, const char *c, bool s)
  { return MODEL_PARAMS::createPerTypePairProperty(r, "gammat", c, s, 0.0); }
  static MatrixProperty *createEt(PropertyRegistry &r, const char *c, bool s)
  { return MODEL_PARAMS::createPerTypePairProperty(r, "coefficientRestitutionTangential", c, s, 0.0); }
  static MatrixProperty *createLangston(PropertyRegistry &r, const char *c, bool s)
  { return MODEL_PARAMS::createPerTypePairProperty(r, "langstonDamping", c, s, 0.0); }
  static MatrixProperty *createTvisc(PropertyRegistry &r, const char *c, bool s)
  { return MODEL_PARAMS::createPerTypePairProperty(r, "tangentialViscoelasticTime", c, s, 0.0); }

  int law, stiffness, damping;
  int history_offset, stride;   /* stride: the number of types + 1, of models' rows */
  IntersectFn intersect_;       /* the law's evaluation */
  std::vector<dc_classical_tangential> models;
  ContactPatchReader patch;
  RollingHandover handover;
};

}
}
#endif
#endif
