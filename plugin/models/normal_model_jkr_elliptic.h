/* LIGGGHTS normal model `jkr_elliptic`: adhesive elastic contact (c_core:
   dc/jkr_elliptic.h: classical JKR for spheres, the Johnson-Greenwood
   elliptic theory for superquadrics, review Eqs. 19-28; dissipation:
   dc/dissipation_adhesive.h).

   Deck: pair_style gran model jkr_elliptic tangential history [surface superquadric] [settings]
         fix ID all wall/gran model jkr_elliptic tangential history [surface superquadric] primitive ... [settings]
         neigh_modify contact_distance_factor F   (see below)
   Settings: tangential_damping on|off (default on);
     viscoelastic on|off (default off): damping from the viscoelastic law
       F_dis = A (d delta/dt) k_punch instead of the restitution coefficient
       (property viscoelasticTime A [s], as in hertz_elliptic);
     maxRadiusFactor R   superquadrics: cap on the relative principal radii,
       as in hertz_elliptic (default 100).
   Properties: youngsModulus, poissonsRatio, coefficientRestitution (or
     viscoelasticTime), coefficientFriction as usual, and workOfAdhesion
     peratomtypepair [J/m^2] (w = 2 x surface energy for like surfaces; w >= 0).
   A contact forms when the surfaces touch (delta = 0) and is kept, with
   tensile force, on the stable branch of the JKR curve until the overlap
   falls below delta_break (spheres: -3/4 (pi^2 w^2 R / E*^2)^1/3;
   superquadrics: that of the elliptic contact, dc_jkr_geometry). LIGGGHTS'
   contact history carries the state across neighbour rebuilds and MPI
   ranks. LIGGGHTS only looks at pairs within contact_distance_factor
   (r_i + r_j), so the deck must set F >= 1 + |delta_break| / (r_i + r_j)
   (walls: 1 + |delta_break| / r_i; superquadrics: bounding radii for pairs,
   volume-equivalent radius for walls); the run stops with the value needed
   otherwise. Damping acts on the flat-punch stiffness k_punch = pi E* a /
   K(e^2) of the current contact ellipse (2 E* a for a circle; dF/d delta
   itself is unbounded at separation); tangential stiffness 8 G (a b)^1/2.
   Superquadrics: relative principal radii from both surfaces' curvatures
   (superquadric_curvature.h), the gap of a formed contact from
   superquadric_gap.h, and the elliptic solve warm-started from the previous
   step (three history values). w = 0 is exactly `hertz_elliptic`. */
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
#include "superquadric_curvature.h"
#include "superquadric_gap.h"
#include "dc/dissipation_adhesive.h"
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
    Yeff(NULL), Geff(NULL), betaeff(NULL), work(NULL), viscoelasticTime(NULL),
    tangential_damping(true), viscoelastic(false), maxRadiusFactor(100.0), hint_offset(-1)
  {
    contact_offset = hsetup->add_history_value("jkr_contact", "0");
#ifdef SUPERQUADRIC_ACTIVE_FLAG
    if (atom->superquadric_flag) {
      hint_offset = hsetup->add_history_value("jkr_hint_v", "0");
      hsetup->add_history_value("jkr_hint_L", "0");
      hsetup->add_history_value("jkr_hint_s", "0");
    }
    gap.addHistory(lmp, hsetup);
#endif
  }

  void registerSettings(Settings &settings)
  {
    settings.registerOnOff("tangential_damping", tangential_damping, true);
    settings.registerOnOff("viscoelastic", viscoelastic, false);
    settings.registerDoubleSetting("maxRadiusFactor", maxRadiusFactor, 100.0);
  }

  void postSettings(IContactHistorySetup *, ContactModelBase *c)
  {
#ifdef SUPERQUADRIC_ACTIVE_FLAG
    curvature.setup(lmp, c, maxRadiusFactor, "jkr_elliptic");
    gap.setup(lmp, c);
#else
    (void)c;
#endif
  }

  void connectToProperties(PropertyRegistry &registry)
  {
    const char *caller = "model jkr_elliptic";
    connectElasticProperties(registry, caller, Yeff, Geff, betaeff, !viscoelastic);
    registry.registerProperty("workOfAdhesion", &createWork, caller);
    registry.connect("workOfAdhesion", work, caller);
    if (viscoelastic) connectViscoelasticTime(registry, caller, viscoelasticTime);
  }

  inline double stressStrainExponent() { return 1.5; }

  inline void surfacesIntersect(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)
  {
    if (sidata.contact_flags) *sidata.contact_flags |= CONTACT_NORMAL_MODEL;
    double &formed = sidata.contact_history[contact_offset];
    const bool forming = formed == 0.0;
    formed = 1.0;
    jkrForce(sidata, sidata.deltan, sidata.vn, forming, i_forces, j_forces);
  }

  /* A formed contact with negative overlap: tensile JKR force until delta_break. */
  void surfacesClose(SurfacesCloseData &scdata, ForceData &i_forces, ForceData &j_forces)
  {
    double &formed = scdata.contact_history[contact_offset];
    const double w = work[scdata.itype][scdata.jtype];
    if (formed == 0.0 || w == 0.0) {
      release(scdata);
      return;
    }
    SurfacesIntersectData &sidata = static_cast<SurfacesIntersectData &>(scdata);
    double delta, vn;
#ifdef SUPERQUADRIC_ACTIVE_FLAG
    if (atom->superquadric_flag) {
      if (!gap.closeOverlap(lmp, sidata, sidata.radsum, delta, vn)) {
        release(scdata);
        return;
      }
    } else
#endif
    delta = closeSphereContact(scdata, vn);
    if (!jkrForce(sidata, delta, vn, false, i_forces, j_forces)) {
      release(scdata);
      return;
    }
    if (scdata.contact_flags) *scdata.contact_flags |= CONTACT_NORMAL_MODEL;
    sidata.has_force_update = true;
  }

  void beginPass(SurfacesIntersectData &, ForceData &, ForceData &) {}
  void endPass(SurfacesIntersectData &, ForceData &, ForceData &) {}

