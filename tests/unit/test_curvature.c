/* Principal curvatures of superquadrics and ellipsoids from gradient and
   Hessian against an independent mpmath evaluation (explicit sections,
   tests/reference/curvature.csv); dc_superquadric_form against mpmath's
   numerical derivatives of LIGGGHTS' shape function (superquadric_form.csv,
   gen_superquadric_form.py) and against dc_curvature_form of this file's
   gradient and Hessian; relative radii: the form sum against review Eqs.
   3-4 with the angle, and the sphere and plane cases. */
#include "check.h"
#include "dc/curvature.h"
#include "dc/status.h"

/* f = |x/a|^n + |y/b|^n + |z/c|^n - 1: gradient and Hessian */
static void superquadric(const double s[3], double n, const double p[3], double g[3], double H[9])
{
  for (int i = 0; i < 9; i++) H[i] = 0.0;
  for (int k = 0; k < 3; k++) {
    const double t = fabs(p[k]) / s[k];
    g[k] = n * pow(t, n - 1.0) * copysign(1.0, p[k]) / s[k];
    H[4 * k] = n * (n - 1.0) * pow(t, n - 2.0) / (s[k] * s[k]);
  }
}

static void normalize(double v[3])
{
  const double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  for (int k = 0; k < 3; k++) v[k] /= l;
}

