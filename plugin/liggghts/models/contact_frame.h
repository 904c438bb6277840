/* Pair / wall / superquadric contact geometry in one place: the effective
   radius, the overlap and normal velocity of a pair that does not touch,
   and the application of a normal and a tangential force (with their
   torques). Data plumbing only. */
#ifndef DC_PLUGIN_CONTACT_FRAME_H
#define DC_PLUGIN_CONTACT_FRAME_H

#include <cmath>
#include "atom.h"
#include "contact_interface.h"
#include "vector_liggghts.h"

namespace LIGGGHTS {
namespace ContactModels {

/* Effective radius of a sphere pair (wall: the sphere's radius). */
inline double sphereEffectiveRadius(const SurfacesCloseData &d)
{
  return d.is_wall ? d.radi : d.radi * d.radj / (d.radi + d.radj);
}

/* The radius the neighbour list's reach scales: the radius sum (wall: the
   particle's radius); a pair stays listed while its centre distance is
   below contact_distance_factor times it. */
inline double reachRadius(const SurfacesCloseData &d)
{
  return d.is_wall ? d.radi : d.radsum;
}

/* True when a force acting up to `range` [m] apart (surface to surface)
   reaches beyond the neighbour list: the factor needed is 1 + range /
   reachRadius. */
inline bool outOfReach(const SurfacesCloseData &d, double contact_distance_factor, double range)
{
  const double r0 = reachRadius(d);
  return contact_distance_factor * r0 < r0 + range;
}

/* The radius LIGGGHTS' stock models use: the sphere's effective radius, or
   for superquadrics the volume-equivalent one (sidata.reff). */
inline double stockEffectiveRadius(const SurfacesIntersectData &sidata, bool superquadric_atoms)
{
#ifdef SUPERQUADRIC_ACTIVE_FLAG
  if (sidata.is_non_spherical && superquadric_atoms) return sidata.reff;
#else
  (void)superquadric_atoms;
#endif
  return sphereEffectiveRadius(sidata);
}

/* For a sphere contact handed to surfacesClose (not touching): the overlap
   (negative), left in deltan too; fills en for pairs (walls have set both).
   Both LIGGGHTS callers pass a SurfacesIntersectData. */
inline double closeSphereOverlap(SurfacesCloseData &scdata)
{
  SurfacesIntersectData &sidata = static_cast<SurfacesIntersectData &>(scdata);
  if (sidata.is_wall) return sidata.deltan;
  const double r = sqrt(sidata.rsq);
  for (int k = 0; k < 3; k++) sidata.en[k] = sidata.delta[k] / r;
  sidata.deltan = sidata.radsum - r;
  return sidata.deltan;
}

/* closeSphereOverlap for a sub-model after the normal model: a sub-model
   that acted on this pair in this surfacesClose call (has_force_update,
   which LIGGGHTS clears before the call) has called closeSphereOverlap, so
   deltan and en hold; otherwise they are computed here. */
inline double closeSphereOverlapAgain(SurfacesCloseData &scdata)
{
  SurfacesIntersectData &sidata = static_cast<SurfacesIntersectData &>(scdata);
  return sidata.has_force_update ? sidata.deltan : closeSphereOverlap(scdata);
}

/* The same, with the normal velocity; fills meff too for pairs. */
inline double closeSphereContact(SurfacesCloseData &scdata, double &vn)
{
  SurfacesIntersectData &sidata = static_cast<SurfacesIntersectData &>(scdata);
  const double delta = closeSphereOverlap(scdata);
  if (!sidata.is_wall) sidata.meff = sidata.mi * sidata.mj / (sidata.mi + sidata.mj);
  const double *vi = sidata.v_i, *vj = sidata.v_j;
  vn = (vi[0] - vj[0]) * sidata.en[0] + (vi[1] - vj[1]) * sidata.en[1] + (vi[2] - vj[2]) * sidata.en[2];
  return delta;
}

/* For a sphere contact handed to surfacesClose after closeSphereContact
   (en set, overlap delta < 0): the relative tangential velocity at the
   contact point, as LIGGGHTS' default surface model computes it for
   touching pairs (lever arms r_i - delta/2). */
inline void closeTangentialVelocity(const SurfacesCloseData &d, const double *en, double delta, double vtr[3])
{
  double vr[3], w[3];
  for (int k = 0; k < 3; k++) vr[k] = d.v_i[k] - (d.is_wall ? 0.0 : d.v_j[k]);
  const double vn = vr[0] * en[0] + vr[1] * en[1] + vr[2] * en[2];
  const double cri = d.radi - 0.5 * delta;
  for (int k = 0; k < 3; k++) w[k] = cri * d.omega_i[k] + (d.is_wall ? 0.0 : (d.radj - 0.5 * delta) * d.omega_j[k]);
  /* v_t - (w x en), w = cr_i omega_i + cr_j omega_j */
  vtr[0] = vr[0] - vn * en[0] - (w[1] * en[2] - w[2] * en[1]);
  vtr[1] = vr[1] - vn * en[1] - (w[2] * en[0] - w[0] * en[2]);
  vtr[2] = vr[2] - vn * en[2] - (w[0] * en[1] - w[1] * en[0]);
}

/* The same for a non-spherical contact handed to surfacesClose (the normal
   model's gap code has set en and contact_point): the relative velocity of
   the material points at the contact point, less its normal part. */
inline void closeContactPointVelocity(const SurfacesCloseData &d, const double *en, const double *cp, double **x,
                                      double vtr[3])
{
  double v[3];
  const double ri[3] = {cp[0] - x[d.i][0], cp[1] - x[d.i][1], cp[2] - x[d.i][2]};
  const double *wi = d.omega_i;
  for (int k = 0; k < 3; k++) v[k] = d.v_i[k];
  v[0] += wi[1] * ri[2] - wi[2] * ri[1];
  v[1] += wi[2] * ri[0] - wi[0] * ri[2];
  v[2] += wi[0] * ri[1] - wi[1] * ri[0];
  for (int k = 0; k < 3; k++) v[k] -= d.v_j[k];
  if (!d.is_wall) {
    const double rj[3] = {cp[0] - x[d.j][0], cp[1] - x[d.j][1], cp[2] - x[d.j][2]};
    const double *wj = d.omega_j;
    v[0] -= wj[1] * rj[2] - wj[2] * rj[1];
    v[1] -= wj[2] * rj[0] - wj[0] * rj[2];
    v[2] -= wj[0] * rj[1] - wj[1] * rj[0];
  }
  const double vn = v[0] * en[0] + v[1] * en[1] + v[2] * en[2];
  for (int k = 0; k < 3; k++) vtr[k] = v[k] - vn * en[k];
}

#ifdef NONSPHERICAL_ACTIVE_FLAG
/* The torques of applyNormalForce for non-spherical particles (a force off
   the centre line). */
inline void applyNormalTorque(const SurfacesIntersectData &sidata, double Fn, double **x, ForceData &i_forces,
                              ForceData &j_forces)
{
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

/* Adds Fn along en to i (and -Fn to j), with the torque of a force off the
   centre line for non-spherical particles; walls scale by area_ratio.
   Inline: it runs once per contact and sub-model that acts. */
__attribute__((always_inline)) inline void applyNormalForce(const SurfacesIntersectData &sidata, double Fn,
                                                            double **x, ForceData &i_forces, ForceData &j_forces)
{
  const double Fn_ = sidata.is_wall ? Fn * sidata.area_ratio : Fn;
  const double F[3] = {Fn_ * sidata.en[0], Fn_ * sidata.en[1], Fn_ * sidata.en[2]};
  for (int k = 0; k < 3; k++) i_forces.delta_F[k] += F[k];
  if (!sidata.is_wall)
    for (int k = 0; k < 3; k++) j_forces.delta_F[k] -= F[k];
#ifdef NONSPHERICAL_ACTIVE_FLAG
  if (sidata.is_non_spherical) applyNormalTorque(sidata, Fn, x, i_forces, j_forces);
#else
  (void)x;
#endif
}

/* Adds the tangential force F to i (-F to j) at the contact point, with its
   torques (spheres: lever arms cri, crj along -en and +en; non-spherical
   particles: from the contact point); walls scale by area_ratio. With
   ON_J, F is the force on j (-F on i, as the c_core laws give it): the
   same sums without negating F first (the same bits). Inline: it runs
   once per contact and sub-model that acts. */
template<bool ON_J>
__attribute__((always_inline)) inline void applyTangentialForceAs(const SurfacesIntersectData &sidata, const double *F,
                                                                  double cri, double crj, double **x,
                                                                  ForceData &i_forces, ForceData &j_forces)
{
  const double *n = sidata.en;
  double ti[3], tj[3];   /* torques on i and j */
#ifdef NONSPHERICAL_ACTIVE_FLAG
  if (sidata.is_non_spherical) {
    double xc[3], Fi[3], Fj[3];
    for (int c = 0; c < 3; c++) {
      Fi[c] = ON_J ? -F[c] : F[c];
      Fj[c] = -Fi[c];
    }
    LAMMPS_NS::vectorSubtract3D(sidata.contact_point, x[sidata.i], xc);
    LAMMPS_NS::vectorCross3D(xc, Fi, ti);
    if (!sidata.is_wall) {
      LAMMPS_NS::vectorSubtract3D(sidata.contact_point, x[sidata.j], xc);
      LAMMPS_NS::vectorCross3D(xc, Fj, tj);
    }
  } else
#else
  (void)x;
#endif
  {
    /* t = en x F; on i -cri t (+cri t for F on j), on j -crj t (+crj t) */
    const double t0 = n[1] * F[2] - n[2] * F[1], t1 = n[2] * F[0] - n[0] * F[2], t2 = n[0] * F[1] - n[1] * F[0];
    const double ci = ON_J ? cri : -cri, cj = ON_J ? crj : -crj;
    ti[0] = ci * t0;
    ti[1] = ci * t1;
    ti[2] = ci * t2;
    tj[0] = cj * t0;
    tj[1] = cj * t1;
    tj[2] = cj * t2;
  }
  double *fi = i_forces.delta_F, *mi = i_forces.delta_torque;
  if (sidata.is_wall) {
    const double s = sidata.area_ratio;
    if (ON_J) {
      fi[0] -= s * F[0];
      fi[1] -= s * F[1];
      fi[2] -= s * F[2];
    } else {
      fi[0] += s * F[0];
      fi[1] += s * F[1];
      fi[2] += s * F[2];
    }
    mi[0] += s * ti[0];
    mi[1] += s * ti[1];
    mi[2] += s * ti[2];
    return;
  }
  double *fj = j_forces.delta_F, *mj = j_forces.delta_torque;
  if (ON_J) {
    fi[0] -= F[0];
    fi[1] -= F[1];
    fi[2] -= F[2];
    fj[0] += F[0];
    fj[1] += F[1];
    fj[2] += F[2];
  } else {
    fi[0] += F[0];
    fi[1] += F[1];
    fi[2] += F[2];
    fj[0] -= F[0];
    fj[1] -= F[1];
    fj[2] -= F[2];
  }
  mi[0] += ti[0];
  mi[1] += ti[1];
  mi[2] += ti[2];
  mj[0] += tj[0];
  mj[1] += tj[1];
  mj[2] += tj[2];
}

/* The force F on i. */
__attribute__((always_inline)) inline void applyTangentialForce(const SurfacesIntersectData &sidata, const double *F,
                                                                double cri, double crj, double **x,
                                                                ForceData &i_forces, ForceData &j_forces)
{
  applyTangentialForceAs<false>(sidata, F, cri, crj, x, i_forces, j_forces);
}

}
}
#endif
