/* LIGGGHTS normal model `gw_rough`: Greenwood-Williamson rough contact of
   spheres (c_core: dc/feng_rough.h, Feng et al. 2016 Eq. 75; dc/gw_rough.h,
   review Eqs. 29-36).

   Deck: pair_style gran model gw_rough tangential history [settings]
         fix ID all wall/gran model gw_rough tangential history primitive ... [settings]
         neigh_modify contact_distance_factor F   (see below)
   Settings:
     gwElliptic on|off   off: Feng explicit law (default); on: GW closed form
                         F = 4/3 n_asp E* Rc^1/2 sigma^3/2 gamma F_3/2(-delta/sigma)
     fengFitted on|off   Feng law coefficients from the fitted formulas instead
                         of the interpolated tables (default off)
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
   contact_distance_factor >= 1 + 3 sigma / (r_i + r_j) (walls: 1 + 3 sigma / r_i)
   for every rough pair; the model stops the run, naming the value needed,
   when a rough contact is computed with a smaller factor. Damping: LIGGGHTS'
   restitution damping on the law's tangent stiffness dF/d(delta); the
   tangential stiffness is Mindlin's 8 G (R delta)^1/2 once delta > 0.
   sigma = 0 gives exactly `hertz_elliptic` (the same arithmetic). */
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
    ntypes(0)
  {}

  void registerSettings(Settings &settings)
  {
    settings.registerOnOff("tangential_damping", tangential_damping, true);
    settings.registerOnOff("limitForce", limitForce);
    settings.registerOnOff("gwElliptic", gwElliptic, false);
    settings.registerOnOff("fengFitted", fengFitted, false);
  }

  void postSettings(IContactHistorySetup *, ContactModelBase *)
  {
    if (atom->superquadric_flag)
      error->all(FLERR, "Normal model gw_rough: superquadric particles are not supported yet (spheres only)");
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
    laws.assign((ntypes + 1) * (ntypes + 1), dc_feng_law());
    for (int i = 1; i <= ntypes; i++)
      for (int j = 1; j <= ntypes; j++)
        if (dc_feng_init(mu[i][j], fengFitted ? DC_FENG_FITTED : DC_FENG_TABLE, &laws[i * (ntypes + 1) + j]) != DC_OK) {
          char msg[256];
          snprintf(msg, sizeof msg, "Normal model gw_rough: roughnessMu = %g for types %d and %d is outside [%g, %g]",
                   mu[i][j], i, j, DC_FENG_MU_MIN, DC_FENG_MU_MAX);
          error->all(FLERR, msg);
        }
  }

  inline double stressStrainExponent() { return 1.5; }

  inline void surfacesIntersect(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)
  {
    if (sidata.contact_flags) *sidata.contact_flags |= CONTACT_NORMAL_MODEL;
    roughForce(sidata, sidata.deltan, sidata.vn, i_forces, j_forces);
  }

  /* Rough contact before the spheres touch: -3 sigma < delta < 0. */
  void surfacesClose(SurfacesCloseData &scdata, ForceData &i_forces, ForceData &j_forces)
  {
    if (scdata.contact_flags) *scdata.contact_flags |= CONTACT_NORMAL_MODEL;
    const double sigma = roughness[scdata.itype][scdata.jtype];
    if (sigma == 0.0) return;
    double vn;
    const double delta = closeSphereContact(scdata, vn);
    if (delta <= -3.0 * sigma) return;
    SurfacesIntersectData &sidata = static_cast<SurfacesIntersectData &>(scdata);
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
    const double reff = sphereEffectiveRadius(sidata);
    const double sigma = roughness[itype][jtype];
    const double Y = Yeff[itype][jtype];
    const double reach = sidata.is_wall ? sidata.radi : sidata.radsum;
    if (neighbor->contactDistanceFactor < 1.0 + 3.0 * sigma / reach) {
      char msg[256];
      snprintf(msg, sizeof msg, "Normal model gw_rough: rough contacts begin 3 sigma = %g before touch: "
               "set neigh_modify contact_distance_factor >= %.6g", 3.0 * sigma, 1.0 + 3.0 * sigma / reach);
      error->one(FLERR, msg);
    }
    double P, Sn, kn, kt = 0.0;
    if (sigma == 0.0) {
      hertzStiffness(Y, Geff[itype][jtype], reff, reff, delta, kn, Sn, kt);
      P = kn * delta;
    } else {
      int st;
      if (gwElliptic) {
        dc_hertz_geom g;
        dc_hertz_geometry(reff, reff, &g);
        dc_gw_rough_state s;
        st = dc_gw_rough_elliptic(&g, Y, n_asp[itype][jtype], sigma, delta, &s);
        P = s.F;
        Sn = s.kn;
      } else {
        st = dc_feng_force(&laws[itype * (ntypes + 1) + jtype], Y, reff, sigma, delta, &P, &Sn);
      }
      if (st != DC_OK) {
        char msg[256];
        snprintf(msg, sizeof msg, "Normal model gw_rough: overlap %g, roughness %g, radius %g: %s", delta, sigma, reff, dc_status_str(st));
        error->one(FLERR, msg);
      }
      kn = delta > 0.0 ? P / delta : 0.0;
      if (delta > 0.0) kt = 8. * Geff[itype][jtype] * sqrt(reff * delta);
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
  int ntypes;
  std::vector<dc_feng_law> laws;
};

}
}
#endif
#endif
