/* Contact geometry of smooth convex bodies: principal curvatures of an
   implicit surface f(x) = 0 (f < 0 inside) from its gradient and Hessian, and
   the relative principal radii of two touching surfaces (review Eqs. 3-10).

   The curvature form of a body on a tangent basis (u, v) of the contact plane
   is II = [u.Hu, u.Hv; v.Hu, v.Hv] / |grad f|; its eigenvalues are the
   principal curvatures (positive for a convex body). The relative curvature
   of two bodies is the sum of their forms on one common basis; its
   eigenvalues are 1/R_major <= 1/R_minor. This is review Eqs. 3-4 without
   the angle: Eqs. 3-4 are the eigenvalues of the sum of two 2x2 forms whose
   principal axes make the angle omega. A plane has the zero form. */
#ifndef DC_CURVATURE_H
#define DC_CURVATURE_H

#ifdef __cplusplus
extern "C" {
#endif

/* A unit tangent basis (u, v) of the plane normal to the unit vector n,
   right-handed with n. */
void dc_tangent_basis(const double n[3], double u[3], double v[3]);

/* Curvature form (uu, uv, vv) of the level surface of f through a point,
   from grad f and the symmetric Hessian (row-major 3x3) there, on the basis
   (u, v). DC_EDOM if grad f is 0 or an input is not finite; DC_ERANGE
   if an entry of the form overflows. */
int dc_curvature_form(const double grad[3], const double hess[9],
                      const double u[3], const double v[3], double form[3]);

/* Curvature form, on the basis (u, v), of the superquadric
   f = (|x/a|^n2 + |y/b|^n2)^(n1/n2) + |z/c|^n1 - 1 (LIGGGHTS' shape
   function: shape = (a, b, c), blockiness = (n1, n2)) at the point p on it,
   all in the body's frame: dc_curvature_form of f's gradient and Hessian,
   computed without forming them (integer blockiness by products). DC_EDOM
   for a, b, c not finite and > 0, n1 or n2 not in [2, 1e3], non-finite p, u, v, or a
   gradient 0 or not finite at p (f < 0 inside, so the form is positive
   on a convex face). */
int dc_superquadric_form(const double shape[3], const double blockiness[2], const double p[3],
                         const double u[3], const double v[3], double form[3]);

/* Eigenvalues k1 >= k2 of a form and the angle theta of the k1 direction
   from u (direction cos(theta) u + sin(theta) v). */
void dc_form_principal(const double form[3], double *k1, double *k2, double *theta);

/* Relative principal radii R_major >= R_minor from a relative curvature form
   (sum of both bodies' forms). DC_EDOM when an entry is not finite or the
   smaller relative curvature is <= 0 (flat, concave or degenerate
   contact): Hertz does not apply. DC_ERANGE when a radius overflows (a
   subnormal curvature) or underflows (a curvature beyond DBL_MAX). */
int dc_form_relative_radii(const double form[3], double *R_major, double *R_minor);

/* Review Eqs. 3-4: relative principal radii from the principal curvatures
   (k1I, k2I) and (k1II, k2II) of the two bodies and the angle omega between
   the k1 directions. Same domain and statuses as dc_form_relative_radii
   (all five inputs finite). */
int dc_relative_radii(double k1I, double k2I, double k1II, double k2II,
                      double omega, double *R_major, double *R_minor);

/* Unit direction, in space, of the major axis of the contact ellipse of a
   relative curvature form on the basis (u, v): the principal direction of
   the smaller relative curvature (the R_major direction, along which the
   semi-axis a lies). Zero vector when the form is circular to rounding
   (the patch has no major axis) or not finite. */
void dc_form_major_axis(const double form[3], const double u[3], const double v[3], double axis[3]);

#ifdef __cplusplus
}
#endif
#endif