private:
  void release(SurfacesCloseData &scdata)
  {
    if (scdata.contact_flags) *scdata.contact_flags &= ~CONTACT_NORMAL_MODEL;
    scdata.contact_history[contact_offset] = 0.0;
  }

  /* On forming a contact: can LIGGGHTS follow it down to delta_break? */
  void checkReach(const SurfacesIntersectData &sidata, double delta_break)
  {
    const double reach = sidata.is_wall ? sidata.radi : sidata.radsum;
    const double need = 1.0 - delta_break / reach;
    if (neighbor->contactDistanceFactor < need) {
      char msg[256];
      snprintf(msg, sizeof msg, "Normal model jkr_elliptic: adhesive contacts are kept until separation: "
               "set neigh_modify contact_distance_factor >= %.6g", need);
      error->one(FLERR, msg);
    }
  }

  void fail(const char *what, double delta, double R1, double R2, double w, int st)
  {
    char msg[256];
    snprintf(msg, sizeof msg, "Normal model jkr_elliptic: %s at overlap %g, radii %g, %g, work of adhesion %g: %s",
             what, delta, R1, R2, w, dc_status_str(st));
    error->one(FLERR, msg);
  }

  /* Applies the force at overlap delta; false (nothing applied) when the
     contact has separated (delta < delta_break). */
  bool jkrForce(SurfacesIntersectData &sidata, double delta, double vn, bool forming,
                ForceData &i_forces, ForceData &j_forces)
  {
    const int itype = sidata.itype, jtype = sidata.jtype;
    const double Y = Yeff[itype][jtype], G = Geff[itype][jtype], w = work[itype][jtype];
    double R_major = sphereEffectiveRadius(sidata), R_minor = R_major;
#ifdef SUPERQUADRIC_ACTIVE_FLAG
    const bool sq = sidata.is_non_spherical && atom->superquadric_flag;
    if (sq) curvature.relativeRadii(lmp, sidata, R_major, R_minor, "jkr_elliptic");
#else
    const bool sq = false;
#endif
    double P, Sn, kn, kt;
    if (w == 0.0) {
      double r_force = R_major, r_area = R_major;
      if (sq) {
        dc_hertz_geom g;
        const int st = dc_hertz_geometry(R_major, R_minor, &g);
        if (st != DC_OK) fail("contact geometry", delta, R_major, R_minor, w, st);
        r_force = g.R_force;
        r_area = g.R_area;
      }
      hertzStiffness(Y, G, r_force, r_area, delta, kn, Sn, kt);
      P = kn * delta;
    } else {
      dc_jkr_state s;
      int st;
      if (!sq) {
        /* separation (contact = 0) is decided inside, with the same delta_break */
        st = dc_jkr_sphere(R_major, Y, w, delta, &s);
        if (forming) checkReach(sidata, dc_jkr_sphere_delta_break(R_major, Y, w));
      } else {
        dc_jkr_geom g;
        st = dc_jkr_geometry(R_major, R_minor, Y, w, &g);
        if (st != DC_OK) fail("contact geometry", delta, R_major, R_minor, w, st);
        if (forming) checkReach(sidata, g.delta_break);
        dc_jkr_hint *hint = reinterpret_cast<dc_jkr_hint *>(&sidata.contact_history[hint_offset]);
        st = dc_jkr_contact(&g, delta, hint, &s);
      }
      if (st != DC_OK) fail("contact state", delta, R_major, R_minor, w, st);
      if (!s.contact) return false;
      P = s.F;
      /* flat-punch stiffness of the contact ellipse (circle: 2 E* a) */
      if (sq) {
        st = dc_dissip_adhesive_state(1.0, Y, &s, 1.0, &Sn);
        if (st != DC_OK) fail("punch stiffness", delta, R_major, R_minor, w, st);
        kt = 8.0 * G * sqrt(s.a * s.b);
      } else {
        Sn = 2.0 * Y * s.a;
        kt = 8.0 * G * s.a;
      }
      kn = Sn;
    }
    if (viscoelastic) {
      /* F_dis = A (d delta/dt) k_punch (dc/dissipation_adhesive.h) */
      viscoelasticNormalForce(sidata, P, vn, Sn, kn, kt, viscoelasticTime[itype][jtype], tangential_damping,
                              false, force->nktv2p, atom->x, i_forces, j_forces);
    } else {
      dampedNormalForce(sidata, P, vn, Sn, kn, kt, betaeff[itype][jtype], tangential_damping,
                        false, force->nktv2p, atom->x, i_forces, j_forces);
    }
    return true;
  }

  static MatrixProperty *createWork(PropertyRegistry &registry, const char *caller, bool sanity_checks)
  {
    return MODEL_PARAMS::createPerTypePairProperty(registry, "workOfAdhesion", caller, sanity_checks, 0.0);
  }

  double **Yeff, **Geff, **betaeff, **work, **viscoelasticTime;
  bool tangential_damping, viscoelastic;
  double maxRadiusFactor;
  int contact_offset, hint_offset;
#ifdef SUPERQUADRIC_ACTIVE_FLAG
  SuperquadricCurvature curvature;
  SuperquadricGap gap;
#endif
};

}
}
#endif
#endif
