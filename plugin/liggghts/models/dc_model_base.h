/* What the project's normal-model wrappers share: the elastic and damping
   properties, the settings every model takes (same names, same defaults),
   the superquadric curvature, one contact-distance check, the damped force
   and the contact patch. A wrapper derives from DcNormalModel and only
   translates between LIGGGHTS data and its c_core law.

   Settings (after the model keywords in pair_style gran; at the end of a
   fix wall/gran line):
     tangential_damping on|off   damping on the tangential spring (default on)
     limitForce on|off           clip the total normal force at zero (default off;
                                 models with an adhesive force stop the run if on)
     damping LAW                 normal damping force -gamma d(delta)/dt (c_core
                                 dc/damping.h), LAW one of
                                   restitution (default): LIGGGHTS' damping for
                                     coefficientRestitution on dF/d delta
                                   viscoelastic: gamma = A dF/d delta (BSHP),
                                     property viscoelasticTime A [s]
                                   kuwabaraKono: gamma = eta delta^1/2, property
                                     kuwabaraKonoDamping eta [N s m^-3/2]
                                   tsuji: gamma = alpha (2/3 m dF/d delta)^1/2,
                                     alpha from coefficientRestitution (the
                                     lecture notes' fit, Norouzi et al.)
                                   none
                                 tangential_damping applies the same law with
                                 the tangential stiffness in place of dF/d delta
     viscoelastic on|off         the same as damping viscoelastic
     maxRadiusFactor X           superquadrics: cap on each relative principal
                                 radius, X times the volume-equivalent effective
                                 radius, X in (1, 1e12] (default 100)
     curvatureTolerance T        superquadrics: reuse a contact's relative radii
                                 and Hertz geometry across steps while the bodies'
                                 contact points and relative orientation stay put
                                 (superquadric_curvature.h has the rule); T in
                                 [0, 0.1], the aimed relative change of the radii
                                 (default 0: recomputed every step, exact; pays
                                 off in lasting contacts: settled beds, slow flow)
     curvatureCheck X            superquadrics, to test the reuse: the geometry is
                                 also recomputed every step; stops the run when a
                                 reused R_force, R_area, R_major or R_minor is off
                                 by more than X relative, X in [0, 1] (default 0:
                                 no check); prints the count and the largest
                                 deviation at exit
     contactPatch on|off         store the contact patch in history values, for
                                 compute pair/gran/local ... history (default off;
                                 a sub-model that reads the patch gets it in
                                 memory either way) */
#ifndef DC_PLUGIN_DC_MODEL_BASE_H
#define DC_PLUGIN_DC_MODEL_BASE_H

#include <cfloat>
#include <cstring>
#include <cstdio>
#include <string>
#include <vector>
#include "atom.h"
#include "contact_frame.h"
#include "contact_models.h"
#include "contact_patch.h"
#include "warn_once.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "global_properties.h"
#include "neighbor.h"
#include "normal_model_base.h"
#include "property_registry.h"
#include "superquadric_curvature.h"
#include "dc/contract.h"
#include "dc/curvature.h"
#include "dc/damping.h"
#include "dc/hertz_elliptic.h"
#include "dc/status.h"

namespace LIGGGHTS {
namespace ContactModels {

class DcNormalModel : public NormalModelBase {
public:
  enum { NO_LIMIT_FORCE = 1, NO_CURVATURE_REUSE = 2 };  /* settings a model does not take */

  DcNormalModel(LAMMPS *lmp, IContactHistorySetup *hsetup, ContactModelBase *c, const char *name,
                int unsupported = 0) :
    NormalModelBase(lmp, hsetup, c),
    Yeff(NULL), Geff(NULL), tangential_damping(true), limitForce(false), viscoelastic(false), contactPatch(false),
    dampingSetting(DC_DAMPING_RESTITUTION), dampingLaw(DC_DAMPING_RESTITUTION), invNktv2p(1.0 / force->nktv2p), ntypes_(0), maxRadiusFactor(100.0), curvatureTolerance(0.0),
    curvatureCheck(0.0), name_(name), unsupported_(unsupported), rank_(0), checkMax_(0.0), checked_(0), refreshed_(0),
    over_()
  {}

