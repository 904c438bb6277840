/* Scene measures: the figures that tell which physics a scene's contacts
   need (dclaw scene, and the deck advisor tools/dcadvise.py on top of it;
   doc/advisor.md). Each is a named formula or a sampling of the laws of the
   other headers; none is a force law of its own. */
#ifndef DC_SCENE_H
#define DC_SCENE_H

#include "dc/hertz_elliptic.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Rayleigh time T_R = pi R (rho/G)^1/2 / (0.1631 nu + 0.8766): the time a
   Rayleigh wave takes across a particle of radius R [m], density rho
   [kg/m^3], shear modulus G = E / (2 (1 + nu)) [Pa], Poisson's ratio nu
   (the linear fit of the Rayleigh speed over the shear speed, within 0.3 %
   of the root of Rayleigh's equation on [0, 0.5]: tests/unit/test_scene.c).
   DC_EDOM unless R, rho, E > 0 finite and nu in [0, 0.5]; DC_ERANGE when
   T_R leaves the doubles' normal range (no partial product overflows
   before: mantissas and exponents apart). */
int dc_scene_rayleigh_time(double R, double rho, double E, double nu, double *T);

/* Tabor parameter mu_T = (R w^2 / (E*^2 z0^3))^1/3 (Tabor 1977): elastic
   neck height over the range z0 [m] of the surface forces; JKR applies for
   mu_T >> 1 (above about 5), DMT for mu_T << 1 (below about 0.1). R the
   effective radius [m], w the work of adhesion [J/m^2] >= 0, E* [Pa].
   DC_EDOM unless R, E*, z0 > 0 and w >= 0, all finite; DC_ERANGE when mu_T
   leaves the normal range (w = 0 gives 0). */
int dc_scene_tabor(double R, double w, double Estar, double z0, double *mu);

/* The overlap at which elliptic Hertz carries the force F >= 0 [N] (review
   Eq. 1 inverted: delta = (3 F / (4 E* R_force^1/2))^2/3); g from
   dc_hertz_geometry. DC_EDOM for F < 0, E* <= 0 or a non-finite input;
   DC_ERANGE when delta leaves the normal range (F = 0 gives 0). */
int dc_scene_hertz_overlap(const dc_hertz_geom *g, double Estar, double F, double *delta);

/* Volume-equivalent radius of LIGGGHTS' superquadric (shape (a, b, c),
   blockiness (n1, n2)): (3 V / 4 pi)^1/3 with V = 2 a b c e1 e2
   B(e1/2 + 1, e1) B(e2/2, e2/2), e1 = 2/n1, e2 = 2/n2 (Jaklic et al.,
   Segmentation and Recovery of Superquadrics, 2000, Eq. 2.60). Domain as
   dc_superquadric_form's shape and blockiness (DC_EDOM). */
int dc_scene_superquadric_radius(const double shape[3], const double blockiness[2], double *R_eq);

/* The force error of the one-radius model on a superquadric: Hertz with the
   volume-equivalent radius (LIGGGHTS' stock superquadric default) against
   elliptic Hertz from the relative principal radii, at equal overlap:
   F_1/F - 1 = (R_1 / R_force)^1/2 - 1, R_1 = R_eq / 2 for two such bodies
   and R_eq against a flat wall. Sampled on an m x m grid of the parametric
   angles of one octant (cell midpoints), every pair of sampled points at
   the angles 0, pi/8, ..., pi/2 between their k1 directions; principal
   radii capped at cap x R_eq (LIGGGHTS' curvatureLimitFactor does the
   same; a face of a blocky shape is flat at its centre). */
typedef struct {
  double R_eq;                        /* volume-equivalent radius [m] */
  double err_pair_max, err_pair_rms;  /* |F_1/F - 1|, two bodies */
  double err_wall_max, err_wall_rms;  /* |F_1/F - 1|, body on a wall */
  double R_body_min, R_body_max;      /* smallest, largest principal radius sampled (capped) [m] */
} dc_scene_shape;

/* DC_EDOM outside dc_superquadric_form's domain, m outside [2, 64] or cap
   not in [1, 1e6]; DC_ERANGE when a radius leaves the doubles or two
   relative radii lie beyond dc_hertz_geometry's ratio. Costs m^4 x 2.5
   elliptic Hertz geometries (m = 12: a few milliseconds). */
int dc_scene_shape_error(const double shape[3], const double blockiness[2], int m, double cap, dc_scene_shape *s);

#ifdef __cplusplus
}
#endif
#endif
