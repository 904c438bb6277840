/* LIGGGHTS normal model `gw_rough`: Greenwood-Williamson rough contact of
   spheres and superquadrics (c_core: dc/feng_rough.h, Feng et al. 2016
   Eq. 75; dc/gw_rough.h, review Eqs. 29-36).

   Deck: pair_style gran model gw_rough tangential history [surface superquadric] [settings]
         fix ID all wall/gran model gw_rough tangential history [surface superquadric] primitive ... [settings]
         neigh_modify contact_distance_factor F   (see below)
   Settings: those of every project normal model (dc_model_base.h), and
     roughSphereLaw table|feng   the rough-sphere law (gwElliptic off): table,
                         the law tabulated from the full GW solver
                         (dc/gw_rough_table.h, within 3e-5 of it; its force
                         begins at -6 sigma; default); feng, Feng's explicit law
     gwElliptic on|off   off: the rough-sphere law (spheres only); on:
                         GW closed form F = 4/3 n_asp E* Rc^1/2 sigma^3/2 gamma
                         F_3/2(-delta/sigma) (required for superquadrics)
     fengFitted on|off   Feng law coefficients from the fitted formulas instead
                         of the interpolated tables (default off)
     gwPlastic on|off    with gwElliptic on: elastic, elastic-plastic and fully
                         plastic summits (Jeng & Wang; dc/gw_rough_plastic.h),
                         loading curve only (unloading retraces it); property
                         hardness peratomtype [Pa] (the softer type's per pair)
                         and the settings plasticityKv (default 0: 0.454 + 0.41
                         nu), plasticityCh (1), plasticityCa (108) of jamari_ep
                         (default off)
   Properties: youngsModulus, poissonsRatio, coefficientRestitution (or
     viscoelasticTime), and
     surfaceRoughness peratomtype [m] >= 0: rms summit height sigma_i of each
       type (walls: of the wall's type); a contact has sigma = (sigma_i^2 + sigma_j^2)^1/2;
     roughnessMu peratomtypepair [-]: Feng's mu in [1, 50] (Feng law);
     asperityCount peratomtypepair [-]: n_asp > 0 (GW closed form).
   The rough force begins at overlap delta = -6 sigma with the tabulated
   sphere law and -3 sigma with the Feng law and the closed form (below,
   read 6 for 3 with the table) (the closed form's
   Gaussian tail is cut there too), before the surfaces touch, so the deck
   must set contact_distance_factor >= 1 + 3 sigma / (r_i + r_j) (walls:
   1 + 3 sigma / r_i; superquadrics: bounding radii for pairs,
   volume-equivalent radius for walls); the run stops naming the value
   needed otherwise. Damping acts on dF/d delta (none where it is negative:
   Feng's Case III quartic is not monotonic for every mu); tangential
   stiffness 8 G* (R_area delta)^1/2 once delta > 0. Contact patch: the
   smooth contact's ellipse at max(delta, 0), formed while the rough force
   acts. sigma = 0 gives exactly `hertz_elliptic`. */
#ifdef NORMAL_MODEL
NORMAL_MODEL(GW_ROUGH,gw_rough,@DC_MODEL_ID@)
#else
#ifndef NORMAL_MODEL_GW_ROUGH_H_
#define NORMAL_MODEL_GW_ROUGH_H_

#include <vector>
#include "contact_slot.h"
#include "dc_model_base.h"
#include "dc_properties.h"
#include "superquadric_gap.h"
#include "dc/feng_rough.h"
#include "dc/gw_rough.h"
#include "dc/gw_rough_plastic.h"
#include "dc/gw_rough_table.h"
#include "dc/mindlin.h"
#include "dc/rough_tangential.h"

namespace LIGGGHTS {
namespace ContactModels {

template<>
class NormalModel<GW_ROUGH> : public DcNormalModel
{
public:
  NormalModel(LAMMPS *lmp, IContactHistorySetup *hsetup, class ContactModelBase *c) :
    DcNormalModel(lmp, hsetup, c, "gw_rough"),
    roughness(NULL), mu(NULL), n_asp(NULL), gwElliptic(false), fengFitted(false), gwPlastic(false),
    sphereLaw(DC_GW_SPHERE_TABULATED), ntypes(0), offeredTo(0), roughOfferedTo(0)
  {
    memset(&rough, 0, sizeof rough);
#ifdef SUPERQUADRIC_ACTIVE_FLAG
    gap.addHistory(lmp, hsetup);
#endif
  }

