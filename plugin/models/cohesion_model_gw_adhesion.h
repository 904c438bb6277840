/* LIGGGHTS cohesion model `gw_adhesion`: the adhesive part of rough contact
   with adhesive (JKR) summits (c_core: dc/gw_rough_adhesive_table.h, the
   tabulated form of dc/gw_rough_adhesive.h, review Eq. 29), added to the
   elastic GW force of `gw_rough gwElliptic on`, with its loading and
   unloading branches kept in the contact history.

   Deck: pair_style gran model gw_rough tangential history cohesion gw_adhesion gwElliptic on
         fix ID all wall/gran model gw_rough tangential history cohesion gw_adhesion primitive ... gwElliptic on
   Properties: workOfAdhesion (peratomtypepair, J/m^2, >= 0; 0 gives exactly
     gw_rough), surfaceRoughness (peratomtype, m: sigma = (sigma_i^2 +
     sigma_j^2)^1/2 per pair) and asperityCount (peratomtypepair) as
     gw_rough, youngsModulus and poissonsRatio (E*).
   Spheres only (circular summits); pairs with sigma = 0 get no force. The
   force acts from the Gaussian tail of the summit heights on (12 sigma
   apart, dc_gwa_table_apart) and, once pressed, until the lowest attached summit
   lets go, (D + 8) sigma apart at most
   (dc_gwa_table_reach): the deck must set contact_distance_factor so that
   the pair stays in reach; the run stops naming the value needed. */
#ifdef COHESION_MODEL
COHESION_MODEL(COHESION_GW_ADHESION,gw_adhesion,@DC_MODEL_ID@)
#else
#ifndef COHESION_MODEL_GW_ADHESION_H_
#define COHESION_MODEL_GW_ADHESION_H_

#include <cstdio>
#include <cstring>
#include <memory>
#include <vector>
#include "atom.h"
#include "cohesion_model_base.h"
#include "contact_frame.h"
#include "dc_properties.h"
#include "contact_models.h"
#include "error.h"
#include "global_properties.h"
#include "neighbor.h"
#include "dc/contract.h"
#include "dc/gw_rough.h"
#include "dc/gw_rough_adhesive_table.h"
#include "dc/status.h"

namespace LIGGGHTS {
namespace ContactModels {

template<>
class CohesionModel<COHESION_GW_ADHESION> : public CohesionModelBase
{
public:
  CohesionModel(LAMMPS *lmp, IContactHistorySetup *hsetup, class ContactModelBase *c) :
    CohesionModelBase(lmp, hsetup, c), history_offset(-1), contact_offset(-1), ntypes(0)
  {
    for (int k = 0; k < DC_GWA_TABLE_HISTORY_NFIELDS; k++) {
      const int off = hsetup->add_history_value(dc_gwa_table_history[k].name, dc_gwa_table_history[k].flips ? "1" : "0");
      if (k == 0) history_offset = off;
    }
    /* what the contact's radius fixes and its last table cell
       (dc_gwa_table_contact, a struct of doubles read in place): 8 more
       values, consecutive */
    static_assert(sizeof(dc_gwa_table_contact) == DC_GWA_TABLE_CONTACT_NFIELDS * sizeof(double),
                  "dc_gwa_table_contact: plain doubles, one per history value");
    for (int k = 0; k < DC_GWA_TABLE_CONTACT_NFIELDS; k++) {
      const int off = hsetup->add_history_value(dc_gwa_table_contact_history[k].name,
                                                dc_gwa_table_contact_history[k].flips ? "1" : "0");
      if (k == 0) contact_offset = off;
      else if (off != contact_offset + k)
        error->all(FLERR, "Cohesion model gw_adhesion: history values not consecutive");
    }
  }

  void registerSettings(Settings &) {}

  void postSettings(IContactHistorySetup *, ContactModelBase *)
  {
    if (atom->superquadric_flag)
      error->all(FLERR, "Cohesion model gw_adhesion: spheres only (the table covers circular summits)");
  }

  void connectToProperties(PropertyRegistry &registry)
  {
    const char *caller = "cohesion_model gw_adhesion";
    registry.registerProperty("workOfAdhesion", &dcCreateWorkOfAdhesion, caller);
    registry.registerProperty("surfaceRoughnessType", &dcCreateRoughnessType, caller);
    registry.registerProperty("asperityCount", &dcCreateAsperityCount, caller);
    registry.registerProperty("Yeff", &MODEL_PARAMS::createYeff, caller);
    double **w = registry.getMatrixProperty("workOfAdhesion", caller)->data;
    double *s = registry.getVectorProperty("surfaceRoughnessType", caller)->data;
    double **na = registry.getMatrixProperty("asperityCount", caller)->data;
    double **Y = registry.getMatrixProperty("Yeff", caller)->data;
    ntypes = registry.max_type();
    pairs.assign((ntypes + 1) * (ntypes + 1), dc_gwa_table_pair());
    for (int i = 1; i <= ntypes; i++)
      for (int j = 1; j <= ntypes; j++) {
        const double sigma = dc_gw_roughness_combine(s[i], s[j]);
        if (sigma == 0.0) continue;   /* smooth pairs: no summits (jkr_elliptic is the smooth law) */
        dc_param_error err;
        if (dc_gwa_table_check(Y[i][j], w[i][j], sigma, na[i][j], &err) != DC_OK ||
            dc_gwa_table_pair_init(Y[i][j], w[i][j], sigma, na[i][j], &pairs[i * (ntypes + 1) + j]) != DC_OK) {
          char msg[256], what[200];
          dc_param_error_format(&err, i, j, what, sizeof what);
          snprintf(msg, sizeof msg, "Cohesion model gw_adhesion: %s", what);
          error->all(FLERR, msg);
        }
      }
  }

