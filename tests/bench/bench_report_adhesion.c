/* Speed-versus-error report, family "adhesion": the normal force along a
   loading-unloading path of two adhesive contacts.

   Scene "elliptic JKR": Johnson-Greenwood elliptic JKR contacts (R_major =
   1 mm, R_minor/R_major = 0.5, 0.1, 0.02, E* = 2.75 MPa, w = 0.05 J/m^2)
   loaded from touch (delta = 0) to 10 |delta_break| and unloaded to the
   separation point. Reference: the exact states of the theory, from its
   forward map (dc_jkr_at_eccentricity: overlap and force in closed form
   at a contact eccentricity; the path's overlaps are those of eccentricities
   found by bisection). Laws at those overlaps: jkr_elliptic (dc_jkr_contact)
   with the per-contact hint carried along the path, as in a DEM run, and
   without it; classical JKR for spheres with the Gaussian-curvature radius
   (R_major R_minor)^1/2 and with the mean-curvature radius
   2 R_major R_minor / (R_major + R_minor); elliptic Hertz without adhesion.
   Kernel call: the force at one overlap, the geometry (dc_jkr_geometry,
   dc_hertz_geometry) set up beforehand (note says what it costs).

   Scene "rough adhesive": GW rough contact with adhesive JKR summits
   (review Eq. 29; summit radius 0.75 mm, E* = 2.75 MPa, w = 0.05 J/m^2,
   sigma = 0.3 and 1 um: Fuller-Tabor parameter E* sigma^3/2 / (w R^1/2)
   = 0.33 and 2, strong adhesion; n_asp = 1) from (D + 8) sigma apart (the
   tabulated law's reach, D = |delta_break|/sigma of a summit) to delta =
   3 sigma and back. Reference: dc_gw_rough_adhesive (quadrature of the summit law),
   loading branch on approach, unloading branch on retraction once delta <=
   delta_max + delta_break (there it is exact; in the band above, the
   partly attached summits lie between the branches and the path is not
   compared). Laws: the tabulated adhesive part (dc_gwa_table_step, with
   its loading/unloading history, the LIGGGHTS cohesion model gw_adhesion)
   plus the GW closed form, and the GW closed form alone (adhesion ignored).

   Scenes "Tabor range": spheres (R = 1 mm, E* = 2.75 MPa, w = 0.05 J/m^2,
   z0 giving Maugis' lambda = 0.1, 1 and 10) under overlap control from
   apart (the model's reach) to Dbar = 3 and back to apart, 400 overlaps
   each way. Reference: Maugis-Dugdale's reference evaluation at each
   overlap (dc_md_at_overlap on the contact branch, dc_md_zone before and
   after it, the phase of dc_md_step's path: its transitions are checked
   against the reference in tests/unit/test_maugis_dugdale.c). Laws:
   adhesionLaw maugis (dc_md_sphere with the contact's history, as in a
   run), jkr (classical JKR: contact from touch to its separation
   overlap), dmt (Hertz less 2 pi w R from touch on), Hertz (adhesion
   ignored). Error per pull-off force of the model (load control).

   Scenes "ellipse at the Tabor limits": adhesionLaw maugis on superquadrics
   is the law of the sphere of elliptic Hertz's force radius (dc_md_ellipse).
   R_major = 1 mm, R_minor/R_major = 0.5 and 0.1: at lambda = 1e-3 against
   elliptic DMT (exact there: Hertz's ellipse less 2 pi w (R_major
   R_minor)^1/2) from touch to 10 overlap scales; at lambda = 1e3 against
   the Johnson-Greenwood elliptic JKR (jkr_elliptic, exact there) on the
   elliptic JKR scene's path.

   Error: max |F - F_exact| over the path / the pull-off force (the largest
   tensile force of the exact path). Prints CSV (report_common.h). */
#include "dc/gw_rough.h"
#include "dc/gw_rough_adhesive.h"
#include "dc/gw_rough_adhesive_table.h"
#include "dc/jkr_elliptic.h"
#include "dc/jkr_sphere.h"
#include "dc/maugis_dugdale.h"
#include "dc/status.h"
#include "report_common.h"

static const double ESTAR = 2.75e6, W = 0.05;
#define NUP 200
#define NDOWN 300
#define NPATH (NUP + NDOWN)

/* ---- elliptic JKR ---- */

static const double RATIOS[] = {0.5, 0.1, 0.02};
enum { NR = sizeof RATIOS / sizeof RATIOS[0] };

