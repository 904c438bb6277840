/* Relative principal radii of a superquadric contact, for the elliptic
   normal models. Reads the contact point that LIGGGHTS' `surface
   superquadric` model (or the superquadric wall code) found, evaluates each
   body's shape-function gradient and Hessian there with LIGGGHTS' own
   Superquadric class, and hands them to c_core (dc/curvature.h). Plane walls
   contribute zero curvature. No physics here: only data plumbing. */
#ifndef DC_PLUGIN_SUPERQUADRIC_CURVATURE_H
#define DC_PLUGIN_SUPERQUADRIC_CURVATURE_H

#ifdef SUPERQUADRIC_ACTIVE_FLAG

#include <cmath>
#include "atom.h"
#include "contact_interface.h"
#include "contact_models.h"
#include "error.h"
#include "math_extra_liggghts_nonspherical.h"
#include "superquadric.h"
#include "dc/curvature.h"

namespace LIGGGHTS {
namespace ContactModels {

class SuperquadricCurvature {
public:
  SuperquadricCurvature() : alpha_i_offset_(-1), alpha_j_offset_(-1), max_radius_factor_(0.0), kind_("Normal model") {}

  /* Call from postSettings. `model` names the normal model in messages.
     Checks the maxRadiusFactor setting's range on every run. */
  void setup(LAMMPS_NS::LAMMPS *lmp, ContactModelBase *cmb, double max_radius_factor, const char *model)
  {
    if (!(max_radius_factor > 1.0 && max_radius_factor <= 1e12)) {
      char msg[128];
      snprintf(msg, sizeof msg, "Normal model %s: maxRadiusFactor must be in (1, 1e12]", model);
      lmp->error->all(FLERR, msg);
    }
    if (!lmp->atom->superquadric_flag) return;
    alpha_i_offset_ = cmb->get_history_offset("alpha1_offset");
    alpha_j_offset_ = cmb->get_history_offset("alpha2_offset");
    if (alpha_i_offset_ < 0 || alpha_j_offset_ < 0) {
      char msg[256];
      snprintf(msg, sizeof msg, "Normal model %s with atom_style superquadric needs 'surface superquadric' in the same pair_style gran / fix wall/gran line", model);
      lmp->error->all(FLERR, msg);
    }
    max_radius_factor_ = max_radius_factor;
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
    if (sidata.is_wall) {
      /* primitive walls hand over the particle's deepest point; mesh walls
         its projection on the triangle, deltan from it along -en */
      double p[3];
      const double back = sidata.mesh ? sidata.deltan : 0.0;
      for (int k = 0; k < 3; k++) p[k] = sidata.contact_point[k] - back * sidata.en[k];
      bodyForm(atom, sidata.i, p, u, v, form, lmp, model);
    } else {
      const double ai = sidata.contact_history[alpha_i_offset_];
      const double aj = sidata.contact_history[alpha_j_offset_];
      double pi[3], pj[3];
      for (int k = 0; k < 3; k++) {
        pi[k] = sidata.contact_point[k] - ai * sidata.en[k];
        pj[k] = sidata.contact_point[k] + aj * sidata.en[k];
      }
      bodyForm(atom, sidata.i, pi, u, v, form, lmp, model);
      bodyForm(atom, sidata.j, pj, u, v, form_j, lmp, model);
      form[0] += form_j[0]; form[1] += form_j[1]; form[2] += form_j[2];
    }
    double k1, k2;
    dc_form_principal(form, &k1, &k2, 0);
    if (axis) dc_form_major_axis(form, u, v, axis);
    const double reff = sidata.is_wall ? sidata.radi : sidata.radi * sidata.radj / (sidata.radi + sidata.radj);
    const double k_min = 1.0 / (max_radius_factor_ * reff);
    R_minor = 1.0 / (k1 > k_min ? k1 : k_min);
    R_major = 1.0 / (k2 > k_min ? k2 : k_min);
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
    if (sidata.is_wall) {
      const double back = sidata.mesh ? sidata.deltan : 0.0;
      for (int k = 0; k < 3; k++) pi[k] = sidata.contact_point[k] - back * sidata.en[k];
    } else {
      const double ai = sidata.contact_history[alpha_i_offset_];
      const double aj = sidata.contact_history[alpha_j_offset_];
      for (int k = 0; k < 3; k++) {
        pi[k] = sidata.contact_point[k] - ai * sidata.en[k];
        pj[k] = sidata.contact_point[k] + aj * sidata.en[k];
      }
    }
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
  void bodyForm(LAMMPS_NS::Atom *atom, int i, const double *p, const double *u, const double *v,
                double *form, LAMMPS_NS::LAMMPS *lmp, const char *model)
  {
    /* the fields shape_function_props_local reads, without Superquadric::set's
       pow() for koef: koef scales f, grad f and the Hessian alike, so the
       curvature form Hessian/|grad f| does not depend on it */
    Superquadric sq;
    sq.center = atom->x[i];
    sq.quat = atom->quaternion[i];
    sq.shape = atom->shape[i];
    sq.blockiness = atom->blockiness[i];
    MathExtraLiggghtsNonspherical::quat_to_mat(sq.quat, sq.rotation_matrix);
    for (int k = 0; k < 3; k++) sq.shape_inv[k] = 1.0 / sq.shape[k];
    sq.useIntBlockiness = MathExtraLiggghtsNonspherical::isInteger(sq.blockiness[0]) &&
                          MathExtraLiggghtsNonspherical::isInteger(sq.blockiness[1]);
    double pl[3], ul[3], vl[3], f, g[3], H[9];
    sq.global2local(p, pl);
    MathExtraLiggghtsNonspherical::transpose_matvec(sq.rotation_matrix, u, ul);
    MathExtraLiggghtsNonspherical::transpose_matvec(sq.rotation_matrix, v, vl);
    sq.shape_function_props_local(pl, &f, g, H);
    if (dc_curvature_form(g, H, ul, vl, form) != 0) {
      char msg[256];
      snprintf(msg, sizeof msg, "%s %s: degenerate curvature at the contact point of atom %d (shape-function gradient zero or not finite)", kind_, model, (int)atom->tag[i]);
      lmp->error->one(FLERR, msg);
    }
  }

  int alpha_i_offset_, alpha_j_offset_;
  double max_radius_factor_;
  const char *kind_;   /* "Normal model" or "Rolling model", in messages */
};

}
}

#endif
#endif