  void surfacesIntersect(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)
  {
    adhesion(sidata, sidata.deltan, i_forces, j_forces);
  }

  /* Apart: the highest summits touch (loading) or the attached ones pull
     until the lowest lets go (unloading). */
  void surfacesClose(SurfacesCloseData &scdata, ForceData &i_forces, ForceData &j_forces)
  {
    SurfacesIntersectData &sidata = static_cast<SurfacesIntersectData &>(scdata);
    const double delta = closeSphereOverlap(scdata);
    if (adhesion(sidata, delta, i_forces, j_forces)) sidata.has_force_update = true;
  }

  void beginPass(SurfacesIntersectData &, ForceData &, ForceData &) {}
  void endPass(SurfacesIntersectData &, ForceData &, ForceData &) {}
  inline void endSurfacesIntersect(SurfacesIntersectData &, ForceData &, ForceData &) {}

private:
  /* Applies the adhesive force at overlap delta; false when none acts. */
  bool adhesion(SurfacesIntersectData &sidata, double delta, ForceData &i_forces, ForceData &j_forces)
  {
    const int k = sidata.itype * (ntypes + 1) + sidata.jtype;
    const dc_gwa_table_pair &p = pairs[k];
    if (p.sigma == 0.0) return false;   /* a smooth pair */
    if (dc_gwa_table_apart(&p, delta, &sidata.contact_history[history_offset])) {
      if (sidata.contact_flags) *sidata.contact_flags &= ~CONTACT_COHESION_MODEL;
      return false;
    }
    const double R = sphereEffectiveRadius(sidata);
    double *h = &sidata.contact_history[history_offset];
    double scratch[DC_GWA_TABLE_HISTORY_NFIELDS];
    const bool keep = sidata.computeflag && sidata.shearupdate;
    if (!keep) {   /* a pass that must not change the history */
      memcpy(scratch, h, sizeof scratch);
      h = scratch;
    }
    /* the set-up for R and the last table cell, kept in the contact's
       history (R is the contact's for its life; set up again when the
       stored R differs: a new contact starts at 0) */
    dc_gwa_table_contact copy;
    dc_gwa_table_contact *con = reinterpret_cast<dc_gwa_table_contact *>(&sidata.contact_history[contact_offset]);
    if (!keep) {
      memcpy(&copy, con, sizeof copy);
      con = &copy;
    }
    if (con->R != R) {
      const int st = dc_gwa_table_contact_init(&p, R, con);
      if (st != DC_OK) {
        char msg[256];
        snprintf(msg, sizeof msg, "Cohesion model gw_adhesion: radius %g: %s", R, dc_status_str(st));
        error->one(FLERR, msg);
      }
    }
    if (h[0] != 0.0) {
      const double r0 = sidata.is_wall ? sidata.radi : sidata.radsum, reach = dc_gwa_table_contact_reach(&p, con);
      if (neighbor->contactDistanceFactor * r0 < r0 + reach) {
        char msg[256];
        snprintf(msg, sizeof msg, "Cohesion model gw_adhesion: attached summits pull up to %g m apart: set "
                 "neigh_modify contact_distance_factor >= %.12g", reach, 1.0 + reach / r0);
        error->one(FLERR, msg);
      }
    }
    dc_gwa_table_out o;
    const int st = dc_gwa_table_step_contact(&p, con, delta, h, &o);
    if (st != DC_OK) {
      char msg[256];
      snprintf(msg, sizeof msg, "Cohesion model gw_adhesion: overlap %g, radius %g: %s", delta, R, dc_status_str(st));
      error->one(FLERR, msg);
    }
    if (sidata.contact_flags) {
      if (h[0] != 0.0) *sidata.contact_flags |= CONTACT_COHESION_MODEL;
      else *sidata.contact_flags &= ~CONTACT_COHESION_MODEL;
    }
    if (o.F == 0.0) return false;
    applyNormalForce(sidata, o.F, atom->x, i_forces, j_forces);
    return true;
  }

  int history_offset, contact_offset, ntypes;
  std::vector<dc_gwa_table_pair> pairs;
};

}
}
#endif
#endif
