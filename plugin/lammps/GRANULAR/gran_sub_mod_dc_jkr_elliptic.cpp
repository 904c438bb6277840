/* dc/jkr_elliptic (gran_sub_mod_dc_jkr_elliptic.h). */
#include "gran_sub_mod_dc_jkr_elliptic.h"

#include "dc/damping.h"
#include "dc/hertz_elliptic.h"
#include "dc/jkr_elliptic.h"
#include "dc/jkr_sphere.h"

#include <cstring>
#include <vector>

using namespace LAMMPS_NS;
using namespace Granular_NS;

GranSubModNormalDcJkrElliptic::GranSubModNormalDcJkrElliptic(GranularModel *gm, LAMMPS *lmp) :
    GranSubModDcNormal(gm, lmp)
{
  num_coeffs = 6;
  cohesive_flag = 1;
  beyond_contact = 1;
  want_patch();    // Fncrit is the patch's friction load
}

void GranSubModNormalDcJkrElliptic::coeffs_to_local()
{
  material_coeffs();
  check_coeff("w", coeffs[3], 0.0, 0, HUGE_VAL, 1, "[0, inf)");
  law_ = dc_check_choice(error, name, "law", coeffs[4], 4, "{0 jkr, 1 dmt, 2 maugis, 3 tabor}");
  if (law_ >= LAW_MD)
    check_coeff("z0", coeffs[5], 0.0, 1, HUGE_VAL, 1, "(0, inf) (laws maugis and tabor)");
  else
    check_coeff("z0", coeffs[5], 0.0, 0, HUGE_VAL, 1, "[0, inf)");
  w_ = coeffs[3];
  z0_ = coeffs[5];
  dc_param_error err;
  if (dc_jkr_check(w_, &err) != DC_OK)
    error->all(FLERR, "{} coefficient w = {} is outside {}", name, err.value, err.range);
  if (law_ >= LAW_MD && w_ > 0.0 && dc_md_sphere_pair_of(Estar_, w_, z0_, &md_, &err) != DC_OK)
    error->all(FLERR, "{}: {} = {} is outside {} (from w, z0 and E*)", name, err.name, err.value, err.range);

  // history: the formed flag, then (laws maugis, tabor) the Maugis-Dugdale state
  std::vector<dc_history_field> table(1, dc_jkr_history[0]);
  if (law_ >= LAW_MD) table.insert(table.end(), dc_md_history, dc_md_history + DC_MD_CONTACT_NFIELDS);
  dc_history_transfer(this, table.data(), (int) table.size());
}

void GranSubModNormalDcJkrElliptic::mix_coeffs(double *icoeffs, double *jcoeffs)
{
  if (icoeffs[4] != jcoeffs[4])
    error->all(FLERR, "{}: types with different adhesion laws ({} and {}) cannot be mixed", name, icoeffs[4],
               jcoeffs[4]);
  mix_material(icoeffs[0], icoeffs[2], jcoeffs[0], jcoeffs[2]);
  coeffs[0] = icoeffs[0] == jcoeffs[0] ? icoeffs[0] : mix_geom(icoeffs[0], jcoeffs[0]);
  coeffs[1] = mix_geom(icoeffs[1], jcoeffs[1]);
  coeffs[2] = mix_geom(icoeffs[2], jcoeffs[2]);
  coeffs[3] = mix_geom(icoeffs[3], jcoeffs[3]);
  coeffs[4] = icoeffs[4];
  coeffs[5] = mix_geom(icoeffs[5], jcoeffs[5]);
  coeffs_to_local();
}

/* The law of a contact of effective radius R: law, or under tabor the one
   the Tabor parameter picks; w = 0: JKR's path (Hertz). */
int GranSubModNormalDcJkrElliptic::law_of(double R) const
{
  if (law_ < LAW_MD) return law_;
  if (w_ == 0.0) return LAW_JKR;
  if (law_ == LAW_MD) return LAW_MD;
  static const int of_tabor[] = {LAW_JKR, LAW_DMT, LAW_MD};    // by DC_ADHESION_JKR, _DMT, _MD
  return of_tabor[dc_md_tabor_law(&md_, R)];
}

/* How far before touch [m] a Maugis-Dugdale contact of effective radius R
   may act: the zone's reach h0 on approach, the last attached state
   (dc_md_reach) once it acts; a little more, the law decides. */
double GranSubModNormalDcJkrElliptic::reach(double R) const
{
  const double c = std::cbrt(R), r = dc_md_reach(md_.Lam * c) * md_.Cd * c;
  return (r > md_.h0 ? r : md_.h0) * (1.0 + 1e-9);
}

/* A new contact when the surfaces overlap (Maugis-Dugdale: within h0); a
   touching one (gm->touch) until the law's separation distance. */
bool GranSubModNormalDcJkrElliptic::touch()
{
  const double rs = gm->radsum;
  if (gm->rsq < rs * rs) return true;
  if (w_ == 0.0) return false;
  const double R = gm->Reff;
  double d = 0.0;
  switch (law_of(R)) {
    case LAW_JKR:
      if (gm->touch) d = -dc_jkr_sphere_delta_break(R, Estar_, w_) * (1.0 + 1e-9);
      break;
    case LAW_MD:
      d = gm->touch ? reach(R) : md_.h0;
      break;
    default:
      return false;
  }
  return gm->rsq < (rs + d) * (rs + d);
}

