/* LIGGGHTS normal model `jkr_elliptic`: adhesive elastic contact (c_core:
   dc/jkr_elliptic.h; classical JKR for spheres, the exact circular limit of
   the Johnson-Greenwood elliptic theory, review Eqs. 19-28).

   Deck: pair_style gran model jkr_elliptic tangential history [settings]
         fix ID all wall/gran model jkr_elliptic tangential history primitive ... [settings]
         neigh_modify contact_distance_factor F   (see below)
   Settings: tangential_damping on|off (default on).
   Properties: youngsModulus, poissonsRatio, coefficientRestitution,
     coefficientFriction as usual, and workOfAdhesion peratomtypepair [J/m^2]
     (w = 2 x surface energy for like surfaces; w >= 0).
   A contact forms when the spheres touch (delta = 0) and is kept, with
   tensile force, on the stable branch of the JKR curve until the overlap
   falls below delta_break = -3/4 (pi^2 w^2 R / E*^2)^1/3 (LIGGGHTS' contact
   history carries the state across neighbour rebuilds and MPI ranks).
   LIGGGHTS only looks at pairs within contact_distance_factor (r_i + r_j),
   so the deck must set F >= 1 + |delta_break| / (r_i + r_j) (walls:
   1 + |delta_break| / r_i); the run stops with the value needed otherwise.
   Damping: LIGGGHTS' restitution damping on the flat-punch stiffness 2 E* a
   of the current contact radius a (dF/d delta itself is unbounded at
   separation); tangential stiffness Mindlin's 8 G a. w = 0 is exactly
   `hertz_elliptic`. Superquadrics: not yet supported. */
#ifdef NORMAL_MODEL
NORMAL_MODEL(JKR_ELLIPTIC,jkr_elliptic,32)
#else
#ifndef NORMAL_MODEL_JKR_ELLIPTIC_H_
#define NORMAL_MODEL_JKR_ELLIPTIC_H_

#include <cmath>
#include <cstdio>
#include "contact_models.h"
#include "global_properties.h"
#include "neighbor.h"
#include "normal_model_base.h"
#include "normal_force_common.h"
#include "dc/jkr_elliptic.h"
#include "dc/status.h"

namespace LIGGGHTS {
namespace ContactModels {

template<>
class NormalModel<JKR_ELLIPTIC> : public NormalModelBase
{
public:
  NormalModel(LAMMPS *lmp, IContactHistorySetup *hsetup, class ContactModelBase *c) :
    NormalModelBase(lmp, hsetup, c),
    Yeff(NULL), Geff(NULL), betaeff(NULL), work(NULL), tangential_damping(true)
  {
    contact_offset = hsetup->add_history_value("jkr_contact", "0");
  }

  void registerSettings(Settings &settings)
  {
    settings.registerOnOff("tangential_damping", tangential_damping, true);
  }

  void postSettings(IContactHistorySetup *, ContactModelBase *)
  {
    if (atom->superquadric_flag)
      error->all(FLERR, "Normal model jkr_elliptic: superquadric particles are not supported yet (spheres only)");
  }

  void connectToProperties(PropertyRegistry &registry)
  {
    const char *caller = "model jkr_elliptic";
    registry.registerProperty("Yeff", &MODEL_PARAMS::createYeff, caller);
    registry.registerProperty("Geff", &MODEL_PARAMS::createGeff, caller);
    registry.registerProperty("betaeff", &MODEL_PARAMS::createBetaEff, caller);
    registry.registerProperty("workOfAdhesion", &createWork, caller);
    registry.connect("Yeff", Yeff, caller);
    registry.connect("Geff", Geff, caller);
    registry.connect("betaeff", betaeff, caller);
    registry.connect("workOfAdhesion", work, caller);
  }

  inline double stressStrainExponent() { return 1.5; }

  inline void surfacesIntersect(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)
  {
    if (sidata.contact_flags) *sidata.contact_flags |= CONTACT_NORMAL_MODEL;
    double &formed = sidata.contact_history[contact_offset];
    if (formed == 0.0) {
      checkReach(sidata);
      formed = 1.0;
    }
    jkrForce(sidata, sidata.deltan, sidata.vn, i_forces, j_forces);
  }