  void registerSettings(Settings &settings)
  {
    settings.registerOnOff("tangential_damping", tangential_damping, true);
    settings.registerOnOff("limitForce", limitForce, false);
    settings.registerOnOff("viscoelastic", viscoelastic, false);
    static const char *const names[] = {"restitution", "viscoelastic", "kuwabaraKono", "tsuji", "none"};
    static const int laws[] = {DC_DAMPING_RESTITUTION, DC_DAMPING_VISCOELASTIC, DC_DAMPING_KUWABARA_KONO,
                               DC_DAMPING_TSUJI, DC_DAMPING_NONE};
    settings.registerChoice("damping", dampingSetting, names, laws, 5, "restitution");
    settings.registerOnOff("contactPatch", contactPatch, false);
    settings.registerDoubleSetting("maxRadiusFactor", maxRadiusFactor, 100.0);
    settings.registerDoubleSetting("curvatureTolerance", curvatureTolerance, 0.0);
    settings.registerDoubleSetting("curvatureCheck", curvatureCheck, 0.0);
  }

  ~DcNormalModel()
  {
#ifdef SUPERQUADRIC_ACTIVE_FLAG
    if (curvatureCheck > 0.0 && curvature.caching() && screen)
      fprintf(screen, "Normal model %s: curvature reused %ld times, computed %ld times; largest relative deviation "
              "%.3e, above curvatureTolerance on %ld, above 10 times it on %ld (rank %d)\n", name_, checked_, refreshed_,
              checkMax_, over_[0], over_[1], rank_);
#endif
  }

  void postSettings(IContactHistorySetup *hsetup, ContactModelBase *c)
  {
    if ((unsupported_ & NO_LIMIT_FORCE) && limitForce)
      stop(true, "'limitForce on' is not available: the model's normal force is tensile by design");
    if (!(curvatureTolerance >= 0.0 && curvatureTolerance <= 0.1)) stop(true, "curvatureTolerance must be in [0, 0.1]");
    if ((unsupported_ & NO_CURVATURE_REUSE) && curvatureTolerance > 0.0)
      stop(true, "curvatureTolerance is not available: the model recomputes its geometry every step");
    if (!(curvatureCheck >= 0.0 && curvatureCheck <= 1.0)) stop(true, "curvatureCheck must be in [0, 1]");
    rank_ = comm->me;   /* for the destructor: LIGGGHTS deletes comm before the pair style */
#ifdef SUPERQUADRIC_ACTIVE_FLAG
    curvature.setup(lmp, c, maxRadiusFactor, name_);
    curvature.setupCache(hsetup, curvatureTolerance, sizeof(dc_hertz_geom) / sizeof(double));
#else
    if (!(maxRadiusFactor > 1.0 && maxRadiusFactor <= 1e12)) stop(true, "maxRadiusFactor must be in (1, 1e12]");
#endif
    patch.setup(lmp, hsetup, c, contactPatch, name_);
  }

  /* At each run's start: the deck's damping law, E*, G* and the law's
     property (connectProperties). */
  void connectToProperties(PropertyRegistry &registry)
  {
    dampingLaw = deckDamping();
    connectProperties(registry);
  }

  /* The damping law the deck's settings give ('viscoelastic on' is
     'damping viscoelastic'). The settings are read once, and each run's
     set-up starts again from them. */
  int deckDamping()
  {
    if (!viscoelastic) return dampingSetting;
    if (dampingSetting != DC_DAMPING_RESTITUTION && dampingSetting != DC_DAMPING_VISCOELASTIC)
      stop(true, "'viscoelastic on' and another damping law: give one 'damping LAW'");
    return DC_DAMPING_VISCOELASTIC;
  }

