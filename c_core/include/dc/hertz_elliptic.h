/* Elliptic Hertz contact from the relative principal radii of two smooth
   bodies (Kildashti, Dong & Yu 2023, "review", Eqs. 1-5 and 11-14).

   Conventions (checked against Johnson, Contact Mechanics, Sec. 4.2):
   - R_major >= R_minor are the relative principal radii (review Eqs. 3-4:
     R_i = R_major, R_j = R_minor); the contact ellipse has its major semi-axis
     a along the direction of R_major.
   - ratio r = R_minor / R_major in (0, 1].
   - Rc = R_major R_minor / (R_major + R_minor). Seed error: the OCR text of
     Eq. 5 reads R_i R_j / (R_i + R_i); the circular limit F = 4/3 E* R^1/2
     delta^3/2 (gamma = sqrt 2, Rc = R/2) fixes the denominator to R_i + R_j.
   - Eccentricity, exact (review Eq. 13 with the ratio the right way up):
       1 - e^2 = r E / ((1 + r) K - E)   <=>   r = (1 - e^2) D / B.
     Seed error: Eq. 13 is printed with R_i/R_j, which under Eqs. 3-4
     (R_i >= R_j) is >= 1 and gives e^2 < 0; it holds with R_j/R_i = r.
     Checked by deriving B/A = R_major/R_minor from Johnson's Eqs. 4.39 and
     by the mpmath generator tests/reference/gen_hertz_elliptic.py, where the
     force of Eq. 1 equals the force 2/3 pi a E* delta / K of the semi-axis
     route to 1e-30.
   - Eq. 14 (approximate eccentricity) also takes r = R_minor/R_major.
   - gamma = pi sqrt(2) E^1/2 / (2 K^3/2 (1-e^2)^1/2)   (Eq. 11)
     beta  = 2 E / (K (1-e^2)^1/2)                       (Eq. 12)
     F = 4/3 E* Rc^1/2 delta^3/2 gamma                   (Eq. 1)
     A = pi Rc delta beta = pi a b                       (Eq. 2)
     a^2 = 2 R_major delta D / K,  b = a (1-e^2)^1/2     (semi-axes)
   For a circle (r = 1): e = 0, gamma = sqrt 2, beta = 2, and with R_force =
   Rc gamma^2 = R, R_area = Rc beta = R everything reduces to spherical Hertz. */
#ifndef DC_HERTZ_ELLIPTIC_H
#define DC_HERTZ_ELLIPTIC_H

#include <float.h>
#include <math.h>
#include "dc/contract.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Smallest ratio R_minor/R_major accepted (contact ellipse b/a ~ 1e-8). */
#define DC_HERTZ_RATIO_MIN 1e-12

/* Everything about a contact that depends on the geometry but not on the
   overlap. Computed once per contact and step; the force for any overlap
   then costs a square root. */
typedef struct {
  double R_major, R_minor; /* relative principal radii, R_major >= R_minor */
  double Rc;               /* Eq. 5 */
  double e2, m1;           /* e^2 and 1 - e^2 = (b/a)^2 */
  double K, E, D;          /* elliptic integrals at m = e^2 */
  double gamma, beta;      /* Eqs. 11-12 */
  double R_force;          /* Rc gamma^2: F = 4/3 E* R_force^1/2 delta^3/2 */
  double R_area;           /* Rc beta:    A = pi R_area delta            */
} dc_hertz_geom;

/* Contact state at one overlap. */
typedef struct {
  double F;      /* normal force, Eq. 1 */
  double area;   /* contact area, Eq. 2 */
  double a, b;   /* semi-axes of the contact ellipse, a >= b */
  double kn;     /* tangent stiffness dF/d delta = 3/2 F / delta */
} dc_hertz_state;

/* e^2 solving the exact relation (Eq. 13) for r = R_minor/R_major in
   [DC_HERTZ_RATIO_MIN, 1], from lane 0 of the polynomials of
   dc_hertz_geometry; returns m1 = 1 - e^2 too, which keeps full relative
   precision when e^2 -> 1 (e^2 itself is as precise as 1 - r as r -> 1).
   DC_EDOM outside the domain. */
int dc_hertz_eccentricity(double ratio, double *e2, double *m1);

/* e^2 from the closed-form approximation (review Eq. 14), same domain. */
int dc_hertz_eccentricity_approx(double ratio, double *e2);