typedef struct {
  dc_jkr_geom G;
  dc_hertz_geom hertz;
  double R_gauss, R_mean;
  double delta[NPATH], F[NPATH];  /* exact states along the path */
} jkr_case;

static jkr_case J[NR];

/* The exact state whose overlap is target (the stable branch: delta
   increases with e^2 from e2_break to e2_hertz), by bisection in e^2. */
static void jkr_exact_at(const dc_jkr_geom *G, double target, double *delta, double *F)
{
  double lo = G->e2_break, hi = G->e2_hertz;
  dc_jkr_state s = {0};
  for (int it = 0; it < 200 && hi - lo > 1e-16 * hi; it++) {
    const double mid = 0.5 * (lo + hi);
    if (dc_jkr_at_eccentricity(G, mid, &s) != DC_OK) { hi = mid; continue; }
    if (s.delta < target) lo = mid; else hi = mid;
  }
  dc_jkr_at_eccentricity(G, 0.5 * (lo + hi), &s);
  *delta = s.delta;
  *F = s.F;
}

static void jkr_setup(void)
{
  for (int r = 0; r < NR; r++) {
    jkr_case *c = &J[r];
    const double R1 = 1e-3, R2 = 1e-3 * RATIOS[r];
    if (dc_jkr_geometry(R1, R2, ESTAR, W, &c->G) != DC_OK || dc_hertz_geometry(R1, R2, &c->hertz) != DC_OK) exit(1);
    c->R_gauss = sqrt(R1 * R2);
    c->R_mean = 2.0 * R1 * R2 / (R1 + R2);
    const double db = c->G.delta_break, top = 10.0 * fabs(db);
    for (int k = 0; k < NUP; k++) jkr_exact_at(&c->G, top * k / (NUP - 1.0), &c->delta[k], &c->F[k]);
    for (int k = 0; k < NDOWN; k++) {
      const double t = (k + 1.0) / NDOWN;   /* down to 1e-6 |db| above the separation point */
      jkr_exact_at(&c->G, top + (db * (1.0 - 1e-6) - top) * t, &c->delta[NUP + k], &c->F[NUP + k]);
    }
  }
}

enum { JKR_WARM, JKR_COLD, JKR_GAUSS, JKR_MEAN, JKR_HERTZ };

static double jkr_force(int law, const jkr_case *c, int i, dc_jkr_hint *hint)
{
  dc_jkr_state s;
  dc_hertz_state h;
  switch (law) {
  case JKR_WARM: dc_jkr_contact(&c->G, c->delta[i], hint, &s); return s.F;
  case JKR_COLD: dc_jkr_contact(&c->G, c->delta[i], NULL, &s); return s.F;
  case JKR_GAUSS: dc_jkr_sphere(c->R_gauss, ESTAR, W, c->delta[i], &s); return s.F;
  case JKR_MEAN: dc_jkr_sphere(c->R_mean, ESTAR, W, c->delta[i], &s); return s.F;
  default: return c->delta[i] > 0.0 && dc_hertz_contact(&c->hertz, ESTAR, c->delta[i], &h) == DC_OK ? h.F : 0.0;
  }
}

static void jkr_rows(void)
{
  const char *names[] = {"jkr_elliptic (hint carried)", "jkr_elliptic (no hint)",
                         "classical JKR: Gaussian-curvature radius", "classical JKR: mean-curvature radius",
                         "hertz_elliptic (adhesion ignored)"};
  double ns_geom;
  dc_jkr_geom g;
  REPORT_TIME(ns_geom, NR, { dc_jkr_geometry(1e-3, 1e-3 * RATIOS[i], ESTAR, W, &g); acc += g.F_pull; });
  char geom_note[96];
  snprintf(geom_note, sizeof geom_note, "geometry per contact %.0f ns more (each step for superquadrics)", ns_geom);
  for (int law = JKR_WARM; law <= JKR_HERTZ; law++) {
    report_err e = {0};
    double ns_sum = 0.0;
    for (int r = 0; r < NR; r++) {
      const jkr_case *c = &J[r];
      dc_jkr_hint hint = {0};
      const double pull = -c->G.F_pull;
      for (int i = 0; i < NPATH; i++) report_err_add(&e, (jkr_force(law, c, i, &hint) - c->F[i]) / pull);
      double ns;
      REPORT_TIME(ns, NPATH, {
        if (i == 0) hint = (dc_jkr_hint){0};
        acc += jkr_force(law, c, i, &hint);
      });
      ns_sum += ns;
    }
    report_row("adhesion", "elliptic JKR load-unload path", names[law], law == JKR_WARM, ns_sum / NR, &e,
               "max |F - F_exact| / pull-off force (rms)", law <= JKR_COLD ? geom_note : "");
  }
}

