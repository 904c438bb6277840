/* Rolling contact plumbing shared by the rolling model `kalker`
   (rolling_model_kalker.h) and the tangential models that hand the
   tangential force over to it (cmd_tangential, classical): the rolling
   kinematics of a contact from LIGGGHTS data, handed to c_core
   (dc/rolling_kalker.h: dc_rolling_kinematics_capped, dc_rolling_acts).

   Who owns the tangential force. While a contact rolls (rolling speed V
   above the setting rollingVelocityMin, patch formed), the rolling model
   applies Kalker's creep force and spin moment and the tangential model
   applies nothing and releases its history (spring, load memory): when
   the contact stops rolling, the tangential model starts afresh. At
   V <= rollingVelocityMin the tangential model acts and the rolling model
   adds nothing (c_core's rule at zero rolling speed: creepage = slip / V
   is never formed there).

   Order. LIGGGHTS calls a contact's tangential model before its rolling
   model, so the decision is made in the tangential model's call: the
   rolling model announces itself in its constructor (history-offset name
   "dc_rolling_model"); a tangential model holding a RollingHandover then
   keeps, per contact and step, the kinematics and the decision in memory
   (contact_slot.h, name "dc_rolling_kin"), which the rolling model reads
   in the same evaluation. A tangential model without a RollingHandover
   (stock history, no_history, off) offers the rolling model no
   "dc_rolling_kin": it stops the run at set-up.

   Kinematics. Body i is the particle, j the other particle or the wall;
   n = en (from j to i). Spheres: curvature 1/r of each sphere (a wall:
   flat), material velocities at the contact point with LIGGGHTS' lever
   arms cri, crj (those its tangential models use). Superquadrics: each
   surface's principal curvatures and directions at its contact point
   (shape-function gradient and Hessian, superquadric_curvature.h), the
   material velocities at sidata.contact_point, the relative radii capped
   at maxRadiusFactor times the effective radius as the normal models
   cap them. A wall moves with LIGGGHTS' wall velocity and does not turn
   (a rotating mesh's spin is not seen). Data plumbing only. */
#ifndef DC_PLUGIN_ROLLING_CONTACT_H
#define DC_PLUGIN_ROLLING_CONTACT_H

#include <cmath>
#include <cstdio>
#include <cstring>
#include "atom.h"
#include "contact_interface.h"
#include "contact_models.h"
#include "contact_slot.h"
#include "error.h"
#include "settings.h"
#include "superquadric_curvature.h"
#include "dc/rolling_kalker.h"
#include "update.h"
#include "dc/status.h"

namespace LIGGGHTS {
namespace ContactModels {

/* The settings the rolling model and the hand-over share (same names, so
   one deck value reaches both). */
static const double DC_ROLLING_VMIN_DEFAULT = 1e-3;   /* rollingVelocityMin [m/s] */
static const double DC_ROLLING_DISTANCE_DEFAULT = 2.0; /* rollingDistanceMin [-]: one patch length */

/* The hand-over record: this evaluation's kinematics and whether the
   rolling model acts. */
struct RollingRecord {
  dc_rolling_kin k;
  bool acts;
};

/* The rolling kinematics of one contact (dc_rolling_kinematics_capped). */
class RollingKinematics {
public:
  RollingKinematics() : superquadric_atoms_(false) {}

  void setup(LAMMPS_NS::LAMMPS *lmp, ContactModelBase *cmb)
  {
    superquadric_atoms_ = lmp->atom->superquadric_flag;
#ifdef SUPERQUADRIC_ACTIVE_FLAG
    curvature_.setupPoints(lmp, cmb);
#else
    (void)cmb;
#endif
  }

  /* Whether a sphere contact cannot roll faster than v_min (c_core's
     speed bound of isotropic bodies, from the relative motion at the
     contact point alone): a settled or sliding contact needs no
     kinematics. Inline: every contact and step. */
  __attribute__((always_inline)) static inline bool sphereStill(const SurfacesIntersectData &d, double v_min)
  {
    const double *n = d.en;
    double ri[3], rj[3], dv[3], dw[3];
    for (int c = 0; c < 3; c++) {
      ri[c] = -d.cri * n[c];
      rj[c] = d.is_wall ? 0.0 : d.crj * n[c];
    }
    relativeMotion(d, ri, rj, dv, dw);
    return dc_rolling_speed_bound_isotropic(1.0 / d.radi, d.is_wall ? 0.0 : 1.0 / d.radj, dv, dw) <= v_min;
  }

