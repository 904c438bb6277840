/* LIGGGHTS normal model `jkr_elliptic`: adhesive elastic contact (c_core:
   dc/jkr_elliptic.h: classical JKR for spheres, the Johnson-Greenwood
   elliptic theory for superquadrics, review Eqs. 19-28; damping on the
   flat-punch stiffness, dc/damping.h and dc/dissipation_adhesive.h).

   Deck: pair_style gran model jkr_elliptic tangential history [surface superquadric] [settings]
         fix ID all wall/gran model jkr_elliptic tangential history [surface superquadric] primitive ... [settings]
         neigh_modify contact_distance_factor F   (see below)
   Settings: those of every project normal model (dc_model_base.h) but
     limitForce (the adhesive force is tensile by design; 'limitForce on'
     stops the run), and
     adhesionLaw jkr|dmt|maugis|tabor
                         jkr (default): JKR, for soft, strongly adhesive
                         contacts (large Tabor parameter); dmt: DMT, for hard,
                         weakly adhesive ones (small Tabor parameter): the
                         Hertz force less 2 pi w (R_major R_minor)^1/2 from
                         touch on, no neck; maugis: Maugis-Dugdale, the
                         transition between them (its zone acts before touch
                         and holds until the model's separation overlap;
                         superquadrics: on the sphere of elliptic Hertz's
                         force radius); tabor: per contact the law its Tabor
                         parameter picks (JKR above 5, DMT below 0.1,
                         Maugis-Dugdale between; spheres) (dc/maugis_dugdale.h)
   Properties: youngsModulus, poissonsRatio, coefficientRestitution (or
     viscoelasticTime), and workOfAdhesion peratomtypepair [J/m^2] >= 0
     (w = 2 x surface energy for like surfaces); maugis and tabor also
     equilibriumSeparation peratomtypepair [m] > 0 (z0 of the surfaces'
     Lennard-Jones potential, about 3e-10 to 4e-10).
   A contact forms when the surfaces touch (delta = 0) and is kept, with
   tensile force, on the stable branch of the JKR curve until the overlap
   falls below delta_break (spheres: -3/4 (pi^2 w^2 R / E*^2)^1/3;
   superquadrics: that of the elliptic contact, dc_jkr_geometry). LIGGGHTS'
   contact history carries the state across neighbour rebuilds and MPI
   ranks. LIGGGHTS only looks at pairs within contact_distance_factor
   (r_i + r_j), so the deck must set F >= 1 + |delta_break| / (r_i + r_j)
   (walls: 1 + |delta_break| / r_i; superquadrics: bounding radii for pairs,
   volume-equivalent radius for walls); the run stops with the value needed
   otherwise. Damping acts on the flat-punch stiffness k_punch = pi E* a /
   K(e^2) of the current contact ellipse (2 E* a for a circle; dF/d delta
   itself is unbounded at separation); tangential stiffness 8 G* (a b)^1/2.
   Contact patch: the JKR ellipse, formed while the neck holds, the normal
   force that bounds friction F + 2 |F_pull| (dc_jkr_friction_load); DMT:
   the Hertz ellipse while delta > 0, friction load F + 2 F_pull;
   Maugis-Dugdale: the contact circle, F + 2 |F_pull| with its pull-off
   force under load control, no friction while only the zone acts.
   Superquadrics: the gap of a formed contact from superquadric_gap.h, the
   elliptic solve warm-started from the previous step (three history
   values). w = 0 is exactly `hertz_elliptic`. */
#ifdef NORMAL_MODEL
NORMAL_MODEL(JKR_ELLIPTIC,jkr_elliptic,@DC_MODEL_ID@)
#else
#ifndef NORMAL_MODEL_JKR_ELLIPTIC_H_
#define NORMAL_MODEL_JKR_ELLIPTIC_H_

#include "dc_model_base.h"
#include "dc_properties.h"
#include "superquadric_gap.h"
#include "dc/jkr_elliptic.h"
#include "dc/maugis_dugdale.h"
#include "dc/mindlin.h"

