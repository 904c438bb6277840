/* LIGGGHTS normal model `classical`: the classical normal laws of the lecture
   notes as one model with a law setting (c_core: dc/classical_normal.h,
   Lopez Rangel 2021 Sec. 3): the cheap baselines of the project's laws.

   Deck: pair_style gran model classical tangential <t> classicalNormal LAW [settings]
         fix ID all wall/gran model classical tangential <t> ... classicalNormal LAW [settings]
   Settings: those of every project normal model (dc_model_base.h), and
     classicalNormal LAW      lsd (linear spring-dashpot, default) | hertz |
                              hlsConstant | hlsVariable (Walton-Braun hysteretic
                              linear spring, unloading stiffness K_L/e^2 or
                              K_L (1 + S delta_max))
     classicalStiffness HOW   K of lsd, K_L of hls: given (property kn) |
                              duration | overlap | energy (default): matched to
                              the elastic Hertz collision at
                              characteristicVelocity (equal collision duration,
                              maximum overlap or strain energy; energy is
                              stock `hooke`'s stiffness); duration not with
                              hlsVariable
     damping LAW              hertz only (lsd takes its dashpot from
                              coefficientRestitution, hls dissipates by its
                              hysteresis): restitution (default) | viscoelastic
                              | kuwabaraKono | tsuji | none
   Properties: youngsModulus, poissonsRatio (E*; G* for the tangential
     stiffness 8 G* a), and as the law needs: coefficientRestitution
     (peratomtypepair; lsd, hlsConstant, hertz with restitution or tsuji),
     kn [N/m] (peratomtypepair, stiffness given), characteristicVelocity
     [m/s] (scalar, matched stiffness), unloadingStiffnessSlope S [1/m]
     (peratomtypepair, hlsVariable), viscoelasticTime [s],
     kuwabaraKonoDamping [N s m^-3/2] (peratomtypepair, hertz).
   R is the effective radius of the spheres (superquadrics: of the
   volume-equivalent spheres, as stock models), m the effective mass.
   Tangential stiffness 8 G* a with a = (R delta)^1/2 (the circle the patch
   publishes); tangential_damping: the normal dashpot coefficient, as stock
   `hooke`. History: hls keeps the largest overlap of a contact (1 value),
   reset when the surfaces part. */
#ifdef NORMAL_MODEL
NORMAL_MODEL(NORMAL_CLASSICAL,classical,@DC_MODEL_ID@)
#else
#ifndef NORMAL_MODEL_CLASSICAL_H_
#define NORMAL_MODEL_CLASSICAL_H_

#include <cstring>
#include <vector>
#include "dc_model_base.h"
#include "dc/classical_normal.h"
#include "dc/mindlin.h"

namespace LIGGGHTS {
namespace ContactModels {

template<>
class NormalModel<NORMAL_CLASSICAL> : public DcNormalModel
{
public:
  NormalModel(LAMMPS *lmp, IContactHistorySetup *hsetup, class ContactModelBase *c) :
    DcNormalModel(lmp, hsetup, c, "classical", NO_CURVATURE_REUSE), law(DC_CLASSICAL_LSD), stiffness(DC_CLASSICAL_K_ENERGY),
    history_offset(-1), ntypes(0)
  {}

  void registerSettings(Settings &settings)
  {
    DcNormalModel::registerSettings(settings);
    static const char *const laws[] = {"lsd", "hertz", "hlsConstant", "hlsVariable"};
    static const int law_ids[] = {DC_CLASSICAL_LSD, DC_CLASSICAL_HERTZ, DC_CLASSICAL_HLS_CONSTANT,
                                  DC_CLASSICAL_HLS_VARIABLE};
    settings.registerChoice("classicalNormal", law, laws, law_ids, 4, "lsd");
    static const char *const ks[] = {"given", "duration", "overlap", "energy"};
    static const int k_ids[] = {DC_CLASSICAL_K_GIVEN, DC_CLASSICAL_K_DURATION, DC_CLASSICAL_K_OVERLAP,
                                DC_CLASSICAL_K_ENERGY};
    settings.registerChoice("classicalStiffness", stiffness, ks, k_ids, 4, "energy");
  }

  void postSettings(IContactHistorySetup *hsetup, ContactModelBase *c)
  {
    DcNormalModel::postSettings(hsetup, c);
    if (hysteretic())
      history_offset = hsetup->add_history_value(dc_classical_normal_history[0].name,
                                                 dc_classical_normal_history[0].flips ? "1" : "0");
  }

