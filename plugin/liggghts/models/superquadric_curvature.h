/* Relative principal radii of a superquadric contact, for the elliptic
   normal models. Reads the contact point that LIGGGHTS' `surface
   superquadric` model (or the superquadric wall code) found, takes it and
   the tangent basis into each body's frame and hands them with the body's
   shape and blockiness to c_core (dc_superquadric_form, dc/curvature.h: the
   curvature form of LIGGGHTS' shape function). Plane walls contribute zero
   curvature. No physics here: only data plumbing. */
#ifndef DC_PLUGIN_SUPERQUADRIC_CURVATURE_H
#define DC_PLUGIN_SUPERQUADRIC_CURVATURE_H

#ifdef SUPERQUADRIC_ACTIVE_FLAG

#include <cmath>
#include <cstring>
#include "atom.h"
#include "update.h"
#include "contact_interface.h"
#include "contact_models.h"
#include "error.h"
#include "math_extra.h"
#include "math_extra_liggghts_nonspherical.h"
#include "dc/curvature.h"

namespace LIGGGHTS {
namespace ContactModels {

class SuperquadricCurvature {
public:
  SuperquadricCurvature() : alpha_i_offset_(-1), alpha_j_offset_(-1), max_radius_factor_(0.0), kind_("Normal model"),
    cache_offset_(-1), payload_(0), tol_(0.0), motion_(0.0), fresh_(-1), capped_(false) {}

  /* Call from postSettings. `model` names the model in messages, `kind`
     its kind. Checks the maxRadiusFactor setting's range on every run. */
  void setup(LAMMPS_NS::LAMMPS *lmp, ContactModelBase *cmb, double max_radius_factor, const char *model,
             const char *kind = "Normal model")
  {
    kind_ = kind;
    if (!(max_radius_factor > 1.0 && max_radius_factor <= 1e12)) {
      char msg[128];
      snprintf(msg, sizeof msg, "%s %s: maxRadiusFactor must be in (1, 1e12]", kind, model);
      lmp->error->all(FLERR, msg);
    }
    if (!lmp->atom->superquadric_flag) return;
    alpha_i_offset_ = cmb->get_history_offset("alpha1_offset");
    alpha_j_offset_ = cmb->get_history_offset("alpha2_offset");
    if (alpha_i_offset_ < 0 || alpha_j_offset_ < 0) {
      char msg[256];
      snprintf(msg, sizeof msg, "%s %s with atom_style superquadric needs 'surface superquadric' in the same pair_style gran / fix wall/gran line", kind, model);
      lmp->error->all(FLERR, msg);
    }
    max_radius_factor_ = max_radius_factor;
  }

  /* Reuse of a contact's curvature across steps (setting
     curvatureTolerance t > 0): the relative radii and what a model derives
     from them alone (payload doubles, a dc_hertz_geom) are kept in the
     contact history with the state they were computed at: each body's
     contact point in its own frame and the bodies' relative orientation.
     The motion since then, m = max(|dp_i| / a_i, |dp_j| / a_j, turn [rad])
     (a: a body's smallest semi-axis; plane and mesh walls: the particle's
     point only), is checked every step against an allowance; past it the
     payload is recomputed. The allowance is the smaller of t R_minor / a
     (a point moves by at most t R_minor) and, from the relative change c
     found at the last recomputation after a motion m, m t / (2 c) (the
     change at the rate just seen stays near t / 2); at most twice the last
     allowance and 0.02, and 1/50 of the first bound while maxRadiusFactor
     caps R_major (a flat face, whose small curvature changes fastest).
     Call from postSettings, after setup. */
  void setupCache(IContactHistorySetup *hsetup, double tolerance, int payload)
  {
    tol_ = tolerance;
    if (!(tolerance > 0.0) || alpha_i_offset_ < 0) return;
    payload_ = payload;
    for (int k = 0; k < CACHE_HEAD + 3 + payload; k++) {
      const int off = hsetup->add_history_value("curvature_cache", "0");
      if (k == 0) cache_offset_ = off;
    }
  }
  bool caching() const { return cache_offset_ >= 0; }