namespace LIGGGHTS {
namespace ContactModels {

template<>
class NormalModel<JKR_ELLIPTIC> : public DcNormalModel
{
public:
  NormalModel(LAMMPS *lmp, IContactHistorySetup *hsetup, class ContactModelBase *c) :
    DcNormalModel(lmp, hsetup, c, "jkr_elliptic", NO_LIMIT_FORCE | NO_CURVATURE_REUSE), work(NULL), law(LAW_JKR),
    hint_offset(-1)
  {
    /* the solver hint (fields 1-3) only where elliptic contacts occur */
    const int nfields = atom->superquadric_flag ? DC_JKR_HISTORY_NFIELDS : 1;
    for (int k = 0; k < nfields; k++) {
      const int off = hsetup->add_history_value(dc_jkr_history[k].name, dc_jkr_history[k].flips ? "1" : "0");
      if (k == 0) contact_offset = off;
      if (k == 1) hint_offset = off;
    }
#ifdef SUPERQUADRIC_ACTIVE_FLAG
    gap.addHistory(lmp, hsetup);
#endif
  }

  void registerSettings(Settings &settings)
  {
    DcNormalModel::registerSettings(settings);
    static const char *const names[] = {"jkr", "dmt", "maugis", "tabor"};
    static const int values[] = {LAW_JKR, LAW_DMT, LAW_MD, LAW_TABOR};
    settings.registerChoice("adhesionLaw", law, names, values, 4, "jkr");
  }

  void postSettings(IContactHistorySetup *hsetup, ContactModelBase *c)
  {
    DcNormalModel::postSettings(hsetup, c);
    if (law >= LAW_MD) {
      if (law == LAW_TABOR && atom->superquadric_flag)
        stop(true, "adhesionLaw tabor is for spheres; superquadrics take adhesionLaw jkr, dmt or maugis");
      for (int k = 0; k < DC_MD_CONTACT_NFIELDS; k++) {
        const int off = hsetup->add_history_value(dc_md_history[k].name, dc_md_history[k].flips ? "1" : "0");
        if (k == 0) md_offset = off;
        else if (off != md_offset + k) stop(true, "the Maugis-Dugdale history fields are not contiguous");
      }
    }
#ifdef SUPERQUADRIC_ACTIVE_FLAG
    gap.setup(lmp, c);
#endif
  }

  void connectToProperties(PropertyRegistry &registry)
  {
    DcNormalModel::connectToProperties(registry);
    const char *caller = "model jkr_elliptic";
    registry.registerProperty("workOfAdhesion", &dcCreateWorkOfAdhesion, caller);
    registry.connect("workOfAdhesion", work, caller);
    const int n = registry.max_type();
    dc_param_error err;
    spheres.assign((n + 1) * (n + 1), dc_jkr_sphere_pair());
    for (int i = 1; i <= n; i++)
      for (int j = 1; j <= n; j++) {
        if (dc_jkr_check(work[i][j], &err) != DC_OK) stopParam(err, i, j);
        spheres[i * (n + 1) + j] = dc_jkr_sphere_pair_of(Yeff[i][j], work[i][j]);
      }
    if (law < LAW_MD) return;
    registry.registerProperty("equilibriumSeparation", &dcCreateEquilibriumSeparation, caller);
    registry.connect("equilibriumSeparation", z0, caller);
    md.assign((n + 1) * (n + 1), dc_md_sphere_pair());
    for (int i = 1; i <= n; i++)
      for (int j = 1; j <= n; j++)
        if (work[i][j] > 0.0 && dc_md_sphere_pair_of(Yeff[i][j], work[i][j], z0[i][j], &md[i * (n + 1) + j], &err) != DC_OK)
          stopParam(err, i, j);
  }