  void connectToProperties(PropertyRegistry &registry)
  {
    const char *caller = "model classical";
    const bool hertz = law == DC_CLASSICAL_HERTZ;
    if (!hertz && (viscoelastic || dampingSetting != DC_DAMPING_RESTITUTION))
      stop(true, "'damping' and 'viscoelastic' apply to classicalNormal hertz: lsd takes its dashpot from "
                 "coefficientRestitution, hlsConstant and hlsVariable dissipate by their hysteresis");
    if (law == DC_CLASSICAL_HLS_VARIABLE && stiffness == DC_CLASSICAL_K_DURATION)
      stop(true, "classicalStiffness duration is not available with classicalNormal hlsVariable (its collision "
                 "duration depends on the speed): use given, overlap or energy");
    dampingLaw = hertz ? deckDamping() : DC_DAMPING_NONE;   /* lsd, hls: no damping property */
    connectProperties(registry);   /* E*, G*, the damping law's coefficient (dampCoef) */
    const bool matched = !hertz && stiffness != DC_CLASSICAL_K_GIVEN;
    const bool uses_e = law == DC_CLASSICAL_LSD || law == DC_CLASSICAL_HLS_CONSTANT ||
                        (hertz && (dampingLaw == DC_DAMPING_RESTITUTION || dampingLaw == DC_DAMPING_TSUJI));
    double **e = matrix(registry, "coefficientRestitution", &MODEL_PARAMS::createCoeffRest, uses_e);
    double **kn = matrix(registry, "kn", &createKn, !hertz && stiffness == DC_CLASSICAL_K_GIVEN);
    double **S = matrix(registry, "unloadingStiffnessSlope", &createSlope, law == DC_CLASSICAL_HLS_VARIABLE);
    double vchar = 0.0;
    if (matched) {
      registry.registerProperty("characteristicVelocity", &MODEL_PARAMS::createCharacteristicVelocity, caller);
      vchar = registry.getScalarProperty("characteristicVelocity", caller)->data;
    }
    ntypes = registry.max_type();
    models.assign((ntypes + 1) * (ntypes + 1), dc_classical_normal());
    for (int i = 1; i <= ntypes; i++)
      for (int j = 1; j <= ntypes; j++) {
        dc_classical_normal_params p;
        memset(&p, 0, sizeof p);
        p.law = law;
        p.stiffness = stiffness;
        p.damping = dampingLaw;
        p.limit = limitForce ? 1 : 0;
        p.Estar = Yeff[i][j];
        p.kn = kn ? kn[i][j] : 0.0;
        p.v_char = vchar;
        p.e = e ? e[i][j] : 1.0;
        p.A = p.eta_kk = dampCoef[i * (ntypes + 1) + j];   /* viscoelasticTime or kuwabaraKonoDamping */
        p.S = S ? S[i][j] : 0.0;
        dc_param_error err;
        if (dc_classical_normal_init(&p, &models[i * (ntypes + 1) + j], &err) != DC_OK) stopParam(err, i, j);
      }
  }

  inline void surfacesIntersect(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)
  {
    if (sidata.contact_flags) *sidata.contact_flags |= CONTACT_NORMAL_MODEL;
    const double R = stockEffectiveRadius(sidata, atom->superquadric_flag);
    dc_classical_normal_state scratch = {0.0};
    dc_classical_normal_state *h = &scratch;
    if (history_offset >= 0) {
      h = reinterpret_cast<dc_classical_normal_state *>(&sidata.contact_history[history_offset]);
      if (!(sidata.computeflag && sidata.shearupdate)) {   /* a pass that must not change the history */
        scratch = *h;
        h = &scratch;
      }
    }
    dc_classical_normal_out out;
    const int st = dc_classical_normal_step(&models[sidata.itype * (ntypes + 1) + sidata.jtype], R, sidata.meff,
                                            sidata.deltan, -sidata.vn, h, &out);
    if (st != DC_OK) {
      char msg[256];
      snprintf(msg, sizeof msg, "contact of atom %d: radius %g, mass %g, overlap %g, normal velocity %g (types %d "
               "and %d): %s", (int)atom->tag[sidata.i], R, sidata.meff, sidata.deltan, sidata.vn, sidata.itype,
               sidata.jtype, dc_status_str(st));
      stop(false, msg);
    }
    const double kt = dc_mindlin_kt_circle(Geff[sidata.itype][sidata.jtype], out.c.a);
    sidata.Fn = out.F * invNktv2p;
    sidata.kn = (sidata.deltan > 0.0 ? out.c.F / sidata.deltan : out.K) * invNktv2p;   /* secant */
    sidata.kt = kt * invNktv2p;
    sidata.gamman = out.gamma;
    sidata.gammat = tangential_damping ? out.gamma : 0.0;
    applyNormalForce(sidata, sidata.Fn, atom->x, i_forces, j_forces);
    publish(sidata, out.c, NULL);
  }

  /* Apart: a new contact starts on the loading line. */
  void surfacesClose(SurfacesCloseData &scdata, ForceData &, ForceData &)
  {
    if (scdata.contact_flags) *scdata.contact_flags |= CONTACT_NORMAL_MODEL;
    if (history_offset >= 0 && scdata.contact_history) scdata.contact_history[history_offset] = 0.0;
    publishNone(scdata);
  }

private:
  bool hysteretic() const { return law == DC_CLASSICAL_HLS_CONSTANT || law == DC_CLASSICAL_HLS_VARIABLE; }

  /* A per-type-pair property the law needs (NULL when it does not). */
  double **matrix(PropertyRegistry &registry, const char *name,
                  MatrixProperty *(*create)(PropertyRegistry &, const char *, bool), bool needed)
  {
    if (!needed) return NULL;
    registry.registerProperty(name, create, "model classical");
    return registry.getMatrixProperty(name, "model classical")->data;
  }
  static MatrixProperty *createKn(PropertyRegistry &r, const char *c, bool s)
  { return MODEL_PARAMS::createPerTypePairProperty(r, "kn", c, s, 0.0); }
  static MatrixProperty *createSlope(PropertyRegistry &r, const char *c, bool s)
  { return MODEL_PARAMS::createPerTypePairProperty(r, "unloadingStiffnessSlope", c, s, 0.0); }

  int law, stiffness;
  int history_offset, ntypes;
  std::vector<dc_classical_normal> models;
};

}
}
#endif
#endif
