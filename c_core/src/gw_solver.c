/* Full GW rough-sphere solver (Feng et al. 2016, Secs. 2-6), sigma-form;
   equations, seed corrections and options in dc/gw_solver.h. GSL provides
   the Gauss-Legendre abscissae and weights (gsl_integration_glfixed), which
   the method is built on; everything else is plain C. */
#include "dc/gw_solver.h"
#include "dc/elliptic_integrals.h"
#include "dc/gw_integrals.h"
#include "dc/status.h"
#include <gsl/gsl_integration.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define N_OUT 48

dc_gw_solve_opts dc_gw_solve_default_opts(void)
{
  dc_gw_solve_opts o = {1.0, 0.0, DC_GW_FORCE_FULL, DC_GW_F32_EXACT, 1e-12, 50};
  return o;
}

/* alpha(r, t) = t/(r + t) K(k), k = 2 sqrt(r t)/(r + t): K with parameter
   k^2 = 1 - ((r - t)/(r + t))^2, via the complement for accuracy near k = 1 */
static double influence(double r, double t)
{
  const double q = (r - t) / (r + t);
  dc_ellint el;
  dc_ellint_m1(q * q, &el);
  return t / (r + t) * el.K;
}

int dc_gw_solver_init(dc_gw_solver *out, int m)
{
  if (m < 2 || m > 1000) return DC_EDOM;
  dc_gw_solver S0, *S = &S0;
  S->m = m;
  S->x = malloc(m * sizeof *S->x);
  S->s = malloc(m * sizeof *S->s);
  S->alpha = malloc((size_t)m * m * sizeof *S->alpha);
  gsl_integration_glfixed_table *t = gsl_integration_glfixed_table_alloc(m);
  if (!S->x || !S->s || !S->alpha || !t) {   /* out of memory: *out untouched */
    dc_gw_solver_free(S);
    if (t) gsl_integration_glfixed_table_free(t);
    return DC_ERANGE;
  }
  for (int i = 0; i < m; i++) gsl_integration_glfixed_point(0.0, 1.0, i, &S->x[i], &S->s[i], t);
  gsl_integration_glfixed_table_free(t);
  for (int i = 0; i < m; i++)
    for (int j = i + 1; j < m; j++) {
      /* Eq. 56: alpha_ij = K(k_ij)/(1 + lambda_ij), K symmetric in i, j */
      const double a = influence(S->x[i], S->x[j]);
      S->alpha[i * m + j] = a;
      S->alpha[j * m + i] = a * S->x[i] / S->x[j];
    }
  /* Eq. 58 on the unit disc with pbar = (1 - x^2)^1/2, E = 1:
     wbar(x) = (pi/2)(1 - x^2/2) and (pi E/4) wbar = pi^2/8 (1 - x^2/2) */
  for (int i = 0; i < m; i++) {
    double sum = 0.0;
    for (int j = 0; j < m; j++)
      if (j != i) sum += S->s[j] * S->alpha[i * m + j] * sqrt(1.0 - S->x[j] * S->x[j]);
    const double ph = sqrt(1.0 - S->x[i] * S->x[i]);
    S->alpha[i * m + i] = (M_PI * M_PI / 8.0 * (1.0 - 0.5 * S->x[i] * S->x[i]) - sum) / (S->s[i] * ph);
  }
  *out = S0;
  return DC_OK;
}

void dc_gw_solver_free(dc_gw_solver *S)
{
  free(S->x); free(S->s); free(S->alpha);
  S->x = S->s = S->alpha = NULL;
}

/* 10-point Gauss-Legendre on [h, 5] (Feng Sec. 6.2) for F_3/2 and F_1/2 */
static const double gl10_x[5] = {0.1488743389816312, 0.4333953941292472, 0.6794095682990244,
                                 0.8650633666889845, 0.9739065285171717};
static const double gl10_w[5] = {0.2955242247147529, 0.2692667193099963, 0.2190863625159820,
                                 0.1494513491505806, 0.0666713443086881};