  inline void surfacesIntersect(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)
  {
    if (sidata.contact_flags) *sidata.contact_flags |= CONTACT_NORMAL_MODEL;
    const int lw = lawOf(sidata);
    if (lw == LAW_MD) {
      if (!mdForce(sidata, sidata.deltan, sidata.vn, i_forces, j_forces)) publishNone(sidata);
      return;
    }
    double &formed = sidata.contact_history[contact_offset];
    const bool forming = !(formed > 0.0);   /* formed is 0 or 1: one test, where == 0 takes a NaN-aware three */
    formed = 1.0;
    if (!forming && lw == LAW_JKR && !superquadric(sidata) && !patchStored()) {
      /* spheres at the Hertz-like end, the patch not stored: the inline
         hot path of dc_jkr_sphere (the same bits) */
      const int itype = sidata.itype, jtype = sidata.jtype;
      const double R = sphereEffectiveRadius(sidata), delta = sidata.deltan;
      const dc_jkr_sphere_pair &pair = spheres[itype * (ntypes_ + 1) + jtype];
      double a, P;
      if (dc_jkr_sphere_near_hertz(&pair, R, delta, &a, &P)) {
        checkHertzRange(sidata, a * a, R);
        const double kn = dc_punch_stiffness_circle(pair.Estar, a);   /* pair.Estar is Yeff */
        applyForce(sidata, P, delta, sidata.vn, kn, kn, dc_mindlin_kt_circle(Geff[itype][jtype], a), i_forces, j_forces);
        return;
      }
    }
    if (lw == LAW_DMT && !superquadric(sidata) && !patchStored()) {
      /* DMT spheres, the patch not stored: the inline path of dc_dmt_contact (the same bits) */
      const int itype = sidata.itype, jtype = sidata.jtype;
      const double R = sphereEffectiveRadius(sidata), delta = sidata.deltan;
      double P, kn, root;
      if (dc_dmt_sphere(R, Yeff[itype][jtype], work[itype][jtype], delta, &P, &kn, &root)) {
        checkHertzRange(sidata, root * root, R);
        applyForce(sidata, P, delta, sidata.vn, kn, kn, dc_mindlin_kt_circle(Geff[itype][jtype], root), i_forces,
                   j_forces);
        return;
      }
    }
    if (!jkrForce(sidata, sidata.deltan, sidata.vn, forming, lw, i_forces, j_forces)) publishNone(sidata);
  }

  /* A formed contact with negative overlap: tensile JKR force until delta_break. */
  void surfacesClose(SurfacesCloseData &scdata, ForceData &i_forces, ForceData &j_forces)
  {
    SurfacesIntersectData &sidata = static_cast<SurfacesIntersectData &>(scdata);
    const int lw = lawOf(sidata);
    double delta, vn;
    if (lw == LAW_MD) {
      /* apart: most pairs handed here are beyond the zone's reach h0 */
      const dc_md_contact *h = reinterpret_cast<const dc_md_contact *>(&sidata.contact_history[md_offset]);
      const double h0 = md[sidata.itype * (ntypes_ + 1) + sidata.jtype].h0, reach = sidata.radsum + h0;
#ifdef SUPERQUADRIC_ACTIVE_FLAG
      if (atom->superquadric_flag) {
        if (!gap.closeOverlap(lmp, sidata, h->phase == DC_MD_APART ? h0 : sidata.radsum, delta, vn))
          return release(scdata);
      } else
#endif
      {
        if (h->phase == DC_MD_APART && !sidata.is_wall && sidata.rsq >= reach * reach) return release(scdata);
        delta = closeSphereContact(scdata, vn);
      }
      if (!mdForce(sidata, delta, vn, i_forces, j_forces)) return release(scdata);
      if (scdata.contact_flags) *scdata.contact_flags |= CONTACT_NORMAL_MODEL;
      sidata.has_force_update = true;
      return;
    }
    double &formed = scdata.contact_history[contact_offset];
    const double w = work[scdata.itype][scdata.jtype];
    if (formed == 0.0 || w == 0.0 || lw == LAW_DMT) return release(scdata);
#ifdef SUPERQUADRIC_ACTIVE_FLAG
    if (atom->superquadric_flag) {
      if (!gap.closeOverlap(lmp, sidata, sidata.radsum, delta, vn)) return release(scdata);
    } else
#endif
    delta = closeSphereContact(scdata, vn);
    if (!jkrForce(sidata, delta, vn, false, lw, i_forces, j_forces)) return release(scdata);
    if (scdata.contact_flags) *scdata.contact_flags |= CONTACT_NORMAL_MODEL;
    sidata.has_force_update = true;
  }

private:
  void release(SurfacesCloseData &scdata)
  {
    if (scdata.contact_flags) *scdata.contact_flags &= ~CONTACT_NORMAL_MODEL;
    scdata.contact_history[contact_offset] = 0.0;
    publishNone(scdata);
  }

  void fail(const char *what, double delta, double R1, double R2, double w, double Y, int st)
  {
    char msg[384];
    snprintf(msg, sizeof msg, "%s at overlap %g, radii %g, %g, workOfAdhesion %g, E* %g (from youngsModulus and "
             "poissonsRatio): %s", what, delta, R1, R2, w, Y, dc_status_str(st));
    stop(false, msg);
  }