/* The neighbour cutoff's extra distance beyond touch. */
double GranSubModNormalDcJkrElliptic::pulloff_distance(double radi, double radj)
{
  const double R = radi * radj / (radi + radj);
  if (!(R > 0.0) || w_ == 0.0) return 0.0;
  switch (law_of(R)) {
    case LAW_JKR:
      return -dc_jkr_sphere_delta_break(R, Estar_, w_) * (1.0 + 1e-9);
    case LAW_MD:
      return reach(R);
    default:
      return 0.0;
  }
}

void GranSubModNormalDcJkrElliptic::none()
{
  F_ = S_ = radius_ = 0.0;
  patch_ = dc_patch();
}

/* The LIGGGHTS model's sphere paths (surfacesIntersect for delta > 0,
   surfacesClose otherwise). History is written only when
   gm->history_update. */
void GranSubModNormalDcJkrElliptic::evaluate()
{
  const double R = gm->Reff, delta = gm->delta;
  double *hist = &gm->history[history_index];
  const bool update = gm->history_update;
  const int lw = law_of(R);
  dc_contact c;
  if (lw == LAW_MD) {
    dc_md_contact h;
    std::memcpy(&h, hist + 1, sizeof h);
    const double reach_pair = gm->radsum + md_.h0;
    if (h.phase == DC_MD_APART && gm->contact_type == PAIR && gm->rsq >= reach_pair * reach_pair) return none();
    double F, a;
    const int st = dc_md_sphere(&md_, R, delta, &h, &F, &a);
    if (st != DC_OK)
      error->one(FLERR, "{}: Maugis-Dugdale contact at overlap {}, radius {}: {}", name, delta, R, dc_status_str(st));
    if (h.phase == DC_MD_APART) {
      if (update) std::memcpy(hist + 1, &h, sizeof h);
      return none();
    }
    double kn = 0.0;
    if (a > 0.0) kn = dc_punch_stiffness_circle(Estar_, a);
    c = {F, kn, M_PI * a * a, a, a, 0.0, a > 0.0};
    if (a > 0.0) {
      const double sF = md_.piw * R;    // the force's scale pi w R
      c.F_bound = dc_md_friction_load(&h, F / sF) * sF;
      if (!(c.F_bound >= 0.0))
        error->one(FLERR, "{}: Maugis-Dugdale pull-off force at overlap {}, radius {}: no convergence", name, delta,
                   R);
    }
    if (update) std::memcpy(hist + 1, &h, sizeof h);
    F_ = F;
    S_ = kn;
    radius_ = a;
    dc_patch_from_contact(&c, nullptr, &patch_);
    return;
  }

  const bool formed = hist[0] > 0.0;
  if (!(delta > 0.0) && (!formed || w_ == 0.0 || lw == LAW_DMT)) {
    if (update) hist[0] = 0.0;
    return none();
  }
  const bool forming = !formed;
  if (update) hist[0] = 1.0;
  if (lw == LAW_DMT) {
    dc_hertz_geom g;
    dc_hertz_geometry_circle(R, &g);
    const int st = dc_dmt_contact(&g, Estar_, w_, delta, &c);
    if (st != DC_OK) error->one(FLERR, "{}: DMT contact at overlap {}, radius {}: {}", name, delta, R, dc_status_str(st));
    if (!c.formed) return none();
    F_ = c.F;
    S_ = c.kn;
    radius_ = c.a;
  } else if (w_ == 0.0) {
    double kn;
    radius_ = dc_hertz_stiffness(Estar_, R, delta, &kn, &S_);
    F_ = kn * delta;
    dc_hertz_geom g;
    dc_hertz_geometry(R, R, &g);
    dc_hertz_normal(&g, Estar_, delta, &c);
  } else {
    const dc_jkr_sphere_pair pair = dc_jkr_sphere_pair_of(Estar_, w_);
    double a, P;
    if (!forming && dc_jkr_sphere_near_hertz(&pair, R, delta, &a, &P)) {
      /* the Hertz-like end: the LIGGGHTS model's inline path (the same bits) */
      S_ = dc_punch_stiffness_circle(Estar_, a);
      F_ = P;
      radius_ = a;
      c = {P, S_, M_PI * a * a, a, a, dc_jkr_friction_load(P, dc_jkr_sphere_pulloff(R, w_)), 1};
    } else {
      dc_jkr_state s;
      const int st = dc_jkr_sphere(R, Estar_, w_, delta, &s);
      if (st != DC_OK)
        error->one(FLERR, "{}: JKR contact at overlap {}, radius {}: {}", name, delta, R, dc_status_str(st));
      if (!s.contact) {
        if (update) hist[0] = 0.0;
        return none();
      }
      S_ = dc_punch_stiffness_circle(Estar_, s.a);
      F_ = s.F;
      radius_ = s.a;
      dc_jkr_normal(&s, dc_jkr_sphere_pulloff(R, w_), &c);
    }
  }
  dc_patch_from_contact(&c, nullptr, &patch_);
}
