/* LIGGGHTS tangential model `cmd_tangential`: Cattaneo-Mindlin-Deresiewicz
   tangential force of elliptic and circular contacts with full load history,
   and (setting) Mindlin twisting (c_core: dc/cmd_tangential.h, review
   Sec. 3.1), or (setting cmdMemory turningPoints) the bounded-memory law of
   dc/cmd_turning_points.h.

   Deck: pair_style gran model <normal> tangential cmd_tangential [settings]
         fix ID all wall/gran model <normal> tangential cmd_tangential ... [settings]
   Settings:
     cmdMemory profile|turningPoints  the exact spring profile (default) or the
                            force with up to 4 remembered turning points
     cmdTwisting on|off     Mindlin twisting moment about the contact normal (default off)
     cmdDissipation on|off  tangential viscoelastic dissipation, review Eq. 85 (default off;
                            property tangentialViscoelasticTime peratomtypepair [s])
     tangentialRoughness on|off  with model gw_rough: the summits' stiffness (Hisakado-
                            Tsukizoe, review Eq. 83; dc/rough_tangential.h), also
                            before touch, in place of the smooth contact's (default off;
                            not with cmdTwisting)
   Properties: coefficientFriction (peratomtypepair, >= 0), youngsModulus and
     poissonsRatio (peratomtype: Mindlin's stiffness of each pair of bodies).
   The contact patch (semi-axes, major axis, friction load, formed flag)
   comes from the normal model (contact_patch.h); under a stock normal model
   it is the circle a = (R delta)^1/2 with friction load = its elastic force.
   The force acts while the normal model says the contact is formed: for
   jkr_elliptic also in tension, bounded by mu (F + 2 F_pulloff). The
   normal model's tangential_damping does not apply: dissipation is the
   law's own (slip, and cmdDissipation). With `rolling_friction kalker` it
   hands the tangential force over while the contact rolls
   (rolling_contact.h): it applies nothing then and its history starts
   afresh when the contact stops rolling. */
#ifdef TANGENTIAL_MODEL
TANGENTIAL_MODEL(TANGENTIAL_CMD,cmd_tangential,@DC_MODEL_ID@)
#else
#ifndef TANGENTIAL_MODEL_CMD_TANGENTIAL_H_
#define TANGENTIAL_MODEL_CMD_TANGENTIAL_H_

#include <cstdio>
#include <cstring>
#include <vector>
#include "atom.h"
#include "contact_frame.h"
#include "contact_models.h"
#include "contact_patch.h"
#include "contact_slot.h"
#include "error.h"
#include "rolling_contact.h"
#include "global_properties.h"
#include "neighbor.h"
#include "tangential_model_base.h"
#include "update.h"
#include "dc/cmd_tangential.h"
#include "dc/cmd_turning_points.h"
#include "dc/contract.h"
#include "dc/mindlin.h"
#include "dc/status.h"

namespace LIGGGHTS {
namespace ContactModels {

template<>
class TangentialModel<TANGENTIAL_CMD> : public TangentialModelBase
{
public:
  TangentialModel(LAMMPS *lmp, IContactHistorySetup *hsetup, class ContactModelBase *c) :
    TangentialModelBase(lmp, hsetup, c), coeffFrict(NULL), tvisc(NULL), twisting(false), dissipation(false),
    roughness(false), memory(0), history_offset(-1), nfields(0), ntypes(0), rough(NULL)
  {
    patch.request(c);
    handover.attach(c);
  }

  void registerSettings(Settings &settings)
  {
    settings.registerOnOff("cmdTwisting", twisting, false);
    settings.registerOnOff("cmdDissipation", dissipation, false);
    settings.registerOnOff("tangentialRoughness", roughness, false);
    static const char *const names[] = {"profile", "turningPoints"};
    static const int values[] = {0, 1};
    settings.registerChoice("cmdMemory", memory, names, values, 2, "profile");
    handover.registerSettings(settings);
  }

  /* The law's history (the profile's or the turning points'), without the
     twist's unless cmdTwisting is on (the law does not touch it then). LIGGGHTS' contact-history pages hold
     neigh_modify one x (values per contact); the default page (100000) is
     too small for this many and LIGGGHTS fails without a message: grow it
     (the margin covers the other models' values). */
  void postSettings(IContactHistorySetup *hsetup, ContactModelBase *c)
  {
    patch.setup(lmp, c);
    handover.setup(lmp, hsetup);
    if (roughness) {
      rough = ContactSlots::find<RoughPatchSlot>(c, "dc_rough_patch");
      if (!rough) stop("tangentialRoughness on needs the normal model gw_rough (its summits' patch)");
      if (twisting) stop("tangentialRoughness on does not take cmdTwisting on (no twisting law for summits)");
      rough->wanted = true;
    }
    const dc_history_field *fields = memory ? dc_cmdtp_history : dc_cmd_history;
    if (memory) nfields = twisting ? DC_CMDTP_HISTORY_NFIELDS : DC_CMDTP_FORCE_NFIELDS;
    else nfields = twisting ? DC_CMD_HISTORY_NFIELDS : DC_CMD_FORCE_NFIELDS;
    const int need = neighbor->oneatom * (nfields + 40);
    if (neighbor->pgsize < need) neighbor->pgsize = need;
    for (int k = 0; k < nfields; k++) {
      const int off = hsetup->add_history_value(fields[k].name, fields[k].flips ? "1" : "0");
      if (k == 0) history_offset = off;
    }
  }

