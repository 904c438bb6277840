/* dclaw scene: the measures of one contact of a scene (two spheres of
   radii R1, R2, or one on a wall) that tell which physics it needs
   (dc/scene.h, doc/advisor.md): its time scales, the Hertz impact at the
   largest speed and the contact at rest under a weight, and per effect a
   dimensionless measure with the change the richer law makes: plasticity
   (yield speed, Jamari-Schipper restitution), adhesion (Tabor parameter,
   JKR pull-off and sticking speed), roughness (the rough-sphere law's force
   over Hertz's), tangential memory (an oblique impact's tangential
   restitution under spring-sliding and Cattaneo-Mindlin). One CSV row. */
#include "cli.h"
#include "dc/classical_normal.h"
#include "dc/classical_tangential.h"
#include "dc/cmd_tangential.h"
#include "dc/cmd_turning_points.h"
#include "dc/gw_rough.h"
#include "dc/jamari_ep.h"
#include "dc/jkr_sphere.h"
#include "dc/maugis_dugdale.h"
#include "dc/mindlin.h"
#include "dc/rolling_kalker.h"
#include "dc/scene.h"
#include "dc/status.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

/* Restitution of a head-on Jamari-Schipper collision at speed v0 of
   effective mass me, integrated as a DEM code does (velocity Verlet,
   `steps` steps per elastic Hertz duration Tel), until the force vanishes
   while the bodies part; *dmax its largest overlap. */
static int jamari_restitution(const dc_hertz_geom *g, double Estar, const dc_jamari_params *p, double me, double v0,
                              double Tel, int steps, double *e, double *dmax)
{
  dc_jamari_state h = {0.0, 0.0, 0.0, 0.0};
  dc_contact c;
  const double dt = Tel / steps;
  double delta = 0.0, v = v0, F = 0.0;
  *dmax = 0.0;
  for (long i = 0; i < 100L * steps; i++) {
    const double vh = v - 0.5 * dt * F / me;
    delta += dt * vh;
    const int st = dc_jamari_step(g, Estar, p, delta, &h, &c);
    if (st) return st;
    F = c.F;
    v = vh - 0.5 * dt * F / me;
    if (delta > *dmax) *dmax = delta;
    if (vh < 0.0 && F <= 0.0) {
      *e = -v / v0;
      return DC_OK;
    }
  }
  return DC_ENOCONV;
}

/* Work the JKR neck takes from a sphere contact on its way apart: the
   tensile force on the unloading branch integrated from touch (delta = 0,
   where the model forms the neck on approach) to delta_break, Simpson's
   rule on 4000 intervals in a0 = (delta - delta_break)^1/2 (the force has a
   square-root vertical tangent at delta_break). */
static int jkr_separation_work(double R, double Estar, double w, double *W)
{
  const double db = dc_jkr_sphere_delta_break(R, Estar, w), s_top = sqrt(-db);
  const int n = 4000;
  double sum = 0.0;
  for (int i = 0; i <= n; i++) {
    const double s = s_top * i / n, delta = db + s * s;
    dc_jkr_state st;
    const int rc = dc_jkr_sphere(R, Estar, w, delta, &st);
    if (rc) return rc;
    /* d delta = 2 s ds */
    const double f = -st.F * 2.0 * s, c = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    sum += c * f;
  }
  *W = sum * s_top / n / 3.0;
  return DC_OK;
}

/* Tangential restitution of an oblique elastic Hertz impact (normal speed
   v, tangential v_t at the contact point, the bodies not spinning): the
   contact point's tangential speed after over before. Spheres of effective
   mass m: the slip speed s changes by -7/2 F_t / m (translation and the
   rolling of both, I = 2/5 m R^2). Tangential law: Cattaneo-Mindlin (cmd
   1: the exact profile, 2: cmdMemory turningPoints) or spring-sliding
   with Mindlin's stiffness (cmd 0, LIGGGHTS' stock history), stepped on
   the Hertz patch; symplectic Euler at Tc/4000.
   rolled (NULL: not wanted): the distance the contact rolls. */