  ~NormalModel()
  {
    if (offeredTo) ContactSlots::withdraw(offeredTo, "gw_rough_elliptic");
    if (roughOfferedTo) ContactSlots::withdraw(roughOfferedTo, "dc_rough_patch");
  }

  void registerSettings(Settings &settings)
  {
    DcNormalModel::registerSettings(settings);
    settings.registerOnOff("gwElliptic", gwElliptic, false);
    settings.registerOnOff("fengFitted", fengFitted, false);
    settings.registerOnOff("gwPlastic", gwPlastic, false);
    static const char *const names[] = {"feng", "table"};
    static const int values[] = {DC_GW_SPHERE_FENG, DC_GW_SPHERE_TABULATED};
    settings.registerChoice("roughSphereLaw", sphereLaw, names, values, 2, "table");
    plasticity.registerSettings(settings, 1.0, 108.0);
  }

  void postSettings(IContactHistorySetup *hsetup, ContactModelBase *c)
  {
    if (atom->superquadric_flag && !gwElliptic)
      stop(true, "superquadric particles need the elliptic closed form: add 'gwElliptic on' (the Feng law is for spheres)");
    if (gwPlastic && !gwElliptic)
      stop(true, "'gwPlastic on' needs 'gwElliptic on' (plastic summits are in the GW closed form with asperityCount)");
    DcNormalModel::postSettings(hsetup, c);
#ifdef SUPERQUADRIC_ACTIVE_FLAG
    gap.setup(lmp, c);
#endif
    /* for cmd_tangential with tangentialRoughness on */
    ContactSlots::offer(c, "dc_rough_patch", &rough);
    roughOfferedTo = c;
    /* for cohesion gw_adhesion, which adds to the elliptic closed form */
    if (gwElliptic) {
      ContactSlots::offer(c, "gw_rough_elliptic", this);
      offeredTo = c;
    }
  }

  void connectToProperties(PropertyRegistry &registry)
  {
    DcNormalModel::connectToProperties(registry);
    const char *caller = "model gw_rough";
    registry.registerProperty("surfaceRoughness", &createRoughness, caller);
    registry.connect("surfaceRoughness", roughness, caller);
    ntypes = registry.max_type();
    dc_param_error err;
    if (gwElliptic) {
      sphereGeom.assign((ntypes + 1) * (ntypes + 1), dc_hertz_geom());
      sphereBound.assign((ntypes + 1) * (ntypes + 1), dc_gw_bound());
      registry.registerProperty("asperityCount", &dcCreateAsperityCount, caller);
      registry.connect("asperityCount", n_asp, caller);
      for (int i = 1; i <= ntypes; i++)
        for (int j = 1; j <= ntypes; j++)
          if (dc_gw_rough_check(n_asp[i][j], &err))
            stopParam(err, i, j);
          else if (!gwPlastic && roughness[i][j] != 0.0 &&
                   dc_gw_bound_material(Yeff[i][j], n_asp[i][j], roughness[i][j], &sphereBound[i * (ntypes + 1) + j]) != DC_OK)
            sphereBound[i * (ntypes + 1) + j].sigma = 0.0;   /* 1/sigma or n_asp E* leaves the normal doubles: the checked form */
      if (gwPlastic)
        plasticParams(registry, caller, plasticity, &dc_gw_plastic_default_params, &dc_gw_plastic_check, plastic);
      return;
    }
    registry.registerProperty("roughnessMu", &createMu, caller);
    registry.connect("roughnessMu", mu, caller);
    laws.assign((ntypes + 1) * (ntypes + 1), dc_gw_sphere_pair());
    for (int i = 1; i <= ntypes; i++)
      for (int j = 1; j <= ntypes; j++) {
        if (dc_feng_check(mu[i][j], &err))   /* the table's domain of mu is the same */
          stopParam(err, i, j);
        /* sigma = 0 pairs take the Hertz branch and never read theirs */
        if (roughness[i][j] > 0.0 &&
            dc_gw_sphere_pair_init(sphereLaw, fengFitted ? DC_FENG_FITTED : DC_FENG_TABLE, mu[i][j], Yeff[i][j],
                                   roughness[i][j], &laws[i * (ntypes + 1) + j])) {
          char msg[256];
          snprintf(msg, sizeof msg, "surfaceRoughness %g with youngsModulus (E* = %g) for types %d and %d is out of "
                   "the range of doubles", roughness[i][j], Yeff[i][j], i, j);
          stop(true, msg);
        }
      }
  }