int main(void)
{
  FILE *f = check_open_reference("curvature.csv");
  if (!f) return check_summary("curvature");
  int rows = 0;
  double row[8], row17[17];
  while (check_read_row(f, row, 8) == 8) {
    const double a = row[0], b = row[1], c = row[2], n = row[3], x = row[4], y = row[5], k_plane = row[6],
                 k_z = row[7];
    const double s[3] = {a, b, c}, p[3] = {x, y, 0.0};
    double g[3], H[9], nrm[3], u[3], v[3], form[3], k1, k2;
    superquadric(s, n, p, g, H);
    for (int k = 0; k < 3; k++) nrm[k] = g[k];
    normalize(nrm);
    dc_tangent_basis(nrm, u, v);
    CHECK(dc_curvature_form(g, H, u, v, form) == DC_OK);
    dc_form_principal(form, &k1, &k2, 0);
    const double want1 = fmax(k_plane, k_z), want2 = fmin(k_plane, k_z);
    char what[96];
    snprintf(what, sizeof what, "k1 of (%g,%g,%g,n=%g) at x=%g", a, b, c, n, x);
    CHECK_REL(k1, want1, 1e-13, what);
    snprintf(what, sizeof what, "k2 of (%g,%g,%g,n=%g) at x=%g", a, b, c, n, x);
    if (want2 == 0.0) CHECK_ABS(k2, 0.0, 1e-14, what); else CHECK_REL(k2, want2, 1e-13, what);
    rows++;
  }
  fclose(f);
  CHECK(rows >= 5);

  /* dc_superquadric_form: to 1e-12 of the form's largest entry (the
     reference's point is rounded to doubles) */
  f = check_open_reference("superquadric_form.csv");
  if (f) {
    int n = 0;
    double worst = 0.0;
    while (check_read_row(f, row17, 17) == 17) {
      double form[3];
      const double *r = row17;
      CHECK(dc_superquadric_form(r, r + 3, r + 5, r + 8, r + 11, form) == DC_OK);
      const double scale = fmax(fabs(r[14]), fmax(fabs(r[15]), fabs(r[16])));
      for (int k = 0; k < 3; k++) worst = fmax(worst, fabs(form[k] - r[14 + k]) / scale);
      n++;
    }
    fclose(f);
    CHECK(n >= 100);
    CHECK_ABS(worst, 0.0, 1e-12, "dc_superquadric_form vs mpmath, worst error / largest entry");
    printf("     dc_superquadric_form: %d mpmath forms, worst %.2e of the largest entry\n", n, worst);
  }
  /* n1 = n2: the same form as dc_curvature_form of the separable gradient
     and Hessian, on random points and bases */
  {
    unsigned long long seed = 7;
    double worst = 0.0;
    for (int i = 0; i < 2000; i++) {
      const double nb = 2.0 + floor(7.0 * check_uniform(&seed)) * (i % 2 ? 1.0 : 0.5);
      const double s[3] = {0.5 + check_uniform(&seed), 0.5 + check_uniform(&seed), 0.5 + check_uniform(&seed)};
      const double bl[2] = {nb, nb};
      double d[3] = {check_uniform(&seed) - 0.5, check_uniform(&seed) - 0.5, check_uniform(&seed) - 0.5}, g[3], H[9];
      double sum = 0.0;
      for (int k = 0; k < 3; k++) sum += pow(fabs(d[k]) / s[k], nb);
      const double t = pow(sum, -1.0 / nb);
      double p[3] = {t * d[0], t * d[1], t * d[2]}, nrm[3], u[3], v[3], want[3], got[3];
      superquadric(s, nb, p, g, H);
      for (int k = 0; k < 3; k++) nrm[k] = g[k];
      normalize(nrm);
      dc_tangent_basis(nrm, u, v);
      CHECK(dc_curvature_form(g, H, u, v, want) == DC_OK);
      CHECK(dc_superquadric_form(s, bl, p, u, v, got) == DC_OK);
      const double scale = fmax(fabs(want[0]), fmax(fabs(want[1]), fabs(want[2])));
      for (int k = 0; k < 3; k++) worst = fmax(worst, fabs(got[k] - want[k]) / scale);
    }
    CHECK_ABS(worst, 0.0, 1e-13, "dc_superquadric_form vs dc_curvature_form, n1 = n2");
  }
  /* its domain */
  {
    const double s[3] = {1.0, 1.0, 1.0}, bl[2] = {4.0, 4.0}, p[3] = {1.0, 0.0, 0.0}, u[3] = {0, 1, 0}, v[3] = {0, 0, 1};
    const double s0[3] = {1.0, 0.0, 1.0}, b1[2] = {1.5, 4.0}, pn[3] = {NAN, 0.0, 0.0}, zero[3] = {0, 0, 0};
    double form[3];
    CHECK(dc_superquadric_form(s, bl, p, u, v, form) == DC_OK);
    CHECK_ABS(form[0], 0.0, 0.0, "n = 4 at the face centre: flat");
    CHECK(dc_superquadric_form(s0, bl, p, u, v, form) == DC_EDOM);
    CHECK(dc_superquadric_form(s, b1, p, u, v, form) == DC_EDOM);
    CHECK(dc_superquadric_form(s, bl, pn, u, v, form) == DC_EDOM);
    CHECK(dc_superquadric_form(s, bl, zero, u, v, form) == DC_EDOM);   /* the centre: grad f = 0 */
  }

  /* ellipsoid at the end of its a axis: curvatures a/b^2 and a/c^2 */
  {
    const double s[3] = {2.0, 1.0, 0.5}, p[3] = {2.0, 0.0, 0.0}, nrm[3] = {1.0, 0.0, 0.0};
    double g[3], H[9], u[3], v[3], form[3], k1, k2;
    superquadric(s, 2.0, p, g, H);
    dc_tangent_basis(nrm, u, v);
    dc_curvature_form(g, H, u, v, form);
    dc_form_principal(form, &k1, &k2, 0);
    CHECK_REL(k1, 2.0 / 0.25, 1e-15, "ellipsoid k1 at a-axis");
    CHECK_REL(k2, 2.0 / 1.0, 1e-15, "ellipsoid k2 at a-axis");
  }

  /* tangent basis: orthonormal and normal to n, for many directions */
  int ortho = 1;
  for (int i = 0; i < 1000; i++) {
    double nrm[3] = {sin(0.37 * i) * cos(1.3 * i), sin(0.37 * i) * sin(1.3 * i), cos(0.37 * i)}, u[3], v[3];
    normalize(nrm);
    dc_tangent_basis(nrm, u, v);
    double uu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2], vv = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    double uv = u[0] * v[0] + u[1] * v[1] + u[2] * v[2], un = u[0] * nrm[0] + u[1] * nrm[1] + u[2] * nrm[2];
    double vn = v[0] * nrm[0] + v[1] * nrm[1] + v[2] * nrm[2];
    ortho &= fabs(uu - 1) < 1e-14 && fabs(vv - 1) < 1e-14 && fabs(uv) < 1e-14 && fabs(un) < 1e-14 && fabs(vn) < 1e-14;
  }
  CHECK(ortho);

  /* Eqs. 3-4 with the angle equal the eigenvalues of the summed forms */
  for (int i = 0; i < 50; i++) {
    const double k1I = 3.0 + i, k2I = 1.0 + 0.5 * i, k1II = 2.0 + 0.1 * i, k2II = 0.5, w = 0.07 * i;
    /* body I principal axes along (u, v); body II rotated by w */
    const double c = cos(w), s = sin(w);
    double form[3] = {k1I + k1II * c * c + k2II * s * s, (k1II - k2II) * c * s, k2I + k1II * s * s + k2II * c * c};
    double Ra, Rb, Rc_, Rd;
    CHECK(dc_form_relative_radii(form, &Ra, &Rb) == DC_OK);
    CHECK(dc_relative_radii(k1I, k2I, k1II, k2II, w, &Rc_, &Rd) == DC_OK);
    CHECK_REL(Rc_, Ra, 1e-14, "Eq. 3 R_major vs form sum");
    CHECK_REL(Rd, Rb, 1e-14, "Eq. 4 R_minor vs form sum");
  }
  /* two spheres: R_major = R_minor = R1 R2/(R1 + R2); sphere on a plane: R */
  double Ra, Rb;
  dc_relative_radii(1.0 / 0.002, 1.0 / 0.002, 1.0 / 0.003, 1.0 / 0.003, 0.4, &Ra, &Rb);
  CHECK_REL(Ra, 0.0012, 1e-15, "sphere-sphere R_major");
  CHECK_REL(Rb, 0.0012, 1e-15, "sphere-sphere R_minor");
  dc_relative_radii(1.0 / 0.002, 1.0 / 0.002, 0.0, 0.0, 0.0, &Ra, &Rb);
  CHECK_REL(Ra, 0.002, 1e-15, "sphere-plane");
  /* flat on flat and degenerate input: a status */
  CHECK(dc_relative_radii(0.0, 0.0, 0.0, 0.0, 0.0, &Ra, &Rb) == DC_EDOM);
  CHECK(dc_relative_radii(1.0, -2.0, 0.0, 0.0, 0.0, &Ra, &Rb) == DC_EDOM);
  const double g0[3] = {0, 0, 0}, H0[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, u[3] = {1, 0, 0}, v[3] = {0, 1, 0};
  double form[3];
  CHECK(dc_curvature_form(g0, H0, u, v, form) == DC_EDOM);
  return check_summary("curvature");
}