/* Geometry factors from the two relative principal radii (either order).
   Domain: radii > 0 and finite, ratio >= DC_HERTZ_RATIO_MIN (else
   DC_EDOM). Rc, R_force and R_area are at most R_major and are computed
   without intermediate overflow or underflow over the whole domain.
   Every output comes from one evaluation of piecewise polynomials in
   ln(R_minor/R_major), fitted to Eqs. 11-13 with mpmath
   (tests/reference/gen_hertz_geometry_poly.py), in about 45 ns: e2, m1,
   K, E, D, gamma, beta, R_force and R_area within 2.1 ulp of the exact
   values over the whole ratio range (tests/unit/test_hertz_elliptic.c). */
int dc_hertz_geometry(double R1, double R2, dc_hertz_geom *g);

/* dc_hertz_geometry(R, R, g) for a circular contact, without its checks
   (R > 0 finite): the hot path of sphere contacts. Same bits. */
static inline void dc_hertz_geometry_circle(double R, dc_hertz_geom *g)
{
  const double prod = R * R;
  g->R_major = g->R_minor = R;
  g->Rc = prod >= DBL_MIN && prod <= DBL_MAX ? prod / (R + R) : 0.5 * R;
  g->e2 = 0.0;
  g->m1 = 1.0;
  g->K = g->E = 0.5 * M_PI;
  g->D = 0.25 * M_PI;
  g->gamma = M_SQRT2;
  g->beta = 2.0;
  g->R_force = g->R_area = R;
}

/* Force, area, semi-axes, stiffness at overlap delta >= 0 for effective
   modulus Estar = 1 / sum (1 - nu^2)/E > 0, both finite (else DC_EDOM);
   DC_ERANGE when a result overflows. g: from dc_hertz_geometry. */
int dc_hertz_contact(const dc_hertz_geom *g, double Estar, double delta,
                     dc_hertz_state *s);

/* Eq. 1 in the hot path, for a force-equivalent radius R_force (= R for
   spheres, Rc gamma^2 for ellipses): with root = (R_force delta)^1/2,
   secant stiffness kn = 4/3 E* root (F = kn delta) and tangent stiffness
   S = dF/d delta = 2 E* root; returns root. The order of operations is that
   of LIGGGHTS' hertz, so spheres match it bit for bit. Inline, unchecked:
   E* > 0, R_force > 0, delta >= 0 finite. */
static inline double dc_hertz_stiffness(double Estar, double R_force, double delta, double *kn, double *S)
{
  const double root = sqrt(R_force * delta);
  *S = 2. * Estar * root;
  *kn = 4. / 3. * Estar * root;
  return root;
}

/* The law contract's output (dc/contract.h) at overlap delta: force,
   tangent stiffness, area, semi-axes, friction load = force; delta <= 0
   (finite) gives formed = 0 and zeros. Same domain as dc_hertz_contact
   otherwise; DC_EDOM leaves c untouched. */
int dc_hertz_normal(const dc_hertz_geom *g, double Estar, double delta, dc_contact *c);

/* The contact patch (dc/contract.h) of a circular Hertz contact of radius
   R at overlap delta >= 0 with elastic force F (dc_hertz_stiffness's
   kn delta): inline, the same bits as dc_hertz_normal on
   dc_hertz_geometry_circle(R) (Eq. 1 with a^2 = 2 R delta D / K, D/K = 1/2),
   which a sphere contact publishes every step. Returns 0 where a product
   leaves the doubles (call dc_hertz_normal then), 1 otherwise. */
static inline int dc_hertz_patch_circle(double R, double delta, double F, dc_patch *p)
{
  double a = 0.0, Fp = 0.0, formed = 0.0;
  if (delta > 0.0) {   /* a touching contact (the hot path) */
    a = sqrt(2.0 * R * delta * (0.25 * M_PI) / (0.5 * M_PI));
    if (!(a <= DBL_MAX && F <= DBL_MAX) || a == 0.0) return 0;
    Fp = F;
    formed = 1.0;
  } else if (!(F <= DBL_MAX)) {
    return 0;
  }
  p->a = p->b = a;
  p->axis[0] = p->axis[1] = p->axis[2] = 0.0;
  p->F_elastic = p->F_bound = Fp;
  p->formed = formed;
  return 1;
}

#ifdef __cplusplus
}
#endif
#endif