  inline void surfacesIntersect(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)
  {
    if (sidata.contact_flags) *sidata.contact_flags |= CONTACT_NORMAL_MODEL;
    roughForce(sidata, sidata.deltan, sidata.vn, i_forces, j_forces);
  }

  /* Rough contact before the surfaces touch: -reach sigma < delta < 0. */
  void surfacesClose(SurfacesCloseData &scdata, ForceData &i_forces, ForceData &j_forces)
  {
    if (scdata.contact_flags) *scdata.contact_flags |= CONTACT_NORMAL_MODEL;
    const double sigma = roughness[scdata.itype][scdata.jtype];
    if (sigma == 0.0) return apart(scdata);
    SurfacesIntersectData &sidata = static_cast<SurfacesIntersectData &>(scdata);
    double delta, vn;
#ifdef SUPERQUADRIC_ACTIVE_FLAG
    if (atom->superquadric_flag) {
      if (!gap.closeOverlap(lmp, sidata, reachSigma() * sigma, delta, vn)) return apart(scdata);
    } else
#endif
    {
      /* most pairs inside the contact distance are farther apart than the reach */
      const double reach = sidata.radsum + reachSigma() * sigma;
      if (!sidata.is_wall && sidata.rsq >= reach * reach) return apart(scdata);
      delta = closeSphereContact(scdata, vn);
    }
    if (delta <= -reachSigma() * sigma) return apart(scdata);
    sidata.has_force_update = true;
    roughForce(sidata, delta, vn, i_forces, j_forces);
  }

private:
  /* No rough force: no patch, smooth or rough. */
  void apart(SurfacesCloseData &scdata)
  {
    publishNone(scdata);
    if (rough.wanted) memset(&rough.patch, 0, sizeof rough.patch);
  }

  /* The summits' patch (rough.wanted): the smooth patch just published with
     the summits' semi-axes (dc/rough_tangential.h; n_asp 1 for the
     rough-sphere laws, which have no asperityCount) and the major axis
     also before touch; sigma = 0: the smooth patch itself. */
  void publishRough(const dc_hertz_geom &g, double sigma, double delta, int itype, int jtype, const double *ax)
  {
    rough.patch = patchPublished();
    if (sigma == 0.0) return;
    double a, b;
    const int st = dc_rough_tangential_axes(&g, gwElliptic ? n_asp[itype][jtype] : 1.0, sigma, delta, &a, &b);
    if (st != DC_OK) {
      char msg[256];
      snprintf(msg, sizeof msg, "the summits' patch at overlap %g, roughness %g: %s", delta, sigma, dc_status_str(st));
      stop(false, msg);
    }
    rough.patch.a = a;
    rough.patch.b = b;
    for (int k = 0; k < 3; k++) rough.patch.axis[k] = a > b && ax ? ax[k] : 0.0;
  }

  /* The force's reach before touch in units of sigma: 3 (Feng, the
     closed form) or 6 (the tabulated sphere law). */
  double reachSigma() const { return gwElliptic ? 3.0 : -dc_gw_sphere_reach(sphereLaw); }

