/* LIGGGHTS cohesion model `gw_adhesion`: the adhesive part of rough contact
   with adhesive (JKR) summits (c_core: dc/gw_rough_adhesive_table.h, the
   tabulated form of dc/gw_rough_adhesive.h, review Eq. 29), added to the
   elastic GW force of `gw_rough gwElliptic on`, with its loading and
   unloading branches kept in the contact history.

   Deck: pair_style gran model gw_rough tangential history cohesion gw_adhesion gwElliptic on
         fix ID all wall/gran model gw_rough tangential history cohesion gw_adhesion primitive ... gwElliptic on
         (superquadrics: `surface superquadric` after `cohesion gw_adhesion`)
   Properties: workOfAdhesion (peratomtypepair, J/m^2, >= 0; 0 gives exactly
     gw_rough), surfaceRoughness (peratomtype, m: sigma = (sigma_i^2 +
     sigma_j^2)^1/2 per pair) and asperityCount (peratomtypepair) as
     gw_rough, youngsModulus and poissonsRatio (E*).
   Spheres: circular summits, what the contact's radius fixes kept in its
   history (dc_gwa_table_contact). Superquadrics: elliptic summits of the
   contact's relative principal radii (dc_gwa_table_radius_init_elliptic,
   radii from superquadric_curvature.h with gw_rough's maxRadiusFactor, the
   overlap before touch from superquadric_gap.h). Pairs with sigma = 0 get
   no force. The force acts from the Gaussian tail of the summit heights on
   (8 sigma apart, dc_gwa_table_apart) and, once pressed, until the lowest
   attached summit lets go, (D + 8) sigma apart at most: the deck must set
   contact_distance_factor so that the pair stays in reach; the run stops
   naming the value needed. */
#ifdef COHESION_MODEL
COHESION_MODEL(COHESION_GW_ADHESION,gw_adhesion,@DC_MODEL_ID@)
#else
#ifndef COHESION_MODEL_GW_ADHESION_H_
#define COHESION_MODEL_GW_ADHESION_H_

#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <vector>
#include "atom.h"
#include "cohesion_model_base.h"
#include "contact_frame.h"
#include "contact_slot.h"
#include "dc_properties.h"
#include "contact_models.h"
#include "error.h"
#include "global_properties.h"
#include "neighbor.h"
#include "warn_once.h"
#include "dc/contract.h"
#include "dc/gw_rough.h"
#include "dc/gw_rough_adhesive_table.h"
#include "dc/status.h"
#ifdef SUPERQUADRIC_ACTIVE_FLAG
#include "superquadric_curvature.h"
#include "superquadric_gap.h"
#endif