static void F_gauss10(double h, double *F32, double *F12)
{
  *F32 = *F12 = 0.0;
  if (h >= 5.0) return;
  const double c = 0.5 * (5.0 + h), hw = 0.5 * (5.0 - h);
  for (int k = 0; k < 5; k++)
    for (int sg = -1; sg <= 1; sg += 2) {
      const double sv = c + sg * hw * gl10_x[k], u = sv - h;
      const double ph = exp(-0.5 * sv * sv) / 2.5066282746310005024 * gl10_w[k] * hw;
      *F32 += ph * u * sqrt(u);
      *F12 += ph * sqrt(u);
    }
}

static void eval_F(int mode, double h, double *F32, double *F12)
{
  if (mode == DC_GW_F32_GAUSS10) { F_gauss10(h, F32, F12); return; }
  double Fa[4];
  dc_gw_F_all(h, Fa);
  *F32 = Fa[DC_GW_F32];
  *F12 = Fa[DC_GW_F12];
}

/* LU with partial pivoting, solve in place: A (n x n) x = b */
static int lu_solve(double *A, double *b, int n)
{
  for (int k = 0; k < n; k++) {
    int p = k;
    for (int i = k + 1; i < n; i++) if (fabs(A[i * n + k]) > fabs(A[p * n + k])) p = i;
    if (A[p * n + k] == 0.0) return DC_ERANGE;
    if (p != k) {
      for (int j = 0; j < n; j++) { double t = A[k * n + j]; A[k * n + j] = A[p * n + j]; A[p * n + j] = t; }
      double t = b[k]; b[k] = b[p]; b[p] = t;
    }
    const double inv = 1.0 / A[k * n + k];
    for (int i = k + 1; i < n; i++) {
      const double f = A[i * n + k] * inv;
      if (f == 0.0) continue;
      for (int j = k + 1; j < n; j++) A[i * n + j] -= f * A[k * n + j];
      b[i] -= f * b[k];
    }
  }
  for (int i = n - 1; i >= 0; i--) {
    double s = b[i];
    for (int j = i + 1; j < n; j++) s -= A[i * n + j] * b[j];
    b[i] = s / A[i * n + i];
  }
  return DC_OK;
}