static int oblique_beta(int cmd, const dc_mindlin_pair *mp, double Gstar, double Estar, double mu,
                        const dc_hertz_geom *g, double me, double v, double vt, double Tc, double *beta,
                        double *rolled)
{
  const dc_cmd_params cp = {mu, 0.0, 0, 0};
  const dc_classical_tangential_params sp = {DC_CT_SPRING_SLIDING, DC_CT_KT_MINDLIN, DC_CT_DAMP_NONE, mu, 0.0, 0.0,
                                             0.0, Gstar, Estar, 0.0, 0.0};
  dc_classical_tangential ct;
  dc_param_error perr;
  int st = dc_classical_tangential_init(&sp, &ct, &perr);
  if (st) return st;
  const dc_classical_tangential_contact cc = {me, 0.0, 0.0};
  const double n[3] = {0.0, 0.0, 1.0}, dt = Tc / 4000.0;
  dc_cmd_state hc;
  memset(&hc, 0, sizeof hc);
  dc_cmdtp_state ht;
  memset(&ht, 0, sizeof ht);
  dc_classical_tangential_state hs;
  memset(&hs, 0, sizeof hs);
  /* the rolled distance: the rolling speed of the kinematics (dc/rolling_kalker.h)
     of a sphere (relative radius R_force, spin R omega = wR) on a plane */
  const dc_rolling_curvature ci = {1.0 / g->R_force, 1.0 / g->R_force, {1.0, 0.0, 0.0}}, cj = {0.0, 0.0, {1.0, 0.0, 0.0}};
  double delta = 0.0, vn = v, slip = vt, wR = 0.0;
  if (rolled) *rolled = 0.0;
  for (long i = 0; i < 400000; i++) {
    delta += vn * dt;
    if (delta <= 0.0) {
      *beta = slip / vt;
      return DC_OK;
    }
    if (rolled) {
      const double dv[3] = {slip, 0.0, 0.0}, dw[3] = {0.0, wR / g->R_force, 0.0};
      dc_rolling_kin kin;
      if ((st = dc_rolling_kinematics(n, &ci, &cj, dv, dw, &kin))) return st;
      *rolled += kin.V * dt;
    }
    dc_hertz_state h;
    if ((st = dc_hertz_contact(g, Estar, delta, &h))) return st;
    const dc_patch pa = {h.a, h.a, {0.0, 0.0, 0.0}, h.F, h.F, 1.0};
    const double du[3] = {slip * dt, 0.0, 0.0}, vv[3] = {slip, 0.0, 0.0};
    double Ft;
    if (cmd) {
      dc_cmd_out o;
      if ((st = cmd == 2 ? dc_cmdtp_step(&cp, mp, &pa, n, du, 0.0, dt, &ht, &o)
                         : dc_cmd_step(&cp, mp, &pa, n, du, 0.0, dt, &hc, &o)))
        return st;
      Ft = o.Ft[0];
    } else {
      dc_classical_tangential_out o;
      if ((st = dc_classical_tangential_step(&ct, &pa, &cc, n, du, vv, dt, &hs, &o))) return st;
      Ft = o.Ft[0];
    }
    vn -= h.F / me * dt;
    slip -= 3.5 * Ft / me * dt;   /* the centre by F_t / m, the spin's R omega by 5/2 F_t / m */
    wR += 2.5 * Ft / me * dt;
  }
  return DC_ENOCONV;
}

