/* Signed overlap of two superquadrics that do not touch, for the normal
   models whose force starts before touch (gw_rough) or lasts past it
   (jkr_elliptic). LIGGGHTS' `surface superquadric` model measures only
   touching pairs; here its own pieces measure the gap the same way:
   the contact point (where both shape functions take the same value with
   opposite gradients, calc_contact_point) and the surface points on the
   line through it along the normal en = (grad f_j - grad f_i)/|...|
   (extended_overlap_algorithm). The overlap (p_j - p_i).en is then one
   function through touch: LIGGGHTS' deltan when touching, minus the gap
   when apart. Walls: LIGGGHTS' superquadric wall code hands surfacesClose
   the support-point gap as sidata.deltan > 0 (the sign opposite to that of
   spheres); closeOverlap turns it into the overlap.
   Contact points are warm-started from the previous step; pairs whose
   bounding boxes, grown by the range, are apart cost one box test. Only
   data plumbing here: the physics is in c_core. */
#ifndef DC_PLUGIN_SUPERQUADRIC_GAP_H
#define DC_PLUGIN_SUPERQUADRIC_GAP_H

#ifdef SUPERQUADRIC_ACTIVE_FLAG

#include <cstdio>
#include "atom.h"
#include "contact_interface.h"
#include "contact_models.h"
#include "error.h"
#include "math_extra_liggghts_superquadric.h"
#include "superquadric.h"
#include "update.h"
#include "vector_liggghts.h"

namespace LIGGGHTS {
namespace ContactModels {

class SuperquadricGap {
public:
  SuperquadricGap() : cp_offset_(-1), seen_offset_(-1), alpha_i_offset_(-1), alpha_j_offset_(-1), warm_offset_(-1) {}

  /* Call from the normal model's constructor (adds one history value). */
  void addHistory(LAMMPS_NS::LAMMPS *lmp, IContactHistorySetup *hsetup)
  {
    if (lmp->atom->superquadric_flag) warm_offset_ = hsetup->add_history_value("sq_gap_warm", "0");
  }

  /* Call from postSettings, after SuperquadricCurvature::setup. */
  void setup(LAMMPS_NS::LAMMPS *lmp, ContactModelBase *cmb)
  {
    if (!lmp->atom->superquadric_flag) return;
    cp_offset_ = cmb->get_history_offset("contact_point_offset");
    alpha_i_offset_ = cmb->get_history_offset("alpha1_offset");
    alpha_j_offset_ = cmb->get_history_offset("alpha2_offset");
    /* the surface model registers "particles_were_in_contact" just before "cpx" */
    seen_offset_ = cp_offset_ - 1;
  }