/* ---- rough adhesive ---- */

static const double SIGMAS[] = {3e-7, 1e-6};
enum { NSIG = sizeof SIGMAS / sizeof SIGMAS[0] };
static const double R_SUMMIT = 0.75e-3;

typedef struct {
  double sigma;
  dc_jkr_geom G;
  dc_hertz_geom circle;
  dc_gwa_table_pair table;
  double delta[NPATH], F[NPATH];
  int compared[NPATH];   /* 0 in the band where the exact force is not defined */
  double pull;
} rough_case;

static rough_case Q[NSIG];

static void rough_setup(void)
{
  for (int k = 0; k < NSIG; k++) {
    rough_case *c = &Q[k];
    c->sigma = SIGMAS[k];
    if (dc_jkr_geometry(R_SUMMIT, R_SUMMIT, ESTAR, W, &c->G) != DC_OK ||
        dc_gwa_table_pair_init(ESTAR, W, c->sigma, 1.0, &c->table) != DC_OK)
      exit(1);
    dc_hertz_geometry_circle(R_SUMMIT, &c->circle);
    /* from the table's reach (D + 8) sigma, D = |delta_break|/sigma */
    const double lo = c->G.delta_break - 8.0 * c->sigma, top = 3.0 * c->sigma;
    c->pull = 0.0;
    for (int i = 0; i < NPATH; i++) {
      const int up = i < NUP;
      c->delta[i] = up ? lo + (top - lo) * i / (NUP - 1.0) : top + (lo - top) * (i - NUP + 1.0) / NDOWN;
      c->compared[i] = up || c->delta[i] <= top + c->G.delta_break;
      dc_gw_adhesive_state s;
      if (dc_gw_rough_adhesive(&c->G, 1.0, c->sigma, c->delta[i], up ? DC_GW_LOADING : DC_GW_UNLOADING, &s) != DC_OK)
        exit(1);
      c->F[i] = s.F;
      if (c->compared[i] && -s.F > c->pull) c->pull = -s.F;
    }
  }
}

enum { GWA_EXACT, GWA_TABLE, GWA_NONE };

static double rough_force(int law, const rough_case *c, int i, double hist[2])
{
  dc_gw_rough_state s;
  dc_gw_adhesive_state a;
  dc_gwa_table_out o;
  switch (law) {
  case GWA_EXACT:
    dc_gw_rough_adhesive(&c->G, 1.0, c->sigma, c->delta[i], i < NUP ? DC_GW_LOADING : DC_GW_UNLOADING, &a);
    return a.F;
  case GWA_TABLE:
    dc_gwa_table_step(&c->table, R_SUMMIT, c->delta[i], hist, &o);
    dc_gw_rough_elliptic(&c->circle, ESTAR, 1.0, c->sigma, c->delta[i], &s);
    return s.F + o.F;
  default:
    dc_gw_rough_elliptic(&c->circle, ESTAR, 1.0, c->sigma, c->delta[i], &s);
    return s.F;
  }
}

static void rough_rows(void)
{
  const char *names[] = {"gw_rough_adhesive (exact)", "gw_adhesion table + GW closed form",
                         "GW closed form (adhesion ignored)"};
  for (int law = GWA_EXACT; law <= GWA_NONE; law++) {
    report_err e = {0};
    double ns_sum = 0.0;
    for (int k = 0; k < NSIG; k++) {
      const rough_case *c = &Q[k];
      double hist[2] = {0, 0};
      for (int i = 0; i < NPATH; i++) {
        const double F = rough_force(law, c, i, hist);
        if (c->compared[i]) report_err_add(&e, (F - c->F[i]) / c->pull);
      }
      double ns;
      REPORT_TIME(ns, NPATH, {
        if (i == 0) hist[0] = hist[1] = 0.0;
        acc += rough_force(law, c, i, hist);
      });
      ns_sum += ns;
    }
    report_row("adhesion", "rough adhesive load-unload path", names[law], law == GWA_EXACT, ns_sum / NSIG, &e,
               "max |F - F_exact| / pull-off force (rms)", law == GWA_TABLE ? "LIGGGHTS cohesion gw_adhesion" : "");
  }
}