  /* Applies the force at overlap delta; false (nothing applied) when the
     contact has separated (delta < delta_break). */
  bool jkrForce(SurfacesIntersectData &sidata, double delta, double vn, bool forming, int lw,
                ForceData &i_forces, ForceData &j_forces)
  {
    const int itype = sidata.itype, jtype = sidata.jtype;
    const double Y = Yeff[itype][jtype], G = Geff[itype][jtype], w = work[itype][jtype];
    const bool sq = superquadric(sidata);
    double R_major, R_minor, axis[3];
    double *ax = axisWanted(axis);
    relativeRadii(sidata, R_major, R_minor, ax);
    dc_contact c;
    double P, Sn, kn, kt;
    if (lw == LAW_DMT) {
      dc_hertz_geom g;
      if (sq) {
        const int st = dc_hertz_geometry(R_major, R_minor, &g);
        if (st != DC_OK) fail("contact geometry", delta, R_major, R_minor, w, Y, st);
      } else {
        dc_hertz_geometry_circle(R_major, &g);   /* the same bits, without the polynomials */
      }
      const int sc = dc_dmt_contact(&g, Y, w, delta, &c);
      if (sc != DC_OK) fail("DMT contact", delta, R_major, R_minor, w, Y, sc);
      if (!c.formed) return false;
      P = c.F;
      Sn = kn = c.kn;
      kt = dc_mindlin_kt_circle(G, sqrt(g.R_area * delta));
      checkHertzRange(sidata, c.a * c.a, R_minor);
    } else if (w == 0.0) {
      double r_force = R_major, r_area = R_major;
      dc_hertz_geom g;
      if (sq) {
        const int st = dc_hertz_geometry(R_major, R_minor, &g);
        if (st != DC_OK) fail("contact geometry", delta, R_major, R_minor, w, Y, st);
        r_force = g.R_force;
        r_area = g.R_area;
      }
      const double root = dc_hertz_stiffness(Y, r_force, delta, &kn, &Sn);
      kt = dc_mindlin_kt_circle(G, r_area == r_force ? root : sqrt(r_area * delta));
      P = kn * delta;
      checkHertzRange(sidata, sq ? 2.0 * g.R_major * delta * g.D / g.K : R_major * delta, R_minor);
      if (ax) {
        if (!sq) dc_hertz_geometry(R_major, R_major, &g);
        dc_hertz_normal(&g, Y, delta, &c);
      }
    } else {
      dc_jkr_state s;
      double F_pull = 0.0;
      int st;
      if (!sq) {
        /* separation (contact = 0) is decided inside, with the same delta_break */
        st = dc_jkr_sphere(R_major, Y, w, delta, &s);
        if (forming) checkReach(sidata, -dc_jkr_sphere_delta_break(R_major, Y, w), whyReach(), w);
        if (ax) F_pull = dc_jkr_sphere_pulloff(R_major, w);
      } else {
        dc_jkr_geom g;
        st = dc_jkr_geometry(R_major, R_minor, Y, w, &g);
        if (st != DC_OK) fail("contact geometry", delta, R_major, R_minor, w, Y, st);
        if (forming) checkReach(sidata, -g.delta_break, whyReach(), w);
        dc_jkr_hint *hint = reinterpret_cast<dc_jkr_hint *>(&sidata.contact_history[hint_offset]);
        st = dc_jkr_contact(&g, delta, hint, &s);
        F_pull = -g.F_pull;
      }
      if (st != DC_OK) fail("contact state", delta, R_major, R_minor, w, Y, st);
      if (!s.contact) return false;
      P = s.F;
      if (sq) {
        st = dc_punch_stiffness(Y, s.a, s.b > 0.0 ? s.b : s.a, &Sn);
        if (st != DC_OK) fail("punch stiffness", delta, R_major, R_minor, w, Y, st);
        kt = dc_mindlin_kt_circle(G, sqrt(s.a * s.b));
      } else {
        Sn = dc_punch_stiffness_circle(Y, s.a);
        kt = dc_mindlin_kt_circle(G, s.a);
      }
      kn = Sn;
      if (ax) dc_jkr_normal(&s, F_pull, &c);
      const double a_major = s.b > s.a ? s.b : s.a;
      checkHertzRange(sidata, a_major * a_major, R_minor);
    }
    applyForce(sidata, P, delta, vn, Sn, kn, kt, i_forces, j_forces);
    if (ax) publish(sidata, c, ax);
    return true;
  }

