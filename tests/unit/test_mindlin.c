/* Mindlin no-slip stiffness (dc/mindlin.h) against an independent
   quadrature of Cerruti's kernel under Mindlin's traction
   (tests/reference/gen_mindlin.py, mindlin.csv): both axes, 7 axis ratios
   b/a from 1 to 1e-3, 4 Poisson ratios; the circle 8 G* a; two different
   bodies (compliances add); review Eq. 57's chi on the axes. */
#include "check.h"
#include "dc/elliptic_integrals.h"
#include "dc/mindlin.h"
#include "dc/status.h"

int main(void)
{
  FILE *f = check_open_reference("mindlin.csv");
  if (!f) return check_summary("test_mindlin");
  double v[4];
  int rows = 0;
  double k25[2] = {0, 0}, k50[2] = {0, 0};
  while ((v[0] = 0, check_read_row(f, v, 4)) == 4) {
    const double g = v[0], nu = v[1];
    dc_ellint el;
    CHECK(dc_ellint_m1(g * g, &el) == DC_OK);
    /* two bodies of G = 2 each: the compliance of one G = 1 body on a rigid one */
    const double E = 4.0 * (1.0 + nu);
    dc_mindlin_pair p;
    CHECK(dc_mindlin_pair_init(E, nu, E, nu, &p) == DC_OK);
    double km, kn;
    CHECK(dc_mindlin_stiffness(&p, 1.0, el.K, el.D, &km, &kn) == DC_OK);
    CHECK_REL(km, v[2], 2e-14, "k_major vs Cerruti quadrature");
    CHECK_REL(kn, v[3], 2e-14, "k_minor vs Cerruti quadrature");
    if (g == 1.0) CHECK_REL(dc_mindlin_kt_circle(1.0 / (2.0 - nu), 1.0), v[2], 1e-15, "circle: 8 G* a");
    /* Eq. 57: F = 2 pi G a chi delta along the axes (G = 1, a = 1) */
    dc_hertz_geom hg = {0};
    hg.K = el.K;
    hg.D = el.D;
    double chi0, chi90;
    CHECK(dc_mindlin_chi(&hg, nu, 0.0, &chi0) == DC_OK && dc_mindlin_chi(&hg, nu, M_PI / 2, &chi90) == DC_OK);
    CHECK_REL(2.0 * M_PI * chi0, v[2], 2e-14, "Eq. 57 chi at theta = 0");
    CHECK_REL(2.0 * M_PI * chi90, v[3], 2e-14, "Eq. 57 chi at theta = pi/2");
    if (g == 0.2 && nu == 0.25) { k25[0] = v[2]; k25[1] = v[3]; }
    if (g == 0.2 && nu == 0.5) {
      k50[0] = v[2]; k50[1] = v[3];
      /* body 1: G = 3, nu = 0.25; body 2: G = 0.7, nu = 0.5: compliances add */
      dc_mindlin_pair q;
      CHECK(dc_mindlin_pair_init(6.0 * 1.25, 0.25, 1.4 * 1.5, 0.5, &q) == DC_OK);
      CHECK(dc_mindlin_stiffness(&q, 2.0, el.K, el.D, &km, &kn) == DC_OK);
      CHECK_REL(km, 2.0 / (1.0 / (3.0 * k25[0]) + 1.0 / (0.7 * k50[0])), 2e-14, "dissimilar bodies, major axis");
      CHECK_REL(kn, 2.0 / (1.0 / (3.0 * k25[1]) + 1.0 / (0.7 * k50[1])), 2e-14, "dissimilar bodies, minor axis");
    }
    rows++;
  }
  fclose(f);
  CHECK(rows == 28);
  dc_mindlin_pair p;
  double km = -1, kn = -1;
  CHECK(dc_mindlin_pair_init(1e9, 0.6, 1e9, 0.3, &p) == DC_EDOM);
  CHECK(dc_mindlin_pair_init(0.0, 0.3, 1e9, 0.3, &p) == DC_EDOM);
  CHECK(dc_mindlin_pair_init(1e9, 0.3, 1e9, 0.3, &p) == DC_OK);
  /* G* and E* of the pair against their textbook forms: one material,
     G* = E / (4 (2 - nu)(1 + nu)), E* = E / (2 (1 - nu^2)); two materials
     (E 7.5, nu 0.25 and E 2.1, nu 0.5): 1/sum (2 - nu_i)/G_i, 1/sum (1 - nu_i^2)/E_i */
  CHECK_REL(dc_mindlin_pair_gstar(&p), 1e9 / (4.0 * 1.7 * 1.3), 1e-15, "G* of one material");
  CHECK_REL(dc_mindlin_pair_estar(&p), 1e9 / (2.0 * 0.91), 1e-15, "E* of one material");
  dc_mindlin_pair q;
  CHECK(dc_mindlin_pair_init(7.5, 0.25, 2.1, 0.5, &q) == DC_OK);
  CHECK_REL(dc_mindlin_pair_gstar(&q), 1.0 / (1.75 / 3.0 + 1.5 / 0.7), 1e-15, "G* of two materials");
  CHECK_REL(dc_mindlin_pair_estar(&q), 1.0 / (0.9375 / 7.5 + 0.75 / 2.1), 1e-15, "E* of two materials");
  CHECK(dc_mindlin_stiffness(&p, -1.0, 1.6, 0.8, &km, &kn) == DC_EDOM && km == -1 && kn == -1);
  return check_summary("test_mindlin");
}