  /* Normal force at overlap delta (any sign > -reach sigma) and normal velocity vn. */
  void roughForce(SurfacesIntersectData &sidata, double delta, double vn,
                  ForceData &i_forces, ForceData &j_forces)
  {
    const int itype = sidata.itype, jtype = sidata.jtype;
    double reff = sphereEffectiveRadius(sidata);
    const double sigma = roughness[itype][jtype];
    const double Y = Yeff[itype][jtype];
    checkReach(sidata, reachSigma() * sigma, "rough contacts begin at delta = -%g m before touch", reachSigma() * sigma);
    /* the smooth contact's geometry; spheres: circular with Rc = reff */
    double axis[3];
    double *ax = axisWanted(axis);
    const bool sq = superquadric(sidata);
    dc_hertz_geom g;
    const dc_hertz_geom *gp = &g;   /* the geometry in use: g, or the pair's kept circle */
    g.R_force = g.R_area = reff;
    if (sq) {
      superquadricGeometry(sidata, g, ax);
      reff = g.Rc;
    } else if (gwElliptic && sigma != 0.0) {
      /* the circle's geometry and the closed form bound to it, kept per
         type pair while reff repeats */
      const int k = itype * (ntypes + 1) + jtype;
      dc_hertz_geom &c = sphereGeom[k];
      if (c.R_major != reff) {
        dc_hertz_geometry_circle(reff, &c);
        /* products that leave the doubles make dc_gw_bound_force take the checked form */
        if (sphereBound[k].sigma != 0.0) dc_gw_bound_bind(&sphereBound[k], &c);
      }
      gp = &c;
    }
    if (delta > 0.0)   /* the smooth bodies' Hertz semi-axis: a^2 = 2 R_major delta D / K, spheres R delta */
      checkHertzRange(sidata, sq ? 2.0 * gp->R_major * delta * gp->D / gp->K : reff * delta, sq ? gp->R_minor : reff);
    double P, Sn, kn, kt = 0.0;
    if (sigma == 0.0) {
      const double root = dc_hertz_stiffness(Y, gp->R_force, delta, &kn, &Sn);
      kt = dc_mindlin_kt_circle(Geff[itype][jtype], gp->R_area == gp->R_force ? root : sqrt(gp->R_area * delta));
      P = kn * delta;
    } else {
      if (gwElliptic) {
        const dc_gw_bound *bound = sq || gwPlastic ? NULL : &sphereBound[itype * (ntypes + 1) + jtype];
        int st;
        if (bound && bound->sigma != 0.0) {
          st = dc_gw_bound_force(bound, delta, &P, &Sn);
        } else {
          dc_gw_rough_state s;
          st = gwPlastic ? dc_gw_rough_plastic(gp, Y, &plastic[itype * (ntypes + 1) + jtype],
                                               n_asp[itype][jtype], sigma, delta, &s)
                         : dc_gw_rough_elliptic(gp, Y, n_asp[itype][jtype], sigma, delta, &s);
          if (st == DC_OK) { P = s.F; Sn = s.kn; }
        }
        if (st != DC_OK) {
          char msg[256];
          snprintf(msg, sizeof msg, "overlap %g, roughness %g, radius %g: %s", delta, sigma, reff, dc_status_str(st));
          stop(false, msg);
        }
      } else {
        dc_gw_sphere_pair_force(&laws[itype * (ntypes + 1) + jtype], sqrt(reff), delta, &P, &Sn);
      }
      kn = delta > 0.0 ? P / delta : 0.0;
      if (delta > 0.0) kt = dc_mindlin_kt_circle(Geff[itype][jtype], sqrt(gp->R_area * delta));
    }
    applyForce(sidata, P, delta, vn, Sn, kn, kt, i_forces, j_forces);
    if (ax) {
      if (!sq && !(gwElliptic && sigma != 0.0)) hertzGeometry(reff, reff, g);  /* spheres: only R_force, R_area were set */
      dc_contact c;
      dc_gw_rough_normal(gp, Y, delta, P, Sn, &c);
      publish(sidata, c, ax);
      if (rough.wanted) publishRough(*gp, sigma, delta, itype, jtype, ax);
    }
  }

  static MatrixProperty *createRoughness(PropertyRegistry &registry, const char *caller, bool)
  {
    const int n = registry.max_type();
    registry.registerProperty("surfaceRoughnessType", &dcCreateRoughnessType);
    VectorProperty *v = registry.getVectorProperty("surfaceRoughnessType", caller);
    MatrixProperty *m = new MatrixProperty(n + 1, n + 1);
    for (int i = 1; i <= n; i++)
      for (int j = 1; j <= n; j++) m->data[i][j] = dc_gw_roughness_combine(v->data[i], v->data[j]);
    return m;
  }
  static MatrixProperty *createMu(PropertyRegistry &registry, const char *caller, bool sanity_checks)
  {
    return MODEL_PARAMS::createPerTypePairProperty(registry, "roughnessMu", caller, sanity_checks);
  }

  double **roughness, **mu, **n_asp;
  bool gwElliptic, fengFitted, gwPlastic;
  const ContactModelBase *offeredTo;   /* the contact model offered "gw_rough_elliptic" */
  const ContactModelBase *roughOfferedTo;   /* ... and "dc_rough_patch" */
  RoughPatchSlot rough;
  Plasticity plasticity;
  int ntypes;
  int sphereLaw;   /* DC_GW_SPHERE_* */
  std::vector<dc_gw_sphere_pair> laws;
  std::vector<dc_hertz_geom> sphereGeom;   /* gwElliptic on, spheres: per type pair */
  std::vector<dc_gw_bound> sphereBound;    /* the closed form bound to sphereGeom (sigma = 0: not bound) */
  std::vector<dc_gw_plastic_params> plastic;
#ifdef SUPERQUADRIC_ACTIVE_FLAG
  SuperquadricGap gap;
#endif
};

}
}
#endif
#endif