  /* E*, G* and the property of the damping law in force (dampingLaw), as a
     coefficient per type pair (dc_damping_gamma's coef). */
  void connectProperties(PropertyRegistry &registry)
  {
    const std::string caller = std::string("model ") + name_;
    registry.registerProperty("Yeff", &MODEL_PARAMS::createYeff, caller.c_str());
    registry.registerProperty("Geff", &MODEL_PARAMS::createGeff, caller.c_str());
    registry.connect("Yeff", Yeff, caller.c_str());
    registry.connect("Geff", Geff, caller.c_str());
    const int n = registry.max_type();
    dampCoef.assign((n + 1) * (n + 1), 0.0);
    double **coef = NULL;
    if (dampingLaw == DC_DAMPING_VISCOELASTIC) {
      registry.registerProperty("viscoelasticTime", &createViscoelasticTime, caller.c_str());
      registry.connect("viscoelasticTime", coef, caller.c_str());
    } else if (dampingLaw == DC_DAMPING_KUWABARA_KONO) {
      registry.registerProperty("kuwabaraKonoDamping", &createKuwabaraKono, caller.c_str());
      registry.connect("kuwabaraKonoDamping", coef, caller.c_str());
    } else if (dampingLaw == DC_DAMPING_RESTITUTION) {
      registry.registerProperty("betaeff", &MODEL_PARAMS::createBetaEff, caller.c_str());
      registry.connect("betaeff", coef, caller.c_str());
    } else if (dampingLaw == DC_DAMPING_TSUJI) {
      registry.registerProperty("coefficientRestitution", &MODEL_PARAMS::createCoeffRest, caller.c_str());
      double **e = registry.getMatrixProperty("coefficientRestitution", caller.c_str())->data;
      for (int i = 1; i <= n; i++)
        for (int j = 1; j <= n; j++)
          if (dc_damping_tsuji_alpha(e[i][j], &dampCoef[i * (n + 1) + j]) != DC_OK) {
            char msg[160];
            snprintf(msg, sizeof msg, "coefficientRestitution = %g for types %d and %d is outside (0, 1] (damping tsuji)",
                     e[i][j], i, j);
            stop(true, msg);
          }
    }
    if (coef)
      for (int i = 1; i <= n; i++)
        for (int j = 1; j <= n; j++) dampCoef[i * (n + 1) + j] = coef[i][j];
    ntypes_ = n;
    for (int i = 1; i <= n; i++)
      for (int j = 1; j <= n; j++)
        if (!(Yeff[i][j] > 0.0 && Yeff[i][j] <= DBL_MAX && Geff[i][j] > 0.0 && Geff[i][j] <= DBL_MAX)) {
          char msg[256];
          snprintf(msg, sizeof msg, "youngsModulus and poissonsRatio of types %d and %d give E* = %g, G* = %g: "
                   "youngsModulus is outside the range of doubles for this pair", i, j, Yeff[i][j], Geff[i][j]);
          stop(true, msg);
        }
  }

  inline double stressStrainExponent() { return 1.5; }
  void beginPass(SurfacesIntersectData &, ForceData &, ForceData &) {}
  void endPass(SurfacesIntersectData &, ForceData &, ForceData &) {}

protected:
  /* Stops the run with "Normal model <name>: <what>" (all: every rank). */
  void stop(bool all, const char *what)
  {
    char msg[512];
    snprintf(msg, sizeof msg, "Normal model %s: %s", name_, what);
    if (all) error->all(FLERR, msg);
    else error->one(FLERR, msg);
  }

  /* A parameter of type pair (i, j) outside its domain (dc/contract.h). */
  void stopParam(const dc_param_error &err, int i, int j)
  {
    char msg[256];
    dc_param_error_format(&err, i, j, msg, sizeof msg);
    stop(true, msg);
  }

  /* The one contact-distance check: a force that acts at overlaps down to
     -range needs contact_distance_factor >= 1 + range / reach (reach: the
     sum of the radii, a wall's sphere radius); why_format (one %g, filled
     with why_value) says what needs it. Inline: rough contacts check at
     every step; the message is out of line. */
  __attribute__((always_inline)) inline void checkReach(const SurfacesCloseData &d, double range,
                                                        const char *why_format, double why_value)
  {
    if (!(range <= DBL_MAX) || outOfReach(d, neighbor->contactDistanceFactor, range))
      reachFailed(d, range, reachRadius(d), why_format, why_value);
  }

  __attribute__((noinline)) void reachFailed(const SurfacesCloseData &d, double range, double reach,
                                             const char *why_format, double why_value)
  {
    if (!(range <= DBL_MAX)) {
      char why[256], msg[512];
      snprintf(why, sizeof why, why_format, why_value);
      snprintf(msg, sizeof msg, "%s, but this reach is not finite: youngsModulus of types %d and %d (E* = %g) is "
               "too small", why, d.itype, d.jtype, Yeff[d.itype][d.jtype]);
      stop(false, msg);
    }
    if (outOfReach(d, neighbor->contactDistanceFactor, range)) {
      char why[256], msg[512];
      snprintf(why, sizeof why, why_format, why_value);
      const double factor = 1.0 + range / reach;
      if (factor <= 2.0)
        snprintf(msg, sizeof msg, "%s: set neigh_modify contact_distance_factor >= %.12g", why, factor);
      else   /* a reach beyond the particles' size: the material input is suspect */
        snprintf(msg, sizeof msg, "%s: set neigh_modify contact_distance_factor >= %.12g; a reach beyond the "
                 "particle size points at too small a youngsModulus (E* = %g for types %d and %d)", why, factor,
                 Yeff[d.itype][d.jtype], d.itype, d.jtype);
      stop(false, msg);
    }
  }