  void connectToProperties(PropertyRegistry &registry)
  {
    const char *caller = "tangential_model cmd_tangential";
    registry.registerProperty("coeffFrict", &MODEL_PARAMS::createCoeffFrict);
    registry.connect("coeffFrict", coeffFrict, caller);
    if (dissipation) {
      registry.registerProperty("tangentialViscoelasticTime", &createTvisc);
      registry.connect("tangentialViscoelasticTime", tvisc, caller);
    }
    registry.registerProperty("youngsModulus", &MODEL_PARAMS::createYoungsModulus);
    registry.registerProperty("poissonsRatio", &MODEL_PARAMS::createPoissonsRatio);
    const double *E = registry.getVectorProperty("youngsModulus", caller)->data;
    const double *nu = registry.getVectorProperty("poissonsRatio", caller)->data;
    ntypes = registry.max_type();
    params.assign((ntypes + 1) * (ntypes + 1), dc_cmd_params());
    pairs.assign((ntypes + 1) * (ntypes + 1), dc_mindlin_pair());
    for (int i = 1; i <= ntypes; i++)
      for (int j = 1; j <= ntypes; j++) {
        dc_cmd_params &p = params[i * (ntypes + 1) + j];
        p.mu = coeffFrict[i][j];
        p.t_visc = dissipation ? tvisc[i][j] : 0.0;
        p.dissipation = dissipation;
        p.twisting = twisting;
        dc_param_error err;
        char msg[256];
        if (dc_cmd_check(&p, &err) != DC_OK) {
          dc_param_error_format(&err, i, j, msg, sizeof msg);
          stop(msg);
        }
        if (dc_mindlin_pair_init(E[i], nu[i], E[j], nu[j], &pairs[i * (ntypes + 1) + j]) != DC_OK) {
          snprintf(msg, sizeof msg, "youngsModulus %g, %g and poissonsRatio %g, %g for types %d and %d: need E > 0 "
                   "and poissonsRatio in (-1, 0.5]", E[i], E[j], nu[i], nu[j], i, j);
          stop(msg);
        }
      }
  }

  inline void surfacesIntersect(const SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)
  {
    if (sidata.contact_flags) *sidata.contact_flags |= CONTACT_TANGENTIAL_MODEL;
    if (handover.active()) {
      dc_patch stock;
      const dc_patch &p = patch.read(sidata, stock);
      if (handover.rolls(lmp, sidata, p)) {   /* the rolling model owns the tangential force */
        if (sidata.computeflag && sidata.shearupdate) memset(state(sidata), 0, nfields * sizeof(double));
        return;
      }
    }
    const double vtr[3] = {sidata.vtr1, sidata.vtr2, sidata.vtr3};
    step(sidata, vtr, sidata.cri, sidata.crj, i_forces, j_forces);
  }

  /* A contact the normal model keeps formed although the surfaces are apart
     (jkr_elliptic in tension): the force acts as long as it is formed. */
  void surfacesClose(SurfacesCloseData &scdata, ForceData &i_forces, ForceData &j_forces)
  {
    if (!patch.formed()) {
      /* both laws' histories begin with the normal, nonzero once stepped */
      double *h = state(scdata);
      if (h[0] != 0.0 || h[1] != 0.0 || h[2] != 0.0) memset(h, 0, nfields * sizeof(double));
      return;
    }
    SurfacesIntersectData &sidata = static_cast<SurfacesIntersectData &>(scdata);
    double vtr[3];
    if (scdata.is_non_spherical) {
      /* superquadrics: the normal model's gap code has set en and the contact point */
      closeContactPointVelocity(sidata, sidata.en, sidata.contact_point, atom->x, vtr);
      if (scdata.contact_flags) *scdata.contact_flags |= CONTACT_TANGENTIAL_MODEL;
      step(sidata, vtr, 0.0, 0.0, i_forces, j_forces);
      return;
    }
    /* spheres: a formed contact's normal model has set en and the overlap */
    const double delta = closeSphereOverlapAgain(scdata);
    closeTangentialVelocity(sidata, sidata.en, delta, vtr);
    if (scdata.contact_flags) *scdata.contact_flags |= CONTACT_TANGENTIAL_MODEL;
    step(sidata, vtr, sidata.radi - 0.5 * delta, sidata.radj - 0.5 * delta, i_forces, j_forces);
  }

