/* LIGGGHTS normal model `gw_rough`: Greenwood-Williamson rough contact of
   spheres and superquadrics (c_core: dc/feng_rough.h, Feng et al. 2016
   Eq. 75; dc/gw_rough.h, review Eqs. 29-36).

   Deck: pair_style gran model gw_rough tangential history [surface superquadric] [settings]
         fix ID all wall/gran model gw_rough tangential history [surface superquadric] primitive ... [settings]
         neigh_modify contact_distance_factor F   (see below)
   Settings:
     gwElliptic on|off   off: Feng explicit law (default, spheres only); on:
                         GW closed form F = 4/3 n_asp E* Rc^1/2 sigma^3/2 gamma
                         F_3/2(-delta/sigma) (required for superquadrics)
     fengFitted on|off   Feng law coefficients from the fitted formulas instead
                         of the interpolated tables (default off)
     maxRadiusFactor R   superquadrics: cap on the relative principal radii,
                         as in hertz_elliptic (default 100)
     tangential_damping on|off, limitForce on|off   as in stock hertz
   Properties: youngsModulus, poissonsRatio, coefficientRestitution,
     surfaceRoughness peratomtype [m]: rms summit height sigma_i of each type
       (walls: of the wall's type); a contact has sigma = sqrt(sigma_i^2 + sigma_j^2);
     roughnessMu peratomtypepair [-]: Feng's mu in [1, 50] (Feng law);
     asperityCount peratomtypepair [-]: n_asp > 0 (GW closed form).
   The rough force begins at overlap delta = -3 sigma (Feng law; the closed
   form decays like a Gaussian tail and is cut there too), i.e. before the
   spheres touch: LIGGGHTS calls surfacesClose for pairs within
   contact_distance_factor * (r_i + r_j), so the deck must set
   contact_distance_factor >= 1 + 3 sigma / (r_i + r_j) (walls: 1 + 3 sigma / r_i;
   superquadrics: bounding radii for pairs, volume-equivalent radius for
   walls) for every rough pair; the model stops the run, naming the value needed,
   when a rough contact is computed with a smaller factor. Damping: LIGGGHTS'
   restitution damping on the law's tangent stiffness dF/d(delta); the
   tangential stiffness is Mindlin's 8 G (R delta)^1/2 once delta > 0.
   Superquadrics: relative principal radii from both surfaces' curvatures
   (superquadric_curvature.h) and, before touch, the gap measured by
   superquadric_gap.h. sigma = 0 gives exactly `hertz_elliptic` (the same
   arithmetic). */
#ifdef NORMAL_MODEL
NORMAL_MODEL(GW_ROUGH,gw_rough,31)
#else
#ifndef NORMAL_MODEL_GW_ROUGH_H_
#define NORMAL_MODEL_GW_ROUGH_H_

#include <cmath>
#include <cstdio>
#include <vector>
#include "contact_models.h"
#include "global_properties.h"
#include "neighbor.h"
#include "normal_model_base.h"
#include "normal_force_common.h"
#include "superquadric_curvature.h"
#include "superquadric_gap.h"
#include "dc/feng_rough.h"
#include "dc/gw_rough.h"
#include "dc/hertz_elliptic.h"
#include "dc/status.h"

namespace LIGGGHTS {
namespace ContactModels {

template<>
class NormalModel<GW_ROUGH> : public NormalModelBase
{
public:
  NormalModel(LAMMPS *lmp, IContactHistorySetup *hsetup, class ContactModelBase *c) :
    NormalModelBase(lmp, hsetup, c),
    Yeff(NULL), Geff(NULL), betaeff(NULL), roughness(NULL), mu(NULL), n_asp(NULL),
    tangential_damping(true), limitForce(false), gwElliptic(false), fengFitted(false),
    maxRadiusFactor(100.0), ntypes(0)
  {
#ifdef SUPERQUADRIC_ACTIVE_FLAG
    gap.addHistory(lmp, hsetup);
#endif
  }

  void registerSettings(Settings &settings)
  {
    settings.registerOnOff("tangential_damping", tangential_damping, true);
    settings.registerOnOff("limitForce", limitForce);
    settings.registerOnOff("gwElliptic", gwElliptic, false);
    settings.registerOnOff("fengFitted", fengFitted, false);
    settings.registerDoubleSetting("maxRadiusFactor", maxRadiusFactor, 100.0);
  }