  bool superquadric(const SurfacesCloseData &d) const
  {
#ifdef SUPERQUADRIC_ACTIVE_FLAG
    return d.is_non_spherical && atom->superquadric_flag;
#else
    (void)d;
    return false;
#endif
  }

  /* Relative principal radii (spheres: the effective radius twice) and,
     when axis is given, the major-axis direction (zero for spheres). */
  void relativeRadii(const SurfacesIntersectData &sidata, double &R_major, double &R_minor, double *axis)
  {
#ifdef SUPERQUADRIC_ACTIVE_FLAG
    if (superquadric(sidata)) {
      curvature.relativeRadii(lmp, sidata, R_major, R_minor, name_, axis);
      return;
    }
#endif
    R_major = R_minor = sphereEffectiveRadius(sidata);
    if (axis) axis[0] = axis[1] = axis[2] = 0.0;
  }

  /* The Hertz geometry of a superquadric contact's relative radii and, when
     axis is given, the major-axis direction; reused across steps within
     curvatureTolerance. */
  void superquadricGeometry(SurfacesIntersectData &sidata, dc_hertz_geom &g, double *axis)
  {
#ifdef SUPERQUADRIC_ACTIVE_FLAG
    const bool cache = curvature.caching();
    const double *kept = NULL;
    int held = -1;
    if (cache) {
      held = curvature.reuse(lmp, sidata, axis, &kept);
      if (held == 1) {
        memcpy(&g, kept, sizeof g);
        if (curvatureCheck > 0.0) checkReuse(sidata, g);
        return;
      }
    }
#endif
    double R_major, R_minor;
    relativeRadii(sidata, R_major, R_minor, axis);
    hertzGeometry(R_major, R_minor, g);
#ifdef SUPERQUADRIC_ACTIVE_FLAG
    if (cache && sidata.computeflag && sidata.shearupdate) {
      refreshed_++;
      double change = -1.0;
      if (held == 0) {
        dc_hertz_geom old;
        memcpy(&old, kept, sizeof old);
        change = geometryChange(old, g);
      }
      curvature.keep(lmp, sidata, reinterpret_cast<const double *>(&g), axis, change);
    }
#endif
  }

  /* The largest relative change of the radii a model uses, a to b. */
  static double geometryChange(const dc_hertz_geom &a, const dc_hertz_geom &b)
  {
    const double x[4] = {a.R_force / b.R_force, a.R_area / b.R_area, a.R_major / b.R_major, a.R_minor / b.R_minor};
    double c = 0.0;
    for (int k = 0; k < 4; k++)
      if (fabs(x[k] - 1.0) > c) c = fabs(x[k] - 1.0);
    return c;
  }

  /* dc_hertz_geometry, or a run-stopping message naming the radii. */
  void hertzGeometry(double R1, double R2, dc_hertz_geom &g)
  {
    const int st = dc_hertz_geometry(R1, R2, &g);
    if (st != DC_OK) {
      char msg[256];
      snprintf(msg, sizeof msg, "relative radii %g, %g: %s", R1, R2, dc_status_str(st));
      stop(false, msg);
    }
  }