  void beginPass(SurfacesIntersectData &, ForceData &, ForceData &) {}
  void endPass(SurfacesIntersectData &, ForceData &, ForceData &) {}

private:
  double *state(const SurfacesCloseData &d) const { return &d.contact_history[history_offset]; }

  void stop(const char *what)
  {
    char msg[384];
    snprintf(msg, sizeof msg, "Tangential model cmd_tangential: %s", what);
    error->all(FLERR, msg);
  }

  /* One step: c_core's law on this step's displacement, force and moment
     applied (force on i is -Ft, lever arms cri, crj for spheres). */
  void step(const SurfacesIntersectData &sidata, const double *vtr, double cri, double crj,
            ForceData &i_forces, ForceData &j_forces)
  {
    const int k = sidata.itype * (ntypes + 1) + sidata.jtype;
    const double dt = update->dt;
    dc_patch stock;
    const dc_patch &p = rough ? rough->patch : patch.read(sidata, stock);
    const double du[3] = {vtr[0] * dt, vtr[1] * dt, vtr[2] * dt};
    double dphi = 0.0;
    if (twisting) {
      const double *wi = sidata.omega_i, *wj = sidata.omega_j, *n = sidata.en;
      const double w[3] = {wi[0] - (sidata.is_wall ? 0.0 : wj[0]), wi[1] - (sidata.is_wall ? 0.0 : wj[1]),
                           wi[2] - (sidata.is_wall ? 0.0 : wj[2])};
      dphi = (w[0] * n[0] + w[1] * n[1] + w[2] * n[2]) * dt;
    }
    double *h = state(sidata);
    double scratch[DC_CMD_HISTORY_NFIELDS];
    static_assert(DC_CMD_HISTORY_NFIELDS >= DC_CMDTP_HISTORY_NFIELDS, "scratch holds either history");
    if (!(sidata.computeflag && sidata.shearupdate)) {   /* a pass that must not change the history */
      memcpy(scratch, h, nfields * sizeof(double));
      h = scratch;
    }
    /* the inputs lie in the law's domain by construction: the trusted
       step; on an error the checked step names the cause */
    dc_cmd_out out;
    dc_cmdtp_state *ht = reinterpret_cast<dc_cmdtp_state *>(h);
    dc_cmd_state *hx = reinterpret_cast<dc_cmd_state *>(h);
    const int trusted = memory ? dc_cmdtp_step_trusted(&params[k], &pairs[k], &p, sidata.en, du, dphi, dt, ht, &out)
                               : dc_cmd_step_trusted(&params[k], &pairs[k], &p, sidata.en, du, dphi, dt, hx, &out);
    if (trusted != DC_OK) {
      const int st = memory ? dc_cmdtp_step(&params[k], &pairs[k], &p, sidata.en, du, dphi, dt, ht, &out)
                            : dc_cmd_step(&params[k], &pairs[k], &p, sidata.en, du, dphi, dt, hx, &out);
      char msg[384];
      snprintf(msg, sizeof msg, "Tangential model cmd_tangential: contact of atom %d: patch a = %g, b = %g, friction "
               "load %g, displacement %g %g %g: %s", (int)atom->tag[sidata.i], p.a, p.b, p.F_bound, du[0], du[1],
               du[2], dc_status_str(st));
      error->one(FLERR, msg);
    }
    const double F[3] = {-out.Ft[0], -out.Ft[1], -out.Ft[2]};   /* on i */
    applyTangentialForce(sidata, F, cri, crj, atom->x, i_forces, j_forces);
    if (twisting) {
      for (int c = 0; c < 3; c++) {
        i_forces.delta_torque[c] -= out.Mt * sidata.en[c];
        if (!sidata.is_wall) j_forces.delta_torque[c] += out.Mt * sidata.en[c];
      }
    }
  }

  static MatrixProperty *createTvisc(PropertyRegistry &registry, const char *caller, bool sanity_checks)
  {
    return MODEL_PARAMS::createPerTypePairProperty(registry, "tangentialViscoelasticTime", caller, sanity_checks, 0.0);
  }

  double **coeffFrict, **tvisc;
  bool twisting, dissipation, roughness;
  int memory;           /* cmdMemory: 0 profile, 1 turningPoints */
  int history_offset, nfields, ntypes;
  RoughPatchSlot *rough;   /* tangentialRoughness on: gw_rough's summits' patch */
  std::vector<dc_cmd_params> params;
  std::vector<dc_mindlin_pair> pairs;
  ContactPatchReader patch;
  RollingHandover handover;
};

}
}
#endif
#endif
