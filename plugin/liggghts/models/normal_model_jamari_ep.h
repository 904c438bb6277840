/* LIGGGHTS normal model `jamari_ep`: Jamari-Schipper elastic / elastic-plastic
   / fully plastic contact of spheres and superquadrics, with elastic
   unloading and reloading from the largest overlap (c_core: dc/jamari_ep.h,
   review Eqs. 41-46).

   Deck: pair_style gran model jamari_ep tangential history [surface superquadric] [settings]
         fix ID all wall/gran model jamari_ep tangential history [surface superquadric] ... [settings]
   Settings: those of every project normal model (dc_model_base.h), and
     plasticityKv X   maximum Hertz pressure at first yield over the hardness,
                      > 0 (default 0: 0.454 + 0.41 nu of the softer body,
                      Chang, Etsion & Bogy)
     plasticityCh X   mean pressure at full plasticity over the hardness,
                      >= 2/3 plasticityKv (default 1)
     plasticityCa X   area at the onset of full plasticity over the Hertz area
                      at first yield, >= 2 (default 108: delta_n2 = 54 delta_n1
                      for spheres, Zhao, Maietta & Chang)
   Properties: youngsModulus, poissonsRatio, coefficientRestitution (or
     viscoelasticTime with viscoelastic on), and
     hardness peratomtype [Pa] > 0: a contact takes the smaller (softer body).
   The plastic dissipation is the law's own (loading and unloading differ);
   the damping of coefficientRestitution / viscoelasticTime acts on top of it
   (coefficientRestitution 1: none). History: the largest overlap beyond first
   yield and its unloading branch (4 values), kept while the pair stays within
   the contact distance (neigh_modify contact_distance_factor; with the
   default 1, while the surfaces overlap): a pair that parts and touches again
   within it meets its flattened contact, a farther one starts elastic. Below first yield the force
   is `hertz_elliptic`'s (spheres: its arithmetic, bit for bit). */
#ifdef NORMAL_MODEL
NORMAL_MODEL(JAMARI_EP,jamari_ep,@DC_MODEL_ID@)
#else
#ifndef NORMAL_MODEL_JAMARI_EP_H_
#define NORMAL_MODEL_JAMARI_EP_H_

#include <vector>
#include "dc_model_base.h"
#include "dc/jamari_ep.h"
#include "dc/mindlin.h"

namespace LIGGGHTS {
namespace ContactModels {

template<>
class NormalModel<JAMARI_EP> : public DcNormalModel
{
public:
  NormalModel(LAMMPS *lmp, IContactHistorySetup *hsetup, class ContactModelBase *c) :
    DcNormalModel(lmp, hsetup, c, "jamari_ep"), history_offset(-1), ntypes(0), contactModel(c)
  {
    for (int k = 0; k < DC_JAMARI_HISTORY_NFIELDS; k++) {
      const int off = hsetup->add_history_value(dc_jamari_history[k].name, dc_jamari_history[k].flips ? "1" : "0");
      if (k == 0) history_offset = off;
    }
  }

  void registerSettings(Settings &settings)
  {
    DcNormalModel::registerSettings(settings);
    plasticity.registerSettings(settings, DC_JAMARI_CH_DEFAULT, DC_JAMARI_CA_DEFAULT);
  }

  void connectToProperties(PropertyRegistry &registry)
  {
    DcNormalModel::connectToProperties(registry);
    plasticParams(registry, "model jamari_ep", plasticity, &dc_jamari_defaults, &dc_jamari_check, params);
    ntypes = registry.max_type();
    yield_ratio.assign((ntypes + 1) * (ntypes + 1), 0.0);
    for (int i = 1; i <= ntypes; i++)
      for (int j = 1; j <= ntypes; j++)
        yield_ratio[i * (ntypes + 1) + j] = dc_jamari_circle_yield_ratio(Yeff[i][j], &params[i * (ntypes + 1) + j]);
    checkCohesion(registry);
  }

