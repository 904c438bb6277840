/* LIGGGHTS normal model `hertz_elliptic`: exact elliptic Hertz contact
   (c_core: dc/hertz_elliptic.h, review Eqs. 1-14).

   Deck: pair_style gran model hertz_elliptic tangential history [surface superquadric] [settings]
         fix ID all wall/gran model hertz_elliptic tangential history [surface superquadric] ...
   Settings: those of every project normal model (dc_model_base.h).
   Properties: youngsModulus, poissonsRatio; coefficientRestitution (or
   viscoelasticTime [s] with viscoelastic on).

   Spheres: R_force = R_area = effective radius, the arithmetic of stock
   `hertz` (forces agree to the last bit). Superquadrics: relative principal
   radii from both surfaces' curvatures, F = 4/3 E* (R_force delta)^1/2 delta
   with R_force = Rc gamma^2 (Eq. 1); damping on dF/d delta, tangential
   stiffness 8 G* (R_area delta)^1/2 with R_area = Rc beta (Eq. 2), i.e. of
   the circle of the contact's area. */
#ifdef NORMAL_MODEL
NORMAL_MODEL(HERTZ_ELLIPTIC,hertz_elliptic,@DC_MODEL_ID@)
#else
#ifndef NORMAL_MODEL_HERTZ_ELLIPTIC_H_
#define NORMAL_MODEL_HERTZ_ELLIPTIC_H_

#include "dc_model_base.h"
#include "dc/hertz_elliptic.h"
#include "dc/mindlin.h"

namespace LIGGGHTS {
namespace ContactModels {

template<>
class NormalModel<HERTZ_ELLIPTIC> : public DcNormalModel
{
public:
  NormalModel(LAMMPS *lmp, IContactHistorySetup *hsetup, class ContactModelBase *c) :
    DcNormalModel(lmp, hsetup, c, "hertz_elliptic")
  {}

  inline void surfacesIntersect(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)
  {
    if (sidata.contact_flags) *sidata.contact_flags |= CONTACT_NORMAL_MODEL;
    if (superquadric(sidata)) return superquadricIntersect(sidata, i_forces, j_forces);
    /* spheres: stock hertz's arithmetic, R_force = R_area = R */
    const int itype = sidata.itype, jtype = sidata.jtype;
    const double deltan = sidata.deltan, R = sphereEffectiveRadius(sidata);
    checkHertzRange(sidata, R * deltan, R);   /* a^2 = R delta */
    double kn, Sn;
    const double root = dc_hertz_stiffness(Yeff[itype][jtype], R, deltan, &kn, &Sn);
    const double P = kn * deltan;
    applyForce(sidata, P, deltan, sidata.vn, Sn, kn, dc_mindlin_kt_circle(Geff[itype][jtype], root), i_forces,
               j_forces);
    if (patchStored()) publishCircle(sidata, R, deltan, P, Yeff[itype][jtype]);
  }

  void surfacesClose(SurfacesCloseData &scdata, ForceData &, ForceData &)
  {
    if (scdata.contact_flags) *scdata.contact_flags |= CONTACT_NORMAL_MODEL;
    publishNone(scdata);
  }

private:
  /* Superquadrics: the relative principal radii from both surfaces'
     curvatures (out of line: the sphere path stays small). */
  __attribute__((noinline)) void superquadricIntersect(SurfacesIntersectData &sidata, ForceData &i_forces,
                                                       ForceData &j_forces)
  {
    const int itype = sidata.itype, jtype = sidata.jtype;
    const double deltan = sidata.deltan;
    double axis[3];
    double *ax = axisWanted(axis);
    dc_hertz_geom g;
    superquadricGeometry(sidata, g, ax);
    checkHertzRange(sidata, 2.0 * g.R_major * deltan * g.D / g.K, g.R_minor);   /* a^2 = 2 R_major delta D / K */
    double kn, Sn;
    const double root = dc_hertz_stiffness(Yeff[itype][jtype], g.R_force, deltan, &kn, &Sn);
    const double kt = dc_mindlin_kt_circle(Geff[itype][jtype], g.R_area == g.R_force ? root : sqrt(g.R_area * deltan));
    const double P = kn * deltan;
    applyForce(sidata, P, deltan, sidata.vn, Sn, kn, kt, i_forces, j_forces);
    if (!ax) return;
    dc_contact c;
    dc_hertz_normal(&g, Yeff[itype][jtype], deltan, &c);
    publish(sidata, c, ax);
  }
};

}
}
#endif
#endif