  /* Elastic force P at overlap delta with damping (the damping setting) on
     the stiffness Sn (normal; none where Sn <= 0 or delta <= 0 for the laws
     that need them) and kt (tangential), clipped at 0 with limitForce;
     stored in sidata with the secant kn and kt, applied. Inline, with the
     default damping (restitution) tested first. */
  __attribute__((always_inline)) inline void applyForce(SurfacesIntersectData &sidata, double P, double delta,
                                                        double vn, double Sn, double kn, double kt,
                                                        ForceData &i_forces, ForceData &j_forces)
  {
    const double coef = dampCoef[sidata.itype * (ntypes_ + 1) + sidata.jtype];
    double gamman, gammat = 0.0;
    if (dampingLaw == DC_DAMPING_RESTITUTION) {
      gamman = dc_damping_restitution(coef, Sn > 0.0 ? Sn : 0.0, sidata.meff);
      if (tangential_damping) gammat = dc_damping_restitution(coef, kt, sidata.meff);
    } else if (dampingLaw == DC_DAMPING_VISCOELASTIC) {   /* acts on a negative stiffness too */
      gamman = dc_damping_viscoelastic(coef, Sn);
      if (tangential_damping) gammat = dc_damping_viscoelastic(coef, kt);
    } else {
      const double d = delta > 0.0 ? delta : 0.0;
      gamman = dc_damping_gamma(dampingLaw, coef, Sn > 0.0 ? Sn : 0.0, d, sidata.meff);
      if (tangential_damping) gammat = dc_damping_gamma(dampingLaw, coef, kt, d, sidata.meff);
    }
    double Fn = -gamman * vn + P * invNktv2p;
    if (limitForce && Fn < 0.0) Fn = 0.0;
    sidata.Fn = Fn;
    sidata.kn = kn * invNktv2p;
    sidata.kt = kt * invNktv2p;
    sidata.gamman = gamman;
    sidata.gammat = gammat;
    applyNormalForce(sidata, Fn, atom->x, i_forces, j_forces);
  }

  /* The settings and the per-type-pair parameters of a plastic law (fields
     K_v, c_h, c_A; dc/jamari_ep.h, dc/gw_rough_plastic.h): property hardness
     [Pa] per type, a pair taking the softer type's with its poissonsRatio.
     Settings plasticityKv (0: the law's default from nu), plasticityCh,
     plasticityCa. */
  struct Plasticity {
    double kv = 0.0, ch = 1.0, ca = 108.0;
    void registerSettings(Settings &settings, double ch_default, double ca_default)
    {
      settings.registerDoubleSetting("plasticityKv", kv, 0.0);
      settings.registerDoubleSetting("plasticityCh", ch, ch_default);
      settings.registerDoubleSetting("plasticityCa", ca, ca_default);
    }
  };
  template<class P>
  void plasticParams(PropertyRegistry &registry, const char *caller, const Plasticity &set,
                     P (*defaults)(double, double), int (*check)(const P *, dc_param_error *), std::vector<P> &out)
  {
    registry.registerProperty("hardness", &createHardness, caller);
    registry.registerProperty("poissonsRatio", &MODEL_PARAMS::createPoissonsRatio, caller);
    const double *H = registry.getVectorProperty("hardness", caller)->data;
    const double *nu = registry.getVectorProperty("poissonsRatio", caller)->data;
    const int n = registry.max_type();
    out.assign((n + 1) * (n + 1), P());
    for (int i = 1; i <= n; i++)
      for (int j = 1; j <= n; j++) {
        const int soft = H[j] < H[i] ? j : i;
        P p = defaults(H[soft], nu[soft]);
        if (set.kv != 0.0) p.K_v = set.kv;
        p.c_h = set.ch;
        p.c_A = set.ca;
        dc_param_error err;
        if (check(&p, &err) != DC_OK) stopParam(err, i, j);
        out[i * (n + 1) + j] = p;
      }
  }

  /* Hertz theory holds while the contact semi-axis a is small against the
     bodies' curvature radii: a warning (once per process for the pair style
     and every wall together, naming the atoms) when a > R_minor / 2
     (Fessler & Ollerton's limit, quoted in the review), a2 = a^2. */
  __attribute__((always_inline)) inline void checkHertzRange(const SurfacesIntersectData &sidata, double a2,
                                                             double R_minor)
  {
    if (a2 > 0.25 * R_minor * R_minor) warnHertzRange(sidata, a2, R_minor);
  }
  __attribute__((noinline)) void warnHertzRange(const SurfacesIntersectData &sidata, double a2, double R_minor)
  {
    if (warnedBefore(DC_WARN_HERTZ_RANGE)) return;
    char msg[320];
    snprintf(msg, sizeof msg, "Normal model %s: the contact of atom %d with %s %d has a semi-axis %g m above half "
             "its smaller relative curvature radius (%g m / 2), where Hertz theory no longer holds (overlap %g m; "
             "warned once)", name_, (int)atom->tag[sidata.i], sidata.is_wall ? "wall type" : "atom",
             sidata.is_wall ? sidata.jtype : (int)atom->tag[sidata.j], sqrt(a2), R_minor, sidata.deltan);
    error->warning(FLERR, msg);
  }