/* ---- the Tabor range ---- */

/* equilibriumSeparation z0 for Maugis' lambda at the effective radius R */
static double z0_of_lambda(double lambda, double R, double w)
{
  const double K = 4.0 / 3.0 * ESTAR;
  return 32.0 * w / (9.0 * sqrt(3.0) * lambda) * cbrt(R / (M_PI * w * K * K));
}

static const double LAMBDAS[] = {0.1, 1.0, 10.0};
enum { NL = sizeof LAMBDAS / sizeof LAMBDAS[0], NT = 800 };

enum { TB_MD, TB_JKR, TB_DMT, TB_HERTZ };

/* One law along the path (delta[0..NT-1]): its forces into F */
static void tabor_path(int law, const dc_md_sphere_pair *p, double R, const double *delta, double *F)
{
  dc_md_contact h = {0};
  int formed = 0;
  for (int i = 0; i < NT; i++) {
    const double d = delta[i];
    double a;
    dc_jkr_state s;
    dc_hertz_state hz;
    dc_hertz_geom g;
    dc_contact c;
    switch (law) {
    case TB_MD: dc_md_sphere(p, R, d, &h, &F[i], &a); break;
    case TB_JKR:   /* forms at touch, holds to the separation overlap */
      if (d >= 0.0) formed = 1;
      F[i] = 0.0;
      if (formed && dc_jkr_sphere(R, ESTAR, W, d, &s) == DC_OK && s.contact) F[i] = s.F;
      else formed = 0;
      break;
    case TB_DMT:
      dc_hertz_geometry_circle(R, &g);
      F[i] = dc_dmt_contact(&g, ESTAR, W, d, &c) == DC_OK ? c.F : NAN;
      break;
    default:
      dc_hertz_geometry_circle(R, &g);
      F[i] = d > 0.0 && dc_hertz_contact(&g, ESTAR, d, &hz) == DC_OK ? hz.F : 0.0;
    }
  }
}

static void tabor_rows(void)
{
  const char *names[] = {"adhesionLaw maugis (Maugis-Dugdale)", "adhesionLaw jkr (classical JKR)",
                         "adhesionLaw dmt (DMT)", "hertz_elliptic (adhesion ignored)"};
  const double R = 1e-3;
  for (int L = 0; L < NL; L++) {
    const double lam = LAMBDAS[L];
    dc_md_sphere_pair p;
    dc_param_error err;
    if (dc_md_sphere_pair_of(ESTAR, W, z0_of_lambda(lam, R, W), &p, &err) != DC_OK) exit(1);
    const double r3 = cbrt(R), sd = p.Cd * r3, sF = p.piw * R, reach = dc_md_reach(lam);
    static double delta[NT], F[NT], Fref[NT];
    for (int i = 0; i < NT; i++) {
      const double t = i < NT / 2 ? i / (NT / 2 - 1.0) : (NT - 1.0 - i) / (NT / 2 - 1.0);
      delta[i] = (-reach - 0.2 + (3.2 + reach) * t) * sd;
    }
    /* the reference: the phase of the model's path, the state from the reference evaluation */
    dc_md_contact h = {0};
    double Pc, ac;
    if (dc_md_pulloff(lam, &Pc, &ac) != DC_OK) exit(1);
    for (int i = 0; i < NT; i++) {
      double Fm, a;
      dc_md_sphere(&p, R, delta[i], &h, &Fm, &a);
      const double D = delta[i] / sd;
      Fref[i] = 0.0;
      if (h.phase == DC_MD_CONTACT) {
        int contact;
        double ar, m, P;
        if (dc_md_at_overlap(lam, D, &contact, &ar, &m, &P) != DC_OK || !contact) exit(1);
        Fref[i] = P * sF;
      } else if (h.phase == DC_MD_ZONE) {
        int zone;
        double cb, P;
        dc_md_zone(lam, D, &zone, &cb, &P);
        Fref[i] = P * sF;
      }
    }
    char scene[96];
    snprintf(scene, sizeof scene, "Tabor range: sphere load-unload path lambda %g", lam);
    for (int law = TB_MD; law <= TB_HERTZ; law++) {
      report_err e = {0};
      tabor_path(law, &p, R, delta, F);
      for (int i = 0; i < NT; i++) report_err_add(&e, (F[i] - Fref[i]) / (-Pc * sF));
      double ns;
      REPORT_TIME(ns, 1, { tabor_path(law, &p, R, delta, F); acc += F[NT / 2]; });
      report_row("adhesion", scene, names[law], law == TB_MD, ns / NT, &e, "max |F - F_exact| / pull-off force (rms)",
                 law == TB_MD ? "the contact's history carried; before touch the zone" : "");
    }
  }
}

