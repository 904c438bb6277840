/* LIGGGHTS rolling model `kalker`: rolling contact of elliptic and
   circular patches, Kalker's linear creep theory with the Vermeulen-Johnson
   saturation as a setting (c_core: dc/rolling_kalker.h, review Sec. 4,
   Eqs. 86-93 corrected). Creep forces and the spin moment from the
   longitudinal, lateral and spin creepages; not a rolling-resistance
   torque (LIGGGHTS' epsd, cdt, luding are those).

   Deck: pair_style gran model <normal> tangential <cmd_tangential|classical> rolling_friction kalker [surface superquadric] [settings]
         fix ID all wall/gran model <normal> tangential <...> rolling_friction kalker [surface superquadric] <wall> [settings]
   Settings:
     rollingCreepModel kalker|vermeulenJohnson
                           kalker: Kalker's linear force, bounded by mu F_bound;
                           vermeulenJohnson (default): saturating at mu F_bound
                           (review Eqs. 92-93)
     rollingVelocityMin V  rolling speed [m/s] at or below which the contact does
                           not roll (the tangential model acts), V in (0, inf),
                           default 1e-3 m/s
     maxRadiusFactor X     superquadrics: the relative radii of the kinematics are
                           capped as the normal model caps them (the same
                           setting, default 100)
   Properties: coefficientFriction (peratomtypepair, >= 0: saturation at mu
     F_bound), youngsModulus (peratomtype, Pa) and poissonsRatio (peratomtype,
     the pair's combined value s1/s0 in [0, 0.5]): Kalker's combined shear
     modulus G = 2 / (1/G_i + 1/G_j) and nu.

   Who owns the tangential force (rolling_contact.h): while the contact
   rolls (V > rollingVelocityMin) this model applies the creep force at the
   contact point and the spin moment about the normal, and the tangential
   model applies nothing and releases its history; at V <= rollingVelocityMin
   the tangential model acts and this model adds nothing. So the tangential
   model must be one that hands over (cmd_tangential or classical), and the
   normal model one that publishes the contact patch (hertz_elliptic,
   gw_rough, jkr_elliptic, jamari_ep, classical): else the run stops at
   set-up. The creep force acts while the surfaces touch (a contact the normal model
   keeps formed apart, jkr_elliptic in tension, gets the tangential model's
   force). No history of its own: steady rolling is assumed (c_core's
   domain statement). */
#ifdef ROLLING_MODEL
ROLLING_MODEL(ROLLING_KALKER,kalker,@DC_MODEL_ID@)
#else
#ifndef ROLLING_MODEL_KALKER_H_
#define ROLLING_MODEL_KALKER_H_

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>
#include "atom.h"
#include "contact_frame.h"
#include "contact_models.h"
#include "contact_patch.h"
#include "error.h"
#include "global_properties.h"
#include "rolling_contact.h"
#include "rolling_model_base.h"
#include "update.h"
#include "dc/contract.h"
#include "dc/mindlin.h"
#include "dc/rolling_kalker.h"
#include "dc/status.h"

namespace LIGGGHTS {
namespace ContactModels {

template<>
class RollingModel<ROLLING_KALKER> : public RollingModelBase
{
public:
  RollingModel(LAMMPS *lmp, IContactHistorySetup *hsetup, class ContactModelBase *c) :
    RollingModelBase(lmp, hsetup, c), creepModel(DC_ROLLING_VJ), vMin(DC_ROLLING_VMIN_DEFAULT),
    rollMin(DC_ROLLING_DISTANCE_DEFAULT),
    maxRadiusFactor(100.0), handed(0), ntypes(0)
  {
    patch.request(c);
    c->add_history_offset("dc_rolling_model", 0, true);   /* announces the hand-over (rolling_contact.h) */
  }

