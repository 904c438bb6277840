/* Scene measures (dc/scene.h) against independent references
   (tests/reference/gen_scene.py, mpmath): the Rayleigh time against the
   root of Rayleigh's equation (the fit within 0.3 %), superquadric
   volume-equivalent radii against quadrature of the shape function, the
   one-radius force errors of ellipsoids against curvatures, review Eqs.
   3-4 and elliptic Hertz evaluated in mpmath; the Tabor parameter and the
   inverse Hertz overlap against their formulas and dc_hertz_contact. */
#include "check.h"
#include "dc/hertz_elliptic.h"
#include "dc/scene.h"
#include "dc/status.h"

int main(void)
{
  /* Rayleigh: T_R = pi R / (xi c_S), c_S = (G/rho)^1/2 */
  FILE *f = check_open_reference("scene_rayleigh.csv");
  double row[9];
  int n = 0;
  if (f) {
    while (check_read_row(f, row, 2) == 2) {
      const double nu = row[0], xi = row[1], R = 1.5e-3, rho = 2500.0, E = 5e6, G = E / (2.0 * (1.0 + nu));
      double T;
      CHECK(dc_scene_rayleigh_time(R, rho, E, nu, &T) == DC_OK);
      CHECK_REL(T, M_PI * R / (xi * sqrt(G / rho)), 3.0e-3, "Rayleigh time against the root of Rayleigh's equation");
      CHECK_REL(T, M_PI * R * sqrt(rho / G) / (0.1631 * nu + 0.8766), 1e-15, "Rayleigh time: the fit as documented");
      n++;
    }
    fclose(f);
  }
  CHECK(n == 11);
  /* volume-equivalent radii */
  f = check_open_reference("scene_volume.csv");
  n = 0;
  if (f) {
    while (check_read_row(f, row, 6) == 6) {
      const double shape[3] = {row[0], row[1], row[2]}, bl[2] = {row[3], row[4]};
      double R;
      CHECK(dc_scene_superquadric_radius(shape, bl, &R) == DC_OK);
      CHECK_REL(R, row[5], 1e-12, "volume-equivalent radius against quadrature");
      n++;
    }
    fclose(f);
  }
  CHECK(n == 7);
  /* one-radius force errors of ellipsoids (cap 100: not reached) */
  f = check_open_reference("scene_shape.csv");
  n = 0;
  if (f) {
    while (check_read_row(f, row, 9) == 9) {
      const double shape[3] = {row[0], row[1], row[2]}, bl[2] = {2.0, 2.0};
      dc_scene_shape s;
      CHECK(dc_scene_shape_error(shape, bl, (int)row[3], 100.0, &s) == DC_OK);
      CHECK_REL(s.R_eq, row[4], 1e-14, "R_eq of the ellipsoid");
      CHECK_REL(s.err_pair_max, row[5], 1e-9, "one-radius error, pairs, max");
      CHECK_REL(s.err_pair_rms, row[6], 1e-9, "one-radius error, pairs, rms");
      CHECK_REL(s.err_wall_max, row[7], 1e-9, "one-radius error, wall, max");
      CHECK_REL(s.err_wall_rms, row[8], 1e-9, "one-radius error, wall, rms");
      n++;
    }
    fclose(f);
  }
  CHECK(n == 3);
  /* a sphere: no error; scaling all lengths scales the radii only */
  {
    const double s1[3] = {1e-3, 1e-3, 1e-3}, s2[3] = {3e-3, 5e-3, 7e-3}, s3[3] = {3.0, 5.0, 7.0}, bl[2] = {3.0, 4.0},
                 b2[2] = {2.0, 2.0};
    dc_scene_shape a, b;
    CHECK(dc_scene_shape_error(s1, b2, 8, 100.0, &a) == DC_OK);
    CHECK(a.err_pair_max < 1e-15 && a.err_wall_max < 1e-15);
    CHECK_REL(a.R_body_min, 1e-3, 1e-14, "sphere radius of curvature");
    CHECK(dc_scene_shape_error(s2, bl, 6, 100.0, &a) == DC_OK && dc_scene_shape_error(s3, bl, 6, 100.0, &b) == DC_OK);
    CHECK(a.err_pair_max == b.err_pair_max && a.err_wall_rms == b.err_wall_rms);
    CHECK_REL(a.R_eq * 1e3, b.R_eq, 1e-15, "R_eq scales with the lengths");
    /* the cap: a blocky face's centre is flat; radii stop at cap R_eq */
    const double cube[3] = {1.0, 1.0, 1.0}, b8[2] = {8.0, 8.0};
    CHECK(dc_scene_shape_error(cube, b8, 8, 10.0, &a) == DC_OK);
    CHECK(a.R_body_max <= 10.0 * a.R_eq * (1.0 + 1e-15) && a.R_body_max >= 10.0 * a.R_eq * (1.0 - 1e-15));
    CHECK(dc_scene_shape_error(cube, b8, 1, 10.0, &a) == DC_EDOM && dc_scene_shape_error(cube, b8, 8, 0.5, &a) == DC_EDOM);
  }
  /* Tabor parameter: the formula, w = 0, the domain */
  {
    double mu;
    CHECK(dc_scene_tabor(1e-3, 0.05, 1e9, 0.4e-9, &mu) == DC_OK);
    CHECK_REL(mu, cbrt(1e-3 * 0.05 * 0.05 / (1e18 * 0.4e-9 * 0.4e-9 * 0.4e-9)), 1e-15, "Tabor parameter");
    CHECK(dc_scene_tabor(1e-3, 0.0, 1e9, 0.4e-9, &mu) == DC_OK && mu == 0.0);
    CHECK(dc_scene_tabor(1e-3, -0.1, 1e9, 0.4e-9, &mu) == DC_EDOM && dc_scene_tabor(1e-3, 0.05, 1e9, 0.0, &mu) == DC_EDOM);
  }
  /* the overlap at a force: dc_hertz_contact gives the force back, circle and ellipse */
  {
    const double radii[3][2] = {{1e-3, 1e-3}, {2e-3, 5e-4}, {1.0, 1e-6}};
    for (int i = 0; i < 3; i++) {
      dc_hertz_geom g;
      dc_hertz_state hs;
      double d;
      CHECK(dc_hertz_geometry(radii[i][0], radii[i][1], &g) == DC_OK);
      CHECK(dc_scene_hertz_overlap(&g, 2.75e6, 3.4e-4, &d) == DC_OK && dc_hertz_contact(&g, 2.75e6, d, &hs) == DC_OK);
      CHECK_REL(hs.F, 3.4e-4, 2e-15, "force at the overlap of dc_scene_hertz_overlap");
    }
  }
  return check_summary("scene");
}