  /* 1: the kept payload of this contact holds (*kept; with axis: the major
     axis, carried along with body i); 0: it no longer holds (*kept: the old
     payload, to measure the change against); -1: none kept. Unless 1, the
     caller computes the payload and hands it to keep(). */
  int reuse(LAMMPS_NS::LAMMPS *lmp, const SurfacesIntersectData &sidata, double *axis, const double **kept)
  {
    LAMMPS_NS::Atom *atom = lmp->atom;
    const double *h = &sidata.contact_history[cache_offset_];
    double pi[3], pj[3];
    contactPoints(sidata, pi, pj);
    const int i = sidata.i;
    double *s = probe_;   /* [0] tag of i, [1..3] point of i, [4..6] of j, [7..10] relative orientation */
    s[0] = (double)atom->tag[i];
    toBody(atom, i, pi, s + 1);
    if (sidata.is_wall) {
      s[4] = s[5] = s[6] = s[7] = s[8] = s[9] = s[10] = 0.0;
    } else {
      toBody(atom, sidata.j, pj, s + 4);
      double qc[4];
      MathExtra::qconjugate(atom->quaternion[i], qc);
      MathExtra::quatquat(qc, atom->quaternion[sidata.j], s + 7);
    }
    *kept = h + CACHE_HEAD + 3;
    if (h[0] != s[0]) return fresh_ = -1;
    /* m^2, the turn from its quaternion: theta^2 ~ 8 (1 - |cos theta/2|) */
    const double ai = minAxis(atom, i);
    double m2 = dist2(h + 1, s + 1) / (ai * ai);
    if (!sidata.is_wall) {
      const double aj = minAxis(atom, sidata.j);
      const double mj = dist2(h + 4, s + 4) / (aj * aj);
      const double dot = h[7] * s[7] + h[8] * s[8] + h[9] * s[9] + h[10] * s[10];
      const double mt = 8.0 * (1.0 - fabs(dot));
      if (mj > m2) m2 = mj;
      if (mt > m2) m2 = mt;
    }
    if (m2 > h[ALLOW] * h[ALLOW]) {
      motion_ = sqrt(m2);
      return fresh_ = 0;
    }
    if (axis) {
      double w[3];
      MathExtraLiggghtsNonspherical::rotate_local2global(atom->quaternion[i], h + CACHE_HEAD, w);
      const double *n = sidata.en;
      const double wn = w[0] * n[0] + w[1] * n[1] + w[2] * n[2];
      for (int k = 0; k < 3; k++) w[k] -= wn * n[k];
      const double len = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
      for (int k = 0; k < 3; k++) axis[k] = len > 0.0 ? w[k] / len : 0.0;
    }
    return fresh_ = 1;
  }

  /* Stores the payload computed at this step's state (after reuse returned
     0 or -1), with change, its largest relative change against the old
     payload (reuse 0); axis (the world major axis, or NULL) is kept in body
     i's frame. */
  void keep(LAMMPS_NS::LAMMPS *lmp, const SurfacesIntersectData &sidata, const double *payload, const double *axis,
            double change)
  {
    if (fresh_ == 1) return;
    double *h = &sidata.contact_history[cache_offset_];
    /* each body's point moves by at most t R_minor (R_minor first in the
       payload, after R_major: a dc_hertz_geom) */
    const double a = sidata.is_wall ? minAxis(lmp->atom, sidata.i)
                                    : fmax(minAxis(lmp->atom, sidata.i), minAxis(lmp->atom, sidata.j));
    double allow = tol_ * payload[1] / a;
    if (capped_) {
      allow *= 0.02;
    } else if (fresh_ == 0) {
      const double adapt = change > 0.0 ? 0.5 * tol_ * motion_ / change : HUGE_VAL;
      allow = fmin(allow, fmin(2.0 * h[ALLOW], adapt));
    }
    if (allow > 0.02) allow = 0.02;
    memcpy(h, probe_, sizeof probe_);
    h[ALLOW] = allow;
    if (axis) MathExtraLiggghtsNonspherical::rotate_global2local(lmp->atom->quaternion[sidata.i], axis, h + CACHE_HEAD);
    memcpy(h + CACHE_HEAD + 3, payload, payload_ * sizeof(double));
  }

