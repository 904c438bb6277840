/* Pieces shared by the plugin normal models: stock-`hertz` arithmetic for a
   given force- and area-equivalent radius, LIGGGHTS' restitution damping,
   and the application of a normal force (with its torque on non-spherical
   particles). Only translation between LIGGGHTS data and numbers here. */
#ifndef DC_PLUGIN_NORMAL_FORCE_COMMON_H
#define DC_PLUGIN_NORMAL_FORCE_COMMON_H

#include <cmath>
#include <cstdio>
#include "atom.h"
#include "contact_interface.h"
#include "error.h"
#include "global_properties.h"
#include "property_registry.h"
#include "vector_liggghts.h"
#include "dc/hertz_elliptic.h"
#include "dc/status.h"

namespace LIGGGHTS {
namespace ContactModels {

/* Effective radius of a sphere pair (wall: the sphere's radius). */
inline double sphereEffectiveRadius(const SurfacesIntersectData &sidata)
{
  return sidata.is_wall ? sidata.radi : sidata.radi * sidata.radj / (sidata.radi + sidata.radj);
}

/* dc_hertz_geometry of relative radii R1, R2; a degenerate geometry stops
   the run with a message naming the model and the radii. */
inline void hertzGeometry(LAMMPS_NS::Error *error, const char *model, double R1, double R2, dc_hertz_geom &g)
{
  const int st = dc_hertz_geometry(R1, R2, &g);
  if (st != DC_OK) {
    char msg[256];
    snprintf(msg, sizeof msg, "Normal model %s: relative radii %g, %g: %s", model, R1, R2, dc_status_str(st));
    error->one(FLERR, msg);
  }
}

/* Connects the per-type-pair E*, G* and, for restitution damping, its
   coefficient (which needs coefficientRestitution in the deck). */
inline void connectElasticProperties(PropertyRegistry &registry, const char *caller,
                                     double **&Yeff, double **&Geff, double **&betaeff,
                                     bool restitution = true)
{
  registry.registerProperty("Yeff", &MODEL_PARAMS::createYeff, caller);
  registry.registerProperty("Geff", &MODEL_PARAMS::createGeff, caller);
  registry.connect("Yeff", Yeff, caller);
  registry.connect("Geff", Geff, caller);
  if (!restitution) return;
  registry.registerProperty("betaeff", &MODEL_PARAMS::createBetaEff, caller);
  registry.connect("betaeff", betaeff, caller);
}

/* Connects the per-type-pair viscoelastic time A [s] (`viscoelastic on`). */
inline MatrixProperty *createViscoelasticTime(PropertyRegistry &registry, const char *caller, bool sanity_checks)
{
  return MODEL_PARAMS::createPerTypePairProperty(registry, "viscoelasticTime", caller, sanity_checks, 0.0);
}
inline void connectViscoelasticTime(PropertyRegistry &registry, const char *caller, double **&viscoelasticTime)
{
  registry.registerProperty("viscoelasticTime", &createViscoelasticTime, caller);
  registry.connect("viscoelasticTime", viscoelasticTime, caller);
}

/* For a sphere contact handed to surfacesClose (not touching): the overlap
   (negative) and normal velocity; fills en and meff for pairs (walls have
   set them). Both LIGGGHTS callers pass a SurfacesIntersectData. */
inline double closeSphereContact(SurfacesCloseData &scdata, double &vn)
{
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
  const double *vi = sidata.v_i, *vj = sidata.v_j;
  vn = (vi[0] - vj[0]) * sidata.en[0] + (vi[1] - vj[1]) * sidata.en[1] + (vi[2] - vj[2]) * sidata.en[2];
  return delta;
}

/* LIGGGHTS' restitution-based damping coefficient for a tangent stiffness S
   (stock hertz: gamma = -2 sqrt(5/6) beta sqrt(S m), beta = ln e / sqrt(ln^2 e + pi^2)). */
inline double restitutionDamping(double betaeff, double S, double meff)
{
  const double sqrtFiveOverSix = 0.91287092917527685576161630466800355658790782499663875;
  return -2. * sqrtFiveOverSix * betaeff * sqrt(S * meff);
}

/* Hertz with force-equivalent radius r_force and area-equivalent radius
   r_area, in stock hertz's order of operations (bitwise equal to it when
   r_force = r_area = effective radius): fills kn (secant), Sn (tangent
   normal stiffness) and kt (Mindlin tangential stiffness). */
inline void hertzStiffness(double Y, double G, double r_force, double r_area, double deltan,
                           double &kn, double &Sn, double &kt)
{
  const double sqrtval = sqrt(r_force * deltan);
  Sn = 2. * Y * sqrtval;
  kt = 8. * G * (r_area == r_force ? sqrtval : sqrt(r_area * deltan));
  kn = 4. / 3. * Y * sqrtval;
}

/* Adds Fn along en to i (and -Fn to j), with the torque of a force off the
   centre line for non-spherical particles; walls scale by area_ratio. */
inline void applyNormalForce(const SurfacesIntersectData &sidata, double Fn, double **x,
                             ForceData &i_forces, ForceData &j_forces)
{
  const double Fn_ = sidata.is_wall ? Fn * sidata.area_ratio : Fn;
  const double F[3] = {Fn_ * sidata.en[0], Fn_ * sidata.en[1], Fn_ * sidata.en[2]};
  for (int k = 0; k < 3; k++) i_forces.delta_F[k] += F[k];
  if (!sidata.is_wall)
    for (int k = 0; k < 3; k++) j_forces.delta_F[k] -= F[k];
#ifdef NONSPHERICAL_ACTIVE_FLAG
  if (sidata.is_non_spherical) {
    double xc[3], t[3];
    const double Fi[3] = {Fn * sidata.en[0], Fn * sidata.en[1], Fn * sidata.en[2]};
    LAMMPS_NS::vectorSubtract3D(sidata.contact_point, x[sidata.i], xc);
    LAMMPS_NS::vectorCross3D(xc, Fi, t);
    for (int k = 0; k < 3; k++) i_forces.delta_torque[k] += t[k];
    if (!sidata.is_wall) {
      LAMMPS_NS::vectorSubtract3D(sidata.contact_point, x[sidata.j], xc);
      LAMMPS_NS::vectorCross3D(xc, Fi, t);
      for (int k = 0; k < 3; k++) j_forces.delta_torque[k] -= t[k];
    }
  }
#endif
}

/* Elastic force P with damping coefficients gamman, gammat, clipped at 0
   with limitForce, stored in sidata with the stiffnesses kn, kt, and applied. */
inline void dampedForce(SurfacesIntersectData &sidata, double P, double vn, double gamman, double gammat,
                        double kn, double kt, bool limitForce, double nktv2p, double **x,
                        ForceData &i_forces, ForceData &j_forces)
{
  double Fn = -gamman * vn + P / nktv2p;
  if (limitForce && Fn < 0.0) Fn = 0.0;
  sidata.Fn = Fn;
  sidata.kn = kn / nktv2p;
  sidata.kt = kt / nktv2p;
  sidata.gamman = gamman;
  sidata.gammat = gammat;
  applyNormalForce(sidata, Fn, x, i_forces, j_forces);
}

/* dampedForce with LIGGGHTS' restitution damping on the tangent stiffness
   Sn (none where Sn <= 0). */
inline void dampedNormalForce(SurfacesIntersectData &sidata, double P, double vn, double Sn,
                              double kn, double kt, double betaeff, bool tangential_damping,
                              bool limitForce, double nktv2p, double **x,
                              ForceData &i_forces, ForceData &j_forces)
{
  const double gamman = restitutionDamping(betaeff, Sn > 0.0 ? Sn : 0.0, sidata.meff);
  const double gammat = tangential_damping ? restitutionDamping(betaeff, kt, sidata.meff) : 0.0;
  dampedForce(sidata, P, vn, gamman, gammat, kn, kt, limitForce, nktv2p, x, i_forces, j_forces);
}

/* dampedForce with viscoelastic damping of time A on the tangent stiffness:
   F_dis = A (d delta/dt) Sn (`viscoelastic on`; d delta/dt = -vn). */
inline void viscoelasticNormalForce(SurfacesIntersectData &sidata, double P, double vn, double Sn,
                                    double kn, double kt, double A, bool tangential_damping,
                                    bool limitForce, double nktv2p, double **x,
                                    ForceData &i_forces, ForceData &j_forces)
{
  dampedForce(sidata, P, vn, A * Sn, tangential_damping ? A * kt : 0.0, kn, kt, limitForce, nktv2p, x,
              i_forces, j_forces);
}

}
}
#endif