static int cmd_scene(int argc, char **argv)
{
  dc_cli_option o[] = {
    {"R1", "radius of body 1 (volume-equivalent for a superquadric) [m]", 1e-3, 0},
    {"R2", "radius of body 2 [m]; 0: body 1 on a flat wall", 1e-3, 0},
    {"E1", "Young's modulus of body 1 [Pa] (deck: youngsModulus)", 5e6, 0},
    {"E2", "Young's modulus of body 2 or the wall [Pa]", 5e6, 0},
    {"nu1", "Poisson's ratio of body 1 (deck: poissonsRatio)", 0.3, 0},
    {"nu2", "Poisson's ratio of body 2 or the wall", 0.3, 0},
    {"rho1", "density of body 1 [kg/m^3] (deck: particle template)", 2500, 0},
    {"rho2", "density of body 2 [kg/m^3] (not read on a wall)", 2500, 0},
    {"v", "largest normal impact speed [m/s]", 1.0, 0},
    {"vt", "tangential speed at impact [m/s] (default: --v)", 0, 0},
    {"g", "gravity [m/s^2]: the resting contact carries body 1's weight", 9.81, 0},
    {"dt", "time step [s] (deck: timestep)", 1e-5, 0},
    {"mu", "friction coefficient (deck: coefficientFriction)", 0.5, 0},
    {"w", "work of adhesion [J/m^2]; 0: none", 0, 0},
    {"z0", "range of the surface forces for the Tabor parameter [m]", 0.4e-9, 0},
    {"sigma", "combined rms roughness [m] (deck: surfaceRoughness); 0: smooth", 0, 0},
    {"mu_rough", "Feng roughness parameter in [1, 50] (deck: roughnessMu)", 4, 0},
    {"H", "hardness of the softer body [Pa] (deck: hardness); 0: none given", 0, 0},
    {"steps", "time steps per elastic collision duration of the plastic impact", 2000, 0},
    {0, 0, 0, 0}};
  int st = dc_cli_parse(argc, argv, o,
                        "--R1 R --R2 R|0 --E1 E --E2 E --nu1 nu --nu2 nu --rho1 rho [--rho2 rho] --v v [--vt v] [--g g] "
                        "--dt dt [--mu mu] [--w w] [--z0 z] [--sigma s] [--mu_rough m] [--H H] [--steps N]");
  if (st) return st == 1 ? 0 : st;
  int steps;
  if (dc_cli_count(argv[0], o, "steps", &steps)) return 2;
  const double R1 = dc_cli_get(o, "R1"), R2 = dc_cli_get(o, "R2"), E1 = dc_cli_get(o, "E1"), E2 = dc_cli_get(o, "E2");
  const double nu1 = dc_cli_get(o, "nu1"), nu2 = dc_cli_get(o, "nu2"), rho1 = dc_cli_get(o, "rho1");
  const double rho2 = dc_cli_get(o, "rho2"), v = dc_cli_get(o, "v"), grav = dc_cli_get(o, "g"), dt = dc_cli_get(o, "dt");
  const double vt = dc_cli_given(o, "vt") ? dc_cli_get(o, "vt") : v, mu = dc_cli_get(o, "mu"), w = dc_cli_get(o, "w");
  const double sigma = dc_cli_get(o, "sigma"), H = dc_cli_get(o, "H");
  const int wall = R2 == 0.0;
  if (!(R1 > 0.0 && (wall || R2 > 0.0) && rho1 > 0.0 && (wall || rho2 > 0.0) && v > 0.0 && vt >= 0.0 &&
        grav >= 0.0 && dt > 0.0 && mu >= 0.0 && w >= 0.0 && sigma >= 0.0 && H >= 0.0)) {
    fprintf(stderr, "dclaw scene: --R1, --R2, --rho1, --rho2, --v, --vt, --g, --dt, --mu, --w, --sigma, --H: need "
                    "R1, rho1, v, dt > 0, R2 and rho2 > 0 (or R2 = 0: a wall), the others >= 0\n");
    return 2;
  }
  dc_mindlin_pair mp;
  if (!(E1 > 0.0 && E2 > 0.0 && nu1 >= 0.0 && nu1 <= 0.5 && nu2 >= 0.0 && nu2 <= 0.5) ||
      dc_mindlin_pair_init(E1, nu1, E2, nu2, &mp) != DC_OK) {
    fprintf(stderr, "dclaw scene: --E1, --E2, --nu1, --nu2: need E > 0 and nu in [0, 0.5]\n");
    return 2;
  }
  /* the pair: E*, G*, effective radius and mass (a wall: rigid in mass, its own modulus) */
  const double Estar = 1.0 / ((1.0 - nu1 * nu1) / E1 + (1.0 - nu2 * nu2) / E2);
  const double Gstar = 1.0 / (2.0 * mp.s0 - mp.s1);   /* 1 / sum (2 - nu_i)/G_i */
  const double R = wall ? R1 : R1 * R2 / (R1 + R2);
  const double m1 = 4.0 / 3.0 * M_PI * R1 * R1 * R1 * rho1, m2 = wall ? 0.0 : 4.0 / 3.0 * M_PI * R2 * R2 * R2 * rho2;
  const double me = wall ? m1 : m1 * m2 / (m1 + m2);
  dc_hertz_geom g;
  if ((st = dc_hertz_geometry(R, R, &g))) goto range;
  /* time scales: the Rayleigh time of the smaller body, the Hertz collision at v */
  double TR, TR2 = HUGE_VAL;
  if ((st = dc_scene_rayleigh_time(R1, rho1, E1, nu1, &TR)) ||
      (!wall && (st = dc_scene_rayleigh_time(R2, rho2, E2, nu2, &TR2))))
    goto range;
  TR = fmin(TR, TR2);
  const double Khz = 4.0 / 3.0 * Estar * sqrt(g.R_force);
  dc_classical_collision col;
  if ((st = dc_classical_hertz_collision(Khz, me, v, &col))) goto range;
  dc_hertz_state imp, rest;
  double d_rest;
  const double W = m1 * grav;
  if ((st = dc_hertz_contact(&g, Estar, col.dmax, &imp)) || (st = dc_scene_hertz_overlap(&g, Estar, W, &d_rest)) ||
      (st = dc_hertz_contact(&g, Estar, d_rest, &rest)))
    goto range;
  /* Hertz range (Fessler-Ollerton): semi-axis over the smaller body radius, below 0.5 */
  const double fessler = imp.a / (wall ? R1 : fmin(R1, R2));
  /* plasticity: overlap at impact over the yield onset delta_n1, restitution
     of the elastic-plastic impact (the softer body's nu for K_v) */
  double d_n1 = 0.0, d_n2 = 0.0, e_plastic = 1.0, dmax_plastic = col.dmax;
  if (H > 0.0) {
    const dc_jamari_params jp = dc_jamari_defaults(H, E1 <= E2 ? nu1 : nu2);
    dc_param_error err;
    if (dc_jamari_check(&jp, &err) != DC_OK) {
      fprintf(stderr, "dclaw scene: --H: %s = %g is outside %s\n", err.name, err.value, err.range);
      return 2;
    }
    if ((st = dc_jamari_onsets(&g, Estar, &jp, &d_n1, &d_n2)) ||
        (st = jamari_restitution(&g, Estar, &jp, me, v, col.Tc, steps, &e_plastic, &dmax_plastic)))
      goto range;
  }
  /* the impact speed that reaches delta_n1: 1/2 m v_y^2 = 2/5 K delta_n1^5/2 */
  const double v_yield = H > 0.0 ? sqrt(0.8 * Khz * d_n1 * d_n1 * sqrt(d_n1) / me) : 0.0;
  /* adhesion: Tabor parameter, JKR pull-off 3/2 pi w R against the weight and the impact force */
  double tabor = 0.0;
  if ((st = dc_scene_tabor(R, w, Estar, dc_cli_get(o, "z0"), &tabor))) goto range;
  const double pulloff = w > 0.0 ? dc_jkr_sphere_pulloff(R, w) : 0.0;
  /* JKR sticking: an impact slower than v_stick cannot pay the neck's work of separation */
  double W_sep = 0.0;
  if (w > 0.0 && (st = jkr_separation_work(R, Estar, w, &W_sep))) goto range;
  const double v_stick = sqrt(2.0 * W_sep / me);
  /* how far apart the models act: JKR until delta_break, the rough law from its reach */
  const double jkr_break = w > 0.0 ? -dc_jkr_sphere_delta_break(R, Estar, w) : 0.0;
  const double rough_reach = -dc_gw_sphere_reach(DC_GW_SPHERE_TABULATED) * sigma;
  /* Maugis-Dugdale (lambda from the Tabor parameter) acts from and to dc_md_reach overlap scales apart */
  const double lam = dc_md_lambda_of_tabor(tabor), K = 4.0 / 3.0 * Estar;
  const double md_reach = w > 0.0 && lam >= 1e-10 && lam <= 1e10 ? dc_md_reach(lam) * cbrt(M_PI * M_PI * w * w * R / (K * K)) : 0.0;
  /* roughness: the rough-sphere law (tabulated GW, dc/gw_rough.h) over Hertz, at rest and at impact */
  double rough_rest = 0.0, rough_imp = 0.0;
  if (sigma > 0.0) {
    dc_gw_sphere_pair gp;
    if ((st = dc_gw_sphere_pair_init(DC_GW_SPHERE_TABULATED, DC_FENG_TABLE, dc_cli_get(o, "mu_rough"), Estar, sigma,
                                     &gp))) {
      fprintf(stderr, "dclaw scene: --sigma, --mu_rough: %s (mu_rough in [1, 50], sigma > 0)\n", dc_status_str(st));
      return 2;
    }
    double P, kn;
    dc_gw_sphere_pair_force(&gp, sqrt(R), d_rest, &P, &kn);
    rough_rest = W > 0.0 ? P / W - 1.0 : 0.0;
    dc_gw_sphere_pair_force(&gp, sqrt(R), col.dmax, &P, &kn);
    rough_imp = P / col.Fmax - 1.0;
  }
  /* tangential memory: Mindlin's slip distance 3 mu F / (16 G* a) at the
     impact's largest force against the tangential displacement of one
     impact, vt times its duration */
  const double slip = mu > 0.0 ? 3.0 * mu * col.Fmax / (16.0 * Gstar * imp.a) : 0.0, ut = vt * col.Tc;
  /* the oblique impact's tangential restitution under both tangential laws */
  double beta_cmd = 0.0, beta_hist = 0.0, beta_tp = 0.0, rolled = 0.0;
  if (mu > 0.0 && vt > 0.0 &&
      ((st = oblique_beta(1, &mp, Gstar, Estar, mu, &g, me, v, vt, col.Tc, &beta_cmd, &rolled)) ||
       (st = oblique_beta(0, &mp, Gstar, Estar, mu, &g, me, v, vt, col.Tc, &beta_hist, NULL)) ||
       (st = oblique_beta(2, &mp, Gstar, Estar, mu, &g, me, v, vt, col.Tc, &beta_tp, NULL))))
    goto range;
  const char *cols =
    "R,Estar,Gstar,meff,weight,T_rayleigh,t_c,dt_over_T_rayleigh,steps_per_collision,delta_max,F_max,a_max,"
    "delta_rest,a_rest,fessler,delta_n1,v_yield,plastic_ratio,e_plastic,tabor,pulloff,pulloff_over_weight,"
    "pulloff_over_F_max,sigma_over_delta_rest,sigma_over_delta_max,rough_force_rest,rough_force_max,"
    "slip_distance,u_t,slip_ratio,jkr_separation,rough_reach,W_separation,v_stick,beta_cmd,beta_history,rolled_semi_axes,"
    "md_reach,beta_turning_points";
  printf("%s\n", cols);
  const double row[] = {R, Estar, Gstar, me, W, TR, col.Tc, dt / TR, col.Tc / dt, col.dmax, col.Fmax, imp.a,
                        d_rest, rest.a, fessler, d_n1, v_yield, H > 0.0 ? dmax_plastic / d_n1 : 0.0, e_plastic, tabor, pulloff,
                        W > 0.0 ? pulloff / W : 0.0, pulloff / col.Fmax, d_rest > 0.0 ? sigma / d_rest : 0.0, sigma / col.dmax, rough_rest,
                        rough_imp, slip, ut, slip > 0.0 ? ut / slip : 0.0, jkr_break, rough_reach, W_sep,
                        v_stick, beta_cmd, beta_hist, rolled / imp.a, md_reach, beta_tp};
  return dc_cli_row("scene", o, cols, (int)(sizeof row / sizeof row[0]), row);
range:
  fprintf(stderr, "dclaw scene: --R1, --R2, --E1, --E2, --rho1, --v, --g: %s (a figure of the scene leaves the doubles)\n",
          dc_status_str(st));
  return 2;
}

DC_CLI_COMMAND(scene, cmd_scene,
               "measures of one contact of a scene: time scales, Hertz impact and rest, and per effect (plasticity, "
               "adhesion, roughness, tangential memory) the change the richer law makes");