  inline void surfacesIntersect(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)
  {
    if (sidata.contact_flags) *sidata.contact_flags |= CONTACT_NORMAL_MODEL;
    const int itype = sidata.itype, jtype = sidata.jtype;
    const double Y = Yeff[itype][jtype];
    double R_major, R_minor, axis[3];
    double *ax = axisWanted(axis);
    const bool sq = superquadric(sidata);
    dc_hertz_geom g;
    if (sq) {
      superquadricGeometry(sidata, g, ax);
      R_major = g.R_major;
      R_minor = g.R_minor;
    } else {
      relativeRadii(sidata, R_major, R_minor, ax);
    }
    const int k = itype * (ntypes + 1) + jtype;
    dc_jamari_state *h = reinterpret_cast<dc_jamari_state *>(&sidata.contact_history[history_offset]);
    if (!sq && h->delta_max == 0.0 && sidata.deltan <= yield_ratio[k] * R_major) {
      /* a sphere contact below first yield with no plastic memory: hertz_elliptic's arithmetic */
      checkHertzRange(sidata, R_major * sidata.deltan, R_major);
      double kn, Sn;
      const double root = dc_hertz_stiffness(Y, R_major, sidata.deltan, &kn, &Sn);
      const double P = kn * sidata.deltan;
      applyForce(sidata, P, sidata.deltan, sidata.vn, Sn, kn, dc_mindlin_kt_circle(Geff[itype][jtype], root),
                 i_forces, j_forces);
      if (ax) publishCircle(sidata, R_major, sidata.deltan, P, Y);
      return;
    }
    if (!sq) dc_hertz_geometry_circle(R_major, &g);
    dc_jamari_state scratch;
    if (!(sidata.computeflag && sidata.shearupdate)) {   /* a pass that must not change the history */
      scratch = *h;
      h = &scratch;
    }
    dc_contact c;
    const int st = dc_jamari_step(&g, Y, &params[k], sidata.deltan, h, &c);
    if (st != DC_OK) {
      char msg[256];
      snprintf(msg, sizeof msg, "overlap %g, radii %g, %g, E* %g (youngsModulus, poissonsRatio of types %d and %d): "
               "%s", sidata.deltan, R_major, R_minor, Y, itype, jtype, dc_status_str(st));
      stop(false, msg);
    }
    checkHertzRange(sidata, c.a * c.a, g.R_minor);
    const double kt = dc_mindlin_kt_circle(Geff[itype][jtype], sqrt(c.a * c.b));
    /* damping on the tangent stiffness; the secant stiffness for LIGGGHTS' time-step checks */
    const double kn = sidata.deltan > 0.0 ? c.F / sidata.deltan : 0.0;
    applyForce(sidata, c.F, sidata.deltan, sidata.vn, c.kn, kn, kt, i_forces, j_forces);
    if (ax) publish(sidata, c, ax);
  }

  void surfacesClose(SurfacesCloseData &scdata, ForceData &, ForceData &)
  {
    if (scdata.contact_flags) *scdata.contact_flags |= CONTACT_NORMAL_MODEL;
    publishNone(scdata);
  }

private:
  /* Under LIGGGHTS' sjkr or sjkr2 the cohesive pressure cohesionEnergyDensity
     acts on the overlap's truncation area, the area on which the plastic
     contact carries at most plasticityCh x hardness: at or above that
     pressure nothing holds the surfaces apart and they sink into each
     other, turning the cohesion's energy into motion. Stops the run then,
     naming the type pair and both values. */
  void checkCohesion(PropertyRegistry &registry)
  {
    const int cohesion = static_cast<int>((contactModel->style_hash() >> 12) & 63);
    if (cohesion != COHESION_SJKR && cohesion != COHESION_SJKR2) return;
    registry.registerProperty("cohEnergyDens", &MODEL_PARAMS::createCohesionEnergyDensity);
    double **ced = registry.getMatrixProperty("cohEnergyDens", "model jamari_ep")->data;
    for (int i = 1; i <= ntypes; i++)
      for (int j = 1; j <= ntypes; j++) {
        const dc_jamari_params &p = params[i * (ntypes + 1) + j];
        if (ced[i][j] < p.c_h * p.H) continue;
        char msg[512];
        snprintf(msg, sizeof msg, "cohesionEnergyDensity = %g Pa for types %d and %d is not below the largest "
                 "contact pressure of the plastic contact, plasticityCh x hardness = %g Pa: cohesion %s would pull "
                 "the surfaces into each other without bound; lower cohesionEnergyDensity or raise hardness",
                 ced[i][j], i, j, p.c_h * p.H, cohesion == COHESION_SJKR ? "sjkr" : "sjkr2");
        stop(true, msg);
      }
  }

  Plasticity plasticity;
  int history_offset, ntypes;
  const ContactModelBase *contactModel;
  std::vector<dc_jamari_params> params;
  std::vector<double> yield_ratio;   /* delta_n1 / R of sphere contacts per type pair */
};

}
}
#endif
#endif