  /* A formed contact with negative overlap: tensile JKR force until delta_break. */
  void surfacesClose(SurfacesCloseData &scdata, ForceData &i_forces, ForceData &j_forces)
  {
    double &formed = scdata.contact_history[contact_offset];
    const double w = work[scdata.itype][scdata.jtype];
    if (formed == 0.0 || w == 0.0) {
      if (scdata.contact_flags) *scdata.contact_flags &= ~CONTACT_NORMAL_MODEL;
      formed = 0.0;
      return;
    }
    /* both callers pass a SurfacesIntersectData; walls have filled en, r, meff */
    SurfacesIntersectData &sidata = static_cast<SurfacesIntersectData &>(scdata);
    double delta;
    if (sidata.is_wall) {
      delta = sidata.deltan;
    } else {
      const double r = sqrt(sidata.rsq);
      delta = sidata.radsum - r;
      for (int k = 0; k < 3; k++) sidata.en[k] = sidata.delta[k] / r;
      sidata.meff = sidata.mi * sidata.mj / (sidata.mi + sidata.mj);
    }
    const double reff = effectiveRadius(sidata);
    if (delta < dc_jkr_sphere_delta_break(reff, Yeff[sidata.itype][sidata.jtype], w)) {
      if (scdata.contact_flags) *scdata.contact_flags &= ~CONTACT_NORMAL_MODEL;
      formed = 0.0;
      return;
    }
    if (scdata.contact_flags) *scdata.contact_flags |= CONTACT_NORMAL_MODEL;
    const double *vj = sidata.v_j;
    const double vn = (sidata.v_i[0] - vj[0]) * sidata.en[0] + (sidata.v_i[1] - vj[1]) * sidata.en[1]
                    + (sidata.v_i[2] - vj[2]) * sidata.en[2];
    sidata.has_force_update = true;
    jkrForce(sidata, delta, vn, i_forces, j_forces);
  }

  void beginPass(SurfacesIntersectData &, ForceData &, ForceData &) {}
  void endPass(SurfacesIntersectData &, ForceData &, ForceData &) {}

private:
  static double effectiveRadius(const SurfacesIntersectData &sidata)
  {
    return sidata.is_wall ? sidata.radi : sidata.radi * sidata.radj / (sidata.radi + sidata.radj);
  }

  /* On forming a contact: can LIGGGHTS follow it down to delta_break? */
  void checkReach(const SurfacesIntersectData &sidata)
  {
    const double w = work[sidata.itype][sidata.jtype];
    if (w == 0.0) return;
    const double reach = sidata.is_wall ? sidata.radi : sidata.radsum;
    const double need = 1.0 - dc_jkr_sphere_delta_break(effectiveRadius(sidata), Yeff[sidata.itype][sidata.jtype], w) / reach;
    if (neighbor->contactDistanceFactor < need) {
      char msg[256];
      snprintf(msg, sizeof msg, "Normal model jkr_elliptic: adhesive contacts are kept until separation: "
               "set neigh_modify contact_distance_factor >= %.6g", need);
      error->one(FLERR, msg);
    }
  }

  void jkrForce(SurfacesIntersectData &sidata, double delta, double vn,
                ForceData &i_forces, ForceData &j_forces)
  {
    const int itype = sidata.itype, jtype = sidata.jtype;
    const double reff = effectiveRadius(sidata);
    const double Y = Yeff[itype][jtype], G = Geff[itype][jtype], w = work[itype][jtype];
    double P, Sn, kn, kt;
    if (w == 0.0) {
      hertzStiffness(Y, G, reff, reff, delta, kn, Sn, kt);
      P = kn * delta;
    } else {
      dc_jkr_state s;
      const int st = dc_jkr_sphere(reff, Y, w, delta, &s);
      if (st != DC_OK) {
        char msg[256];
        snprintf(msg, sizeof msg, "Normal model jkr_elliptic: overlap %g, radius %g, work of adhesion %g: %s", delta, reff, w, dc_status_str(st));
        error->one(FLERR, msg);
      }
      P = s.F;
      Sn = 2.0 * Y * s.a;             /* flat-punch stiffness of the contact */
      kt = 8.0 * G * s.a;
      kn = Sn;
    }
    const double gamman = restitutionDamping(betaeff[itype][jtype], Sn, sidata.meff);
    const double gammat = tangential_damping ? restitutionDamping(betaeff[itype][jtype], kt, sidata.meff) : 0.0;
    const double Fn = -gamman * vn + P / force->nktv2p;
    sidata.Fn = Fn;
    sidata.kn = kn / force->nktv2p;
    sidata.kt = kt / force->nktv2p;
    sidata.gamman = gamman;
    sidata.gammat = gammat;
    applyNormalForce(sidata, Fn, atom->x, i_forces, j_forces);
  }

  static MatrixProperty *createWork(PropertyRegistry &registry, const char *caller, bool sanity_checks)
  {
    return MODEL_PARAMS::createPerTypePairProperty(registry, "workOfAdhesion", caller, sanity_checks, 0.0);
  }

  double **Yeff, **Geff, **betaeff, **work;
  bool tangential_damping;
  int contact_offset;
};

}
}
#endif
#endif