  void registerSettings(Settings &settings)
  {
    static const char *const names[] = {"kalker", "vermeulenJohnson"};
    static const int ids[] = {DC_ROLLING_KALKER, DC_ROLLING_VJ};
    settings.registerChoice("rollingCreepModel", creepModel, names, ids, 2, "vermeulenJohnson");
    settings.registerDoubleSetting("rollingVelocityMin", vMin, DC_ROLLING_VMIN_DEFAULT);
    settings.registerDoubleSetting("rollingDistanceMin", rollMin, DC_ROLLING_DISTANCE_DEFAULT);
    settings.registerDoubleSetting("maxRadiusFactor", maxRadiusFactor, 100.0);
  }

  void postSettings(IContactHistorySetup *, ContactModelBase *c)
  {
    patch.setup(lmp, c);
    if (!patch.published())
      error->all(FLERR, "Rolling model kalker needs a normal model that publishes the contact patch: "
                        "model hertz_elliptic, gw_rough, jkr_elliptic, jamari_ep or classical");
    handed = ContactSlots::find<const RollingRecord>(c, "dc_rolling_kin");
    if (!handed)
      error->all(FLERR, "Rolling model kalker needs a tangential model that hands the tangential force over "
                        "while the contact rolls: tangential cmd_tangential or tangential classical");
    if (!(vMin > 0.0 && std::isfinite(vMin))) {
      char msg[160];
      snprintf(msg, sizeof msg, "Rolling model kalker: rollingVelocityMin = %g m/s is outside (0, inf)", vMin);
      error->all(FLERR, msg);
    }
  }

  /* Per type pair: mu, v_min, the creep model (dc_rolling_check), Kalker's
     G and nu with the coefficient series (dc_rolling_material_init). */
  void connectToProperties(PropertyRegistry &registry)
  {
    const char *caller = "rolling_model kalker";
    registry.registerProperty("coeffFrict", &MODEL_PARAMS::createCoeffFrict);
    double **mu = NULL;
    registry.connect("coeffFrict", mu, caller);
    registry.registerProperty("youngsModulus", &MODEL_PARAMS::createYoungsModulus);
    registry.registerProperty("poissonsRatio", &MODEL_PARAMS::createPoissonsRatio);
    const double *E = registry.getVectorProperty("youngsModulus", caller)->data;
    const double *nu = registry.getVectorProperty("poissonsRatio", caller)->data;
    ntypes = registry.max_type();
    params.assign((ntypes + 1) * (ntypes + 1), dc_rolling_params());
    materials.assign((ntypes + 1) * (ntypes + 1), dc_rolling_material());
    for (int i = 1; i <= ntypes; i++)
      for (int j = 1; j <= ntypes; j++) {
        dc_rolling_params &p = params[i * (ntypes + 1) + j];
        p.mu = mu[i][j];
        p.v_min = vMin;
        p.model = creepModel;
        p.roll_min = rollMin;
        dc_param_error err;
        char msg[320], what[256];
        if (dc_rolling_check(&p, &err) != DC_OK) {
          dc_param_error_format(&err, i, j, what, sizeof what);
          snprintf(msg, sizeof msg, "Rolling model kalker: %s", what);
          error->all(FLERR, msg);
        }
        dc_mindlin_pair m;
        if (dc_mindlin_pair_init(E[i], nu[i], E[j], nu[j], &m) != DC_OK) {
          snprintf(msg, sizeof msg, "Rolling model kalker: youngsModulus %g, %g and poissonsRatio %g, %g for types %d "
                   "and %d: need youngsModulus > 0 and poissonsRatio in [0, 0.5]", E[i], E[j], nu[i], nu[j], i, j);
          error->all(FLERR, msg);
        }
        if (dc_rolling_material_init(&m, &materials[i * (ntypes + 1) + j], &err) != DC_OK) {
          dc_param_error_format(&err, i, j, what, sizeof what);
          snprintf(msg, sizeof msg, "Rolling model kalker: %s", what);
          error->all(FLERR, msg);
        }
      }
  }