  /* Kinematics of a touching contact in k; a c_core error stops the run
     with a message naming the atom and the inputs. */
  void compute(LAMMPS_NS::LAMMPS *lmp, const SurfacesIntersectData &d, double max_radius_factor, dc_rolling_kin &k)
  {
    double **x = lmp->atom->x;
    const double *n = d.en;
    dc_rolling_curvature ci, cj;
    double ri[3], rj[3];
    double R_max = INFINITY;
#ifdef SUPERQUADRIC_ACTIVE_FLAG
    const bool sq = d.is_non_spherical && superquadric_atoms_;
#else
    const bool sq = false;
#endif
    if (sq) {
#ifdef SUPERQUADRIC_ACTIVE_FLAG
      double k1[2], k2[2], d1[2][3];
      curvature_.bodyCurvatures(lmp, d, k1, k2, d1, "kalker");
      ci.k1 = k1[0]; ci.k2 = k2[0];
      cj.k1 = k1[1]; cj.k2 = k2[1];
      for (int c = 0; c < 3; c++) {
        ci.d1[c] = d1[0][c];
        cj.d1[c] = d1[1][c];
        ri[c] = d.contact_point[c] - x[d.i][c];
        rj[c] = d.is_wall ? 0.0 : d.contact_point[c] - x[d.j][c];
      }
      const double reff = d.is_wall ? d.radi : d.radi * d.radj / (d.radi + d.radj);
      R_max = max_radius_factor * reff;
#endif
    } else {
      ci.k1 = ci.k2 = 1.0 / d.radi;
      cj.k1 = cj.k2 = d.is_wall ? 0.0 : 1.0 / d.radj;
      for (int c = 0; c < 3; c++) {
        ci.d1[c] = cj.d1[c] = 0.0;
        ri[c] = -d.cri * n[c];
        rj[c] = d.is_wall ? 0.0 : d.crj * n[c];
      }
    }
    double dv[3], dw[3];
    relativeMotion(d, ri, rj, dv, dw);
    const int st = dc_rolling_kinematics_capped(n, &ci, &cj, dv, dw, R_max, &k);
    if (st != DC_OK) {
      char msg[512];
      snprintf(msg, sizeof msg, "Rolling model kalker: contact of atom %d with %s %d: rolling kinematics: %s "
               "(curvatures %g, %g and %g, %g 1/m, relative velocity %g %g %g m/s, relative spin %g %g %g 1/s)",
               (int)lmp->atom->tag[d.i], d.is_wall ? "wall type" : "atom",
               d.is_wall ? d.jtype : (int)lmp->atom->tag[d.j], dc_status_str(st), ci.k1, ci.k2, cj.k1, cj.k2,
               dv[0], dv[1], dv[2], dw[0], dw[1], dw[2]);
      lmp->error->one(FLERR, msg);
    }
  }

  bool superquadricAtoms() const { return superquadric_atoms_; }

private:
  /* The relative velocity dv of the material points at the contact point
     (w = v + omega x r, lever arms ri, rj from the centres) and the
     relative spin dw; a wall moves with LIGGGHTS' wall velocity and does
     not turn. */
  __attribute__((always_inline)) static inline void relativeMotion(const SurfacesIntersectData &d, const double *ri,
                                                                   const double *rj, double *dv, double *dw)
  {
    double wi[3], wj[3];
    const double *oi = d.omega_i;
    wi[0] = d.v_i[0] + oi[1] * ri[2] - oi[2] * ri[1];
    wi[1] = d.v_i[1] + oi[2] * ri[0] - oi[0] * ri[2];
    wi[2] = d.v_i[2] + oi[0] * ri[1] - oi[1] * ri[0];
    if (d.is_wall) {
      for (int c = 0; c < 3; c++) {
        wj[c] = d.v_j[c];
        dw[c] = oi[c];
      }
    } else {
      const double *oj = d.omega_j;
      wj[0] = d.v_j[0] + oj[1] * rj[2] - oj[2] * rj[1];
      wj[1] = d.v_j[1] + oj[2] * rj[0] - oj[0] * rj[2];
      wj[2] = d.v_j[2] + oj[0] * rj[1] - oj[1] * rj[0];
      for (int c = 0; c < 3; c++) dw[c] = oi[c] - oj[c];
    }
    for (int c = 0; c < 3; c++) dv[c] = wi[c] - wj[c];
  }