  /* Relative principal radii R_major >= R_minor at this contact. Each
     relative principal radius is capped at maxRadiusFactor times the
     volume-equivalent effective radius (flat superquadric faces have zero
     curvature). Ends the run on a degenerate (zero or non-finite) gradient.
     With axis, also the major-axis direction of the contact ellipse. */
  void relativeRadii(LAMMPS_NS::LAMMPS *lmp, const SurfacesIntersectData &sidata,
                     double &R_major, double &R_minor, const char *model, double *axis = 0)
  {
    LAMMPS_NS::Atom *atom = lmp->atom;
    double u[3], v[3], form[3], form_j[3];
    dc_tangent_basis(sidata.en, u, v);
    double pi[3], pj[3];
    contactPoints(sidata, pi, pj);
    /* the sub-models of one contact ask in turn: the last answer is kept */
    FormMemo &m = formMemo();
    const long step = (long)lmp->update->ntimestep;
    if (m.step == step && m.i == sidata.i && m.j == (sidata.is_wall ? -1 : sidata.j) &&
        !memcmp(m.en, sidata.en, sizeof m.en) && !memcmp(m.pi, pi, sizeof m.pi) &&
        (sidata.is_wall || !memcmp(m.pj, pj, sizeof m.pj))) {
      memcpy(form, m.form, sizeof form);
    } else {
      bodyForm(atom, sidata.i, pi, u, v, form, lmp, model);
      if (!sidata.is_wall) {
        bodyForm(atom, sidata.j, pj, u, v, form_j, lmp, model);
        form[0] += form_j[0]; form[1] += form_j[1]; form[2] += form_j[2];
      }
      m.step = step;
      m.i = sidata.i;
      m.j = sidata.is_wall ? -1 : sidata.j;
      memcpy(m.en, sidata.en, sizeof m.en);
      memcpy(m.pi, pi, sizeof m.pi);
      memcpy(m.pj, pj, sizeof m.pj);
      memcpy(m.form, form, sizeof m.form);
    }
    double k1, k2;
    dc_form_principal(form, &k1, &k2, 0);
    if (axis) dc_form_major_axis(form, u, v, axis);
    const double reff = sidata.is_wall ? sidata.radi : sidata.radi * sidata.radj / (sidata.radi + sidata.radj);
    const double k_min = 1.0 / (max_radius_factor_ * reff);
    R_minor = 1.0 / (k1 > k_min ? k1 : k_min);
    R_major = 1.0 / (k2 > k_min ? k2 : k_min);
    capped_ = k2 <= k_min;
  }

  /* For the rolling kinematics (rolling_contact.h): the history offsets of
     the bodies' contact points only (the normal model checks the settings
     and names a missing `surface superquadric`). */
  void setupPoints(LAMMPS_NS::LAMMPS *lmp, ContactModelBase *cmb)
  {
    kind_ = "Rolling model";
    if (!lmp->atom->superquadric_flag) return;
    alpha_i_offset_ = cmb->get_history_offset("alpha1_offset");
    alpha_j_offset_ = cmb->get_history_offset("alpha2_offset");
  }

  /* Principal curvatures k1 >= k2 of each body's surface at its contact
     point and the unit k1 direction (in the contact plane), body i in [0],
     j in [1]; a wall is flat (zero, no direction). */
  void bodyCurvatures(LAMMPS_NS::LAMMPS *lmp, const SurfacesIntersectData &sidata, double k1[2], double k2[2],
                      double d1[2][3], const char *model)
  {
    LAMMPS_NS::Atom *atom = lmp->atom;
    double u[3], v[3], form[3], pi[3], pj[3];
    dc_tangent_basis(sidata.en, u, v);
    contactPoints(sidata, pi, pj);
    for (int b = 0; b < 2; b++) {
      if (b == 1 && sidata.is_wall) {
        k1[1] = k2[1] = 0.0;
        d1[1][0] = d1[1][1] = d1[1][2] = 0.0;
        break;
      }
      bodyForm(atom, b ? sidata.j : sidata.i, b ? pj : pi, u, v, form, lmp, model);
      double theta;
      dc_form_principal(form, &k1[b], &k2[b], &theta);
      const double c = cos(theta), s = sin(theta);
      for (int k = 0; k < 3; k++) d1[b][k] = c * u[k] + s * v[k];
    }
  }

private:
  enum { ALLOW = 11, CACHE_HEAD = 12 };   /* tag, two points, relative orientation, allowance */