  /* The tangential model has kept this evaluation's kinematics and the
     decision (rolling_contact.h); while the contact rolls, the creep force
     at the contact point and the spin moment about en. */
  void surfacesIntersect(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)
  {
    if (!handed->acts) return;
    if (sidata.contact_flags) *sidata.contact_flags |= CONTACT_ROLLING_MODEL;
    const dc_rolling_kin &k = handed->k;
    dc_patch stock;
    const dc_patch &p = patch.read(sidata, stock);
    const int t = sidata.itype * (ntypes + 1) + sidata.jtype;
    dc_rolling_step step;
    stepOf(sidata, step);
    dc_rolling_out out;
    const int st = dc_rolling_force_step(&params[t], &materials[t], &p, sidata.en, &k, &step, &out);
    if (st != DC_OK) {
      char msg[512];
      snprintf(msg, sizeof msg, "Rolling model kalker: contact of atom %d: patch a = %g, b = %g, friction load %g, "
               "rolling speed %g m/s, slip %g %g %g m/s, spin %g 1/s: %s", (int)atom->tag[sidata.i], p.a, p.b,
               p.F_bound, k.V, k.slip[0], k.slip[1], k.slip[2], k.spin, dc_status_str(st));
      error->one(FLERR, msg);
    }
    applyTangentialForce(sidata, out.F, sidata.cri, sidata.crj, atom->x, i_forces, j_forces);
    const double scale = sidata.is_wall ? sidata.area_ratio : 1.0;
    for (int c = 0; c < 3; c++) {
      i_forces.delta_torque[c] += scale * out.Mz * sidata.en[c];
      if (!sidata.is_wall) j_forces.delta_torque[c] -= out.Mz * sidata.en[c];
    }
  }

  void surfacesClose(SurfacesCloseData &scdata, ForceData &, ForceData &)
  {
    if (scdata.contact_flags) *scdata.contact_flags &= ~CONTACT_ROLLING_MODEL;
  }

  void beginPass(SurfacesIntersectData &, ForceData &, ForceData &) {}
  void endPass(SurfacesIntersectData &, ForceData &, ForceData &) {}

private:
  /* The time step and the bodies' inverse masses for the stable step
     (dc_rolling_step): lever arms to the contact point as the kinematics
     take them; a superquadric's smallest principal moment of inertia. */
  void stepOf(const SurfacesIntersectData &d, dc_rolling_step &s) const
  {
    s.dt = update->dt;
    s.inv_m = s.inv_I = 0.0;
    addBody(d, d.i, d.cri, s);
    if (!d.is_wall) addBody(d, d.j, d.crj, s);
  }

  void addBody(const SurfacesIntersectData &d, int i, double lever, dc_rolling_step &s) const
  {
    const double m = atom->rmass[i];
    double I = 0.4 * m * atom->radius[i] * atom->radius[i];
#ifdef SUPERQUADRIC_ACTIVE_FLAG
    if (d.is_non_spherical && atom->superquadric_flag) {
      const double *J = atom->inertia[i];
      I = std::min(J[0], std::min(J[1], J[2]));
      double r2 = 0.0;
      for (int c = 0; c < 3; c++) r2 += (d.contact_point[c] - atom->x[i][c]) * (d.contact_point[c] - atom->x[i][c]);
      lever = std::sqrt(r2);
    }
#else
    (void)d;
#endif
    s.inv_m += 1.0 / m + lever * lever / I;
    s.inv_I += 1.0 / I;
  }

  int creepModel;
  double vMin, rollMin, maxRadiusFactor;
  const RollingRecord *handed;   /* the tangential model's hand-over record (rolling_contact.h) */
  int ntypes;
  std::vector<dc_rolling_params> params;
  std::vector<dc_rolling_material> materials;
  ContactPatchReader patch;
};

}
}
#endif
#endif