  bool superquadric_atoms_;
#ifdef SUPERQUADRIC_ACTIVE_FLAG
  SuperquadricCurvature curvature_;
#endif
};

/* The tangential models' side of the hand-over. */
class RollingHandover {
public:
  RollingHandover() : cmb_(0), offered_(false), rolled_offset_(-1), v_min_(DC_ROLLING_VMIN_DEFAULT),
    roll_min_(DC_ROLLING_DISTANCE_DEFAULT), max_radius_factor_(100.0)
  {
    memset(&record_, 0, sizeof record_);
  }
  ~RollingHandover()
  {
    if (offered_) ContactSlots::withdraw(cmb_, "dc_rolling_kin");
  }

  /* From the tangential model's constructor. */
  void attach(ContactModelBase *cmb) { cmb_ = cmb; }

  /* From its registerSettings (after every sub-model's constructor):
     the rolling model's settings, when there is one. */
  void registerSettings(Settings &settings)
  {
    if (!announced()) return;
    settings.registerDoubleSetting("rollingVelocityMin", v_min_, DC_ROLLING_VMIN_DEFAULT);
    settings.registerDoubleSetting("rollingDistanceMin", roll_min_, DC_ROLLING_DISTANCE_DEFAULT);
    settings.registerDoubleSetting("maxRadiusFactor", max_radius_factor_, 100.0);
  }

  /* From its postSettings: the record offered to the rolling model, and
     the contact's net rolled distance (3 history values) when the
     creep law waits for one. */
  void setup(LAMMPS_NS::LAMMPS *lmp, IContactHistorySetup *hsetup)
  {
    if (!announced()) return;
    ContactSlots::offer(cmb_, "dc_rolling_kin", &record_);
    offered_ = true;
    kinematics_.setup(lmp, cmb_);
    if (roll_min_ > 0.0) {
      rolled_offset_ = hsetup->add_history_value("dc_rolled_x", "0");
      if (hsetup->add_history_value("dc_rolled_y", "0") != rolled_offset_ + 1 ||
          hsetup->add_history_value("dc_rolled_z", "0") != rolled_offset_ + 2)
        lmp->error->all(FLERR, "Rolling model kalker: history values not consecutive");
    }
  }

  /* Whether a rolling model shares this contact. */
  bool active() const { return offered_; }

  /* From its surfacesIntersect: the kinematics of this contact kept for
     the rolling model; true when the rolling model acts (the tangential
     model then applies nothing and releases its history). */
  bool rolls(LAMMPS_NS::LAMMPS *lmp, const SurfacesIntersectData &d, const dc_patch &p)
  {
#ifdef SUPERQUADRIC_ACTIVE_FLAG
    const bool sphere = !(d.is_non_spherical && kinematics_.superquadricAtoms());
#else
    const bool sphere = true;
#endif
    /* the net rolled distance, or (a pass that must not change it) a copy */
    double scratch[3] = {0.0, 0.0, 0.0}, *rolled = scratch;
    if (rolled_offset_ >= 0) {
      rolled = &d.contact_history[rolled_offset_];
      if (!(d.computeflag && d.shearupdate)) {
        memcpy(scratch, rolled, sizeof scratch);
        rolled = scratch;
      }
    }
    if (sphere && RollingKinematics::sphereStill(d, v_min_)) {
      rolled[0] = rolled[1] = rolled[2] = 0.0;
      return record_.acts = false;
    }
    kinematics_.compute(lmp, d, max_radius_factor_, record_.k);
    dc_rolling_params prm;
    prm.mu = 0.0;
    prm.v_min = v_min_;
    prm.model = DC_ROLLING_VJ;
    prm.roll_min = roll_min_;
    record_.acts = dc_rolling_acts_rolled(&prm, &p, &record_.k, lmp->update->dt, rolled) != 0;
    return record_.acts;
  }

private:
  bool announced() const { return cmb_ && cmb_->get_history_offset("dc_rolling_model") >= 0; }

  ContactModelBase *cmb_;
  bool offered_;
  int rolled_offset_;   /* the net rolled distance in contact history, or -1 */
  RollingRecord record_;
  double v_min_, roll_min_, max_radius_factor_;
  RollingKinematics kinematics_;
};

}
}
#endif