int dc_gw_solve(const dc_gw_solver *S, double ap, double mu, const dc_gw_solve_opts *o,
                dc_gw_solve_result *out)
{
  if (!(ap >= -10.0 && ap <= 1e4 && mu > 0.0 && mu <= 1e3 && o->domain_scale > 0.0 &&
        isfinite(o->domain_scale) && o->abar >= 0.0 && o->abar < 1e3 && o->max_iter > 0 &&
        isfinite(o->tol) && (o->force_mode == DC_GW_FORCE_DOMAIN || o->force_mode == DC_GW_FORCE_FULL) &&
        (o->f32_mode == DC_GW_F32_EXACT || o->f32_mode == DC_GW_F32_GAUSS10)))
    return DC_EDOM;
  const int m = S->m;
  /* Eq. 60 in r* units: a = sqrt(R delta) -> sqrt(alpha'/2); sqrt(R sigma) -> 1/sqrt 2 */
  double abar;
  if (ap >= 1.0) abar = (1.75 + 1.0 / ap) * sqrt(0.5 * ap);
  else abar = (1.75 + fmin(fabs(ap), ap != 0.0 ? fabs(1.0 / ap) : INFINITY)) * sqrt(0.5);
  abar = o->abar > 0.0 ? o->abar : abar * o->domain_scale;
  if (!(abar < 1e3)) return DC_EDOM;   /* domain_scale too large: as o->abar */
  dc_gw_solve_result res, *r = &res;
  const size_t mm = (size_t)m * m;
  double *buf = malloc((2 * mm + 5 * (size_t)m) * sizeof *buf);
  if (!buf) return DC_ERANGE;
  double *A = buf, *J = A + mm, *p = J + mm, *w = p + m, *rhs = w + m, *rr = rhs + m, *F12 = rr + m;
  /* A_ij = (2/pi) abar s_j alpha_ij: w*_i = sum_j A_ij p*_j (Eqs. 28, 47) */
  for (int i = 0; i < m; i++) {
    rr[i] = abar * S->x[i];
    for (int j = 0; j < m; j++) A[i * m + j] = 2.0 / M_PI * abar * S->s[j] * S->alpha[i * m + j];
  }
  /* initial guess: Hertz pressure for the overlap max(delta, sigma)
     (sigma-form: p* = (4 sqrt 2/pi) sqrt(a') (1 - r*^2/a*^2)^1/2, a*^2 = a'/2) */
  const double ae = fmax(ap, 1.0), a2 = 0.5 * ae;
  for (int i = 0; i < m; i++) {
    const double u = 1.0 - rr[i] * rr[i] / a2;
    p[i] = u > 0.0 ? 4.0 * M_SQRT2 / M_PI * sqrt(ae) * sqrt(u) : 0.0;
  }
  int st = DC_ENOCONV;
  r->iterations = 0;
  for (int it = 0; it < o->max_iter; it++) {
    for (int i = 0; i < m; i++) {
      double s = 0.0;
      for (int j = 0; j < m; j++) s += A[i * m + j] * p[j];
      w[i] = s;
      double F32;
      eval_F(o->f32_mode, w[i] + rr[i] * rr[i] - ap, &F32, &F12[i]);
      rhs[i] = -(p[i] - mu * F32);                       /* -F(p), Eq. 49 */
    }
    /* J_ij = delta_ij - mu dF_3/2/dh dh_i/dp_j = delta_ij + 3/2 mu F_1/2 A_ij */
    for (int i = 0; i < m; i++)
      for (int j = 0; j < m; j++)
        J[i * m + j] = (i == j) + 1.5 * mu * F12[i] * A[i * m + j];
    if (lu_solve(J, rhs, m)) { st = DC_ERANGE; break; }
    double nd = 0.0, np = 0.0;
    for (int i = 0; i < m; i++) { p[i] += rhs[i]; nd += rhs[i] * rhs[i]; np += p[i] * p[i]; }
    double e = np > 0.0 ? sqrt(nd / np) : sqrt(nd);
    if (!isfinite(e)) e = sqrt(nd) / sqrt(np);   /* tiny p (tiny mu): nd/np overflows */
    if (it < DC_GW_SOLVER_MAX_HIST) r->hist[it] = e;
    r->iterations = it + 1;
    if (e < o->tol || nd == 0.0) { st = DC_OK; break; }
  }
  /* total force, Eq. 21 / 54 */
  double P = 0.0;
  for (int j = 0; j < m; j++) P += abar * S->s[j] * rr[j] * p[j];
  if (o->force_mode == DC_GW_FORCE_FULL) {
    const double rmax = sqrt(fmax(ap + 14.0, 0.0));
    if (rmax > abar) {
      gsl_integration_glfixed_table *t = gsl_integration_glfixed_table_alloc(N_OUT);
      for (int k = 0; k < N_OUT; k++) {
        double ro, wo;
        gsl_integration_glfixed_point(abar, rmax, k, &ro, &wo, t);
        double wr = 0.0;
        for (int j = 0; j < m; j++) wr += 2.0 / M_PI * abar * S->s[j] * influence(ro, rr[j]) * p[j];
        double F32, f12;
        eval_F(o->f32_mode, wr + ro * ro - ap, &F32, &f12);
        P += wo * ro * mu * F32;
      }
      gsl_integration_glfixed_table_free(t);
    }
  }
  r->Pstar_sigma = 3.0 * M_SQRT2 / 8.0 * 2.0 * M_PI * P;
  r->Pstar_delta = ap > 0.0 ? r->Pstar_sigma / (ap * sqrt(ap)) : 0.0;
  r->abar = abar;
  r->p0 = p[0];
  free(buf);
  /* P/P_h(delta) overflows for alpha' below ~1e-205; an iteration that
     left the range of doubles: DC_ERANGE, result untouched */
  int ok = isfinite(r->Pstar_sigma) && isfinite(r->Pstar_delta) && isfinite(r->p0);
  for (int i = 0; i < r->iterations && i < DC_GW_SOLVER_MAX_HIST; i++) ok &= isfinite(r->hist[i]) != 0;
  if (st == DC_ERANGE || !ok) return DC_ERANGE;
  memcpy(out, r, sizeof *out);
  return st;
}