  /* For a superquadric contact handed to surfacesClose, wall or pair: the
     overlap delta (< 0 apart) and normal velocity vn; false when a pair's
     surfaces are farther apart than `range` (walls: always true). */
  bool closeOverlap(LAMMPS_NS::LAMMPS *lmp, SurfacesIntersectData &sidata, double range,
                    double &delta, double &vn)
  {
    if (!sidata.is_wall) return pairOverlap(lmp, sidata, range, delta, vn);
    delta = -sidata.deltan;   /* the wall code passes the gap as deltan > 0 */
    vn = contactNormalVelocity(lmp->atom, sidata);
    return true;
  }

private:
  /* For a pair handed to surfacesClose: if the surfaces are within `range`
     of touching, fills sidata.en, contact_point, meff, the overlap delta
     (< 0 apart) and the normal velocity vn at the contact point, and
     returns true. Otherwise false (nothing filled). */
  bool pairOverlap(LAMMPS_NS::LAMMPS *lmp, SurfacesIntersectData &sidata, double range,
                   double &delta, double &vn)
  {
    LAMMPS_NS::Atom *atom = lmp->atom;
    double *hist = sidata.contact_history;
    const int i = sidata.i, j = sidata.j;
    /* the sub-models of one pair ask in turn (gw_rough, then gw_adhesion
       with a longer range): the last pair's answer is kept */
    GapMemo &m = gapMemo();
    const long step = (long)lmp->update->ntimestep;
    const bool same = m.step == step && m.hist == hist && m.i == i && m.j == j;
    if (same && m.measured) {
      hist[warm_offset_] = 1.0;
      if (!(m.delta > -range)) return false;
      delta = m.delta;
      sidata.is_non_spherical = true;
      LAMMPS_NS::vectorCopy3D(m.en, sidata.en);
      LAMMPS_NS::vectorCopy3D(m.cp, sidata.contact_point);
      sidata.meff = sidata.mi * sidata.mj / (sidata.mi + sidata.mj);
      vn = contactNormalVelocity(atom, sidata);
      return true;
    }
    if (same && range <= m.box_range) return false;   /* the boxes, grown by more, were apart */
    m.step = step;
    m.hist = hist;
    m.i = i;
    m.j = j;
    m.measured = false;
    m.box_range = -1.0;
    Superquadric pi(atom->x[i], atom->quaternion[i], atom->shape[i], atom->blockiness[i]);
    Superquadric pj(atom->x[j], atom->quaternion[j], atom->shape[j], atom->blockiness[j]);
    double *cp = &hist[cp_offset_];
    double fi, fj;
    /* the surface model ran this step (bounding spheres overlap) and left a
       fresh contact point; otherwise its state is from an earlier step */
    const bool ran = sidata.rsq < sidata.radsum * sidata.radsum;
    if (!(ran && hist[seen_offset_] == SURFACES_CLOSE)) {
      /* bounding boxes grown by range */
      double si[3], sj[3];
      for (int k = 0; k < 3; k++) {
        si[k] = atom->shape[i][k] + range;
        sj[k] = atom->shape[j][k] + range;
      }
      Superquadric gi(atom->x[i], atom->quaternion[i], si, atom->blockiness[i]);
      Superquadric gj(atom->x[j], atom->quaternion[j], sj, atom->blockiness[j]);
      if (!MathExtraLiggghtsNonspherical::obb_intersect(&gi, &gj)) {
        hist[warm_offset_] = 0.0;
        m.box_range = range;
        return false;
      }
      double found[3];
      if (hist[warm_offset_] != 0.0 || (!ran && hist[seen_offset_] != SURFACES_FAR)) {
        const double ri = cbrt(pi.shape[0] * pi.shape[1] * pi.shape[2]);
        const double rj = cbrt(pj.shape[0] * pj.shape[1] * pj.shape[2]);
        MathExtraLiggghtsNonspherical::calc_contact_point_using_prev_step(sidata, &pi, &pj, ri / (ri + rj),
            lmp->update->dt, cp, found, fi, fj, lmp->error);
      } else {
        MathExtraLiggghtsNonspherical::calc_contact_point_if_no_previous_point_avaialable(sidata, &pi, &pj,
            found, fi, fj, lmp->error);
      }
      LAMMPS_NS::vectorCopy3D(found, cp);
      /* the surface model warm-starts from this point when the boxes meet */
      hist[seen_offset_] = SURFACES_CLOSE;
    }
    hist[warm_offset_] = 1.0;

    double gi[3], gj[3], en[3], p_i[3], p_j[3], d[3];
    pi.shape_function_gradient_global(cp, gi);
    pj.shape_function_gradient_global(cp, gj);
    LAMMPS_NS::vectorSubtract3D(gj, gi, en);
    const double len = LAMMPS_NS::vectorMag3D(en);
    if (!(len > 0.0) || !std::isfinite(len)) {
      char msg[200];
      snprintf(msg, sizeof msg, "superquadric gap: no normal between atoms %d and %d (contact point solver failed)",
               (int)atom->tag[i], (int)atom->tag[j]);
      lmp->error->one(FLERR, msg);
    }
    LAMMPS_NS::vectorScalarMult3D(en, 1.0 / len);
    MathExtraLiggghtsNonspherical::extended_overlap_algorithm(&pi, &pj, en, &hist[alpha_i_offset_],
        &hist[alpha_j_offset_], cp, p_i, p_j, d);
    delta = LAMMPS_NS::vectorDot3D(d, en);
    m.measured = true;
    m.delta = delta;
    LAMMPS_NS::vectorCopy3D(en, m.en);
    LAMMPS_NS::vectorCopy3D(cp, m.cp);
    if (!(delta > -range)) return false;

    /* LIGGGHTS sets this flag only for pairs whose bounding spheres overlap */
    sidata.is_non_spherical = true;
    LAMMPS_NS::vectorCopy3D(en, sidata.en);
    LAMMPS_NS::vectorCopy3D(cp, sidata.contact_point);
    sidata.meff = sidata.mi * sidata.mj / (sidata.mi + sidata.mj);
    vn = contactNormalVelocity(atom, sidata);
    return true;
  }

  /* Relative normal velocity (v_i - v_j).en of the material points at the
     contact point, rotation included (walls: the wall is v_j, not rotating). */
  static double contactNormalVelocity(LAMMPS_NS::Atom *atom, const SurfacesIntersectData &sidata)
  {
    double r[3], w[3], v[3];
    LAMMPS_NS::vectorSubtract3D(sidata.contact_point, atom->x[sidata.i], r);
    LAMMPS_NS::vectorCross3D(sidata.omega_i, r, w);
    LAMMPS_NS::vectorAdd3D(sidata.v_i, w, v);
    LAMMPS_NS::vectorSubtract3D(v, sidata.v_j, v);
    if (!sidata.is_wall) {
      LAMMPS_NS::vectorSubtract3D(sidata.contact_point, atom->x[sidata.j], r);
      LAMMPS_NS::vectorCross3D(sidata.omega_j, r, w);
      LAMMPS_NS::vectorSubtract3D(v, w, v);
    }
    return LAMMPS_NS::vectorDot3D(v, sidata.en);
  }

  enum { SURFACES_FAR, SURFACES_CLOSE }; /* surface_model_superquadric.h's states */

  /* The last pair's gap: measured (delta, normal, contact point), or its
     bounding boxes apart when grown by box_range. */
  struct GapMemo {
    long step;
    const double *hist;
    int i, j;
    bool measured;
    double box_range, delta, en[3], cp[3];
  };
  static GapMemo &gapMemo()
  {
    static GapMemo m = {-1, NULL, -1, -1, false, -1.0, 0.0, {0, 0, 0}, {0, 0, 0}};
    return m;
  }
  int cp_offset_, seen_offset_, alpha_i_offset_, alpha_j_offset_, warm_offset_;
};

}
}

#endif
#endif