  void postSettings(IContactHistorySetup *, ContactModelBase *c)
  {
    if (atom->superquadric_flag && !gwElliptic)
      error->all(FLERR, "Normal model gw_rough: superquadric particles need the elliptic closed form: "
                 "add 'gwElliptic on' (the Feng law is for spheres)");
#ifdef SUPERQUADRIC_ACTIVE_FLAG
    curvature.setup(lmp, c, maxRadiusFactor, "gw_rough");
    gap.setup(lmp, c);
#else
    (void)c;
#endif
  }

  void connectToProperties(PropertyRegistry &registry)
  {
    const char *caller = "model gw_rough";
    connectElasticProperties(registry, caller, Yeff, Geff, betaeff);
    registry.registerProperty("surfaceRoughness", &createRoughness, caller);
    registry.connect("surfaceRoughness", roughness, caller);
    ntypes = registry.max_type();
    if (gwElliptic) {
      registry.registerProperty("asperityCount", &createAsperityCount, caller);
      registry.connect("asperityCount", n_asp, caller);
      return;
    }
    registry.registerProperty("roughnessMu", &createMu, caller);
    registry.connect("roughnessMu", mu, caller);
    laws.assign((ntypes + 1) * (ntypes + 1), dc_feng_pair());
    for (int i = 1; i <= ntypes; i++)
      for (int j = 1; j <= ntypes; j++) {
        dc_feng_law law;
        if (dc_feng_init(mu[i][j], fengFitted ? DC_FENG_FITTED : DC_FENG_TABLE, &law) != DC_OK) {
          char msg[256];
          snprintf(msg, sizeof msg, "Normal model gw_rough: roughnessMu = %g for types %d and %d is outside [%g, %g]",
                   mu[i][j], i, j, DC_FENG_MU_MIN, DC_FENG_MU_MAX);
          error->all(FLERR, msg);
        }
        /* sigma = 0 pairs take the Hertz branch and never read theirs */
        if (roughness[i][j] > 0.0) dc_feng_pair_init(&law, Yeff[i][j], roughness[i][j], &laws[i * (ntypes + 1) + j]);
      }
  }

  inline double stressStrainExponent() { return 1.5; }

  inline void surfacesIntersect(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)
  {
    if (sidata.contact_flags) *sidata.contact_flags |= CONTACT_NORMAL_MODEL;
    roughForce(sidata, sidata.deltan, sidata.vn, i_forces, j_forces);
  }

  /* Rough contact before the surfaces touch: -3 sigma < delta < 0. */
  void surfacesClose(SurfacesCloseData &scdata, ForceData &i_forces, ForceData &j_forces)
  {
    if (scdata.contact_flags) *scdata.contact_flags |= CONTACT_NORMAL_MODEL;
    const double sigma = roughness[scdata.itype][scdata.jtype];
    if (sigma == 0.0) return;
    SurfacesIntersectData &sidata = static_cast<SurfacesIntersectData &>(scdata);
    double delta, vn;
#ifdef SUPERQUADRIC_ACTIVE_FLAG
    if (atom->superquadric_flag) {
      if (!gap.closeOverlap(lmp, sidata, 3.0 * sigma, delta, vn)) return;
    } else
#endif
    {
      /* most pairs inside the contact distance are farther apart than 3 sigma */
      const double reach = sidata.radsum + 3.0 * sigma;
      if (!sidata.is_wall && sidata.rsq >= reach * reach) return;
      delta = closeSphereContact(scdata, vn);
    }
    if (delta <= -3.0 * sigma) return;
    sidata.has_force_update = true;
    roughForce(sidata, delta, vn, i_forces, j_forces);
  }