  /* The law of this contact: adhesionLaw, or under tabor the one the
     pair's Tabor parameter picks; w = 0: JKR's path (Hertz). */
  int lawOf(const SurfacesCloseData &d) const
  {
    if (law < LAW_MD) return law;
    if (work[d.itype][d.jtype] == 0.0) return LAW_JKR;
    if (law == LAW_MD) return LAW_MD;
    static const int of_tabor[] = {LAW_JKR, LAW_DMT, LAW_MD};   /* by DC_ADHESION_JKR, _DMT, _MD */
    return of_tabor[dc_md_tabor_law(&md[d.itype * (ntypes_ + 1) + d.jtype], sphereEffectiveRadius(d))];
  }

  /* Maugis-Dugdale at overlap delta (superquadrics: the sphere of elliptic
     Hertz's force radius, dc_md_ellipse): false (nothing applied) when the
     contact is apart. Damping on the punch stiffness 2 E* a (none while
     only the zone acts). */
  bool mdForce(SurfacesIntersectData &sidata, double delta, double vn, ForceData &i_forces, ForceData &j_forces)
  {
    const int itype = sidata.itype, jtype = sidata.jtype;
    const dc_md_sphere_pair &p = md[itype * (ntypes_ + 1) + jtype];
    dc_md_contact *h = reinterpret_cast<dc_md_contact *>(&sidata.contact_history[md_offset]);
    const bool forming = h->phase == DC_MD_APART;
    double R = sphereEffectiveRadius(sidata), R_minor = R, R_law = R, F, a;   /* R_law: the law's sphere */
    int st;
    if (superquadric(sidata)) {
      dc_hertz_geom g;
      relativeRadii(sidata, R, R_minor, NULL);
      st = dc_hertz_geometry(R, R_minor, &g);
      R_law = g.R_force;
      if (st == DC_OK) st = dc_md_ellipse(&p, &g, delta, h, &F, &a);
    } else {
      st = dc_md_sphere(&p, R, delta, h, &F, &a);
    }
    if (st != DC_OK) fail("Maugis-Dugdale contact", delta, R, R_minor, work[itype][jtype], Yeff[itype][jtype], st);
    if (h->phase == DC_MD_APART) return false;
    if (forming) checkReach(sidata, dc_md_reach(h->lambda) * p.Cd * (h->lambda / p.Lam), whyReach(), work[itype][jtype]);
    double kn = 0.0, kt = 0.0;
    if (a > 0.0) {
      kn = dc_punch_stiffness_circle(Yeff[itype][jtype], a);
      kt = dc_mindlin_kt_circle(Geff[itype][jtype], a);
      checkHertzRange(sidata, a * a, R_minor);
    }
    applyForce(sidata, F, delta, vn, kn, kn, kt, i_forces, j_forces);
    double axis[3];
    double *ax = axisWanted(axis);
    if (ax) {
      const double sF = p.piw * R_law;   /* the force's scale pi w R */
      dc_contact c = {F, kn, M_PI * a * a, a, a, 0.0, a > 0.0};
      if (a > 0.0) c.F_bound = dc_md_friction_load(h, F / sF) * sF;
      if (!(c.F_bound >= 0.0))
        fail("Maugis-Dugdale pull-off force", delta, R, R_minor, work[itype][jtype], Yeff[itype][jtype], DC_ENOCONV);
      publish(sidata, c, ax);
    }
    return true;
  }

  static const char *whyReach() { return "adhesive contacts (work of adhesion %g J/m^2) are kept until separation"; }
  enum { LAW_JKR = 0, LAW_DMT = 1, LAW_MD = 2, LAW_TABOR = 3 };
  double **work, **z0 = NULL;
  int law;   /* adhesionLaw */
  std::vector<dc_jkr_sphere_pair> spheres;   /* per type pair, for the sphere hot path */
  std::vector<dc_md_sphere_pair> md;         /* per type pair (maugis, tabor) */
  int contact_offset, hint_offset, md_offset = -1;
#ifdef SUPERQUADRIC_ACTIVE_FLAG
  SuperquadricGap gap;
#endif
};

}
}
#endif
#endif