  /* Each body's point of the contact (a wall: the particle's only):
     primitive walls hand over the particle's deepest point; mesh walls its
     projection on the triangle, deltan from it along -en. */
  void contactPoints(const SurfacesIntersectData &sidata, double *pi, double *pj) const
  {
    if (sidata.is_wall) {
      const double back = sidata.mesh ? sidata.deltan : 0.0;
      for (int k = 0; k < 3; k++) pi[k] = sidata.contact_point[k] - back * sidata.en[k];
      return;
    }
    const double ai = sidata.contact_history[alpha_i_offset_];
    const double aj = sidata.contact_history[alpha_j_offset_];
    for (int k = 0; k < 3; k++) {
      pi[k] = sidata.contact_point[k] - ai * sidata.en[k];
      pj[k] = sidata.contact_point[k] + aj * sidata.en[k];
    }
  }

  /* p - x_i in body i's frame: rotated by the conjugate of its unit
     quaternion q = (w, r), out = d + w t - r x t with t = 2 d x r (the
     transpose of LIGGGHTS' quat_to_mat applied to d) */
  static void toBody(LAMMPS_NS::Atom *atom, int i, const double *p, double *out)
  {
    const double *q = atom->quaternion[i], *x = atom->x[i];
    const double d[3] = {p[0] - x[0], p[1] - x[1], p[2] - x[2]};
    const double t[3] = {2.0 * (d[1] * q[3] - d[2] * q[2]), 2.0 * (d[2] * q[1] - d[0] * q[3]),
                         2.0 * (d[0] * q[2] - d[1] * q[1])};
    out[0] = d[0] + q[0] * t[0] - (q[2] * t[2] - q[3] * t[1]);
    out[1] = d[1] + q[0] * t[1] - (q[3] * t[0] - q[1] * t[2]);
    out[2] = d[2] + q[0] * t[2] - (q[1] * t[1] - q[2] * t[0]);
  }
  static double minAxis(LAMMPS_NS::Atom *atom, int i)
  {
    const double *a = atom->shape[i];
    const double m = a[0] < a[1] ? a[0] : a[1];
    return m < a[2] ? m : a[2];
  }
  static double dist2(const double *a, const double *b)
  {
    const double d0 = a[0] - b[0], d1 = a[1] - b[1], d2 = a[2] - b[2];
    return d0 * d0 + d1 * d1 + d2 * d2;
  }

  void bodyForm(LAMMPS_NS::Atom *atom, int i, const double *p, const double *u, const double *v,
                double *form, LAMMPS_NS::LAMMPS *lmp, const char *model)
  {
    /* the contact point and the basis in the body's frame */
    double R[9], d[3], pl[3], ul[3], vl[3];
    MathExtraLiggghtsNonspherical::quat_to_mat(atom->quaternion[i], R);
    for (int k = 0; k < 3; k++) d[k] = p[k] - atom->x[i][k];
    MathExtraLiggghtsNonspherical::transpose_matvec(R, d, pl);
    MathExtraLiggghtsNonspherical::transpose_matvec(R, u, ul);
    MathExtraLiggghtsNonspherical::transpose_matvec(R, v, vl);
    if (dc_superquadric_form(atom->shape[i], atom->blockiness[i], pl, ul, vl, form) != 0) {
      char msg[256];
      snprintf(msg, sizeof msg, "%s %s: degenerate curvature at the contact point of atom %d (shape-function gradient zero or not finite)", kind_, model, (int)atom->tag[i]);
      lmp->error->one(FLERR, msg);
    }
  }

  int alpha_i_offset_, alpha_j_offset_;
  double max_radius_factor_;
  /* The last contact's relative curvature form (step, atoms, normal and
     contact points: the same inputs give the same form). */
  struct FormMemo {
    long step;
    int i, j;
    double en[3], pi[3], pj[3], form[3];
  };
  static FormMemo &formMemo()
  {
    static FormMemo m = {-1, -1, -1, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    return m;
  }
  const char *kind_;   /* "Normal model", "Cohesion model" or "Rolling model", in messages */
  int cache_offset_, payload_;
  double tol_;
  double probe_[ALLOW];   /* this step's state and motion, from reuse() to keep() */
  double motion_;
  int fresh_;           /* what reuse() returned */
  bool capped_;         /* the last relativeRadii capped R_major */
};

}
}

#endif
#endif