namespace LIGGGHTS {
namespace ContactModels {

template<>
class CohesionModel<COHESION_GW_ADHESION> : public CohesionModelBase
{
public:
  CohesionModel(LAMMPS *lmp, IContactHistorySetup *hsetup, class ContactModelBase *c) :
    CohesionModelBase(lmp, hsetup, c), history_offset(-1), contact_offset(-1), ntypes(0), reachEveryStep(true),
    maxRadiusFactor(100.0)
  {
    for (int k = 0; k < DC_GWA_TABLE_HISTORY_NFIELDS; k++) {
      const int off = hsetup->add_history_value(dc_gwa_table_history[k].name, dc_gwa_table_history[k].flips ? "1" : "0");
      if (k == 0) history_offset = off;
    }
#ifdef SUPERQUADRIC_ACTIVE_FLAG
    /* superquadrics: the set-up depends on both relative radii, which move
       with the contact point; no record, the gap's warm start instead */
    if (atom->superquadric_flag) {
      gap.addHistory(lmp, hsetup);
      return;
    }
#endif
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

  /* the normal model's setting (the same value) */
  void registerSettings(Settings &settings) { settings.registerDoubleSetting("maxRadiusFactor", maxRadiusFactor, 100.0); }

  void postSettings(IContactHistorySetup *, ContactModelBase *cmb)
  {
    if (!ContactSlots::find<void>(cmb, "gw_rough_elliptic"))
      error->all(FLERR, "Cohesion model gw_adhesion needs the normal model gw_rough with 'gwElliptic on' (the "
                 "adhesive part adds to that closed form): pair_style gran model gw_rough tangential ... cohesion "
                 "gw_adhesion gwElliptic on, and the same on wall/gran");
#ifdef SUPERQUADRIC_ACTIVE_FLAG
    curvature.setup(lmp, cmb, maxRadiusFactor, "gw_adhesion", "Cohesion model");
    gap.setup(lmp, cmb);
#else
#endif
  }

  /* at each run's start (LIGGGHTS' init) */
  void connectToProperties(PropertyRegistry &registry)
  {
    reachEveryStep = true;   /* the contact distance may have changed */
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
#ifdef SUPERQUADRIC_ACTIVE_FLAG
    if (atom->superquadric_flag) {
      if (sidata.is_wall && sidata.mesh && !warnedBefore(DC_WARN_GWA_MESH)) {
        error->warning(FLERR, "Cohesion model gw_adhesion: superquadrics on a mesh wall: LIGGGHTS measures no gap "
                       "to a mesh for superquadrics, so their summits pull only while the surfaces touch, not "
                       "before touch or after they part (primitive walls and pairs have the whole law); warned once");
      }
      if (const dc_gwa_table_pair *p = acting(sidata, sidata.deltan))
        adhesionSuperquadric(sidata, *p, sidata.deltan, i_forces, j_forces);
      return;
    }
#endif
    if (const dc_gwa_table_pair *p = acting(sidata, sidata.deltan)) adhesion(sidata, *p, sidata.deltan, i_forces, j_forces);
  }

  /* Apart: the highest summits touch (loading) or the attached ones pull
     until the lowest lets go (unloading). */
  void surfacesClose(SurfacesCloseData &scdata, ForceData &i_forces, ForceData &j_forces)
  {
    SurfacesIntersectData &sidata = static_cast<SurfacesIntersectData &>(scdata);
#ifdef SUPERQUADRIC_ACTIVE_FLAG
    if (atom->superquadric_flag) return closeSuperquadric(sidata, i_forces, j_forces);
#endif
    /* inline up to the apart test: most pairs in a polydisperse packing stop there */
    const double delta = closeSphereOverlapAgain(scdata);
    if (const dc_gwa_table_pair *p = acting(sidata, delta))
      if (adhesion(sidata, *p, delta, i_forces, j_forces)) sidata.has_force_update = true;
  }

  void beginPass(SurfacesIntersectData &, ForceData &, ForceData &) {}
  /* after a run's first pass over the pairs: settled contacts need no reach check (adhesion) */
  void endPass(SurfacesIntersectData &, ForceData &, ForceData &) { reachEveryStep = false; }
  inline void endSurfacesIntersect(SurfacesIntersectData &, ForceData &, ForceData &) {}

private:
#ifdef SUPERQUADRIC_ACTIVE_FLAG
  /* surfacesClose for superquadrics: the overlap from the gap, measured
     out to 8 sigma for an untouched pair, anywhere in the neighbour list
     for a touched one. */
  __attribute__((noinline)) void closeSuperquadric(SurfacesIntersectData &sidata, ForceData &i_forces,
                                                   ForceData &j_forces)
  {
    const dc_gwa_table_pair &p = pairs[sidata.itype * (ntypes + 1) + sidata.jtype];
    if (p.sigma == 0.0) return;
    const double *h = &sidata.contact_history[history_offset];
    const double r0 = reachRadius(sidata);
    const double range = h[0] != 0.0 ? (neighbor->contactDistanceFactor - 1.0) * r0 : DC_GWA_TABLE_X_CUT * p.sigma;
    double delta, vn;
    if (!gap.closeOverlap(lmp, sidata, range, delta, vn)) return;
    if (acting(sidata, delta) && adhesionSuperquadric(sidata, p, delta, i_forces, j_forces))
      sidata.has_force_update = true;
  }

  /* A superquadric contact of pair p at overlap delta (acting): the
     elliptic summits of its relative radii; false when no force acts. */
  bool adhesionSuperquadric(SurfacesIntersectData &sidata, const dc_gwa_table_pair &p, double delta,
                            ForceData &i_forces, ForceData &j_forces)
  {
    double R_major, R_minor;
    curvature.relativeRadii(lmp, sidata, R_major, R_minor, "gw_adhesion");
    dc_gwa_table_radius rad;
    const int si = dc_gwa_table_radius_init_elliptic(&p, R_major, R_minor, &rad);
    if (si != DC_OK) fail("relative radii %g, %g: %s", R_major, R_minor, dc_status_str(si));
    if (R_minor < DC_GWAE_RHO_MIN * R_major && !warnedBefore(DC_WARN_GWA_RATIO)) {
      char msg[320];
      snprintf(msg, sizeof msg, "Cohesion model gw_adhesion: atoms %d and %d touch with relative radii %g and %g, a "
               "ratio below %g: the elliptic summits are taken at that ratio, which overestimates the adhesive "
               "force (at a fixed overlap it falls 3.4 to 4.3 times per decade of ratio there; a smaller "
               "maxRadiusFactor keeps flat faces in range); warned once",
               (int)atom->tag[sidata.i], sidata.is_wall ? 0 : (int)atom->tag[sidata.j], R_major, R_minor,
               DC_GWAE_RHO_MIN);
      error->warning(FLERR, msg);
    }
    double scratch[DC_GWA_TABLE_HISTORY_NFIELDS];
    double *h = history(sidata, scratch);
    if (h[0] != 0.0) checkReach(sidata, rad.reach);
    dc_gwa_table_out o;
    const int st = dc_gwa_table_step_radius(&p, &rad, delta, h, &o);
    return finish(sidata, st, delta, R_major, h, o, i_forces, j_forces);
  }
#endif

  /* The pair's table set-up, or NULL where no force acts at overlap
     delta: a smooth pair, or an untouched one apart (its flag cleared). */
  const dc_gwa_table_pair *acting(SurfacesIntersectData &sidata, double delta)
  {
    const dc_gwa_table_pair &p = pairs[sidata.itype * (ntypes + 1) + sidata.jtype];
    if (p.sigma == 0.0) return NULL;   /* a smooth pair */
    if (dc_gwa_table_apart(&p, delta, &sidata.contact_history[history_offset])) {
      if (sidata.contact_flags) *sidata.contact_flags &= ~CONTACT_COHESION_MODEL;
      return NULL;
    }
    return &p;
  }

  /* Applies the adhesive force of pair p at overlap delta (acting); false
     when none acts. */
  __attribute__((noinline)) bool adhesion(SurfacesIntersectData &sidata, const dc_gwa_table_pair &p, double delta,
                                          ForceData &i_forces, ForceData &j_forces)
  {
    const double R = sphereEffectiveRadius(sidata);
    double scratch[DC_GWA_TABLE_HISTORY_NFIELDS];
    double *h = history(sidata, scratch);
    /* the set-up for R and the last table cell, kept in the contact's
       history (R is the contact's for its life; set up again when the
       stored R differs: a new contact starts at 0) */
    dc_gwa_table_contact copy;
    dc_gwa_table_contact *con = reinterpret_cast<dc_gwa_table_contact *>(&sidata.contact_history[contact_offset]);
    if (h == scratch) {
      memcpy(&copy, con, sizeof copy);
      con = &copy;
    }
    if (con->R != R) {
      const int st = dc_gwa_table_contact_init(&p, R, con);
      if (st != DC_OK) fail("radius %g: %s", R, dc_status_str(st));
    }
    /* the reach is the record's and the contact distance the run's: a
       touched contact is checked after each step that left the short path
       (a settled contact formed its cell in such a step, touched: its
       short path steps need no check) and at every step of a run's first
       pass, and of every wall pass (walls have no endPass) */
    dc_gwa_table_out o;
    int st = DC_OK;
    if (dc_gwa_table_step_settled(&p, con, delta, h, &o)) {
      if (reachEveryStep) checkReach(sidata, dc_gwa_table_contact_reach(&p, con));
    } else {
      st = dc_gwa_table_step_contact_any(&p, con, delta, h, &o);
      if (st == DC_OK && h[0] != 0.0) checkReach(sidata, dc_gwa_table_contact_reach(&p, con));
    }
    return finish(sidata, st, delta, R, h, o, i_forces, j_forces);
  }

  /* The contact's history, or (a pass that must not change it) a copy in scratch. */
  double *history(SurfacesIntersectData &sidata, double *scratch)
  {
    double *h = &sidata.contact_history[history_offset];
    if (sidata.computeflag && sidata.shearupdate) return h;
    memcpy(scratch, h, DC_GWA_TABLE_HISTORY_NFIELDS * sizeof(double));
    return scratch;
  }

  /* Stops the run when attached summits could pull beyond the neighbour list. */
  void checkReach(const SurfacesIntersectData &sidata, double reach)
  {
    if (outOfReach(sidata, neighbor->contactDistanceFactor, reach))
      fail("attached summits pull up to %g m apart: set neigh_modify contact_distance_factor >= %.12g", reach,
           1.0 + reach / reachRadius(sidata));
  }

  /* After the step (status st, history h, output o): the contact flag and
     the force; false when none acts. */
  __attribute__((always_inline)) inline bool finish(SurfacesIntersectData &sidata, int st, double delta, double R,
                                                    const double *h, const dc_gwa_table_out &o, ForceData &i_forces,
                                                    ForceData &j_forces)
  {
    if (st != DC_OK) fail("overlap %g, radius %g: %s", delta, R, dc_status_str(st));
    if (sidata.contact_flags) {
      if (h[0] != 0.0) *sidata.contact_flags |= CONTACT_COHESION_MODEL;
      else *sidata.contact_flags &= ~CONTACT_COHESION_MODEL;
    }
    if (o.F == 0.0) return false;
    applyNormalForce(sidata, o.F, atom->x, i_forces, j_forces);
    return true;
  }

  /* Stops the run on this process: "Cohesion model gw_adhesion: " and the
     message (out of line: the callers are on the hot path). */
  __attribute__((noinline, format(printf, 2, 3))) void fail(const char *fmt, ...)
  {
    char what[256], msg[320];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    snprintf(msg, sizeof msg, "Cohesion model gw_adhesion: %s", what);
    error->one(FLERR, msg);
  }

  int history_offset, contact_offset, ntypes;
  bool reachEveryStep;
  double maxRadiusFactor;
#ifdef SUPERQUADRIC_ACTIVE_FLAG
  SuperquadricCurvature curvature;
  SuperquadricGap gap;
#endif
  std::vector<dc_gwa_table_pair> pairs;
};

}
}
#endif
#endif
