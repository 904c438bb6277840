/* LIGGGHTS normal model `hertz_elliptic`: exact elliptic Hertz contact
   (c_core: dc/hertz_elliptic.h, review Eqs. 1-14).

   Deck: pair_style gran model hertz_elliptic tangential history [surface superquadric] [settings]
         fix ID all wall/gran model hertz_elliptic tangential history [surface superquadric] ...
   Settings (after the model keywords):
     tangential_damping on|off   restitution damping on the tangential spring (default on)
     limitForce on|off           clip attractive normal force from damping (default off)
     viscoelastic on|off         Brilliantov viscoelastic dissipation instead of the
                                 restitution-based damping (default off)
     maxRadiusFactor X           cap on each relative principal radius, in units of the
                                 volume-equivalent effective radius (default 100, > 1)
   Properties: youngsModulus, poissonsRatio (always); coefficientRestitution (unless
   viscoelastic on); viscoelasticTime peratomtypepair [s] (Brilliantov's A, with
   viscoelastic on).

   Spheres: R_force = R_area = effective radius, and the arithmetic is that of
   stock `hertz`, so forces agree to round-off. Superquadrics: relative
   principal radii from both surfaces' curvatures (superquadric_curvature.h),
   then F = 4/3 E* sqrt(R_force delta) delta with R_force = Rc gamma^2 (Eq. 1),
   normal damping and tangential stiffness as in stock `hertz` with R_force
   and the area-equivalent radius R_area = Rc beta (Eq. 2) respectively. */
#ifdef NORMAL_MODEL
NORMAL_MODEL(HERTZ_ELLIPTIC,hertz_elliptic,30)
#else
#ifndef NORMAL_MODEL_HERTZ_ELLIPTIC_H_
#define NORMAL_MODEL_HERTZ_ELLIPTIC_H_

#include <cmath>
#include <cstdio>
#include "contact_models.h"
#include "global_properties.h"
#include "normal_model_base.h"
#include "normal_force_common.h"
#include "superquadric_curvature.h"
#include "dc/hertz_elliptic.h"
#include "dc/status.h"

namespace LIGGGHTS {
namespace ContactModels {

template<>
class NormalModel<HERTZ_ELLIPTIC> : public NormalModelBase
{
public:
  NormalModel(LAMMPS *lmp, IContactHistorySetup *hsetup, class ContactModelBase *c) :
    NormalModelBase(lmp, hsetup, c),
    Yeff(NULL), Geff(NULL), betaeff(NULL), viscoelasticTime(NULL),
    tangential_damping(true), limitForce(false), viscoelastic(false),
    maxRadiusFactor(100.0)
  {}

  void registerSettings(Settings &settings)
  {
    settings.registerOnOff("tangential_damping", tangential_damping, true);
    settings.registerOnOff("limitForce", limitForce);
    settings.registerOnOff("viscoelastic", viscoelastic, false);
    settings.registerDoubleSetting("maxRadiusFactor", maxRadiusFactor, 100.0);
  }

  void postSettings(IContactHistorySetup *, ContactModelBase *c)
  {
#ifdef SUPERQUADRIC_ACTIVE_FLAG
    curvature.setup(lmp, c, maxRadiusFactor, "hertz_elliptic");
#else
    (void)c;
#endif
  }

  void connectToProperties(PropertyRegistry &registry)
  {
    const char *caller = "model hertz_elliptic";
    connectElasticProperties(registry, caller, Yeff, Geff, betaeff, !viscoelastic);
    if (viscoelastic) connectViscoelasticTime(registry, caller, viscoelasticTime);
  }

  inline double stressStrainExponent() { return 1.5; }

  inline void surfacesIntersect(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)
  {
    if (sidata.contact_flags) *sidata.contact_flags |= CONTACT_NORMAL_MODEL;
    const int itype = sidata.itype;
    const int jtype = sidata.jtype;
    const double deltan = sidata.deltan;

    /* R_force and R_area: the effective radius for spheres (stock hertz) */
    double r_force = sphereEffectiveRadius(sidata);
    double r_area = r_force;
#ifdef SUPERQUADRIC_ACTIVE_FLAG
    if (sidata.is_non_spherical && atom->superquadric_flag)
      ellipticRadii(sidata, r_force, r_area);
#endif

    double kn, Sn, kt;
    hertzStiffness(Yeff[itype][jtype], Geff[itype][jtype], r_force, r_area, deltan, kn, Sn, kt);
    /* viscoelastic: Brilliantov, F_dis = A d(delta)/dt dF/d(delta) (review Eq. 37) */
    if (viscoelastic)
      viscoelasticNormalForce(sidata, kn * deltan, sidata.vn, Sn, kn, kt, viscoelasticTime[itype][jtype],
                              tangential_damping, limitForce, force->nktv2p, atom->x, i_forces, j_forces);
    else
      dampedNormalForce(sidata, kn * deltan, sidata.vn, Sn, kn, kt, betaeff[itype][jtype],
                        tangential_damping, limitForce, force->nktv2p, atom->x, i_forces, j_forces);
  }

  void surfacesClose(SurfacesCloseData &scdata, ForceData &, ForceData &)
  {
    if (scdata.contact_flags) *scdata.contact_flags |= CONTACT_NORMAL_MODEL;
  }
  void beginPass(SurfacesIntersectData &, ForceData &, ForceData &) {}
  void endPass(SurfacesIntersectData &, ForceData &, ForceData &) {}

private:
#ifdef SUPERQUADRIC_ACTIVE_FLAG
  /* Force- and area-equivalent radii Rc gamma^2 and Rc beta of the contact. */
  void ellipticRadii(const SurfacesIntersectData &sidata, double &r_force, double &r_area)
  {
    double R_major, R_minor;
    curvature.relativeRadii(lmp, sidata, R_major, R_minor, "hertz_elliptic");
    dc_hertz_geom g;
    hertzGeometry(error, "hertz_elliptic", R_major, R_minor, g);
    r_force = g.R_force;
    r_area = g.R_area;
  }
#endif

  double **Yeff;
  double **Geff;
  double **betaeff;
  double **viscoelasticTime;
  bool tangential_damping;
  bool limitForce;
  bool viscoelastic;
  double maxRadiusFactor;
#ifdef SUPERQUADRIC_ACTIVE_FLAG
  SuperquadricCurvature curvature;
#endif
};

}
}
#endif
#endif
