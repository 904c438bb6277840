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
    connectElasticProperties(registry, caller, Yeff, Geff, betaeff);
    registry.registerProperty("workOfAdhesion", &createWork, caller);
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
    double vn;
    const double delta = closeSphereContact(scdata, vn);
    SurfacesIntersectData &sidata = static_cast<SurfacesIntersectData &>(scdata);
    const double reff = sphereEffectiveRadius(sidata);
    if (delta < dc_jkr_sphere_delta_break(reff, Yeff[sidata.itype][sidata.jtype], w)) {
      if (scdata.contact_flags) *scdata.contact_flags &= ~CONTACT_NORMAL_MODEL;
      formed = 0.0;
      return;
    }
    if (scdata.contact_flags) *scdata.contact_flags |= CONTACT_NORMAL_MODEL;
    sidata.has_force_update = true;
    jkrForce(sidata, delta, vn, i_forces, j_forces);
  }

  void beginPass(SurfacesIntersectData &, ForceData &, ForceData &) {}
  void endPass(SurfacesIntersectData &, ForceData &, ForceData &) {}

private:
  /* On forming a contact: can LIGGGHTS follow it down to delta_break? */
  void checkReach(const SurfacesIntersectData &sidata)
  {
    const double w = work[sidata.itype][sidata.jtype];
    if (w == 0.0) return;
    const double reach = sidata.is_wall ? sidata.radi : sidata.radsum;
    const double need = 1.0 - dc_jkr_sphere_delta_break(sphereEffectiveRadius(sidata), Yeff[sidata.itype][sidata.jtype], w) / reach;
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
    const double reff = sphereEffectiveRadius(sidata);
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
    dampedNormalForce(sidata, P, vn, Sn, kn, kt, betaeff[itype][jtype], tangential_damping,
                      false, force->nktv2p, atom->x, i_forces, j_forces);
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