  /* Publishes the patch of a contact (when stored). */
  void publish(SurfacesCloseData &d, const dc_contact &c, const double *axis)
  {
    if (!patch.active()) return;
    dc_patch_from_contact(&c, c.a > c.b ? axis : NULL, &patch.next());
    patch.commit(d);
  }
  /* Publishes the patch of a sphere contact: the circle of Hertz contact
     of radius R at overlap delta with elastic force F (= kn delta). */
  void publishCircle(SurfacesCloseData &d, double R, double delta, double F, double Estar)
  {
    if (!patch.active()) return;
    if (!dc_hertz_patch_circle(R, delta, F, &patch.next())) {   /* beyond the doubles: the checked law */
      dc_hertz_geom g;
      dc_contact c;
      dc_hertz_geometry_circle(R, &g);
      dc_hertz_normal(&g, Estar, delta, &c);
      dc_patch_from_contact(&c, NULL, &patch.next());
    }
    patch.commit(d);
  }
  void publishNone(SurfacesCloseData &d)
  {
    if (patch.active()) patch.clear(d);
  }
  /* The patch of this evaluation as published (with the patch active). */
  const dc_patch &patchPublished() { return patch.next(); }
  /* Whether the contact patch is stored; the major-axis direction is worth
     computing only then. */
  bool patchStored() const { return patch.active(); }
  double *axisWanted(double *axis) const { return patchStored() ? axis : NULL; }

  double **Yeff, **Geff;
  bool tangential_damping, limitForce, viscoelastic, contactPatch;
  int dampingSetting;              /* the deck's 'damping' (dc_damping_law) */
  int dampingLaw;                  /* the law in force this run (dc_damping_law) */
  std::vector<double> dampCoef;    /* its coefficient per type pair */
  double invNktv2p;                /* 1/force->nktv2p: 1 in the granular unit styles (si, cgs,
                                      micro, nano), so P/nktv2p to the bit */
  int ntypes_;
  double maxRadiusFactor, curvatureTolerance, curvatureCheck;
#ifdef SUPERQUADRIC_ACTIVE_FLAG
  SuperquadricCurvature curvature;
#endif

private:
  static VectorProperty *createHardness(PropertyRegistry &registry, const char *caller, bool sanity_checks)
  {
    return MODEL_PARAMS::createPerTypeProperty(registry, "hardness", caller, sanity_checks, 0.0, HUGE_VAL);
  }
  static MatrixProperty *createKuwabaraKono(PropertyRegistry &registry, const char *caller, bool sanity_checks)
  {
    return MODEL_PARAMS::createPerTypePairProperty(registry, "kuwabaraKonoDamping", caller, sanity_checks, 0.0);
  }
  static MatrixProperty *createViscoelasticTime(PropertyRegistry &registry, const char *caller, bool sanity_checks)
  {
    return MODEL_PARAMS::createPerTypePairProperty(registry, "viscoelasticTime", caller, sanity_checks, 0.0);
  }

#ifdef SUPERQUADRIC_ACTIVE_FLAG
  /* curvatureCheck: the reused geometry g against this step's */
  void checkReuse(const SurfacesIntersectData &sidata, const dc_hertz_geom &g)
  {
    double R_major, R_minor;
    dc_hertz_geom f;
    curvature.relativeRadii(lmp, sidata, R_major, R_minor, name_, NULL);
    hertzGeometry(R_major, R_minor, f);
    const double dev = geometryChange(g, f);
    if (dev > checkMax_) checkMax_ = dev;
    if (dev > curvatureTolerance) over_[0]++;
    if (dev > 10.0 * curvatureTolerance) over_[1]++;
    checked_++;
    if (checkMax_ > curvatureCheck) {
      char msg[320];
      snprintf(msg, sizeof msg, "curvatureCheck: the reused geometry of the contact of atom %d with %s %d is off by "
               "%.3e (> %g): R_force %g against %g, R_minor %g against %g", (int)atom->tag[sidata.i],
               sidata.is_wall ? "wall type" : "atom", sidata.is_wall ? sidata.jtype : (int)atom->tag[sidata.j],
               checkMax_, curvatureCheck, g.R_force, f.R_force, g.R_minor, f.R_minor);
      stop(false, msg);
    }
  }
#endif

  const char *name_;
  int unsupported_;
  int rank_;          /* this process's rank, kept for the destructor */
  double checkMax_;   /* curvatureCheck: the largest deviation seen, on how many reuses, refreshes */
  long checked_, refreshed_, over_[2];   /* over_: deviations above t, 10 t */
  ContactPatchWriter patch;
};

}
}
#endif