/* ---- ellipses at the Tabor limits ---- */

static void ellipse_rows(void)
{
  const double ratios[] = {0.5, 0.1};
  for (int end = 0; end < 2; end++) {   /* 0: lambda 1e-3 against elliptic DMT; 1: lambda 1e3 against elliptic JKR */
    report_err e_md = {0}, e_ex = {0};
    double ns_md = 0.0, ns_ex = 0.0;
    for (int r = 0; r < 2; r++) {
      const double R1 = 1e-3, R2 = 1e-3 * ratios[r], lam = end ? 1e3 : 1e-3;
      dc_md_sphere_pair p;
      dc_param_error err;
      dc_hertz_geom g;
      dc_jkr_geom G;
      if (dc_hertz_geometry(R1, R2, &g) != DC_OK || dc_jkr_geometry(R1, R2, ESTAR, W, &G) != DC_OK ||
          dc_md_sphere_pair_of(ESTAR, W, z0_of_lambda(lam, g.R_force, W), &p, &err) != DC_OK)
        exit(1);
      static double delta[NPATH], Fex[NPATH], F[NPATH];
      double pull;
      if (end == 0) {   /* from touch to 10 overlap scales, loading */
        const double top = 10.0 * p.Cd * cbrt(g.R_force);
        pull = 2.0 * M_PI * W * sqrt(R1 * R2);
        for (int i = 0; i < NPATH; i++) {
          dc_contact c;
          delta[i] = top * (i + 1.0) / NPATH;
          if (dc_dmt_contact(&g, ESTAR, W, delta[i], &c) != DC_OK) exit(1);
          Fex[i] = c.F;
        }
      } else {   /* the elliptic JKR scene's path */
        pull = -G.F_pull;
        for (int i = 0; i < NPATH; i++) {
          delta[i] = J[r == 0 ? 0 : 1].delta[i];
          Fex[i] = J[r == 0 ? 0 : 1].F[i];
        }
      }
      /* the Gaussian-radius law with its history, from the first overlap on */
      dc_md_contact h = {0};
      double a;
      for (int i = 0; i < NPATH; i++) {
        dc_md_ellipse(&p, &g, delta[i], &h, &F[i], &a);
        report_err_add(&e_md, (F[i] - Fex[i]) / pull);
        report_err_add(&e_ex, 0.0);
      }
      double ns;
      REPORT_TIME(ns, 1, {
        dc_md_contact hh = {0};
        for (int k = 0; k < NPATH; k++) { dc_md_ellipse(&p, &g, delta[k], &hh, &F[k], &a); }
        acc += F[0];
      });
      ns_md += ns / NPATH / 2.0;
      dc_jkr_hint hint = {0};
      REPORT_TIME(ns, NPATH, {
        dc_contact c;
        dc_jkr_state s;
        if (end == 0) { dc_dmt_contact(&g, ESTAR, W, delta[i], &c); acc += c.F; }
        else { if (i == 0) hint = (dc_jkr_hint){0}; dc_jkr_contact(&G, delta[i], &hint, &s); acc += s.F; }
      });
      ns_ex += ns / 2.0;
    }
    const char *scene = end ? "ellipse at the JKR end (lambda 1e3; R_minor/R_major 0.5 and 0.1)"
                            : "ellipse at the DMT end (lambda 1e-3; R_minor/R_major 0.5 and 0.1)";
    report_row("adhesion", scene, end ? "jkr_elliptic (Johnson-Greenwood)" : "adhesionLaw dmt (elliptic DMT)", 1, ns_ex,
               &e_ex, "max |F - F_exact| / pull-off force (rms)", "");
    report_row("adhesion", scene, "adhesionLaw maugis (sphere of the Hertz force radius)", 0, ns_md, &e_md,
               "max |F - F_exact| / pull-off force (rms)", "superquadrics");
  }
}

int main(void)
{
  jkr_setup();
  rough_setup();
  report_header();
  jkr_rows();
  rough_rows();
  tabor_rows();
  ellipse_rows();
  return 0;
}