  void beginPass(SurfacesIntersectData &, ForceData &, ForceData &) {}
  void endPass(SurfacesIntersectData &, ForceData &, ForceData &) {}

private:
  /* Normal force at overlap delta (any sign > -3 sigma) and normal velocity vn. */
  void roughForce(SurfacesIntersectData &sidata, double delta, double vn,
                  ForceData &i_forces, ForceData &j_forces)
  {
    const int itype = sidata.itype, jtype = sidata.jtype;
    double reff = sphereEffectiveRadius(sidata);
    const double sigma = roughness[itype][jtype];
    const double Y = Yeff[itype][jtype];
    const double reach = sidata.is_wall ? sidata.radi : sidata.radsum;
    if (neighbor->contactDistanceFactor * reach < reach + 3.0 * sigma) {
      char msg[256];
      snprintf(msg, sizeof msg, "Normal model gw_rough: rough contacts begin 3 sigma = %g before touch: "
               "set neigh_modify contact_distance_factor >= %.12g", 3.0 * sigma, 1.0 + 3.0 * sigma / reach);
      error->one(FLERR, msg);
    }
    /* the smooth contact's geometry; spheres: circular with Rc = reff */
    dc_hertz_geom g;
    g.R_force = g.R_area = reff;
#ifdef SUPERQUADRIC_ACTIVE_FLAG
    if (sidata.is_non_spherical && atom->superquadric_flag) {
      double R_major, R_minor;
      curvature.relativeRadii(lmp, sidata, R_major, R_minor, "gw_rough");
      hertzGeometry(error, "gw_rough", R_major, R_minor, g);
      reff = g.Rc;
    } else
#endif
    if (gwElliptic && sigma != 0.0) hertzGeometry(error, "gw_rough", reff, reff, g);
    double P, Sn, kn, kt = 0.0;
    if (sigma == 0.0) {
      hertzStiffness(Y, Geff[itype][jtype], g.R_force, g.R_area, delta, kn, Sn, kt);
      P = kn * delta;
    } else {
      if (gwElliptic) {
        dc_gw_rough_state s;
        const int st = dc_gw_rough_elliptic(&g, Y, n_asp[itype][jtype], sigma, delta, &s);
        if (st != DC_OK) {
          char msg[256];
          snprintf(msg, sizeof msg, "Normal model gw_rough: overlap %g, roughness %g, radius %g: %s", delta, sigma, reff, dc_status_str(st));
          error->one(FLERR, msg);
        }
        P = s.F;
        Sn = s.kn;
      } else {
        dc_feng_pair_force(&laws[itype * (ntypes + 1) + jtype], sqrt(reff), delta, &P, &Sn);
      }
      kn = delta > 0.0 ? P / delta : 0.0;
      if (delta > 0.0) kt = 8. * Geff[itype][jtype] * sqrt(g.R_area * delta);
    }
    /* damping needs Sn > 0: the Feng quartic of Case III is not monotonic
       for every mu (dP/d delta < 0 near alpha' = -2.5 at mu = 4) */
    dampedNormalForce(sidata, P, vn, Sn, kn, kt, betaeff[itype][jtype], tangential_damping,
                      limitForce, force->nktv2p, atom->x, i_forces, j_forces);
  }

  static MatrixProperty *createRoughness(PropertyRegistry &registry, const char *caller, bool sanity_checks)
  {
    /* combined roughness of a pair: sqrt(sigma_i^2 + sigma_j^2) */
    const int n = registry.max_type();
    registry.registerProperty("surfaceRoughnessType", &createRoughnessType);
    VectorProperty *v = registry.getVectorProperty("surfaceRoughnessType", caller);
    MatrixProperty *m = new MatrixProperty(n + 1, n + 1);
    for (int i = 1; i <= n; i++)
      for (int j = 1; j <= n; j++)
        m->data[i][j] = sqrt(v->data[i] * v->data[i] + v->data[j] * v->data[j]);
    (void)sanity_checks;
    return m;
  }
  static VectorProperty *createRoughnessType(PropertyRegistry &registry, const char *caller, bool sanity_checks)
  {
    return MODEL_PARAMS::createPerTypeProperty(registry, "surfaceRoughness", caller, sanity_checks, 0.0);
  }
  static MatrixProperty *createMu(PropertyRegistry &registry, const char *caller, bool sanity_checks)
  {
    return MODEL_PARAMS::createPerTypePairProperty(registry, "roughnessMu", caller, sanity_checks);
  }
  static MatrixProperty *createAsperityCount(PropertyRegistry &registry, const char *caller, bool sanity_checks)
  {
    return MODEL_PARAMS::createPerTypePairProperty(registry, "asperityCount", caller, sanity_checks, 1e-300);
  }

  double **Yeff, **Geff, **betaeff, **roughness, **mu, **n_asp;
  bool tangential_damping, limitForce, gwElliptic, fengFitted;
  double maxRadiusFactor;
  int ntypes;
  std::vector<dc_feng_pair> laws;
#ifdef SUPERQUADRIC_ACTIVE_FLAG
  SuperquadricCurvature curvature;
  SuperquadricGap gap;
#endif
};

}
}
#endif
#endif
